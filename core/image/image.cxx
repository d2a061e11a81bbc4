#include "core/image/image.h"

#include "core/error.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <limits>
#include <mutex>
#include <random>
#include <unistd.h>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

// OpenImageIO is not hardened against hostile files: cap what a single image may claim.
constexpr int kMaxSide = 32768;
constexpr std::size_t kMaxValues = std::size_t(256) << 20; // pixels x channels read
constexpr int kMaxReadChannels = 4;
// Decoded as float, kMaxValues is 1 GiB; 2 GiB leaves room for 8-byte native formats.
constexpr int kImageSizeBudgetMB = 2048;

void configureOpenImageIO()
{
  static std::once_flag once;
  std::call_once(once,
                 []
                 {
                   OIIO::attribute("limits:imagesize_MB", kImageSizeBudgetMB);
                   // Many-channel render outputs are legitimate, absurd counts are not.
                   OIIO::attribute("limits:channels", 256);
                 });
}

// OpenImageIO messages can span several lines and repeat the file name; keep the first line.
std::string firstLine(std::string text)
{
  const auto end = text.find('\n');
  if (end != std::string::npos)
  {
    text.erase(end);
  }
  while (!text.empty() && (text.back() == ' ' || text.back() == '\r'))
  {
    text.pop_back();
  }
  return text.empty() ? std::string("no reason given") : text;
}

std::string lowerExtension(const std::string& path)
{
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  return ext;
}

// Checks the file before any decoder sees it: decoders give poor messages for these cases,
// and a FIFO or device would block or never end.
void checkReadableFile(const std::string& path)
{
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status))
  {
    const std::string reason = ec ? ec.message() : std::string(std::strerror(ENOENT));
    throw errorAbout(path, "cannot open (" + reason + ")");
  }
  if (fs::is_directory(status))
  {
    throw errorAbout(path, "is a directory, not an image");
  }
  if (!fs::is_regular_file(status))
  {
    throw errorAbout(path, "not a regular file");
  }
  const auto size = fs::file_size(path, ec);
  if (ec)
  {
    throw errorAbout(path, "cannot open (" + ec.message() + ")");
  }
  if (size == 0)
  {
    throw errorAbout(path, "file is empty");
  }
  std::FILE* probe = std::fopen(path.c_str(), "rb");
  if (!probe)
  {
    throw errorAbout(path, std::string("cannot open (") + std::strerror(errno) + ")");
  }
  std::fclose(probe);
}

void checkSpec(const std::string& path, const OIIO::ImageSpec& spec)
{
  if (spec.width <= 0 || spec.height <= 0)
  {
    throw errorAbout(path,
                     "image is " + std::to_string(spec.width) + "x" + std::to_string(spec.height));
  }
  if (spec.width > kMaxSide || spec.height > kMaxSide)
  {
    throw errorAbout(path, "image is " + std::to_string(spec.width) + "x" +
                               std::to_string(spec.height) + ", larger than " +
                               std::to_string(kMaxSide) + " per side");
  }
  if (spec.depth != 1)
  {
    throw errorAbout(path,
                     "volume images (depth " + std::to_string(spec.depth) + ") are not supported");
  }
  if (spec.deep)
  {
    throw errorAbout(path, "deep images are not supported");
  }
  if (spec.nchannels <= 0)
  {
    throw errorAbout(path, "image has no channels");
  }
  const std::size_t values = std::size_t(spec.width) * std::size_t(spec.height) *
                             std::size_t(std::min(spec.nchannels, kMaxReadChannels));
  if (values > kMaxValues)
  {
    throw errorAbout(path, "image has " + std::to_string(values) +
                               " pixel values, more than the budget of " +
                               std::to_string(kMaxValues));
  }
}

// The file format chosen by extension, or empty when the extension is not one writeImage writes.
std::string formatForExtension(const std::string& ext)
{
  if (ext == ".exr")
  {
    return "openexr";
  }
  if (ext == ".png")
  {
    return "png";
  }
  if (ext == ".tif" || ext == ".tiff")
  {
    return "tiff";
  }
  if (ext == ".hdr")
  {
    return "hdr";
  }
  return {};
}

// Removes the temporary file unless the write was committed by the final rename.
class TempFile
{
public:
  explicit TempFile(std::string path) : path_(std::move(path)) {}
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile()
  {
    if (!committed_)
    {
      std::remove(path_.c_str());
    }
  }
  const std::string& path() const { return path_; }
  void commit() { committed_ = true; }

private:
  std::string path_;
  bool committed_ = false;
};

// A new, empty file beside the target (same file system, so rename is atomic). O_EXCL makes it
// ours even when several writers target the same directory; mode 0666 lets the umask decide.
std::string createTempBeside(const std::string& path)
{
  const fs::path target(path);
  fs::path dir = target.parent_path();
  if (dir.empty())
  {
    dir = ".";
  }
  std::random_device device;
  std::mt19937_64 random(device() ^ (std::uint64_t(::getpid()) << 32));
  int lastErrno = 0;
  for (int attempt = 0; attempt < 16; ++attempt)
  {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".tmp%016llx", static_cast<unsigned long long>(random()));
    const std::string candidate = (dir / ("." + target.filename().string() + suffix)).string();
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0)
    {
      ::close(fd);
      return candidate;
    }
    lastErrno = errno;
    if (lastErrno != EEXIST)
    {
      break;
    }
  }
  throw errorAbout(path, "cannot create a file in " + dir.string() + " (" +
                             std::strerror(lastErrno) + ")");
}

// Writes all bytes to the (already created) temporary file and flushes them to the disk, so the
// rename that follows publishes a complete file even across a crash.
void writeFileBytes(const std::string& path, const std::string& temp,
                    const std::vector<unsigned char>& bytes)
{
  const int fd = ::open(temp.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0)
  {
    throw errorAbout(path, std::string("cannot write (") + std::strerror(errno) + ")");
  }
  std::size_t done = 0;
  while (done < bytes.size())
  {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      const int error = n < 0 ? errno : EIO;
      ::close(fd);
      throw errorAbout(path, std::string("cannot write (") + std::strerror(error) + ")");
    }
    done += std::size_t(n);
  }
  if (::fsync(fd) != 0 && errno != EINVAL)
  {
    const int error = errno;
    ::close(fd);
    throw errorAbout(path, std::string("cannot write (") + std::strerror(error) + ")");
  }
  if (::close(fd) != 0)
  {
    throw errorAbout(path, std::string("cannot write (") + std::strerror(errno) + ")");
  }
}

void checkWritable(const std::string& path, const Image& image)
{
  if (image.width <= 0 || image.height <= 0)
  {
    throw errorAbout(path, "cannot write an image of " + std::to_string(image.width) + "x" +
                               std::to_string(image.height));
  }
  if (image.channels < 1 || image.channels > 4)
  {
    throw errorAbout(path, "cannot write " + std::to_string(image.channels) +
                               " channels (1 to 4 supported)");
  }
  if (image.data.size() != std::size_t(image.width) * image.height * image.channels)
  {
    throw errorAbout(path, "image data holds " + std::to_string(image.data.size()) +
                               " values, not width x height x channels");
  }
  std::error_code ec;
  if (fs::is_directory(path, ec))
  {
    throw errorAbout(path, "is a directory");
  }
}

// Unsigned normalised quantisation with round-to-nearest; NaN stores 0 (it has no integer code).
template <typename T>
std::vector<T> quantise(const std::vector<float>& values)
{
  constexpr double maxCode = double(std::numeric_limits<T>::max());
  std::vector<T> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    const double v = std::isnan(values[i]) ? 0.0 : std::clamp(double(values[i]), 0.0, 1.0);
    out[i] = T(std::lround(v * maxCode));
  }
  return out;
}

// Radiance HDR stores non-negative RGB only: grey is replicated, a missing blue is 0, a fourth
// channel is dropped, and negative or NaN values become 0.
std::vector<float> toHdrRgb(const Image& image)
{
  const std::size_t pixels = std::size_t(image.width) * image.height;
  std::vector<float> rgb(pixels * 3, 0.0f);
  for (std::size_t p = 0; p < pixels; ++p)
  {
    const float* src = &image.data[p * image.channels];
    for (int c = 0; c < 3; ++c)
    {
      float v = 0.0f;
      if (image.channels == 1)
      {
        v = src[0];
      }
      else if (c < image.channels)
      {
        v = src[c];
      }
      rgb[p * 3 + c] = (v > 0.0f) ? v : 0.0f; // also maps NaN to 0
    }
  }
  return rgb;
}

std::vector<std::string> channelNames(int channels)
{
  switch (channels)
  {
  case 1:
    return {"Y"};
  case 2:
    return {"R", "G"};
  case 3:
    return {"R", "G", "B"};
  default:
    return {"R", "G", "B", "A"};
  }
}
} // namespace

Image readImage(const std::string& path, ImageInfo* info)
{
  configureOpenImageIO();
  if (path.empty())
  {
    throw errorAbout("image path", "empty");
  }
  checkReadableFile(path);

  // Keep colour values as stored when there is an alpha channel: a fourth channel of a data map
  // (normals, quaternions) is not coverage, and premultiplying would corrupt it.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path, &config);
  if (!input)
  {
    throw errorAbout(path,
                     "not an image OpenImageIO can read (" + firstLine(OIIO::geterror()) + ")");
  }
  const OIIO::ImageSpec spec = input->spec();
  checkSpec(path, spec);

  // More than four channels (render passes in an EXR): the first four are read, which
  // OpenImageIO orders R, G, B, A when the file names them so.
  const int channels = std::min(spec.nchannels, kMaxReadChannels);
  Image image(spec.width, spec.height, channels);
  const bool decoded = input->read_image(0, 0, 0, channels, OIIO::TypeFloat, image.data.data());
  // Some readers (TIFF) report a short read through geterror() yet return true: both count.
  const std::string decodeError = input->geterror();
  if (!decoded || !decodeError.empty())
  {
    input->close();
    throw errorAbout(path, "cannot decode pixels (" + firstLine(decodeError) + ")");
  }
  if (!input->close())
  {
    throw errorAbout(path, "cannot close (" + firstLine(input->geterror()) + ")");
  }

  if (info)
  {
    // Unsigned integers decode to [0, 1]; signed integers decode to [-1, 1], which are already
    // signed values like floats, so only the former count as integer-encoded.
    info->integerFormat = !spec.format.is_floating_point() && !spec.format.is_signed();
    info->fileChannels = spec.nchannels;
  }
  return image;
}

void writeImage(const std::string& path, const Image& image, const WriteOptions& options)
{
  configureOpenImageIO();
  if (path.empty())
  {
    throw errorAbout("image path", "empty");
  }
  const std::string format = formatForExtension(lowerExtension(path));
  if (format.empty())
  {
    throw errorAbout(path, "unknown image extension (use .exr, .png, .tif, .tiff or .hdr)");
  }
  checkWritable(path, image);

  const int fileChannels = (format == "hdr") ? 3 : image.channels;
  OIIO::TypeDesc fileType = OIIO::TypeFloat;
  if (format == "openexr")
  {
    fileType = options.halfFloat ? OIIO::TypeHalf : OIIO::TypeFloat;
  }
  else if (format == "png")
  {
    fileType = OIIO::TypeUInt8;
  }
  else if (format == "tiff")
  {
    fileType = OIIO::TypeUInt16;
  }
  OIIO::ImageSpec spec(image.width, image.height, fileChannels, fileType);
  spec.channelnames = channelNames(fileChannels);
  spec.alpha_channel = -1;
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (format == "tiff")
  {
    // There is no Exif metadata to write, and OpenImageIO 2.4 fails writing an empty Exif
    // directory to memory.
    spec.attribute("tiff:write_exif", 0);
  }

  // Conversion happens here, not in the writer, so rounding and clamping are defined above.
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint16_t> words;
  std::vector<float> rgb;
  OIIO::TypeDesc bufferType = OIIO::TypeFloat;
  const void* pixels = image.data.data();
  if (format == "png")
  {
    bytes = quantise<std::uint8_t>(image.data);
    bufferType = OIIO::TypeUInt8;
    pixels = bytes.data();
  }
  else if (format == "tiff")
  {
    words = quantise<std::uint16_t>(image.data);
    bufferType = OIIO::TypeUInt16;
    pixels = words.data();
  }
  else if (format == "hdr")
  {
    rgb = toHdrRgb(image);
    pixels = rgb.data();
  }

  // Encoded in memory first; the bytes reach the disk through writeFileBytes, which checks every
  // call (OpenImageIO's PNG writer ignores failed file writes).
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput proxy(encoded);
  auto output = OIIO::ImageOutput::create(format, &proxy);
  if (!output)
  {
    throw errorAbout(path, "no " + format + " writer (" + firstLine(OIIO::geterror()) + ")");
  }
  if (!output->open(path, spec))
  {
    throw errorAbout(path, "cannot encode (" + firstLine(output->geterror()) + ")");
  }
  const bool written = output->write_image(bufferType, pixels);
  const bool closed = output->close();
  const std::string encodeError = output->geterror();
  if (!written || !closed || !encodeError.empty() || encoded.empty())
  {
    throw errorAbout(path, "cannot encode (" + firstLine(encodeError) + ")");
  }
  output.reset();

  TempFile temp(createTempBeside(path));
  writeFileBytes(path, temp.path(), encoded);
  if (std::rename(temp.path().c_str(), path.c_str()) != 0)
  {
    throw errorAbout(path, std::string("cannot replace (") + std::strerror(errno) + ")");
  }
  temp.commit();
}
} // namespace aniso
