#pragma once
// Float images and their I/O through OpenImageIO. Row 0 is the top row, as files store it.
#include <cstddef>
#include <string>
#include <vector>

namespace aniso
{
struct Image
{
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> data; // width * height * channels, interleaved, row-major

  Image() = default;
  Image(int w, int h, int c) : width(w), height(h), channels(c), data(std::size_t(w) * h * c, 0.0f) {}
  float& at(int x, int y, int c) { return data[(std::size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return data[(std::size_t(y) * width + x) * channels + c]; }
  bool empty() const { return data.empty(); }
};

struct ImageInfo
{
  bool integerFormat = false; // 8/16/32-bit integer pixels in the file (decoded to [0,1])
  int fileChannels = 0;
};

// Reads any format OpenImageIO reads, converted to float (integer formats to [0,1]).
// Validates dimensions, channel count and pixel budget before decoding; throws aniso::Error
// "PATH: reason" on any failure. Never returns an empty image.
Image readImage(const std::string& path, ImageInfo* info = nullptr);

// Writes by extension: .exr (32-bit float, or half when halfFloat), .png (8-bit, values
// clamped to [0,1], no transform applied here), .tif/.tiff (16-bit), .hdr (float RGB).
// Written to a temporary file in the same directory and renamed, so a failure never leaves a
// partial file at PATH. Throws aniso::Error "PATH: reason".
struct WriteOptions
{
  bool halfFloat = false;
};
void writeImage(const std::string& path, const Image& image, const WriteOptions& options = {});
} // namespace aniso
