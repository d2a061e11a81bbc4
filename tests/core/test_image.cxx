// Image I/O: round trips through every written format against the values generated here (the
// independent reference), within each format's stated precision, and the failure paths: every
// bad input gives an aniso::Error naming the file, and no failed write leaves a partial or
// temporary file or replaces an existing one.
#include "core/error.h"
#include "core/image/image.h"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <random>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using aniso::Image;

class ImageIo : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::random_device device;
    dir_ = fs::temp_directory_path() /
           ("aniso-test-image-" + std::to_string(::getpid()) + "-" + std::to_string(device()));
    fs::create_directories(dir_);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Every entry of the test directory, so a test can see that nothing was left behind.
  std::vector<std::string> entries() const
  {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
    {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

Image randomImage(int w, int h, int c, float lo, float hi, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> dist(lo, hi);
  Image image(w, h, c);
  for (float& v : image.data)
  {
    v = dist(random);
  }
  return image;
}

std::string fileBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

// The message of the aniso::Error thrown by f, or a test failure when none is thrown.
template <typename F>
std::string errorOf(F&& f)
{
  try
  {
    f();
  }
  catch (const aniso::Error& e)
  {
    return e.what();
  }
  ADD_FAILURE() << "no aniso::Error thrown";
  return {};
}

void expectSameShape(const Image& a, const Image& b)
{
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.channels, b.channels);
  ASSERT_EQ(a.data.size(), b.data.size());
}

// Float EXR stores 32-bit floats, so every value, including NaN and extremes, comes back bit
// for bit; for every channel count writeImage accepts.
TEST_F(ImageIo, ExrFloatRoundTripIsExact)
{
  for (int channels = 1; channels <= 4; ++channels)
  {
    Image image = randomImage(37, 23, channels, -1000.0f, 1000.0f, 11u + unsigned(channels));
    image.data[0] = 3.0e38f;
    image.data[1] = -1.0e-30f;
    image.data[2] = std::nanf("");
    const std::string file = path("float" + std::to_string(channels) + ".exr");
    aniso::writeImage(file, image);
    aniso::ImageInfo info;
    const Image back = aniso::readImage(file, &info);
    expectSameShape(image, back);
    EXPECT_FALSE(info.integerFormat);
    EXPECT_EQ(info.fileChannels, channels);
    EXPECT_TRUE(std::isnan(back.data[2]));
    for (std::size_t i = 0; i < image.data.size(); ++i)
    {
      if (i != 2)
      {
        ASSERT_EQ(back.data[i], image.data[i]) << "value " << i;
      }
    }
  }
}

// Half EXR: round to nearest half, relative error at most 2^-11 for normal halves, absolute
// 2^-25 below them (half the smallest subnormal step 2^-24).
TEST_F(ImageIo, ExrHalfRoundTripWithinHalfPrecision)
{
  Image image = randomImage(31, 17, 4, -1000.0f, 1000.0f, 5u);
  for (std::size_t i = 0; i < image.data.size(); i += 3)
  {
    image.data[i] *= 1e-6f; // some values near and below the smallest normal half (6.1e-5)
  }
  const std::string file = path("half.exr");
  aniso::writeImage(file, image, aniso::WriteOptions{true});
  const Image back = aniso::readImage(file);
  expectSameShape(image, back);
  for (std::size_t i = 0; i < image.data.size(); ++i)
  {
    const double tolerance =
        std::abs(double(image.data[i])) * std::ldexp(1.0, -11) + std::ldexp(1.0, -25);
    ASSERT_NEAR(back.data[i], image.data[i], tolerance) << "value " << i;
  }
}

// 8-bit PNG: round(v * 255) / 255 is within half a step of v in [0, 1]; out-of-range values
// clamp, NaN stores 0. Four channels with zero alpha show that colour is not premultiplied.
TEST_F(ImageIo, Png8BitRoundTripWithinHalfStep)
{
  Image image = randomImage(29, 19, 4, 0.0f, 1.0f, 7u);
  for (int x = 0; x < image.width; ++x)
  {
    image.at(x, 0, 3) = 0.0f;
  }
  image.at(1, 1, 0) = -0.5f;
  image.at(1, 1, 1) = 1.5f;
  image.at(1, 1, 2) = std::nanf("");
  const std::string file = path("bytes.png");
  aniso::writeImage(file, image);
  aniso::ImageInfo info;
  const Image back = aniso::readImage(file, &info);
  expectSameShape(image, back);
  EXPECT_TRUE(info.integerFormat);
  EXPECT_EQ(info.fileChannels, 4);
  EXPECT_EQ(back.at(1, 1, 0), 0.0f);
  EXPECT_EQ(back.at(1, 1, 1), 1.0f);
  EXPECT_EQ(back.at(1, 1, 2), 0.0f);
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      for (int c = 0; c < 4; ++c)
      {
        if (y == 1 && x == 1 && c < 3)
        {
          continue;
        }
        ASSERT_NEAR(back.at(x, y, c), image.at(x, y, c), 0.5 / 255.0 + 1e-6)
            << x << "," << y << "," << c;
      }
    }
  }
}

// 16-bit TIFF: within half a step of 1/65535, for one to four channels.
TEST_F(ImageIo, Tiff16BitRoundTripWithinHalfStep)
{
  for (int channels = 1; channels <= 4; ++channels)
  {
    const Image image = randomImage(23, 13, channels, 0.0f, 1.0f, 3u + unsigned(channels));
    const std::string file = path("words" + std::to_string(channels) + ".tiff");
    aniso::writeImage(file, image);
    aniso::ImageInfo info;
    const Image back = aniso::readImage(file, &info);
    expectSameShape(image, back);
    EXPECT_TRUE(info.integerFormat);
    for (std::size_t i = 0; i < image.data.size(); ++i)
    {
      ASSERT_NEAR(back.data[i], image.data[i], 0.5 / 65535.0 + 1e-7) << "value " << i;
    }
  }
}

// Radiance RGBE: one shared exponent and 8-bit mantissas, so each component is within
// 2^-7 of the pixel's largest component; the fourth channel is dropped.
TEST_F(ImageIo, HdrRoundTripWithinSharedExponentPrecision)
{
  const Image image = randomImage(21, 11, 4, 0.0f, 50.0f, 13u);
  const std::string file = path("radiance.hdr");
  aniso::writeImage(file, image);
  const Image back = aniso::readImage(file);
  ASSERT_EQ(back.width, image.width);
  ASSERT_EQ(back.height, image.height);
  ASSERT_EQ(back.channels, 3);
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      const float largest = std::max({image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)});
      for (int c = 0; c < 3; ++c)
      {
        ASSERT_NEAR(back.at(x, y, c), image.at(x, y, c), largest * std::ldexp(1.0, -7));
      }
    }
  }
}

// The extension decides the format whatever its case.
TEST_F(ImageIo, UpperCaseExtensionIsRecognised)
{
  const Image image = randomImage(4, 3, 3, 0.0f, 1.0f, 17u);
  const std::string file = path("upper.EXR");
  aniso::writeImage(file, image);
  const Image back = aniso::readImage(file);
  EXPECT_EQ(back.data, image.data);
}

// A file with more than four channels gives its first four, in file order R, G, B, A. The
// fixture is written with OpenImageIO directly, so it does not depend on writeImage.
TEST_F(ImageIo, WideExrGivesFirstFourChannels)
{
  const int w = 5;
  const int h = 4;
  const int nc = 6;
  std::vector<float> pixels(std::size_t(w) * h * nc);
  for (std::size_t i = 0; i < pixels.size(); ++i)
  {
    pixels[i] = float(i % nc) * 10.0f + float(i / nc);
  }
  OIIO::ImageSpec spec(w, h, nc, OIIO::TypeFloat);
  spec.channelnames = {"R", "G", "B", "A", "depth.Z", "extra.W"};
  const std::string file = path("wide.exr");
  auto out = OIIO::ImageOutput::create(file);
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(file, spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
  ASSERT_TRUE(out->close());

  aniso::ImageInfo info;
  const Image back = aniso::readImage(file, &info);
  EXPECT_EQ(info.fileChannels, nc);
  ASSERT_EQ(back.channels, 4);
  for (int p = 0; p < w * h; ++p)
  {
    for (int c = 0; c < 4; ++c)
    {
      ASSERT_EQ(back.data[std::size_t(p) * 4 + c], float(c) * 10.0f + float(p));
    }
  }
}

TEST_F(ImageIo, MissingFileNamesThePath)
{
  const std::string file = path("absent.png");
  const std::string message = errorOf([&] { aniso::readImage(file); });
  EXPECT_NE(message.find(file + ": cannot open"), std::string::npos) << message;
}

TEST_F(ImageIo, ZeroByteFileNamesThePath)
{
  const std::string file = path("empty.exr");
  writeBytes(file, "");
  const std::string message = errorOf([&] { aniso::readImage(file); });
  EXPECT_NE(message.find(file + ": "), std::string::npos) << message;
}

TEST_F(ImageIo, TextFileRenamedExrNamesThePath)
{
  const std::string file = path("notes.exr");
  writeBytes(file, "These are notes, not pixels.\nSecond line.\n");
  const std::string message = errorOf([&] { aniso::readImage(file); });
  EXPECT_NE(message.find(file + ": not an image"), std::string::npos) << message;
}

TEST_F(ImageIo, DirectoryIsNotAnImage)
{
  const std::string message = errorOf([&] { aniso::readImage(dir_.string()); });
  EXPECT_NE(message.find(dir_.string() + ": "), std::string::npos) << message;
}

// A valid file cut in half: the header still opens, the pixel data cannot be decoded.
TEST_F(ImageIo, TruncatedFilesNameThePath)
{
  for (const std::string name : {"cut.png", "cut.exr", "cut.tif"})
  {
    const std::string file = path(name);
    aniso::writeImage(file, randomImage(64, 64, 3, 0.0f, 1.0f, 19u));
    const std::string bytes = fileBytes(file);
    writeBytes(file, bytes.substr(0, bytes.size() / 2));
    const std::string message = errorOf([&] { aniso::readImage(file); });
    EXPECT_NE(message.find(file + ": "), std::string::npos) << message;
  }
}

// Headers claiming absurd sizes are rejected before any pixel is decoded (PGM headers are
// plain text, so they can claim anything in a few bytes).
TEST_F(ImageIo, OversizedHeadersAreRejected)
{
  const std::string wide = path("wide.pgm");
  writeBytes(wide, "P5\n40000 1\n255\n" + std::string(64, '\0'));
  std::string message = errorOf([&] { aniso::readImage(wide); });
  EXPECT_NE(message.find(wide + ": image is 40000x1"), std::string::npos) << message;

  const std::string huge = path("huge.pgm");
  writeBytes(huge, "P5\n20000 20000\n255\n" + std::string(64, '\0'));
  message = errorOf([&] { aniso::readImage(huge); });
  EXPECT_NE(message.find(huge + ": "), std::string::npos) << message;
  EXPECT_NE(message.find("budget"), std::string::npos) << message;

  const std::string none = path("none.pgm");
  writeBytes(none, "P5\n0 0\n255\n");
  message = errorOf([&] { aniso::readImage(none); });
  EXPECT_NE(message.find(none + ": "), std::string::npos) << message;
}

// An EXR written by OpenImageIO (tiled, or with two parts) passes readImage's header walk and
// reads back bit for bit; the same file with one size in its header made absurd is refused
// with the attribute named, before OpenEXR allocates what the header claims.
void writeExr(const std::string& file, const std::vector<float>& pixels, int w, int h,
              bool tiled, bool twoParts)
{
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeFloat);
  if (tiled)
  {
    spec.tile_width = 16;
    spec.tile_height = 16;
  }
  auto out = OIIO::ImageOutput::create(file);
  ASSERT_TRUE(out);
  if (twoParts)
  {
    OIIO::ImageSpec specs[2] = {spec, spec};
    ASSERT_TRUE(out->open(file, 2, specs));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
    ASSERT_TRUE(out->open(file, specs[1], OIIO::ImageOutput::AppendSubimage));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
  }
  else
  {
    ASSERT_TRUE(out->open(file, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
  }
  ASSERT_TRUE(out->close());
}

TEST_F(ImageIo, ExrHeadersOfIndependentWriterPassTheWalk)
{
  const int w = 40;
  const int h = 24;
  std::vector<float> pixels(std::size_t(w) * h * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i)
  {
    pixels[i] = float(i) * 0.25f;
  }
  for (const bool tiled : {false, true})
  {
    for (const bool twoParts : {false, true})
    {
      const std::string file = path("writer.exr");
      writeExr(file, pixels, w, h, tiled, twoParts);
      const std::string bytes = fileBytes(file);
      if (twoParts)
      {
        ASSERT_NE(static_cast<unsigned char>(bytes[5]) & 0x10u, 0u) << "not a multi-part file";
      }
      const Image back = aniso::readImage(file);
      ASSERT_EQ(back.width, w);
      ASSERT_EQ(back.height, h);
      ASSERT_EQ(back.channels, 3);
      EXPECT_EQ(back.data, pixels) << "tiled " << tiled << ", two parts " << twoParts;
    }
  }
}

// The position of the 4-byte size of attribute `name` in an EXR's first header.
std::size_t exrAttributeSizeAt(const std::string& bytes, const std::string& name)
{
  const std::size_t at = bytes.find(std::string(name).append(1, '\0'), 8);
  if (at == std::string::npos)
  {
    ADD_FAILURE() << "no attribute " << name;
    return 0;
  }
  const std::size_t type = at + name.size() + 1;
  return bytes.find('\0', type) + 1;
}

TEST_F(ImageIo, ExrHeaderClaimingMoreThanTheFileIsRefused)
{
  const int w = 8;
  const int h = 8;
  const std::vector<float> pixels(std::size_t(w) * h * 3, 0.5f);
  const std::string file = path("claims.exr");
  writeExr(file, pixels, w, h, false, false);
  const std::string good = fileBytes(file);

  // An attribute 2 GiB long in a file of a few hundred bytes.
  std::string bytes = good;
  const std::size_t size = exrAttributeSizeAt(bytes, "compression");
  bytes.replace(size, 4, std::string("\xff\xff\xff\x7f", 4));
  writeBytes(file, bytes);
  std::string message = errorOf([&] { aniso::readImage(file); });
  EXPECT_NE(message.find(file + ": not a valid OpenEXR file (attribute 'compression' claims"),
            std::string::npos)
      << message;

  // A data window of 2^30 lines (OpenEXR would allocate its line offset table).
  bytes = good;
  const std::size_t window = exrAttributeSizeAt(bytes, "dataWindow") + 4;
  bytes.replace(window + 12, 4, std::string("\x00\x00\x00\x40", 4)); // yMax
  writeBytes(file, bytes);
  message = errorOf([&] { aniso::readImage(file); });
  EXPECT_NE(message.find(file + ": not a valid OpenEXR file (data window 8x1073741825"),
            std::string::npos)
      << message;

  // The header cut before its end marker.
  writeBytes(file, good.substr(0, size + 2));
  message = errorOf([&] { aniso::readImage(file); });
  EXPECT_NE(message.find(file + ": not a valid OpenEXR file (header ends"), std::string::npos)
      << message;
}

// The fuzzing finding kept in tests/data/fuzz/image (its first byte picks the harness's
// extension): a 284-byte EXR whose string attribute claims 1.7 GB.
TEST_F(ImageIo, FuzzedExrWithHugeAttributeIsRefused)
{
  const std::string input =
      fileBytes(std::string(ANISO_SOURCE_DIR) + "/tests/data/fuzz/image/exr-huge-string-attribute");
  ASSERT_GT(input.size(), 1u);
  const std::string file = path("fuzzed.exr");
  writeBytes(file, input.substr(1));
  const std::string message = errorOf([&] { aniso::readImage(file); });
  EXPECT_NE(message.find(file + ": not a valid OpenEXR file (attribute 'capDate' claims"),
            std::string::npos)
      << message;
}

TEST_F(ImageIo, UnknownExtensionWritesNothing)
{
  const std::string file = path("picture.xyz");
  const std::string message =
      errorOf([&] { aniso::writeImage(file, randomImage(2, 2, 3, 0.0f, 1.0f, 1u)); });
  EXPECT_NE(message.find(file + ": unknown image extension"), std::string::npos) << message;
  EXPECT_TRUE(entries().empty());
}

TEST_F(ImageIo, InconsistentImagesWriteNothing)
{
  Image fiveChannels(2, 2, 5);
  Image shortData = randomImage(3, 3, 3, 0.0f, 1.0f, 2u);
  shortData.data.pop_back();
  const Image empty;
  for (const Image* image : std::vector<const Image*>{&fiveChannels, &shortData, &empty})
  {
    const std::string file = path("bad.exr");
    const std::string message = errorOf([&] { aniso::writeImage(file, *image); });
    EXPECT_NE(message.find(file + ": "), std::string::npos) << message;
  }
  EXPECT_TRUE(entries().empty());
}

TEST_F(ImageIo, WriteIntoMissingDirectoryThrowsAndCreatesNothing)
{
  const fs::path missing = dir_ / "no-such-directory";
  const std::string file = (missing / "out.exr").string();
  const std::string message =
      errorOf([&] { aniso::writeImage(file, randomImage(4, 4, 3, 0.0f, 1.0f, 3u)); });
  EXPECT_NE(message.find(file + ": "), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_TRUE(entries().empty());
}

TEST_F(ImageIo, WriteOverDirectoryThrowsAndKeepsIt)
{
  const fs::path target = dir_ / "taken.exr";
  fs::create_directory(target);
  const std::string message =
      errorOf([&] { aniso::writeImage(target.string(), randomImage(4, 4, 3, 0.f, 1.f, 4u)); });
  EXPECT_NE(message.find(target.string() + ": "), std::string::npos) << message;
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_EQ(entries(), std::vector<std::string>{"taken.exr"});
}

TEST_F(ImageIo, SuccessfulWriteReplacesExistingFile)
{
  const std::string file = path("replace.exr");
  aniso::writeImage(file, randomImage(8, 8, 3, 0.0f, 1.0f, 5u));
  const Image second = randomImage(6, 5, 2, -1.0f, 1.0f, 6u);
  aniso::writeImage(file, second);
  EXPECT_EQ(aniso::readImage(file).data, second.data);
  EXPECT_EQ(entries(), std::vector<std::string>{"replace.exr"});
}

// A write that fails half-way (the file size limit is hit while pixels are written) leaves the
// previous file untouched and no temporary file beside it.
TEST_F(ImageIo, FailedWriteKeepsExistingTargetAndLeavesNoTemporary)
{
  const Image previous = randomImage(4, 4, 3, 0.0f, 1.0f, 8u);
  // Noise does not compress, so each of these files is far larger than the limit below.
  const Image large = randomImage(256, 256, 4, 0.0f, 1.0f, 9u);
  for (const std::string name : {"kept.exr", "kept.png", "kept.tiff", "kept.hdr"})
  {
    const std::string file = path(name);
    aniso::writeImage(file, previous);
    const std::string before = fileBytes(file);
    ASSERT_LT(before.size(), 16384u);

    rlimit saved{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    // Past the limit write() fails with EFBIG instead of raising SIGXFSZ.
    const auto savedHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = saved;
    limited.rlim_cur = 16384;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
    const std::string message = errorOf([&] { aniso::writeImage(file, large); });
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, savedHandler);

    EXPECT_NE(message.find(file + ": "), std::string::npos) << message;
    EXPECT_TRUE(fileBytes(file) == before) << name << " was modified";
    EXPECT_EQ(entries(), std::vector<std::string>{name});
    fs::remove(file);
  }
}
} // namespace
