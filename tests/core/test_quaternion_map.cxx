// Quaternion maps: the frame of (a, b, c) is a proper rotation (orthonormal, right-handed) that
// carries +z to the input normal and leaves its axis (b, c, 0) fixed (the shortest arc), checked
// over a dense sphere of normals down to the antipode; baked maps of an analytic dome reproduce
// the dome's normals within the file format's precision; texel counts match hand-made inputs.
#include "core/error.h"
#include "core/image/image.h"
#include "core/maps/quaternion_map.h"

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
using aniso::Frame;
using aniso::Image;
using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;

double distance(const dvec3& a, const dvec3& b)
{
  return glm::length(a - b);
}

void expectProperRotationTo(const dvec3& normal, double tolerance)
{
  const dvec3 unit = glm::normalize(normal);
  const dvec3 q = aniso::quaternionFromNormal(normal);
  ASSERT_GE(q.x, 0.0) << "a must be non-negative";
  ASSERT_NEAR(glm::dot(q, q), 1.0, 1e-12);
  const Frame f = aniso::frameFromQuaternion(q);
  ASSERT_NEAR(glm::length(f.t), 1.0, 1e-12);
  ASSERT_NEAR(glm::length(f.b), 1.0, 1e-12);
  ASSERT_NEAR(glm::length(f.n), 1.0, 1e-12);
  ASSERT_NEAR(glm::dot(f.t, f.b), 0.0, 1e-12);
  ASSERT_NEAR(glm::dot(f.t, f.n), 0.0, 1e-12);
  ASSERT_NEAR(glm::dot(f.b, f.n), 0.0, 1e-12);
  ASSERT_LT(distance(glm::cross(f.t, f.b), f.n), 1e-12) << "frame must be right-handed";
  ASSERT_LE(distance(f.n, unit), tolerance) << "n' must reproduce the input normal";
  // The rotation axis lies in the tangent plane, orthogonal to z and n: shortest arc.
  const dvec3 axis{q.y, q.z, 0.0};
  if (glm::length(axis) > 1e-3)
  {
    const dvec3 k = glm::normalize(axis);
    ASSERT_LT(distance(f.toWorld(k), k), 1e-12) << "the axis must be fixed by the rotation";
  }
}

// Dense grid in (theta, phi), plus the poles and normals within 1e-12 of the antipode.
TEST(QuaternionMap, FramesAreRotationsToTheNormalOverTheSphere)
{
  std::vector<double> thetas;
  for (int i = 0; i <= 360; ++i)
  {
    thetas.push_back(kPi * i / 360.0);
  }
  for (double e : {1e-3, 1e-6, 1e-9, 1e-12})
  {
    thetas.push_back(e);
    thetas.push_back(kPi - e);
  }
  for (double theta : thetas)
  {
    for (int j = 0; j < 96; ++j)
    {
      const double phi = 2.0 * kPi * j / 96.0;
      const dvec3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                    std::cos(theta)};
      SCOPED_TRACE("theta " + std::to_string(theta) + " phi " + std::to_string(phi));
      expectProperRotationTo(n, 1e-12);
    }
  }
  // z = -(1 - 1e-12) exactly, with the matching (x, y) in several directions.
  const double z = -(1.0 - 1e-12);
  const double r = std::sqrt((1.0 - z) * (1.0 + z));
  for (int j = 0; j < 8; ++j)
  {
    const double phi = 2.0 * kPi * j / 8.0 + 0.1;
    expectProperRotationTo({r * std::cos(phi), r * std::sin(phi), z}, 1e-12);
  }
  expectProperRotationTo({0.0, 0.0, -1.0}, 0.0);
  expectProperRotationTo({0.0, 0.0, 1.0}, 0.0);
  expectProperRotationTo({1.0, 0.0, 0.0}, 1e-15);
  expectProperRotationTo({0.0, -1.0, 0.0}, 1e-15);
}

// Away from the antipode the stored (a, b, c) equals docs/METHOD.md's formulas evaluated literally.
TEST(QuaternionMap, MatchesTheDesignFormulas)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i)
  {
    const dvec3 n = glm::normalize(dvec3(u(random), u(random), 0.5 * (u(random) + 1.0) - 0.4));
    const double a = std::sqrt((n.z + 1.0) / 2.0);
    const dvec3 expected{a, n.y / (2.0 * a), -n.x / (2.0 * a)};
    ASSERT_LT(distance(aniso::quaternionFromNormal(n), expected), 1e-12);
  }
}

TEST(QuaternionMap, PolesGiveIdentityAndHalfTurn)
{
  const Frame identity = aniso::frameFromQuaternion(aniso::quaternionFromNormal({0, 0, 1}));
  EXPECT_EQ(identity.t, dvec3(1, 0, 0));
  EXPECT_EQ(identity.b, dvec3(0, 1, 0));
  EXPECT_EQ(identity.n, dvec3(0, 0, 1));
  // Exactly (0, 0, -1): the half turn about t, (a, b, c) = (0, 1, 0).
  EXPECT_EQ(aniso::quaternionFromNormal({0, 0, -1}), dvec3(0, 1, 0));
  const Frame half = aniso::frameFromQuaternion({0, 1, 0});
  EXPECT_EQ(half.t, dvec3(1, 0, 0));
  EXPECT_EQ(half.b, dvec3(0, -1, 0));
  EXPECT_EQ(half.n, dvec3(0, 0, -1));
  // Zero and non-finite normals have no rotation: identity.
  EXPECT_EQ(aniso::quaternionFromNormal({0, 0, 0}), dvec3(1, 0, 0));
  EXPECT_EQ(aniso::quaternionFromNormal({std::nan(""), 0, 1}), dvec3(1, 0, 0));
}

// A hemispherical dome of radius R in [-1, 1]^2: inside, the sphere normal (x, y, h)/R with
// h = sqrt(R^2 - x^2 - y^2); outside, flat (0, 0, 1). Evaluated at texel centres.
constexpr double kDomeRadius = 0.8;

dvec3 domeNormal(int col, int row, int size)
{
  const double x = 2.0 * (col + 0.5) / size - 1.0;
  const double y = 1.0 - 2.0 * (row + 0.5) / size;
  const double rho2 = x * x + y * y;
  if (rho2 >= kDomeRadius * kDomeRadius)
  {
    return {0.0, 0.0, 1.0};
  }
  return dvec3(x, y, std::sqrt(kDomeRadius * kDomeRadius - rho2)) / kDomeRadius;
}

class QuaternionMapFiles : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::random_device device;
    dir_ = fs::temp_directory_path() /
           ("aniso-test-quaternion-" + std::to_string(::getpid()) + "-" + std::to_string(device()));
    fs::create_directories(dir_);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // Writes the dome as a normal map (encoded c = (n + 1) / 2 for integer files), reads it back
  // like any user file, bakes it and checks every texel's n' against the analytic normal.
  void checkDome(const std::string& name, bool encode, int channels, double tolerance)
  {
    const int size = 64;
    Image normals(size, size, channels);
    for (int row = 0; row < size; ++row)
    {
      for (int col = 0; col < size; ++col)
      {
        const dvec3 n = domeNormal(col, row, size);
        for (int c = 0; c < 3; ++c)
        {
          normals.at(col, row, c) = float(encode ? 0.5 * (n[c] + 1.0) : n[c]);
        }
        if (channels == 4)
        {
          normals.at(col, row, 3) = 1.0f;
        }
      }
    }
    const std::string file = (dir_ / name).string();
    aniso::writeImage(file, normals);
    aniso::ImageInfo info;
    const Image loaded = aniso::readImage(file, &info);
    ASSERT_EQ(info.integerFormat, encode);

    aniso::QuaternionBakeStats stats;
    const Image map = aniso::bakeQuaternionMap(loaded, info.integerFormat, &stats);
    ASSERT_EQ(map.width, size);
    ASSERT_EQ(map.height, size);
    ASSERT_EQ(map.channels, 4);
    EXPECT_EQ(stats.texels, std::size_t(size) * size);
    EXPECT_EQ(stats.nonUnit, 0u);
    EXPECT_EQ(stats.invalid, 0u);
    EXPECT_EQ(stats.antipodal, 0u);
    double worst = 0.0;
    for (int row = 0; row < size; ++row)
    {
      for (int col = 0; col < size; ++col)
      {
        const dvec3 q{map.at(col, row, 0), map.at(col, row, 1), map.at(col, row, 2)};
        ASSERT_EQ(map.at(col, row, 3), 1.0f);
        const Frame f = aniso::frameFromQuaternion(q);
        worst = std::max(worst, distance(f.n, domeNormal(col, row, size)));
      }
    }
    EXPECT_LT(worst, tolerance) << name;
  }

  fs::path dir_;
};

// 8-bit: each component of n = 2c - 1 is off by at most 1/255, so the normalised direction by
// at most about sqrt(3)/255 (1% margin for second-order terms and float storage).
TEST_F(QuaternionMapFiles, DomeFrom8BitPng)
{
  checkDome("dome.png", true, 3, 1.01 * std::sqrt(3.0) / 255);
}

TEST_F(QuaternionMapFiles, DomeFrom16BitTiffWithAlpha)
{
  checkDome("dome.tif", true, 4, 1.01 * std::sqrt(3.0) / 65535);
}

// Float: (a, b, c) rounded to float moves n' by a few 1e-8.
TEST_F(QuaternionMapFiles, DomeFromFloatExr)
{
  checkDome("dome.exr", false, 3, 1e-6);
}

// Hand-made texels with the count each one must add, decided from the documented thresholds.
TEST(QuaternionMap, CountsCraftedFloatTexels)
{
  const double s05 = std::sin(0.5 * kPi / 180.0);
  const double c05 = std::cos(0.5 * kPi / 180.0);
  const double s2 = std::sin(2.0 * kPi / 180.0);
  const double c2 = std::cos(2.0 * kPi / 180.0);
  const float inf = std::numeric_limits<float>::infinity();
  struct Texel
  {
    float x, y, z, w;
    int nonUnit, invalid, antipodal;
  };
  const std::vector<Texel> texels = {
      {0.0f, 0.0f, 1.0f, 1.0f, 0, 0, 0},              // unit
      {0.6f, 0.0f, 0.8f, std::nanf(""), 0, 0, 0},     // unit; the fourth channel is ignored
      {2.0f, 0.0f, 0.0f, 1.0f, 1, 0, 0},              // length 2
      {0.0f, 0.0f, 1.0005f, 1.0f, 0, 0, 0},           // within 1e-3 of unit
      {0.0f, 0.0f, 1.002f, 1.0f, 1, 0, 0},            // beyond 1e-3
      {std::nanf(""), 0.0f, 1.0f, 1.0f, 0, 1, 0},     // NaN
      {0.0f, inf, 1.0f, 1.0f, 0, 1, 0},               // Inf
      {0.0f, 0.0f, 0.0f, 1.0f, 0, 1, 0},              // zero length
      {0.005f, 0.0f, 0.0f, 1.0f, 0, 1, 0},            // below the minimum length 1e-2
      {0.0f, 0.0f, -1.0f, 1.0f, 0, 0, 1},             // exactly antipodal
      {float(s05), 0.0f, float(-c05), 1.0f, 0, 0, 1}, // 0.5 degree from -z
      {float(s2), 0.0f, float(-c2), 1.0f, 0, 0, 0},   // 2 degrees from -z
      {0.0f, 0.0f, -3.0f, 1.0f, 1, 0, 1},             // long and antipodal
  };
  Image image(int(texels.size()), 1, 4);
  std::size_t nonUnit = 0, invalid = 0, antipodal = 0;
  for (std::size_t i = 0; i < texels.size(); ++i)
  {
    const Texel& t = texels[i];
    image.at(int(i), 0, 0) = t.x;
    image.at(int(i), 0, 1) = t.y;
    image.at(int(i), 0, 2) = t.z;
    image.at(int(i), 0, 3) = t.w;
    nonUnit += std::size_t(t.nonUnit);
    invalid += std::size_t(t.invalid);
    antipodal += std::size_t(t.antipodal);
  }
  aniso::QuaternionBakeStats stats;
  const Image map = aniso::bakeQuaternionMap(image, false, &stats);
  EXPECT_EQ(stats.texels, texels.size());
  EXPECT_EQ(stats.nonUnit, nonUnit);
  EXPECT_EQ(stats.invalid, invalid);
  EXPECT_EQ(stats.antipodal, antipodal);
  for (std::size_t i = 0; i < texels.size(); ++i)
  {
    const dvec3 q{map.at(int(i), 0, 0), map.at(int(i), 0, 1), map.at(int(i), 0, 2)};
    const dvec3 n = aniso::frameFromQuaternion(q).n;
    if (texels[i].invalid)
    {
      EXPECT_EQ(q, dvec3(1, 0, 0)) << "texel " << i; // replaced by (0, 0, 1)
    }
    else
    {
      const dvec3 expected = glm::normalize(dvec3(texels[i].x, texels[i].y, texels[i].z));
      EXPECT_LT(distance(n, expected), 1e-6) << "texel " << i;
    }
  }
}

// Integer maps decode n = 2c - 1 and tolerate 8-bit quantisation (1e-2 on the length).
TEST(QuaternionMap, CountsCraftedIntegerTexels)
{
  Image image(5, 1, 3);
  auto set = [&](int i, double x, double y, double z)
  {
    image.at(i, 0, 0) = float(0.5 * (x + 1.0));
    image.at(i, 0, 1) = float(0.5 * (y + 1.0));
    image.at(i, 0, 2) = float(0.5 * (z + 1.0));
  };
  set(0, 0.0, 0.0, 1.0);   // unit
  set(1, 0.0, 0.0, 0.995); // within 1e-2
  set(2, 0.0, 0.0, 0.98);  // beyond 1e-2
  set(3, 0.0, 0.0, 0.0);   // zero: invalid
  set(4, 0.0, 0.0, -1.0);  // antipodal
  aniso::QuaternionBakeStats stats;
  const Image map = aniso::bakeQuaternionMap(image, true, &stats);
  EXPECT_EQ(stats.texels, 5u);
  EXPECT_EQ(stats.nonUnit, 1u);
  EXPECT_EQ(stats.invalid, 1u);
  EXPECT_EQ(stats.antipodal, 1u);
  EXPECT_NEAR(map.at(4, 0, 0), 0.0f, 1e-7f); // a of the half turn
}

// Two channels: z = sqrt(1 - x^2 - y^2); beyond the unit disc z = 0 and the length counts.
TEST(QuaternionMap, TwoChannelMapsReconstructZ)
{
  Image image(2, 1, 2);
  image.at(0, 0, 0) = 0.6f;
  image.at(0, 0, 1) = 0.0f;
  image.at(1, 0, 0) = 0.8f;
  image.at(1, 0, 1) = 0.8f;
  aniso::QuaternionBakeStats stats;
  const Image map = aniso::bakeQuaternionMap(image, false, &stats);
  EXPECT_EQ(stats.nonUnit, 1u);
  EXPECT_EQ(stats.invalid, 0u);
  const auto normalAt = [&](int i) {
    return aniso::frameFromQuaternion({map.at(i, 0, 0), map.at(i, 0, 1), map.at(i, 0, 2)}).n;
  };
  EXPECT_LT(distance(normalAt(0), dvec3(0.6, 0.0, 0.8)), 1e-6);
  EXPECT_LT(distance(normalAt(1), dvec3(std::sqrt(0.5), std::sqrt(0.5), 0.0)), 1e-6);
}

TEST(QuaternionMap, RejectsUnusableImages)
{
  const Image oneChannel(4, 4, 1);
  Image inconsistent(4, 4, 3);
  inconsistent.data.resize(5);
  const Image empty;
  for (const Image* image : std::vector<const Image*>{&oneChannel, &inconsistent, &empty})
  {
    try
    {
      aniso::bakeQuaternionMap(*image, false, nullptr);
      ADD_FAILURE() << "no error";
    }
    catch (const aniso::Error& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind("normal map: ", 0), 0u) << e.what();
    }
  }
}
} // namespace
