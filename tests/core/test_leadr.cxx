// LEADR mapping: moments of analytic height fields against closed forms, mip levels against the
// mean of the fine texels, the Beckmann distribution from moments against its normalisation,
// Smith masking against the projected-area identity, the slope-grid environment sum against
// sphere quadrature (and its cubemap-LOD version against it), the rough SH9 diffuse against its
// expectation by product quadrature, the silhouette micronormal, and the purpose of it all: a
// coarse level shaded with LEADR matches the supersampled shading of the fine texels it covers,
// while the averaged normal of plain normal-map filtering does not.
#include "core/env/cubemap.h"
#include "core/env/environment.h"
#include "core/env/quadrature.h"
#include "core/error.h"
#include "core/leadr/leadr.h"
#include "core/models/height_field.h"
#include "tests/core/test_models_quadrature.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace
{
using aniso::SlopeStatistics;
using models_test::kPi;

SlopeStatistics stats(glm::dvec2 mean, double vx, double vy, double c)
{
  SlopeStatistics s;
  s.mean = mean;
  s.varX = vx;
  s.varY = vy;
  s.covXY = c;
  return s;
}

glm::dvec3 meanNormal(const SlopeStatistics& s)
{
  return aniso::normalOfSlope(s.mean);
}

// The Beckmann distribution of a texel's statistics, centred or not, correlated or not,
// integrates to 1 in projected solid angle: integral D(m) (m.z) dm = 1.
TEST(Leadr, BeckmannFromMomentsIntegratesToOne)
{
  const SlopeStatistics cases[] = {
      stats({0.0, 0.0}, 0.005, 0.005, 0.0), stats({0.3, -0.2}, 0.02, 0.05, 0.015),
      stats({-0.8, 0.5}, 0.1, 0.01, -0.02), stats({0.1, 0.1}, 5e-7, 5e-7, 0.0)};
  for (const SlopeStatistics& s : cases)
  {
    const double integral = models_test::sphereIntegral(
        [&](const glm::dvec3& m)
        { return m.z > 0.0 ? aniso::beckmannDistribution(s, m) * m.z : 0.0; },
        meanNormal(s), 240, 512, true);
    EXPECT_NEAR(integral, 1.0, 1e-5) << s.mean.x << " " << s.varX;
  }
}

// h = A sin(2 pi k u) (ridges along v), scale s: central differences give the slope
// x = s A W sin(2 pi k / W) cos(2 pi k u), y = 0, so every level covering whole periods has
// E[x] = 0, E[x^2] = (s A W sin(2 pi k / W))^2 / 2 and E[y] = E[y^2] = E[xy] = 0; diagonal ridges
// h = A sin(2 pi k (u + v)) on a square map have x = y, so E[xy] = E[x^2] = E[y^2].
// The continuous limit (2 pi k s A)^2 / 2 is within (2 pi k / W)^2 / 3 relative.
TEST(Leadr, MomentsOfSinusoidalRidgesMatchClosedForm)
{
  const int w = 64;
  const int k = 4;
  const double amplitude = 0.01;
  const double scale = 1.5;
  aniso::Image ridges(w, w, 1);
  aniso::Image diagonal(w, w, 1);
  for (int y = 0; y < w; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const double u = (x + 0.5) / w;
      const double v = 1.0 - (y + 0.5) / w;
      ridges.at(x, y, 0) = float(amplitude * std::sin(2.0 * kPi * k * u));
      diagonal.at(x, y, 0) = float(amplitude * std::sin(2.0 * kPi * k * (u + v)));
    }
  }
  const double peak = scale * amplitude * w * std::sin(2.0 * kPi * k / w);
  const double expectedXX = 0.5 * peak * peak;
  const aniso::LeadrMips mips = aniso::bakeLeadrFromHeight(ridges, scale);
  ASSERT_EQ(mips.levels.size(), 7u);
  // Level 4 texels cover 16 x 16 fine texels, one full period along u.
  for (int level : {4, 6})
  {
    const aniso::SlopeMoments m = aniso::leadrTexel(mips, level, 0, 0);
    EXPECT_NEAR(m.x, 0.0, 1e-6);
    EXPECT_NEAR(m.xx, expectedXX, 1e-6 * expectedXX);
    EXPECT_NEAR(m.y, 0.0, 1e-9);
    EXPECT_NEAR(m.yy, 0.0, 1e-9);
    EXPECT_NEAR(m.xy, 0.0, 1e-9);
  }
  const double continuous = 0.5 * std::pow(2.0 * kPi * k * scale * amplitude, 2.0);
  EXPECT_NEAR(aniso::leadrTexel(mips, 6, 0, 0).xx, continuous,
              continuous * std::pow(2.0 * kPi * k / w, 2.0) / 3.0);

  const aniso::SlopeMoments d =
      aniso::leadrTexel(aniso::bakeLeadrFromHeight(diagonal, scale), 6, 0, 0);
  EXPECT_NEAR(d.xx, expectedXX, 1e-6 * expectedXX);
  EXPECT_NEAR(d.yy, expectedXX, 1e-6 * expectedXX);
  EXPECT_NEAR(d.xy, expectedXX, 1e-6 * expectedXX);
}

// For odd sizes too, the 1 x 1 level is the mean of all fine texels' moments (each counted once,
// with equal weight), and the trilinear lookup at a texel centre of a level returns that texel.
TEST(Leadr, MipLevelsAverageFineTexels)
{
  std::mt19937_64 rng(61);
  std::normal_distribution<double> normal(0.0, 0.3);
  aniso::Image slopes(37, 21, 2);
  double sum[5] = {0, 0, 0, 0, 0};
  for (int y = 0; y < 21; ++y)
  {
    for (int x = 0; x < 37; ++x)
    {
      const float sx = float(normal(rng) + 0.1);
      const float sy = float(normal(rng));
      slopes.at(x, y, 0) = sx;
      slopes.at(x, y, 1) = sy;
      sum[0] += sx;
      sum[1] += sy;
      sum[2] += double(sx) * sx;
      sum[3] += double(sy) * sy;
      sum[4] += double(sx) * sy;
    }
  }
  const aniso::LeadrMips mips = aniso::bakeLeadrFromSlopes(slopes);
  const aniso::SlopeMoments top = aniso::leadrTexel(mips, int(mips.levels.size()) - 1, 0, 0);
  const double n = 37.0 * 21.0;
  EXPECT_NEAR(top.x, sum[0] / n, 1e-6);
  EXPECT_NEAR(top.y, sum[1] / n, 1e-6);
  EXPECT_NEAR(top.xx, sum[2] / n, 1e-6);
  EXPECT_NEAR(top.yy, sum[3] / n, 1e-6);
  EXPECT_NEAR(top.xy, sum[4] / n, 1e-6);

  const aniso::Image& level1 = mips.levels[1];
  for (int y = 0; y < level1.height; ++y)
  {
    for (int x = 0; x < level1.width; ++x)
    {
      const glm::dvec2 uv((x + 0.5) / level1.width, 1.0 - (y + 0.5) / level1.height);
      EXPECT_NEAR(aniso::sampleLeadr(mips, uv, 1.0).xx, aniso::leadrTexel(mips, 1, x, y).xx, 1e-6);
    }
  }
}

// Normal maps give the slopes -n.x / n.z, -n.y / n.z (8-bit decoding included).
TEST(Leadr, NormalMapSlopes)
{
  aniso::Image normals(1, 1, 3);
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.4, 0.8));
  for (int c = 0; c < 3; ++c)
    normals.data[std::size_t(c)] = float(0.5 * n[c] + 0.5);
  const aniso::SlopeMoments m =
      aniso::leadrTexel(aniso::bakeLeadrFromNormals(normals, true), 0, 0, 0);
  EXPECT_NEAR(m.x, -0.3 / 0.8, 1e-6);
  EXPECT_NEAR(m.y, 0.4 / 0.8, 1e-6);
  EXPECT_NEAR(m.xy, m.x * m.y, 1e-6);
}

// Smith masking for the shifted Gaussian: integral G1(v) (v.m)+ D(m) dm equals the projected
// area of the mean surface, v . (-mu_x, -mu_y, 1), with the exact Lambda (to quadrature accuracy)
// and within 1% with Walter's approximation. The largest G1 difference between the two over
// a in (0, 6] is printed and bounded.
TEST(Leadr, SmithMaskingNormalisesProjectedArea)
{
  const SlopeStatistics cases[] = {stats({0.0, 0.0}, 0.02, 0.02, 0.0),
                                   stats({0.25, -0.15}, 0.03, 0.08, 0.02)};
  for (const SlopeStatistics& s : cases)
  {
    for (double theta : {0.0, 35.0, 60.0, 75.0})
    {
      for (double phi : {0.0, 120.0, 250.0})
      {
        const glm::dvec3 v = models_test::fromAngles(theta, phi);
        const double area = glm::dot(v, glm::dvec3(-s.mean.x, -s.mean.y, 1.0));
        ASSERT_GT(aniso::maskingParameter(s, v), 0.0);
        const double visible = models_test::sphereIntegral(
            [&](const glm::dvec3& m)
            { return std::max(glm::dot(v, m), 0.0) * aniso::beckmannDistribution(s, m); },
            meanNormal(s), 160, 384, true);
        for (bool exact : {true, false})
        {
          EXPECT_NEAR(aniso::leadrMasking(s, v, exact) * visible, area,
                      (exact ? 2e-5 : 1e-2) * area)
              << theta << " " << phi << (exact ? " exact" : " Walter");
        }
      }
    }
  }
  double largest = 0.0;
  for (int i = 1; i <= 6000; ++i)
  {
    const double a = i * 1e-3;
    largest = std::max(largest, std::abs(1.0 / (1.0 + aniso::beckmannLambdaExact(a)) -
                                         1.0 / (1.0 + aniso::beckmannLambdaWalter(a))));
  }
  std::printf("largest |G1 Walter - G1 exact|: %.2e\n", largest);
  EXPECT_LT(largest, 5e-3);
}

// The environment sum on a 32 x 32 slope grid (equal-probability quantiles) against quadrature
// over light directions of f L (n.l) with the same distribution, for the studio environment.
TEST(Leadr, EnvironmentGridMatchesQuadrature)
{
  const aniso::StudioEnvironment studio;
  const aniso::Frame frame;
  const aniso::SlopeGrid grid = aniso::makeSlopeGrid(32);
  const glm::dvec3 f0(0.9);
  const SlopeStatistics cases[] = {stats({0.1, -0.05}, 0.01, 0.03, 0.005),
                                   stats({-0.2, 0.1}, 0.06, 0.04, -0.01)};
  for (const SlopeStatistics& s : cases)
  {
    for (double theta : {10.0, 45.0})
    {
      const glm::dvec3 v = models_test::fromAngles(theta, 200.0);
      ASSERT_GT(aniso::maskingParameter(s, v), aniso::kSilhouetteMinA);
      const glm::dvec3 grid32 = aniso::leadrEnvironmentSpecular(s, f0, frame, v, studio, grid);
      const glm::dvec3 mirror = 2.0 * glm::dot(v, meanNormal(s)) * meanNormal(s) - v;
      const double quadrature = models_test::sphereIntegral(
          [&](const glm::dvec3& l) {
            return l.z > 0.0 ? aniso::evalLeadrSpecular(s, f0, v, l).x * studio.radiance(l).x * l.z
                             : 0.0;
          },
          mirror, 120, 256, true);
      std::printf("grid 32: %.5f, quadrature %.5f (%+.2f%%)\n", grid32.x, quadrature,
                  100.0 * (grid32.x / quadrature - 1.0));
      EXPECT_NEAR(grid32.x, quadrature, 0.02 * quadrature);
    }
  }
}

// The cubemap version (per-sample LOD into a 128^2 prefiltered cube) against the direct
// environment version of the same sum, for a narrow and a rough distribution, on a 16 x 16 grid.
TEST(Leadr, CubemapLodMatchesEnvironment)
{
  const aniso::StudioEnvironment studio;
  const aniso::Cubemap cube = aniso::buildCubemap(studio, 128, 2);
  const aniso::Frame frame =
      aniso::Frame::fromNormalTangent(glm::dvec3(0.2, 0.1, 1.0), glm::dvec3(1.0, 0.0, 0.0));
  const aniso::SlopeGrid grid = aniso::makeSlopeGrid(16);
  for (const SlopeStatistics& s :
       {stats({0.05, 0.0}, 0.002, 0.004, 0.0), stats({0.0, 0.1}, 0.08, 0.05, 0.02)})
  {
    for (double theta : {5.0, 50.0})
    {
      const glm::dvec3 v = frame.toWorld(models_test::fromAngles(theta, 30.0));
      const glm::dvec3 direct =
          aniso::leadrEnvironmentSpecular(s, glm::dvec3(1.0), frame, v, studio, grid);
      const glm::dvec3 lod =
          aniso::leadrEnvironmentSpecular(s, glm::dvec3(1.0), frame, v, cube, grid);
      std::printf("environment %.4f, cubemap with LOD %.4f (%+.2f%%)\n", direct.x, lod.x,
                  100.0 * (lod.x / direct.x - 1.0));
      EXPECT_NEAR(lod.x, direct.x, 0.05 * direct.x);
    }
  }
  // The LOD grows with the spread of the distribution and with fewer samples.
  const glm::dvec3 v(0.0, 0.0, 1.0);
  const glm::dvec3 m(0.0, 0.0, 1.0);
  const double narrow = aniso::leadrSampleLod(stats({0, 0}, 0.001, 0.001, 0), v, m, 16, 128);
  const double rough = aniso::leadrSampleLod(stats({0, 0}, 0.1, 0.1, 0), v, m, 16, 128);
  EXPECT_NEAR(rough - narrow, 0.5 * std::log2(100.0), 1e-9); // Omega scales with det(Sigma)^1/2
  EXPECT_NEAR(aniso::leadrSampleLod(stats({0, 0}, 0.1, 0.1, 0), v, m, 8, 128) - rough, 1.0, 1e-9);
}

// The rough diffuse under an environment: with a vanishing spread it is rho / pi E_SH9(mean
// normal); with a spread, the 16 x 16 grid average of E_SH9 over the normals is within 1% of its
// expectation over the slope Gaussian (192 x 192 product quadrature).
TEST(Leadr, RoughDiffuseSh9)
{
  const aniso::StudioEnvironment studio;
  const aniso::Sh9 sh = aniso::projectSh9(studio, 32);
  const aniso::Frame frame =
      aniso::Frame::fromNormalTangent(glm::dvec3(0.3, -0.2, 1.0), glm::dvec3(0.0, 1.0, 0.0));
  const aniso::SlopeGrid grid = aniso::makeSlopeGrid(16);
  const glm::dvec3 rho(0.8);

  const SlopeStatistics sharp = stats({0.2, -0.3}, 1e-12, 1e-12, 0.0);
  const glm::dvec3 expectedSharp =
      rho / kPi * aniso::irradianceSh9(sh, frame.toWorld(meanNormal(sharp)));
  const glm::dvec3 valueSharp = aniso::leadrEnvironmentDiffuse(sharp, rho, frame, sh, grid);
  EXPECT_NEAR(valueSharp.x, expectedSharp.x, 1e-6 * expectedSharp.x);

  // The expectation over the slope Gaussian by a product rule in the standard variables z in
  // [-8, 8]^2 (composite Gauss-Legendre weighted by the normal density), independent of the
  // equal-probability grid.
  const aniso::QuadratureRule rule = aniso::compositeGaussLegendre(24, 8, -8.0, 8.0);
  for (const SlopeStatistics& s :
       {stats({0.1, 0.0}, 0.05, 0.02, 0.01), stats({-0.3, 0.2}, 0.2, 0.3, -0.1)})
  {
    glm::dvec3 expectation(0.0);
    for (std::size_t i = 0; i < rule.nodes.size(); ++i)
    {
      for (std::size_t j = 0; j < rule.nodes.size(); ++j)
      {
        const double z1 = rule.nodes[i];
        const double z2 = rule.nodes[j];
        const double w =
            rule.weights[i] * rule.weights[j] * std::exp(-0.5 * (z1 * z1 + z2 * z2)) / (2.0 * kPi);
        const glm::dvec3 m = aniso::normalOfSlope(aniso::gridSlope(s, z1, z2));
        expectation += w * glm::max(aniso::irradianceSh9(sh, frame.toWorld(m)), glm::dvec3(0.0));
      }
    }
    expectation *= rho / kPi;
    const glm::dvec3 value = aniso::leadrEnvironmentDiffuse(s, rho, frame, sh, grid);
    std::printf("rough diffuse: grid %.5f, expectation %.5f (%+.2f%%)\n", value.x, expectation.x,
                100.0 * (value.x / expectation.x - 1.0));
    EXPECT_NEAR(value.x, expectation.x, 0.01 * expectation.x);
  }
}

// The artificial micronormal: statistics are left alone while the view is well above the mean
// microsurface and its mirror direction about the mean normal stays above the horizon;
// otherwise the mean moves along the view azimuth until the first constraint binds (here the
// mirror direction, from theta_v = 90 - 2 atan(0.6) degrees on), so shading is continuous across
// the threshold; a view below the mean microsurface (which masking alone turns black) and even
// a view below the geometric horizon still get a finite, positive reflection.
TEST(Leadr, SilhouetteMicronormal)
{
  // Mean slope +0.6 along x: the mean microsurface leans away from views on the +X side.
  const SlopeStatistics away = stats({0.6, 0.0}, 0.01, 0.01, 0.0);
  const SlopeStatistics same =
      aniso::withSilhouetteMicronormal(away, models_test::fromAngles(20.0, 0.0));
  EXPECT_EQ(same.mean, away.mean);

  const glm::dvec3 grazing = models_test::fromAngles(75.0, 0.0); // cot 75 = 0.27 < 0.6
  EXPECT_LE(aniso::maskingParameter(away, grazing), 0.0);
  EXPECT_EQ(aniso::leadrMasking(away, grazing), 0.0);
  const SlopeStatistics moved = aniso::withSilhouetteMicronormal(away, grazing);
  const glm::dvec3 m = aniso::normalOfSlope(moved.mean);
  const glm::dvec3 mirror = 2.0 * glm::dot(grazing, m) * m - grazing;
  EXPECT_NEAR(mirror.z, 0.0, 1e-12);
  EXPECT_GE(aniso::maskingParameter(moved, grazing), aniso::kSilhouetteMinA);
  EXPECT_EQ(moved.mean.y, 0.0);

  const aniso::StudioEnvironment studio;
  const aniso::Frame frame;
  const aniso::SlopeGrid grid = aniso::makeSlopeGrid(16);
  auto shade = [&](const glm::dvec3& v)
  { return aniso::leadrEnvironmentSpecular(away, glm::dvec3(1.0), frame, v, studio, grid).x; };
  const double threshold = 90.0 - 2.0 * std::atan(0.6) * 180.0 / kPi;
  const double before = shade(models_test::fromAngles(threshold - 1e-6, 0.0));
  const double after = shade(models_test::fromAngles(threshold + 1e-6, 0.0));
  EXPECT_GT(before, 0.0);
  EXPECT_NEAR(after, before, 1e-4 * before);
  EXPECT_GT(shade(grazing), 0.0);
  const double behind = shade(glm::normalize(glm::dvec3(1.0, 0.0, -0.1)));
  EXPECT_TRUE(std::isfinite(behind));
  EXPECT_GT(behind, 0.0);
}

// A rough surface with Gaussian-like slope statistics: 64 plane waves (integer wave vectors up
// to 4 per tile, so the map tiles; phases from a fixed hash), slope deviation about 0.3 per axis.
// The fine texels are the 4096 level-0 texels, each a Beckmann microsurface of roughness 0.1
// around its own slope; the coarse texel is the 1 x 1 level covering them all; the baseline is
// the renormalised average normal with the same base roughness.
struct FilteringSetup
{
  double baseAlpha = 0.1;
  std::vector<SlopeStatistics> fine;
  SlopeStatistics coarse;
  SlopeStatistics naive;

  static double hash01(std::uint32_t x)
  {
    x = x * 2654435761u + 17u;
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x / 4294967296.0;
  }

  FilteringSetup()
  {
    const int w = 64;
    const int waves = 64;
    aniso::Image height(w, w, 1);
    for (int y = 0; y < w; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const double u = (x + 0.5) / w;
        const double v = 1.0 - (y + 0.5) / w;
        double h = 0.0;
        for (int k = 0; k < waves; ++k)
        {
          int kx = int(hash01(4u * k) * 9.0) - 4;
          const int ky = int(hash01(4u * k + 1u) * 9.0) - 4;
          if (kx == 0 && ky == 0)
            kx = 3;
          const double phase = 2.0 * kPi * hash01(4u * k + 2u);
          const double frequency = 2.0 * kPi * std::sqrt(double(kx * kx + ky * ky));
          h += 0.3 / (frequency * std::sqrt(waves / 2.0)) *
               std::sin(2.0 * kPi * (kx * u + ky * v) + phase);
        }
        height.at(x, y, 0) = float(h);
      }
    }
    const aniso::LeadrMips mips = aniso::bakeLeadrFromHeight(height, 1.0);
    glm::dvec3 normalSum(0.0);
    for (int y = 0; y < w; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const aniso::SlopeMoments m = aniso::leadrTexel(mips, 0, x, y);
        fine.push_back(aniso::slopeStatistics(m, baseAlpha, baseAlpha));
        normalSum += aniso::normalOfSlope({m.x, m.y});
      }
    }
    const int top = int(mips.levels.size()) - 1;
    coarse = aniso::slopeStatistics(aniso::leadrTexel(mips, top, 0, 0), baseAlpha, baseAlpha);
    naive = aniso::statisticsFromAveragedNormal(normalSum, baseAlpha, baseAlpha);
  }
};

double relativeL2(const std::vector<double>& x, const std::vector<double>& reference)
{
  double num = 0.0;
  double den = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    num += (x[i] - reference[i]) * (x[i] - reference[i]);
    den += reference[i] * reference[i];
  }
  return std::sqrt(num / den);
}

// The purpose of LEADR. Over a sweep of directional lights (every 5 degrees of elevation up to
// 85, every 15 of azimuth; specular, F0 = 1) and three views, the coarse texel shaded from its
// moments stays within 15% (relative L2) of the average of the 4096 fine texels' shading, while
// the averaged normal of plain normal-map filtering (a narrow highlight where the fine texels
// spread a wide one) is off by more than 200%. Under the studio environment (the slope-grid sum,
// views up to 25 degrees) the errors are below 6% and above 50%. The numbers are printed. (The
// Gaussian fit is the approximation: regions whose slopes are far from Gaussian, such as one
// period of a regular bump pattern, give larger LEADR errors under point lights.)
TEST(Leadr, FilteredLevelMatchesSupersampledShading)
{
  const FilteringSetup setup;
  const glm::dvec3 f0(1.0);
  std::vector<double> reference;
  std::vector<double> leadr;
  std::vector<double> naive;
  for (double thetaV : {0.0, 25.0, 45.0})
  {
    const glm::dvec3 v = models_test::fromAngles(thetaV, 30.0);
    for (int i = 0; i <= 17; ++i)
    {
      for (int j = 0; j < 24; ++j)
      {
        const glm::dvec3 l = models_test::fromAngles(5.0 * i, 15.0 * j);
        double sum = 0.0;
        for (const SlopeStatistics& s : setup.fine)
          sum += aniso::evalLeadrSpecular(s, f0, v, l).x * l.z;
        reference.push_back(sum / double(setup.fine.size()));
        leadr.push_back(aniso::evalLeadrSpecular(setup.coarse, f0, v, l).x * l.z);
        naive.push_back(aniso::evalLeadrSpecular(setup.naive, f0, v, l).x * l.z);
      }
    }
  }
  const double leadrError = relativeL2(leadr, reference);
  const double naiveError = relativeL2(naive, reference);
  std::printf("light sweep: LEADR %.1f%%, averaged normal %.1f%% (relative L2)\n",
              100.0 * leadrError, 100.0 * naiveError);
  EXPECT_LT(leadrError, 0.15);
  EXPECT_GT(naiveError, 2.0);

  const aniso::StudioEnvironment studio;
  const aniso::Frame frame;
  const aniso::SlopeGrid fineGrid = aniso::makeSlopeGrid(8);
  const aniso::SlopeGrid coarseGrid = aniso::makeSlopeGrid(24);
  std::vector<double> envReference;
  std::vector<double> envLeadr;
  std::vector<double> envNaive;
  for (double thetaV : {0.0, 15.0, 25.0})
  {
    for (double phiV : {30.0, 160.0})
    {
      const glm::dvec3 v = models_test::fromAngles(thetaV, phiV);
      glm::dvec3 sum(0.0);
      for (const SlopeStatistics& s : setup.fine)
        sum += aniso::leadrEnvironmentSpecular(s, f0, frame, v, studio, fineGrid);
      envReference.push_back(sum.x / double(setup.fine.size()));
      envLeadr.push_back(
          aniso::leadrEnvironmentSpecular(setup.coarse, f0, frame, v, studio, coarseGrid).x);
      envNaive.push_back(
          aniso::leadrEnvironmentSpecular(setup.naive, f0, frame, v, studio, fineGrid).x);
    }
  }
  const double envLeadrError = relativeL2(envLeadr, envReference);
  const double envNaiveError = relativeL2(envNaive, envReference);
  std::printf("studio environment: LEADR %.1f%%, averaged normal %.1f%% (relative L2)\n",
              100.0 * envLeadrError, 100.0 * envNaiveError);
  EXPECT_LT(envLeadrError, 0.06);
  EXPECT_GT(envNaiveError, 0.5);
}

// Under a directional light with a vanishing base roughness at level 0, the rough diffuse is
// Lambert on the texel's normal (what normal mapping computes).
TEST(Leadr, DiffuseReducesToNormalMappedLambert)
{
  aniso::LeadrMaterial material;
  material.diffuse = glm::dvec3(0.6);
  material.f0 = glm::dvec3(0.0);
  const SlopeStatistics s = aniso::slopeStatistics(aniso::momentsOfSlope({0.3, -0.2}),
                                                   aniso::kLeadrMinAlpha, aniso::kLeadrMinAlpha);
  const aniso::Light light = aniso::parseLight("dir:0.2,0.5,1:2");
  const glm::dvec3 value =
      aniso::shadeLeadr(material, s, aniso::Frame{}, glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1.0),
                        {light}, aniso::makeSlopeGrid(8));
  const double expected =
      0.6 / kPi * 2.0 * glm::dot(aniso::normalOfSlope({0.3, -0.2}), glm::normalize(light.vector));
  EXPECT_NEAR(value.x, expected, 1e-3 * expected);
}

// Phi(Phi^-1(p)) = p across the range, and Phi^-1 is odd about 1/2.
TEST(Leadr, InverseNormalCdf)
{
  for (double p : {1e-12, 1e-6, 0.01, 0.02425, 0.2, 0.5, 0.7, 0.97575, 0.999, 1.0 - 1e-9})
  {
    const double x = aniso::inverseNormalCdf(p);
    EXPECT_NEAR(0.5 * std::erfc(-x / std::sqrt(2.0)), p, 1e-13 * std::max(p, 1e-3)) << p;
  }
  EXPECT_NEAR(aniso::inverseNormalCdf(0.3), -aniso::inverseNormalCdf(0.7), 1e-14);
  EXPECT_EQ(aniso::makeSlopeGrid(1).quantiles[0], 0.0);
}

// Finite and non-negative for random statistics (mean slopes up to 3, variances over six
// decades, strong correlation) and directions including grazing and back-facing views.
// The progressive frames' grids (slopeGridShift, makeShiftedSlopeGrid): frame 0 is the centred
// grid, every shift lies in [0, 1), and the mean over the frames of a 2 x 2 grid converges to
// expectations under the normal distribution (E cos z = e^-1/2, E e^-z^2 = 1/sqrt(3), and over
// both axes' pairs E cos z1 cos z2 = e^-1), where the centred grid stays at its quadrature.
TEST(Leadr, FrameGridsConvergeToTheDistribution)
{
  EXPECT_EQ(aniso::slopeGridShift(0), glm::dvec2(0.5, 0.5));
  EXPECT_EQ(aniso::makeShiftedSlopeGrid(5, 0.5).quantiles, aniso::makeSlopeGrid(5).quantiles);
  const auto expectations = [](int frames)
  {
    glm::dvec3 sum(0.0);
    for (int k = 0; k < frames; ++k)
    {
      const glm::dvec2 s = aniso::slopeGridShift(uint32_t(k));
      EXPECT_TRUE(s.x >= 0.0 && s.x < 1.0 && s.y >= 0.0 && s.y < 1.0) << k;
      const std::vector<double> x = aniso::makeShiftedSlopeGrid(2, s.x).quantiles;
      const std::vector<double> y = aniso::makeShiftedSlopeGrid(2, s.y).quantiles;
      for (double z1 : x)
      {
        for (double z2 : y)
        {
          sum += glm::dvec3(std::cos(z1), std::exp(-z1 * z1), std::cos(z1) * std::cos(z2));
        }
      }
    }
    return sum / (4.0 * frames);
  };
  const double z = aniso::inverseNormalCdf(0.25);
  const glm::dvec3 one = expectations(1);
  EXPECT_NEAR(one.x, std::cos(z), 1e-12);
  EXPECT_GT(std::abs(one.x - std::exp(-0.5)), 0.15);
  const glm::dvec3 many = expectations(256);
  EXPECT_NEAR(many.x, std::exp(-0.5), 1e-3);
  EXPECT_NEAR(many.y, 1.0 / std::sqrt(3.0), 1e-3);
  EXPECT_NEAR(many.z, std::exp(-1.0), 1e-3);
  EXPECT_THROW(aniso::makeShiftedSlopeGrid(2, 1.0), aniso::Error);
  EXPECT_THROW(aniso::makeShiftedSlopeGrid(2, -0.1), aniso::Error);
}

TEST(Leadr, FiniteAcrossParameterRange)
{
  std::mt19937_64 rng(67);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const aniso::StudioEnvironment studio;
  const aniso::SlopeGrid grid = aniso::makeSlopeGrid(4);
  aniso::LeadrMaterial material;
  material.diffuse = glm::dvec3(0.5);
  for (int i = 0; i < 400; ++i)
  {
    const double vx = std::pow(10.0, -6.0 * u(rng));
    const double vy = std::pow(10.0, -6.0 * u(rng));
    const SlopeStatistics s = stats({6.0 * u(rng) - 3.0, 6.0 * u(rng) - 3.0}, vx, vy,
                                    0.99 * (2.0 * u(rng) - 1.0) * std::sqrt(vx * vy));
    const glm::dvec3 v =
        models_test::fromAngles(i % 5 == 0 ? 90.0 + 5.0 * u(rng) : 89.999 * u(rng), 360.0 * u(rng));
    const glm::dvec3 l = models_test::fromAngles(90.0 * u(rng), 360.0 * u(rng));
    const double f = aniso::evalLeadrSpecular(s, glm::dvec3(1.0), v, l).x;
    EXPECT_TRUE(std::isfinite(f) && f >= 0.0);
    const double e =
        aniso::leadrEnvironmentSpecular(s, glm::dvec3(1.0), aniso::Frame{}, v, studio, grid).x;
    EXPECT_TRUE(std::isfinite(e) && e >= 0.0);
    aniso::Light light;
    light.vector = l;
    const double lit =
        aniso::shadeLeadr(material, s, aniso::Frame{}, glm::dvec3(0.0), v, {light}, grid).x;
    EXPECT_TRUE(std::isfinite(lit) && lit >= 0.0);
  }
}

// Invalid inputs are refused with the subject named.
TEST(Leadr, ValidatesInputs)
{
  EXPECT_THROW(aniso::bakeLeadrFromSlopes(aniso::Image(4, 4, 1)), aniso::Error);
  aniso::Image nan(2, 2, 2);
  nan.data[3] = std::nanf("");
  EXPECT_THROW(aniso::bakeLeadrFromSlopes(nan), aniso::Error);
  EXPECT_THROW(aniso::bakeLeadrFromNormals(aniso::Image(2, 2, 2), false), aniso::Error);
  EXPECT_THROW(aniso::slopeStatistics({}, 0.0, 0.1), aniso::Error);
  EXPECT_THROW(aniso::makeSlopeGrid(0), aniso::Error);
  EXPECT_THROW(aniso::makeSlopeGrid(65), aniso::Error);
}
} // namespace
