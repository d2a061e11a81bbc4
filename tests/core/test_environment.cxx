// Environments: the equirectangular mapping against Blender's convention as docs/METHOD.md states it
// (axes land on known pixels), the bilinear equirect environment against hand-made images (one
// lit texel comes back from exactly its direction), the loader against files written here with
// OpenImageIO directly (and a real Blender HDRI when installed), and the studio's stated
// properties (range, colours, no hard edge).
#include "core/env/environment.h"
#include "core/error.h"
#include "core/image/image.h"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using aniso::Image;
constexpr double kPi = 3.14159265358979323846;

// Blender's convention written out on its own: longitude atan2(d.y, d.x) = pi - 2 pi u,
// polar angle theta = pi (1 - v).
glm::dvec3 blenderDirection(double u, double v)
{
  const double longitude = kPi - 2.0 * kPi * u;
  const double theta = kPi * (1.0 - v);
  return {std::sin(theta) * std::cos(longitude), std::sin(theta) * std::sin(longitude),
          std::cos(theta)};
}

// Direction through the centre of texel (x, y) of a W x H equirect image (row 0 on top).
glm::dvec3 texelCentre(int x, int y, int width, int height)
{
  return blenderDirection((x + 0.5) / width, 1.0 - (y + 0.5) / height);
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance)
{
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

std::string errorOf(const std::string& path)
{
  try
  {
    aniso::loadEquirect(path);
  }
  catch (const aniso::Error& e)
  {
    return e.what();
  }
  return "";
}

// Writes float pixels with OpenImageIO itself, so the fixtures do not depend on writeImage.
void writeExr(const std::string& path, int width, int height, int channels,
              const std::vector<float>& pixels)
{
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out) << OIIO::geterror();
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  ASSERT_TRUE(out->open(path, spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

class TempDir : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::random_device device;
    dir_ = fs::temp_directory_path() / ("aniso-test-environment-" + std::to_string(::getpid()) +
                                        "-" + std::to_string(device()));
    fs::create_directories(dir_);
  }
  void TearDown() override
  {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

// Linear radiance (1 + d) per channel: smooth, positive, and different along every axis.
class ShiftedDirectionEnvironment : public aniso::Environment
{
public:
  glm::dvec3 radiance(const glm::dvec3& d) const override { return glm::dvec3(1.0) + d; }
  std::string key() const override { return "test:1+d"; }
};
} // namespace

// docs/METHOD.md: +X looks at the image centre, +Y at u = 0.25 (left of centre, as in Blender),
// v = 1 is the zenith and v = 0 the nadir.
TEST(EquirectMapping, AxesLandWhereBlenderPutsThem)
{
  using aniso::directionToEquirect;
  auto expectUv = [](const glm::dvec3& d, double u, double v)
  {
    const glm::dvec2 uv = directionToEquirect(d);
    EXPECT_NEAR(uv.x, u, 1e-15) << d.x << ' ' << d.y << ' ' << d.z;
    EXPECT_NEAR(uv.y, v, 1e-15) << d.x << ' ' << d.y << ' ' << d.z;
  };
  expectUv({1, 0, 0}, 0.5, 0.5);
  expectUv({0, 1, 0}, 0.25, 0.5);
  expectUv({0, -1, 0}, 0.75, 0.5);
  expectUv({-1, 0, 0}, 0.0, 0.5);
  expectUv({-1, -0.0, 0}, 0.0, 0.5); // atan2 gives -pi here: still wrapped into [0, 1)
  expectUv({0, 0, 1}, 0.5, 1.0);
  expectUv({0, 0, -1}, 0.5, 0.0);
  expectUv({1, 0, 1}, 0.5, 0.75);
  expectUv({3, 0, 0}, 0.5, 0.5); // not unit

  // Row 0 of an image is v = 1: the zenith is the top row, the nadir the bottom row.
  const int height = 64;
  EXPECT_EQ(int((1.0 - directionToEquirect({0.01, 0, 1}).y) * height), 0);
  EXPECT_EQ(int((1.0 - directionToEquirect({0.01, 0, -1}).y) * height), height - 1);
}

// uv -> direction -> uv and direction -> uv -> direction, and the inverse agrees with the
// convention restated above.
TEST(EquirectMapping, RoundTrips)
{
  for (int i = 0; i < 64; ++i)
    for (int j = 1; j < 32; ++j)
    {
      const glm::dvec2 uv((i + 0.25) / 64.0, j / 32.0);
      const glm::dvec3 d = aniso::equirectToDirection(uv);
      expectNear(d, blenderDirection(uv.x, uv.y), 1e-14);
      EXPECT_NEAR(glm::length(d), 1.0, 1e-14);
      const glm::dvec2 back = aniso::directionToEquirect(d);
      EXPECT_NEAR(back.x, uv.x, 1e-13);
      EXPECT_NEAR(back.y, uv.y, 1e-13);
    }
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < 1000; ++i)
  {
    const glm::dvec3 d = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
    const glm::dvec2 uv = aniso::directionToEquirect(d);
    EXPECT_GE(uv.x, 0.0);
    EXPECT_LT(uv.x, 1.0);
    expectNear(aniso::equirectToDirection(uv), d, 1e-13);
  }
}

// One lit texel is returned from the direction of its centre, half of it half-way to a
// neighbour, nothing from the neighbours' centres; u wraps, v clamps at the poles.
TEST(EquirectEnvironment, OneLitTexelComesFromItsDirection)
{
  const int w = 64;
  const int h = 32;
  const int x0 = 40;
  const int y0 = 9;
  Image image(w, h, 3);
  image.at(x0, y0, 0) = 3.0f;
  image.at(x0, y0, 1) = 2.0f;
  image.at(x0, y0, 2) = 1.0f;
  aniso::EquirectEnvironment env(image, "test");
  const glm::dvec3 lit(3, 2, 1);
  expectNear(env.radiance(texelCentre(x0, y0, w, h)), lit, 1e-9);
  expectNear(env.radiance(texelCentre(x0 + 1, y0, w, h)), glm::dvec3(0.0), 1e-9);
  expectNear(env.radiance(texelCentre(x0 - 1, y0, w, h)), glm::dvec3(0.0), 1e-9);
  expectNear(env.radiance(texelCentre(x0, y0 + 1, w, h)), glm::dvec3(0.0), 1e-9);
  expectNear(env.radiance(texelCentre(x0, y0 - 1, w, h)), glm::dvec3(0.0), 1e-9);
  // Half-way to the right neighbour in u, and to the row below in v.
  expectNear(env.radiance(blenderDirection((x0 + 1.0) / w, 1.0 - (y0 + 0.5) / h)), 0.5 * lit, 1e-9);
  expectNear(env.radiance(blenderDirection((x0 + 0.5) / w, 1.0 - (y0 + 1.0) / h)), 0.5 * lit, 1e-9);

  // Wrap: the left edge (u = 0, direction -X) is half-way between the last and first columns.
  Image edge(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int c = 0; c < 3; ++c)
      edge.at(0, y, c) = 4.0f;
  aniso::EquirectEnvironment edgeEnv(edge, "edge");
  expectNear(edgeEnv.radiance({-1, 0, 0}), glm::dvec3(2.0), 1e-9);
  expectNear(edgeEnv.radiance(texelCentre(w - 1, 5, w, h)), glm::dvec3(0.0), 1e-9);

  // Clamp: above the centre of the top row only the top row contributes.
  Image top(w, h, 3);
  for (int x = 0; x < w; ++x)
    for (int c = 0; c < 3; ++c)
      top.at(x, 0, c) = 5.0f;
  aniso::EquirectEnvironment topEnv(top, "top");
  expectNear(topEnv.radiance({0, 0, 1}), glm::dvec3(5.0), 1e-9);
  expectNear(topEnv.radiance({0, 0, -1}), glm::dvec3(0.0), 1e-9);
}

// Grey images become RGB; NaN/Inf texels become black and negative channels 0, all counted.
TEST(EquirectEnvironment, GreyAndInvalidTexels)
{
  Image grey(4, 2, 1);
  grey.at(1, 0, 0) = 0.5f;
  aniso::EquirectEnvironment greyEnv(grey, "grey");
  ASSERT_EQ(greyEnv.image().channels, 3);
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(greyEnv.image().at(1, 0, c), 0.5f);
  EXPECT_EQ(greyEnv.invalidTexels(), 0u);

  Image bad(4, 2, 4);
  for (float& value : bad.data)
    value = 1.0f;
  bad.at(0, 0, 1) = std::numeric_limits<float>::quiet_NaN();
  bad.at(1, 0, 2) = std::numeric_limits<float>::infinity();
  bad.at(2, 1, 0) = -0.25f;
  bad.at(3, 1, 3) = std::numeric_limits<float>::quiet_NaN(); // alpha is not radiance
  aniso::EquirectEnvironment env(bad, "bad");
  EXPECT_EQ(env.invalidTexels(), 3u);
  const Image& rgb = env.image();
  ASSERT_EQ(rgb.channels, 3);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(rgb.at(0, 0, c), 0.0f);
    EXPECT_EQ(rgb.at(1, 0, c), 0.0f);
    EXPECT_EQ(rgb.at(3, 1, c), 1.0f);
  }
  EXPECT_EQ(rgb.at(2, 1, 0), 0.0f);
  EXPECT_EQ(rgb.at(2, 1, 1), 1.0f);

  EXPECT_THROW(aniso::EquirectEnvironment(Image(), "empty"), aniso::Error);
}

// A Blender studio-light HDRI (CC0, 1024 x 512 float) loads, and its radiance at a texel centre
// is that texel as the file stores it (read here by OpenImageIO directly). These files hold a
// few slightly negative texels (down to -0.0016, from colour conversion): they read as 0 and are
// counted, and stay a small minority.
TEST(LoadEquirect, BlenderHdri)
{
  const fs::path dir = "/usr/share/blender/datafiles/studiolights/world";
  const fs::path file = dir / "forest.exr";
  if (!fs::exists(file))
    GTEST_SKIP() << file << " not installed (Debian package blender-data)";
  const auto env = aniso::loadEquirect(file.string());
  const Image& image = env->image();
  EXPECT_EQ(image.width, 1024);
  EXPECT_EQ(image.height, 512);
  EXPECT_LT(env->invalidTexels(), std::size_t(1024 * 512 / 100));
  EXPECT_EQ(env->key().rfind(file.string(), 0), 0u);

  auto in = OIIO::ImageInput::open(file.string());
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
  std::mt19937 rng(3);
  for (int i = 0; i < 200; ++i)
  {
    const int x = int(rng() % 1024u);
    const int y = int(rng() % 512u);
    const glm::dvec3 value = env->radiance(texelCentre(x, y, 1024, 512));
    for (int c = 0; c < 3; ++c)
    {
      const double expected =
          std::max(0.0f, pixels[(std::size_t(y) * 1024 + x) * spec.nchannels + c]);
      EXPECT_NEAR(value[c], expected, 1e-5 * std::max(1.0, expected)) << x << ',' << y;
    }
  }
}

// Unreadable, wrongly shaped and fully invalid files are refused with the path in the message;
// a file with a few bad texels loads with them repaired and counted.
TEST_F(TempDir, LoadEquirectErrorsNameThePath)
{
  const std::string missing = path("missing.exr");
  EXPECT_EQ(errorOf(missing).rfind(missing + ": ", 0), 0u) << errorOf(missing);

  const std::string square = path("square.exr");
  writeExr(square, 16, 16, 3, std::vector<float>(16 * 16 * 3, 1.0f));
  const std::string squareError = errorOf(square);
  EXPECT_EQ(squareError.rfind(square + ": ", 0), 0u) << squareError;
  EXPECT_NE(squareError.find("16x16"), std::string::npos) << squareError;

  const std::string nan = path("nan.exr");
  writeExr(nan, 8, 4, 3, std::vector<float>(8 * 4 * 3, std::numeric_limits<float>::quiet_NaN()));
  const std::string nanError = errorOf(nan);
  EXPECT_EQ(nanError.rfind(nan + ": ", 0), 0u) << nanError;

  const std::string fewBad = path("few-bad.exr");
  std::vector<float> pixels(8 * 4 * 3, 2.0f);
  pixels[5] = std::numeric_limits<float>::quiet_NaN();
  pixels[40] = -1.0f;
  writeExr(fewBad, 8, 4, 3, pixels);
  const auto env = aniso::loadEquirect(fewBad);
  EXPECT_EQ(env->invalidTexels(), 2u);

  // One extra column (as some exporters write) is still an equirect image.
  const std::string oddWidth = path("odd.exr");
  writeExr(oddWidth, 201, 100, 1, std::vector<float>(201 * 100, 0.5f));
  EXPECT_NO_THROW(aniso::loadEquirect(oddWidth));
}

TEST(OpenEnvironment, BuiltinsAndErrors)
{
  EXPECT_EQ(aniso::openEnvironment("builtin:studio")->key(), "builtin:studio");
  const auto white = aniso::openEnvironment("builtin:white");
  expectNear(white->radiance({0, 0, 1}), glm::dvec3(1.0), 0.0);
  expectNear(white->radiance({0.6, 0, -0.8}), glm::dvec3(1.0), 0.0);
  try
  {
    aniso::openEnvironment("builtin:nothing");
    ADD_FAILURE() << "no error for an unknown built-in";
  }
  catch (const aniso::Error& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("builtin:nothing: ", 0), 0u) << e.what();
  }
  EXPECT_THROW(aniso::openEnvironment(""), aniso::Error);
}

// The studio as specified: finite and positive everywhere, peak radiance in [5, 20], a floor
// dimmer and warmer than the sky.
TEST(StudioEnvironment, RangeAndColours)
{
  aniso::StudioEnvironment studio;
  double peak = 0.0;
  double lowest = 1e30;
  for (int i = 0; i < 720; ++i)
    for (int j = 0; j < 360; ++j)
    {
      const glm::dvec3 l = studio.radiance(blenderDirection((i + 0.5) / 720, (j + 0.5) / 360));
      for (int c = 0; c < 3; ++c)
      {
        ASSERT_TRUE(std::isfinite(l[c]));
        peak = std::max(peak, l[c]);
        lowest = std::min(lowest, l[c]);
      }
    }
  EXPECT_GE(peak, 5.0);
  EXPECT_LE(peak, 20.0);
  EXPECT_GT(lowest, 0.0);
  const glm::dvec3 floorLight = studio.radiance({0, 0, -1});
  const glm::dvec3 skyLight = studio.radiance(glm::normalize(glm::dvec3(-0.3, 0.8, 0.5)));
  EXPECT_GT(floorLight.x, floorLight.z); // warm
  EXPECT_LT(skyLight.x, skyLight.z);     // cool
  EXPECT_LT(floorLight.y, skyLight.y);
}

// No hard edge: along every meridian and parallel at 2 degree spacing (all cross each soft box),
// radiance changes by at most K * angle between points 2e-4 rad apart. A hard edge of a box
// would jump by its full radiance (~4 to 14) in one step, i.e. K ~ 2e4; K = 300 bounds the
// steepest soft edge (peak 9 over a half-width of 0.12, times max |d exp(-x^6)/dx| = 2.2).
TEST(StudioEnvironment, NoHardEdges)
{
  aniso::StudioEnvironment studio;
  const double step = 2e-4;
  const int steps = int(2.0 * kPi / step);
  const double bound = 300.0 * step;
  double worst = 0.0;
  for (int k = 0; k < 90; ++k)
  {
    const double longitude = k * 2.0 * kPi / 180.0;
    const double latitude = -kPi / 2 + (k + 0.5) * kPi / 90.0;
    glm::dvec3 previousMeridian(0.0);
    glm::dvec3 previousParallel(0.0);
    for (int i = 0; i <= steps; ++i)
    {
      const double a = i * step;
      const glm::dvec3 meridian = studio.radiance(
          {std::cos(a) * std::cos(longitude), std::cos(a) * std::sin(longitude), std::sin(a)});
      const glm::dvec3 parallel = studio.radiance(
          {std::cos(latitude) * std::cos(a), std::cos(latitude) * std::sin(a), std::sin(latitude)});
      if (i > 0)
      {
        for (int c = 0; c < 3; ++c)
        {
          worst = std::max(worst, std::abs(meridian[c] - previousMeridian[c]));
          worst = std::max(worst, std::abs(parallel[c] - previousParallel[c]) /
                                      std::max(std::cos(latitude), 1e-3));
        }
      }
      previousMeridian = meridian;
      previousParallel = parallel;
    }
  }
  EXPECT_LE(worst, bound) << "steepest step " << worst / step << " per radian";
}

// renderEquirect puts each direction where the convention says and averages over solid angle:
// for the radiance 1 + d, texel (x, y) holds 1 + the exact solid-angle mean of d over the texel
// (longitude from pi - 2 pi u, polar angle pi (1 - v), integrated in closed form here).
TEST(RenderEquirect, TexelsAreSolidAngleMeans)
{
  ShiftedDirectionEnvironment env;
  const int w = 128;
  const int h = 64;
  const Image image = aniso::renderEquirect(env, w, h, 4);
  ASSERT_EQ(image.width, w);
  ASSERT_EQ(image.height, h);
  ASSERT_EQ(image.channels, 3);
  double worst = 0.0;
  double worstPolar = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      // Row y spans theta in [pi y / h, pi (y + 1) / h]; column x spans longitude
      // [pi - 2 pi (x + 1) / w, pi - 2 pi x / w].
      const double t0 = kPi * y / h;
      const double t1 = kPi * (y + 1) / h;
      const double p0 = kPi - 2.0 * kPi * (x + 1) / w;
      const double p1 = kPi - 2.0 * kPi * x / w;
      const double area = (std::cos(t0) - std::cos(t1)) * (p1 - p0);
      const double sin2 = 0.5 * (t1 - t0) - 0.25 * (std::sin(2.0 * t1) - std::sin(2.0 * t0));
      const glm::dvec3 mean(
          sin2 * (std::sin(p1) - std::sin(p0)) / area, sin2 * (std::cos(p0) - std::cos(p1)) / area,
          0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) * (p1 - p0) / area);
      const bool nearPole = y < 2 || y >= h - 2;
      double& bound = nearPole ? worstPolar : worst;
      for (int c = 0; c < 3; ++c)
        bound = std::max(bound, std::abs(image.at(x, y, c) - (1.0 + mean[c])));
    }
  // 4 x 4 midpoint samples per texel, weighted by sin(theta): error ~ (texel / 4)^2 / 24, about
  // 1e-5. In the two rows next to each pole sin(theta) is far from linear over a texel and the
  // sampled weights are off by a few percent of a small value.
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(worstPolar, 2e-3);
  EXPECT_THROW(aniso::renderEquirect(env, 0, 4), aniso::Error);
  EXPECT_THROW(aniso::renderEquirect(env, 8, 4, 0), aniso::Error);
}
