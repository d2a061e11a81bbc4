// Cubemaps and SH9 irradiance: texel directions against OpenGL's major-axis table (restated
// here from the specification), exact texel solid angles against 4 pi, mip levels against the
// mean of level 0 (a 2x2 box filter keeps it), and SH9 irradiance against closed forms for
// band-limited radiance and against the brute-force irradiance quadrature of the reference
// integrator for the studio.
#include "core/env/cubemap.h"
#include "core/env/environment.h"
#include "core/error.h"
#include "core/reference/reference_integrator.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <string>

namespace
{
constexpr double kPi = 3.14159265358979323846;

// OpenGL 4.5 core, table 8.19 (cube map face selection): major axis, then sc, tc, ma.
// Returns the face index in +X, -X, +Y, -Y, +Z, -Z order and (s, t).
int glFace(const glm::dvec3& d, double* s, double* t)
{
  const double ax = std::abs(d.x);
  const double ay = std::abs(d.y);
  const double az = std::abs(d.z);
  int face;
  double sc;
  double tc;
  double ma;
  if (ax >= ay && ax >= az)
  {
    face = d.x >= 0 ? 0 : 1;
    sc = d.x >= 0 ? -d.z : d.z;
    tc = -d.y;
    ma = ax;
  }
  else if (ay >= az)
  {
    face = d.y >= 0 ? 2 : 3;
    sc = d.x;
    tc = d.y >= 0 ? d.z : -d.z;
    ma = ay;
  }
  else
  {
    face = d.z >= 0 ? 4 : 5;
    sc = d.z >= 0 ? d.x : -d.x;
    tc = -d.y;
    ma = az;
  }
  *s = 0.5 * (sc / ma + 1.0);
  *t = 0.5 * (tc / ma + 1.0);
  return face;
}

// Radiance equal to the direction itself: every texel then shows where it looks.
class DirectionEnvironment : public aniso::Environment
{
public:
  glm::dvec3 radiance(const glm::dvec3& d) const override { return d; }
  std::string key() const override { return "test:direction"; }
};

// Band-limited radiance with closed-form irradiance E(n) = integral of L (n.l)+ dw:
// R = 1 -> pi; G = 1 + z -> pi + (2 pi / 3) n.z;
// B = z^2 + x y -> pi / 3 + (pi / 12)(3 n.z^2 - 1) + (pi / 4) n.x n.y
// (z^2 = 1/3 + (2/3) P2(z), and band l scales by A_l = pi, 2 pi / 3, pi / 4).
class PolynomialEnvironment : public aniso::Environment
{
public:
  glm::dvec3 radiance(const glm::dvec3& d) const override
  {
    return {1.0, 1.0 + d.z, d.z * d.z + d.x * d.y};
  }
  std::string key() const override { return "test:polynomial"; }
};

glm::dvec3 polynomialIrradiance(const glm::dvec3& n)
{
  return {kPi, kPi + 2.0 * kPi / 3.0 * n.z,
          kPi / 3.0 + kPi / 12.0 * (3.0 * n.z * n.z - 1.0) + kPi / 4.0 * n.x * n.y};
}

std::vector<glm::dvec3> testNormals()
{
  std::vector<glm::dvec3> normals = {{0, 0, 1},  {0, 0, -1}, {1, 0, 0},
                                     {-1, 0, 0}, {0, 1, 0},  {0, -1, 0}};
  for (int i = 0; i < 40; ++i)
  {
    // Spiral over the sphere.
    const double z = 1.0 - (i + 0.5) / 20.0;
    const double phi = i * 2.39996322972865332;
    const double r = std::sqrt(1.0 - z * z);
    normals.push_back({r * std::cos(phi), r * std::sin(phi), z});
  }
  return normals;
}
} // namespace

// cubeFaceOf inverts cubeTexelDirection on every texel of every face, and both agree with the
// OpenGL table.
TEST(Cubemap, TexelDirectionRoundTrip)
{
  for (int size : {1, 2, 5, 16})
    for (int face = 0; face < 6; ++face)
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
        {
          const glm::dvec3 d = aniso::cubeTexelDirection(face, x, y, size);
          EXPECT_NEAR(glm::length(d), 1.0, 1e-14);
          double s = 0;
          double t = 0;
          ASSERT_EQ(aniso::cubeFaceOf(d, &s, &t), face);
          EXPECT_NEAR(s, (x + 0.5) / size, 1e-12);
          EXPECT_NEAR(t, (y + 0.5) / size, 1e-12);
          double glS = 0;
          double glT = 0;
          ASSERT_EQ(glFace(d, &glS, &glT), face);
          EXPECT_NEAR(glS, s, 1e-12);
          EXPECT_NEAR(glT, t, 1e-12);
        }
  double s = 0;
  double t = 0;
  EXPECT_EQ(aniso::cubeFaceOf({0, 0, 0}, &s, &t), 4);
  EXPECT_EQ(s, 0.5);
  EXPECT_EQ(aniso::cubeFaceOf({1, 1, 1}, &s, &t), 0); // ties go to X
  EXPECT_EQ(aniso::cubeFaceOf({0, -1, -1}, &s, &t), 3);
}

// A cube baked from L(d) = d: every texel's value is a direction that the OpenGL table sends
// back to that very texel, so texture(cube, d) returns L(d). Also spot checks written from the
// table by hand: face +X, row 0, column 0 looks towards (+1, +1, +1); face +Y row 0 towards -Z.
TEST(Cubemap, FaceOrientationFollowsOpenGl)
{
  DirectionEnvironment env;
  const int size = 8;
  const aniso::Cubemap cube = aniso::buildCubemap(env, size, 1);
  for (int face = 0; face < 6; ++face)
  {
    const aniso::Image& image = cube.mips[0][std::size_t(face)];
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
      {
        const glm::dvec3 value(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
        double s = 0;
        double t = 0;
        ASSERT_EQ(glFace(value, &s, &t), face) << x << ',' << y;
        EXPECT_NEAR(s, (x + 0.5) / size, 1e-6);
        EXPECT_NEAR(t, (y + 0.5) / size, 1e-6);
      }
  }
  const aniso::Image& px = cube.mips[0][0];
  EXPECT_GT(px.at(0, 0, 0), 0.0f);
  EXPECT_GT(px.at(0, 0, 1), 0.0f);
  EXPECT_GT(px.at(0, 0, 2), 0.0f);
  EXPECT_LT(cube.mips[0][2].at(3, 0, 2), -0.5f);
}

// The exact texel solid angles cover the sphere: 6 faces sum to 4 pi; the centre texel of a
// fine face subtends its area (2 / size)^2 at distance 1.
TEST(Cubemap, TexelSolidAnglesSumTo4Pi)
{
  for (int size : {1, 2, 3, 16, 128, 1000})
  {
    double sum = 0.0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
      {
        const double omega = aniso::cubeTexelSolidAngle(x, y, size);
        ASSERT_GT(omega, 0.0);
        sum += omega;
      }
    EXPECT_NEAR(6.0 * sum, 4.0 * kPi, 1e-9) << size;
  }
  const double centre = aniso::cubeTexelSolidAngle(500, 500, 1001);
  EXPECT_NEAR(centre / std::pow(2.0 / 1001, 2), 1.0, 1e-5);
}

// Full chain down to 1x1; every level of every face keeps level 0's mean (a 2x2 box filter
// preserves the mean exactly, up to float rounding).
TEST(Cubemap, MipChainKeepsTheMean)
{
  aniso::StudioEnvironment studio;
  const int size = 64;
  const aniso::Cubemap cube = aniso::buildCubemap(studio, size, 2);
  ASSERT_EQ(cube.size, size);
  ASSERT_EQ(cube.mips.size(), 7u);
  for (std::size_t face = 0; face < 6; ++face)
  {
    glm::dvec3 baseMean(0.0);
    for (std::size_t level = 0; level < cube.mips.size(); ++level)
    {
      const aniso::Image& image = cube.mips[level][face];
      ASSERT_EQ(image.width, size >> level);
      ASSERT_EQ(image.height, size >> level);
      ASSERT_EQ(image.channels, 3);
      glm::dvec3 mean(0.0);
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
          for (int c = 0; c < 3; ++c)
            mean[c] += image.at(x, y, c);
      mean /= double(image.width) * image.height;
      if (level == 0)
        baseMean = mean;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(mean[c], baseMean[c], 1e-5 * baseMean[c]) << face << '/' << level;
    }
  }
  EXPECT_EQ(cube.mips.back()[0].width, 1);
}

TEST(Cubemap, RejectsBadSizes)
{
  aniso::StudioEnvironment studio;
  for (int size : {0, 3, 100, 16384})
  {
    try
    {
      aniso::buildCubemap(studio, size);
      ADD_FAILURE() << "size " << size << " accepted";
    }
    catch (const aniso::Error& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind("size: ", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(aniso::buildCubemap(studio, 8, 0), aniso::Error);
  EXPECT_THROW(aniso::projectSh9(studio, 1), aniso::Error);
  EXPECT_THROW(aniso::projectSh9(aniso::Cubemap{}), aniso::Error);
}

// Constant radiance 1 gives E = pi in every direction, by both projections (the cube's solid
// angles sum to 4 pi and its texels are symmetric, so this is exact up to rounding).
TEST(Sh9, ConstantEnvironmentGivesPi)
{
  aniso::UniformEnvironment one(glm::dvec3(1.0));
  const aniso::Sh9 fromEnv = aniso::projectSh9(one, 32);
  const aniso::Sh9 fromCube = aniso::projectSh9(aniso::buildCubemap(one, 16, 1));
  for (const glm::dvec3& n : testNormals())
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(aniso::irradianceSh9(fromEnv, n)[c], kPi, 1e-12);
      EXPECT_NEAR(aniso::irradianceSh9(fromCube, n)[c], kPi, 1e-9);
    }
}

// Radiance of degree <= 2 is exactly band-limited: SH9 irradiance equals the closed form.
// The product rule is exact here; the cube (texel averages, evaluated at texel centres) is
// second-order accurate in the texel size.
TEST(Sh9, BandLimitedEnvironmentMatchesClosedForm)
{
  PolynomialEnvironment env;
  const aniso::Sh9 fromEnv = aniso::projectSh9(env, 16);
  const aniso::Sh9 fromCube = aniso::projectSh9(aniso::buildCubemap(env, 64, 2));
  for (const glm::dvec3& n : testNormals())
  {
    const glm::dvec3 expected = polynomialIrradiance(n);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(aniso::irradianceSh9(fromEnv, n)[c], expected[c], 1e-12);
      EXPECT_NEAR(aniso::irradianceSh9(fromCube, n)[c], expected[c], 1e-3);
    }
  }
}

// The studio is not band-limited: SH9 keeps bands 0-2 of the radiance, and the clamped cosine
// passes the higher bands only weakly (A3 = 0, A4 = pi / 24, A6 = pi / 64, ...). The truncation
// error is therefore small in absolute terms but not relative to dim directions: the worst
// |E_SH9 - E| is 2.9% of the brightest irradiance over the normals here (3.6% over 200 normals,
// 7.8% of the mean irradiance), and up to 34% of E itself for normals facing the dark floor. The bound: 5% of the brightest E, against
// the exact integral from the reference integrator. The cube route (64^2 faces) agrees with the
// product rule to 1e-3 of E.
TEST(Sh9, StudioIrradianceWithinBandlimitError)
{
  aniso::StudioEnvironment studio;
  const aniso::Sh9 fromEnv = aniso::projectSh9(studio, 128);
  const aniso::Sh9 fromCube = aniso::projectSh9(aniso::buildCubemap(studio, 64, 2));
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-6;
  double brightest = 0.0;
  double worstAbsolute = 0.0;
  double worstCube = 0.0;
  for (const glm::dvec3& n : testNormals())
  {
    const aniso::ReferenceResult exact = aniso::integrateIrradiance(n, studio, options);
    ASSERT_TRUE(exact.converged);
    const glm::dvec3 sh = aniso::irradianceSh9(fromEnv, n);
    const glm::dvec3 shCube = aniso::irradianceSh9(fromCube, n);
    for (int c = 0; c < 3; ++c)
    {
      brightest = std::max(brightest, exact.value[c]);
      worstAbsolute = std::max(worstAbsolute, std::abs(sh[c] - exact.value[c]));
      worstCube = std::max(worstCube, std::abs(shCube[c] - sh[c]) / exact.value[c]);
    }
  }
  std::printf("SH9 vs exact irradiance: worst error %.4f of the brightest E; cube vs product "
              "rule %.2e\n",
              worstAbsolute / brightest, worstCube);
  EXPECT_LT(worstAbsolute, 0.05 * brightest);
  EXPECT_LT(worstCube, 1e-3);
}
