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
  Image(int w, int h, int c) : width(w), height(h), channels(c), data(std::size_t(w) * h * c, 0.0f)
  {
  }
  float& at(int x, int y, int c) { return data[(std::size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return data[(std::size_t(y) * width + x) * channels + c]; }
  bool empty() const { return data.empty(); }
};

struct ImageInfo
{
  // Unsigned 8/16/32-bit integer pixels in the file, decoded to [0,1]. Signed integer pixels
  // decode to [-1,1], already signed like floats, so they do not count as integer-encoded.
  bool integerFormat = false;
  int fileChannels = 0; // channels in the file (the image holds at most 4 of them)
};

// Reads any format OpenImageIO reads, converted to float (integer formats to [0,1]).
// Validates before decoding: a regular, non-empty file; width and height in 1..32768; depth 1;
// at most 256 Mi values (pixels x channels read). Files with more than 4 channels give their
// first 4 (R, G, B, A when named so). Alpha is never premultiplied or divided out. NaN and Inf
// are kept as stored (callers that need finite data validate it). Throws aniso::Error
// "PATH: reason" on any failure. Never returns an empty image.
Image readImage(const std::string& path, ImageInfo* info = nullptr);

// Writes by extension (case-insensitive): .exr (32-bit float, or half when halfFloat),
// .png (8-bit), .tif/.tiff (16-bit), both quantised with round-to-nearest after clamping to
// [0,1] (NaN stores 0; no transfer function applied here), .hdr (RGB: grey replicated, missing
// blue 0, fourth channel dropped, negative and NaN 0). 1 to 4 channels, never premultiplied.
// Written to a temporary file in the same directory and renamed, so a failure never leaves a
// partial file at PATH nor replaces an existing one. Throws aniso::Error "PATH: reason".
struct WriteOptions
{
  bool halfFloat = false;
};
void writeImage(const std::string& path, const Image& image, const WriteOptions& options = {});
} // namespace aniso
