// Material maps read from files: an 8-bit file's signed vectors come back as 2c - 1 (checked
// against the byte values written, c = byte / 255), a float file's as stored; a TPR text that
// names a file reads it (one channel: angles, (cos pi a, sin pi a)), one that does not is a
// pattern, and one that is neither gives an error naming the subject and the text.
#include "core/error.h"
#include "core/image/image.h"
#include "core/maps/map_files.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

namespace
{
namespace fs = std::filesystem;

std::string tempPath(const std::string& name)
{
  return (fs::temp_directory_path() / ("aniso_map_files_" + name)).string();
}

TEST(MapFiles, IntegerFilesDecodeToSignedValues)
{
  const std::string path = tempPath("signed.png");
  aniso::Image image(4, 2, 3);
  const int bytes[3] = {0, 128, 255};
  for (int y = 0; y < 2; ++y)
  {
    for (int x = 0; x < 4; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        image.at(x, y, c) = static_cast<float>(bytes[c]) / 255.0f;
      }
    }
  }
  aniso::writeImage(path, image);
  const aniso::Image decoded = aniso::readSignedMap(path);
  fs::remove(path);
  ASSERT_EQ(decoded.channels, 3);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(decoded.at(1, 1, c), 2.0 * bytes[c] / 255.0 - 1.0, 1e-6) << c;
  }
}

TEST(MapFiles, FloatFilesKeepTheirValues)
{
  const std::string path = tempPath("signed.exr");
  aniso::Image image(2, 2, 3);
  image.at(0, 0, 0) = -0.75f;
  image.at(1, 1, 2) = 0.5f;
  aniso::writeImage(path, image);
  const aniso::Image decoded = aniso::readSignedMap(path);
  fs::remove(path);
  EXPECT_EQ(decoded.at(0, 0, 0), -0.75f);
  EXPECT_EQ(decoded.at(1, 1, 2), 0.5f);
}

TEST(MapFiles, TprFromAnAngleFile)
{
  const std::string path = tempPath("angles.exr");
  aniso::Image angles(2, 1, 1);
  angles.at(0, 0, 0) = 0.25f; // 45 degrees
  angles.at(1, 0, 0) = 0.5f;  // 90 degrees
  aniso::writeImage(path, angles);
  const aniso::Image tpr = aniso::readTprMap(path, "--tpr");
  fs::remove(path);
  ASSERT_EQ(tpr.width, 2);
  EXPECT_NEAR(tpr.at(0, 0, 0), std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(tpr.at(0, 0, 1), std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(tpr.at(1, 0, 0), 0.0, 1e-6);
  EXPECT_NEAR(tpr.at(1, 0, 1), 1.0, 1e-6);
}

TEST(MapFiles, TprFromAPatternOrAnError)
{
  const aniso::Image linear = aniso::readTprMap("linear:90", "tpr");
  EXPECT_EQ(linear.width, aniso::kTprPatternSide);
  EXPECT_EQ(linear.height, aniso::kTprPatternSide);
  EXPECT_NEAR(linear.at(3, 7, 0), 0.0, 1e-6);
  EXPECT_NEAR(linear.at(3, 7, 1), 1.0, 1e-6);
  try
  {
    aniso::readTprMap("no-such-pattern-or-file", "--tpr");
    FAIL() << "no error";
  }
  catch (const aniso::Error& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("--tpr: 'no-such-pattern-or-file' is no file", 0), 0u)
        << e.what();
  }
}
} // namespace
