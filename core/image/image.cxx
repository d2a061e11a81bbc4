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

// OpenEXR 3.1 trusts the sizes its header states: it allocates an attribute of whatever size
// the header claims (a few bytes can ask for gigabytes) and an offset table for whatever data
// window and tiling it states, before OpenImageIO sees any of it. So for a file with the EXR
// magic number, walk its header(s) first: every attribute must lie inside the file, the data
// window must be within kMaxSide per side, and the tiles must be few enough for their offset
// table. Files without the magic number are left to OpenImageIO.
class ExrHeaderWalk
{
public:
  ExrHeaderWalk(const std::string& path, std::FILE* file, long long size)
    : path_(path)
    , file_(file)
    , size_(size)
  {
  }

  void check()
  {
    unsigned char start[8];
    if (size_ < 8 || std::fread(start, 1, 8, file_) != 8)
    {
      return; // too short for the magic number: OpenImageIO says what it is not
    }
    if (start[0] != 0x76 || start[1] != 0x2f || start[2] != 0x31 || start[3] != 0x01)
    {
      return;
    }
    offset_ = 8;
    const unsigned flags = unsigned(start[5]) << 8 | unsigned(start[6]) << 16;
    maxName_ = (flags & 0x400u) ? 255 : 31;
    const bool multipart = (flags & 0x1000u) != 0;
    const int kMaxParts = 1024;
    for (int part = 0;; ++part)
    {
      if (part >= kMaxParts)
      {
        fail("header names more than " + std::to_string(kMaxParts) + " parts");
      }
      const bool empty = walkHeader(/*mayBeEmpty=*/multipart && part > 0);
      if (!multipart || empty)
      {
        return;
      }
    }
  }

private:
  [[noreturn]] void fail(const std::string& reason) const
  {
    throw errorAbout(path_, "not a valid OpenEXR file (" + reason + ")");
  }

  int nextByte()
  {
    const int ch = std::fgetc(file_);
    if (ch == EOF)
    {
      fail("header ends before its end marker");
    }
    ++offset_;
    return ch;
  }

  // A null-terminated name of at most maxName_ characters; empty marks the end of a header.
  std::string readName(const char* what)
  {
    std::string name;
    for (int ch = nextByte(); ch != 0; ch = nextByte())
    {
      if (int(name.size()) >= maxName_)
      {
        fail(std::string(what) + " longer than " + std::to_string(maxName_) + " characters");
      }
      name.push_back(char(ch));
    }
    return name;
  }

  std::int32_t readInt()
  {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
    {
      v |= std::uint32_t(nextByte()) << (8 * i);
    }
    std::int32_t out;
    std::memcpy(&out, &v, 4);
    return out;
  }

  // Walks one header; returns true when it is the empty header that ends a multi-part list.
  bool walkHeader(bool mayBeEmpty)
  {
    long long xMin = 0, yMin = 0, xMax = -1, yMax = -1;
    bool window = false;
    long long tileX = 0, tileY = 0;
    for (bool first = true;; first = false)
    {
      const std::string name = readName("attribute name");
      if (name.empty())
      {
        if (first && mayBeEmpty)
        {
          return true;
        }
        break;
      }
      const std::string type = readName("attribute type");
      const std::int32_t bytes = readInt();
      if (bytes < 0 || bytes > size_ - offset_)
      {
        fail("attribute '" + name + "' claims " + std::to_string(bytes) + " bytes, the file has " +
             std::to_string(size_ - offset_) + " left");
      }
      if (name == "dataWindow" && type == "box2i" && bytes == 16)
      {
        xMin = readInt();
        yMin = readInt();
        xMax = readInt();
        yMax = readInt();
        window = true;
      }
      else if (name == "tiles" && type == "tiledesc" && bytes == 9)
      {
        tileX = std::uint32_t(readInt());
        tileY = std::uint32_t(readInt());
        nextByte();
      }
      else
      {
        if (std::fseek(file_, bytes, SEEK_CUR) != 0)
        {
          fail("cannot seek past attribute '" + name + "'");
        }
        offset_ += bytes;
      }
    }
    if (window)
    {
      const long long w = xMax - xMin + 1;
      const long long h = yMax - yMin + 1;
      if (w < 1 || h < 1 || w > kMaxSide || h > kMaxSide)
      {
        fail("data window " + std::to_string(w) + "x" + std::to_string(h) + ", allowed 1 to " +
             std::to_string(kMaxSide) + " per side");
      }
      if (tileX > 0 && tileY > 0)
      {
        const long long tiles = ((w + tileX - 1) / tileX) * ((h + tileY - 1) / tileY);
        constexpr long long kMaxTiles = 1LL << 22;
        if (tiles > kMaxTiles)
        {
          fail(std::to_string(tiles) + " tiles of " + std::to_string(tileX) + "x" +
               std::to_string(tileY) + ", more than " + std::to_string(kMaxTiles));
        }
      }
    }
    return false;
  }

  const std::string& path_;
  std::FILE* file_;
  long long size_;
  long long offset_ = 0;
  int maxName_ = 31;
};

void checkExrHeader(const std::string& path)
{
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file)
  {
    throw errorAbout(path, std::string("cannot open (") + std::strerror(errno) + ")");
  }
  struct Closer
  {
    std::FILE* f;
    ~Closer() { std::fclose(f); }
  } closer{file};
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec)
  {
    throw errorAbout(path, "cannot read its size (" + ec.message() + ")");
  }
  ExrHeaderWalk(path, file, static_cast<long long>(size)).check();
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
  checkExrHeader(path);

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
