// Environment importance sampling and the sun-sky test environment, against independent
// references: the density integrates to 1 over the sphere (quadrature on the documented texel
// grid, and on an unrelated grid), follows the luminance texel by texel (the environment
// rendered to an equirect image here), samples land as the density says (chi-square on
// sub-texel bins), a sun of 1e5 gets its share of the samples, the shader tables reproduce the
// sampling by bisection as a shader would, and bad inputs are refused naming the argument.
#include "core/env/env_sampling.h"
#include "core/env/environment.h"
#include "core/env/sun_sky.h"
#include "core/error.h"
#include "core/frame.h"
#include "core/sampling/hammersley.h"
#include "tests/core/chi_square.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;

double luminance(const glm::dvec3& c)
{
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// Direction at equirect longitude fraction u (phi = pi - 2 pi u, environment.h) and z = cos(theta).
glm::dvec3 directionAt(double u, double z)
{
  const double phi = kPi - 2.0 * kPi * u;
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

// Texel (x, y) of a direction on a W x H equirect grid (u = x / W..., theta = pi y / H...).
glm::ivec2 texelOf(const glm::dvec3& d, int width, int height)
{
  double u = 0.5 - std::atan2(d.y, d.x) / (2.0 * kPi);
  u -= std::floor(u);
  const double theta = std::acos(std::clamp(d.z / glm::length(d), -1.0, 1.0));
  return {std::min(width - 1, int(u * width)), std::min(height - 1, int(theta / kPi * height))};
}

// The environment used for most tests: a sun of 1e5 (0.27 degrees) at 35 degrees elevation
// over a sky of 1.
aniso::SunSkyEnvironment sunSky(double sky)
{
  return aniso::SunSkyEnvironment(glm::dvec3(0.6, -0.5, std::tan(35.0 * kPi / 180.0) * 0.781),
                                  aniso::SunSkyEnvironment::kSunAngularRadius, glm::dvec3(1e5),
                                  glm::dvec3(sky));
}

aniso::EnvSamplingOptions options(int width, int supersample, double uniformFraction)
{
  aniso::EnvSamplingOptions o;
  o.width = width;
  o.supersample = supersample;
  o.uniformFraction = uniformFraction;
  return o;
}

// Integral of pdf over the sphere on a sub-grid of the texel grid documented in the header
// (texel x covers u in [x/W, (x+1)/W], row y covers theta in [pi y/H, pi (y+1)/H]): `split`
// sub-cells per texel side, each the pdf at its centre times its exact solid angle.
double integralOnTexelGrid(const aniso::EnvironmentDistribution& d, int split)
{
  const int w = d.width() * split;
  const int h = d.height() * split;
  double total = 0.0;
  for (int y = 0; y < h; ++y)
  {
    const double z0 = std::cos(kPi * y / h);
    const double z1 = std::cos(kPi * (y + 1) / h);
    const double zMid = std::cos(kPi * (y + 0.5) / h);
    for (int x = 0; x < w; ++x)
      total += d.pdf(directionAt((x + 0.5) / w, zMid)) * (2.0 * kPi / w) * (z0 - z1);
  }
  return total;
}
} // namespace

// The density integrates to 1: exactly on the texel grid (it is piecewise constant there), and
// within 1e-3 by a midpoint rule in (u, cos theta) that ignores the texel grid, for the smooth
// studio, the sun-sky (35% of its power in one texel) and a black environment (uniform).
TEST(EnvSampling, DensityIntegratesToOne)
{
  aniso::StudioEnvironment studio;
  const aniso::SunSkyEnvironment sun = sunSky(1.0);
  aniso::UniformEnvironment black(glm::dvec3(0.0));
  const aniso::EnvironmentDistribution a =
      aniso::EnvironmentDistribution::bake(studio, options(64, 2, 0.02));
  const aniso::EnvironmentDistribution b =
      aniso::EnvironmentDistribution::bake(sun, options(128, 16, 0.02));
  const aniso::EnvironmentDistribution c =
      aniso::EnvironmentDistribution::bake(black, options(16, 1, 0.0));
  for (const aniso::EnvironmentDistribution* d : {&a, &b, &c})
  {
    EXPECT_NEAR(integralOnTexelGrid(*d, 3), 1.0, 1e-12) << d->key();
    const int nu = 1999;
    const int nz = 1001;
    double total = 0.0;
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nz; ++j)
        total += d->pdf(directionAt((i + 0.5) / nu, -1.0 + 2.0 * (j + 0.5) / nz));
    total *= (2.0 * kPi / nu) * (2.0 / nz);
    // The sun's texel holds a third of the mass: its edges cost the unaligned grid up to
    // (grid spacing / texel size) of that.
    EXPECT_NEAR(total, 1.0, d == &b ? 2e-2 : 1e-3) << d->key();
  }
  for (const glm::dvec3& dir : {glm::dvec3(0, 0, 1), glm::dvec3(1, 2, -3), glm::dvec3(0, 0, -1)})
    EXPECT_DOUBLE_EQ(c.pdf(dir), 1.0 / (4.0 * kPi));
}

// Texel by texel, density = (1 - f) L / (sum of L times solid angle) + f / (4 pi), with L the
// luminance of the image the distribution is made from (the studio rendered here), for f = 0
// and f = 0.3.
TEST(EnvSampling, DensityFollowsLuminance)
{
  aniso::StudioEnvironment studio;
  const int w = 64;
  const int h = 32;
  const aniso::Image image = aniso::renderEquirect(studio, w, h, 2);
  double power = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      power += luminance({image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)}) *
               (2.0 * kPi / w) * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
  for (double f : {0.0, 0.3})
  {
    const aniso::EnvironmentDistribution d(image, f, "studio image");
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
      {
        const double l = luminance({image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)});
        const double expected = (1.0 - f) * l / power + f / (4.0 * kPi);
        const glm::dvec3 centre = directionAt((x + 0.5) / w, std::cos(kPi * (y + 0.5) / h));
        EXPECT_NEAR(d.pdf(centre), expected, 1e-6 * expected) << x << ',' << y;
      }
  }
}

// Samples against the density: 1M samples binned into 2 x 2 sub-cells of each texel (halves in
// u and in theta, so the placement inside a texel is tested too), the expected count of each
// bin from pdf() at 3 x 3 points times the bin's exact solid angle; Pearson at p > 1e-4 (fixed
// seed). Samples are unit vectors and carry pdf(direction).
TEST(EnvSampling, SamplesMatchDensityChiSquare)
{
  aniso::StudioEnvironment studio;
  const aniso::SunSkyEnvironment sun = sunSky(1.0);
  const aniso::EnvironmentDistribution a =
      aniso::EnvironmentDistribution::bake(studio, options(32, 2, 0.02));
  const aniso::EnvironmentDistribution b =
      aniso::EnvironmentDistribution::bake(sun, options(64, 16, 0.02));
  std::mt19937_64 random(99);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const aniso::EnvironmentDistribution* d : {&a, &b})
  {
    const int w = 2 * d->width();
    const int h = 2 * d->height();
    const int samples = 1000000;
    std::vector<double> observed(std::size_t(w * h), 0.0);
    for (int i = 0; i < samples; ++i)
    {
      const aniso::EnvSample s = d->sample({uniform(random), uniform(random)});
      ASSERT_NEAR(glm::length(s.direction), 1.0, 1e-12);
      ASSERT_NEAR(s.pdf, d->pdf(s.direction), 1e-9 * s.pdf);
      const glm::ivec2 bin = texelOf(s.direction, w, h);
      observed[std::size_t(bin.y * w + bin.x)] += 1.0;
    }
    std::vector<double> expected(observed.size(), 0.0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
      {
        double mean = 0.0;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            mean += d->pdf(directionAt((x + (i + 0.5) / 3.0) / w,
                                       std::cos(kPi * (y + (j + 0.5) / 3.0) / h))) /
                    9.0;
        const double solidAngle =
            (2.0 * kPi / w) * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
        expected[std::size_t(y * w + x)] = mean * solidAngle * samples;
      }
    const aniso_test::ChiSquareResult r = aniso_test::chiSquare(observed, expected);
    EXPECT_GT(r.pValue, 1e-4) << d->key() << " bins " << r.bins;
  }
}

// The bake resolves a small source: with the sky removed, the sun's power in the tables
// (sum over texels of luminance times solid angle) is 1e5 times the disc's exact solid angle
// within 1%, on a coarse grid (disc well inside one texel) and a fine one (disc across texels,
// whose edge texels the bake refines).
TEST(EnvSampling, BakeResolvesTheSun)
{
  for (int width : {256, 1024})
  {
    const aniso::SunSkyEnvironment env = sunSky(1.0);
    const aniso::EnvironmentDistribution d =
        aniso::EnvironmentDistribution::bake(env, options(width, 4, 0.0));
    // density = L / P with P the total power, and the sky's power is 4 pi exactly.
    const double skyDensity = d.pdf(-env.sun().direction);
    const double power = 1.0 / skyDensity;
    const double sunPower = power - 4.0 * kPi;
    EXPECT_NEAR(sunPower, 1e5 * env.sunSolidAngle(), 1e-2 * 1e5 * env.sunSolidAngle())
        << "width " << width;
  }
}

// The sun's share. Over black, every sample not in the uniform part (98%) lands in the texels
// around the sun (within the disc radius plus a texel diagonal of its centre). Over a sky of 1,
// the sun holds P_sun / (P_sun + P_sky) of the power, P_sun = 1e5 x its solid angle, P_sky =
// 4 pi; at least 95% of (1 - f) times that share lands there (the bake resolves the disc with
// ~30 supersamples, so its area is known to a few percent).
TEST(EnvSampling, SunGetsItsShareOfSamples)
{
  const int width = 256;
  const double texelDiagonal = std::sqrt(2.0) * 2.0 * kPi / width;
  for (double sky : {0.0, 1.0})
  {
    const aniso::SunSkyEnvironment env = sunSky(sky);
    const aniso::EnvironmentDistribution d =
        aniso::EnvironmentDistribution::bake(env, options(width, 16, 0.02));
    const uint32_t n = 1u << 16;
    uint32_t inSun = 0;
    const double cosCone = std::cos(env.sun().angularRadius + texelDiagonal);
    for (uint32_t i = 0; i < n; ++i)
      if (glm::dot(d.sample(aniso::hammersley(i, n)).direction, env.sun().direction) >= cosCone)
        ++inSun;
    const double fraction = double(inSun) / n;
    const double sunPower = 1e5 * env.sunSolidAngle();
    const double share = sunPower / (sunPower + 4.0 * kPi * sky);
    std::printf("sky %g: %.4f of the samples at the sun; its share of the power %.4f\n", sky,
                fraction, share);
    if (sky == 0.0)
      EXPECT_GE(fraction, 0.98 - 2e-3);
    else
      EXPECT_GE(fraction, 0.95 * 0.98 * share);
  }
}

// The shader's route: bisection over the float CDF table (largest index whose entry is <= xi,
// as a shader's binary search over texelFetch) finds the same texel as sample() for all but a
// few of 20000 random points (float rounding at texel boundaries), and pdfTable holds pdf() of
// that texel to float precision.
TEST(EnvSampling, ShaderTablesReproduceSampling)
{
  aniso::StudioEnvironment studio;
  const aniso::EnvironmentDistribution d =
      aniso::EnvironmentDistribution::bake(studio, options(128, 2, 0.02));
  const aniso::Image cdf = d.cdfTable();
  const aniso::Image pdf = d.pdfTable();
  const int w = d.width();
  const int h = d.height();
  ASSERT_EQ(cdf.width, w + 1);
  ASSERT_EQ(cdf.height, h + 1);
  ASSERT_EQ(pdf.width, w);
  ASSERT_EQ(pdf.height, h);
  auto search = [&](int row, int count, double xi)
  {
    int lo = 0;
    int hi = count; // cdf(row, lo) <= xi < cdf(row, hi)
    while (hi - lo > 1)
    {
      const int mid = (lo + hi) / 2;
      if (double(cdf.at(mid, row, 0)) <= xi)
        lo = mid;
      else
        hi = mid;
    }
    return lo;
  };
  EXPECT_EQ(cdf.at(0, h, 0), 0.0f);
  EXPECT_EQ(cdf.at(h, h, 0), 1.0f);
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int mismatches = 0;
  for (int i = 0; i < 20000; ++i)
  {
    const glm::dvec2 xi(uniform(random), uniform(random));
    const int y = search(h, h, xi.y);
    const int x = search(y, w, xi.x);
    const aniso::EnvSample s = d.sample(xi);
    const glm::ivec2 texel = texelOf(s.direction, w, h);
    if (texel != glm::ivec2(x, y))
    {
      ++mismatches;
      continue;
    }
    EXPECT_NEAR(pdf.at(x, y, 0), s.pdf, 1e-6 * s.pdf);
  }
  EXPECT_LE(mismatches, 10);
}

// Keys change with every input that changes the tables; the shared cache returns the same
// tables for the same key and new ones otherwise.
TEST(EnvSampling, KeysAndSharedCache)
{
  aniso::StudioEnvironment studio;
  const aniso::SunSkyEnvironment sun = sunSky(1.0);
  const std::string base = aniso::distributionKey(studio.key(), options(64, 2, 0.02));
  EXPECT_NE(base, aniso::distributionKey(studio.key(), options(128, 2, 0.02)));
  EXPECT_NE(base, aniso::distributionKey(studio.key(), options(64, 4, 0.02)));
  EXPECT_NE(base, aniso::distributionKey(studio.key(), options(64, 2, 0.03)));
  EXPECT_NE(base, aniso::distributionKey(sun.key(), options(64, 2, 0.02)));
  EXPECT_NE(sun.key(), sunSky(0.0).key());
  const auto first = aniso::sharedDistribution(studio, options(64, 2, 0.02));
  const auto again = aniso::sharedDistribution(studio, options(64, 2, 0.02));
  const auto other = aniso::sharedDistribution(studio, options(32, 2, 0.02));
  EXPECT_EQ(first.get(), again.get());
  EXPECT_NE(first.get(), other.get());
  EXPECT_EQ(first->key(), base);
}

// Bad options and images are refused naming the argument.
TEST(EnvSampling, Errors)
{
  aniso::StudioEnvironment studio;
  auto messageOf = [&](const aniso::EnvSamplingOptions& o) -> std::string
  {
    try
    {
      aniso::EnvironmentDistribution::bake(studio, o);
    }
    catch (const aniso::Error& e)
    {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(messageOf(options(63, 2, 0.0)).rfind("width: ", 0), 0u);
  EXPECT_EQ(messageOf(options(0, 2, 0.0)).rfind("width: ", 0), 0u);
  EXPECT_EQ(messageOf(options(64, 0, 0.0)).rfind("supersample: ", 0), 0u);
  EXPECT_EQ(messageOf(options(64, 2, -0.1)).rfind("uniformFraction: ", 0), 0u);
  EXPECT_EQ(messageOf(options(64, 2, std::numeric_limits<double>::quiet_NaN()))
                .rfind("uniformFraction: ", 0),
            0u);
  aniso::Image bad(4, 2, 3);
  bad.at(1, 1, 2) = std::numeric_limits<float>::infinity();
  EXPECT_THROW(aniso::EnvironmentDistribution(bad, 0.0, "bad"), aniso::Error);
  EXPECT_THROW(aniso::EnvironmentDistribution(aniso::Image(), 0.0, "empty"), aniso::Error);
}

// The sun-sky environment: radiance sky + sun inside the disc, sky outside; its solid angle
// against a midpoint quadrature of the disc's indicator; bad parameters refused.
TEST(SunSkyEnvironment, DiscAndErrors)
{
  const aniso::SunSkyEnvironment env = sunSky(1.0);
  const glm::dvec3 c = env.sun().direction;
  EXPECT_NEAR(glm::length(c), 1.0, 1e-15);
  const aniso::Frame around = aniso::Frame::fromNormalTangent(c, {1, 0, 0});
  const double r = env.sun().angularRadius;
  auto at = [&](double angle, double turn)
  {
    return std::cos(angle) * around.n +
           std::sin(angle) * (std::cos(turn) * around.t + std::sin(turn) * around.b);
  };
  EXPECT_EQ(env.radiance(c), glm::dvec3(1e5 + 1.0));
  EXPECT_EQ(env.radiance(at(0.99 * r, 1.0)), glm::dvec3(1e5 + 1.0));
  EXPECT_EQ(env.radiance(at(1.01 * r, 1.0)), glm::dvec3(1.0));
  EXPECT_EQ(env.radiance(3.0 * at(0.5 * r, 2.0)), glm::dvec3(1e5 + 1.0)); // not unit
  EXPECT_EQ(env.radiance(-c), glm::dvec3(1.0));
  // Midpoint rule over a square patch of the tangent plane around the sun (gnomonic, with the
  // exact solid-angle element 1 / (1 + x^2 + y^2)^(3/2)).
  const int n = 1000;
  const double half = 1.5 * std::tan(r);
  double area = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const double x = -half + (i + 0.5) * 2.0 * half / n;
      const double y = -half + (j + 0.5) * 2.0 * half / n;
      const glm::dvec3 d = around.n + x * around.t + y * around.b;
      if (env.radiance(d).x > 2.0)
        area += std::pow(1.0 + x * x + y * y, -1.5);
    }
  area *= (2.0 * half / n) * (2.0 * half / n);
  EXPECT_NEAR(area, env.sunSolidAngle(), 5e-3 * env.sunSolidAngle());
  EXPECT_THROW(aniso::SunSkyEnvironment({0, 0, 0}, 0.01, glm::dvec3(1), glm::dvec3(1)),
               aniso::Error);
  EXPECT_THROW(aniso::SunSkyEnvironment({0, 0, 1}, 0.0, glm::dvec3(1), glm::dvec3(1)),
               aniso::Error);
  EXPECT_THROW(aniso::SunSkyEnvironment({0, 0, 1}, 0.01, glm::dvec3(-1), glm::dvec3(1)),
               aniso::Error);
  EXPECT_THROW(aniso::SunSkyEnvironment({0, 0, 1}, 0.01, glm::dvec3(1),
                                        glm::dvec3(std::numeric_limits<double>::infinity())),
               aniso::Error);
}

// The distribution that covers a cube map: wherever a bilinear lookup of the cube's level 0 can
// return radiance, the density is at least that radiance over the environment's power (the sun's
// bilinear reach in a 256 cube is wider than its grid texels); and the level bound keeps filtered
// lookups next to the sun at levels whose reach stays clear of it, while far from it (the sky
// opposite) they keep the whole chain.
TEST(EnvironmentDistribution, CoversTheCubeAndBoundsLevelsNextToTheSun)
{
  const aniso::SunSkyEnvironment env = sunSky(1.0);
  const aniso::Cubemap cube = aniso::buildCubemap(env, 256);
  aniso::EnvSamplingOptions options;
  options.width = 1024; // the shader's grid, finer than the cube's texels
  options.supersample = 2;
  const aniso::EnvironmentDistribution plain = aniso::EnvironmentDistribution::bake(env, options);
  const aniso::EnvironmentDistribution covered =
      aniso::EnvironmentDistribution::bake(env, options, cube);
  EXPECT_NE(plain.key(), covered.key());
  // Directions around the sun within two cube texels, their density relative to the sky's
  // (covering raises the total, so every absolute density falls): not lower than before (but for
  // the uniform share, which the sky's density holds more of), and
  // raised over more than the sun's own texels.
  const glm::dvec3 sun = glm::normalize(env.sun().direction);
  const aniso::Frame around = aniso::Frame::fromNormalTangent(sun, glm::dvec3(0.0, 0.0, 1.0));
  const glm::dvec3 sky = glm::normalize(glm::dvec3(-sun.x, -sun.y, sun.z));
  auto relative = [&](const aniso::EnvironmentDistribution& d, const glm::dvec3& at)
  { return d.pdf(at) / d.pdf(sky); };
  const double reach = 2.0 * 2.0 / 256.0;
  int raised = 0;
  for (int i = -20; i <= 20; ++i)
    for (int j = -20; j <= 20; ++j)
    {
      const glm::dvec3 d =
          glm::normalize(sun + (reach * i / 20.0) * around.t + (reach * j / 20.0) * around.b);
      raised += relative(covered, d) > 1.5 * relative(plain, d) ? 1 : 0;
      EXPECT_GE(relative(covered, d), 0.9 * relative(plain, d)); // 0.9: the uniform share
    }
  EXPECT_GT(raised, 100); // the reach is wider than the sun's texels
  const int maxLevel = 8;
  const aniso::Image bound = covered.lodBoundTable(256, maxLevel);
  auto boundAt = [&](const glm::dvec3& d)
  {
    const glm::dvec2 uv = aniso::directionToEquirect(d);
    const int x = std::clamp(int(uv.x * bound.width), 0, bound.width - 1);
    const int y = std::clamp(int((1.0 - uv.y) * bound.height), 0, bound.height - 1);
    return bound.at(x, y, 0);
  };
  // Ten cube texels from the sun: no level whose reach (1.5 texels of 2^level) gets there.
  const glm::dvec3 near = glm::normalize(sun + 10.0 * (2.0 / 256.0) * around.t);
  EXPECT_LE(boundAt(near), 3.0f);
  EXPECT_GE(boundAt(near), 1.0f);
  EXPECT_EQ(boundAt(sky), float(maxLevel));
  EXPECT_THROW(covered.lodBoundTable(100, maxLevel), aniso::Error);
}
