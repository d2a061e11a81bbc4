// The source groups (core/env/env_source_groups.h) of an image built here: ten lamps of known
// texels and a window on a grey sky. Checked against what the test computes from the grid
// itself: every texel above T in exactly one group, the groups' powers and directions (the
// analysis' listed sources for the first seven), every sample inside its group's cap, the
// sampled directions' histogram against the stated density integrated over each texel, the
// estimator excess / pdf averaging to the integral of the excess as the image interpolates it
// (bilinear, integrated here by quadrature: an identity), and the per-pixel selection following
// the lobe (its bound) with the defensive share kept.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/env/env_source_groups.h"
#include "core/env/env_sources.h"
#include "core/env/environment.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kW = 128;
constexpr int kH = 64;

double texelSolidAngle(int y)
{
  return 2.0 * kPi / kW * (std::cos(kPi * y / kH) - std::cos(kPi * (y + 1) / kH));
}

// Texel centre (x + 0.5, y + 0.5) written out from the mapping (phi = pi - 2 pi u).
glm::dvec3 texelCentre(int x, int y)
{
  const double phi = kPi - 2.0 * kPi * (x + 0.5) / kW;
  const double theta = kPi * (y + 0.5) / kH;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Sky 1; lamps at row 40, columns 4, 16, ..., their luminance falling from 6000 to 1500 (each
// one texel, 8-separated); lamp 0 is 2 x 2; a window of 12 x 6 texels of 150 at rows 12-17.
aniso::EnvAnalysis scene()
{
  aniso::Image image(kW, kH, 3);
  for (float& v : image.data)
    v = 1.0f;
  auto set = [&](int x, int y, float value)
  {
    for (int c = 0; c < 3; ++c)
      image.at(x, y, c) = value;
  };
  for (int k = 0; k < 10; ++k)
    set(4 + 12 * k, 40, float(6000 - 500 * k));
  set(5, 40, 6000.0f);
  set(4, 41, 6000.0f);
  set(5, 41, 6000.0f);
  for (int y = 12; y < 18; ++y)
    for (int x = 90; x < 102; ++x)
      set(x, y, 150.0f);
  return aniso::analyzeEquirect(image, "test:lamps");
}

double luminance(const glm::dvec3& rgb)
{
  return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
}

double excessLuminance(const aniso::EnvAnalysis& a, int x, int y)
{
  return 0.2126 * a.excess.at(x, y, 0) + 0.7152 * a.excess.at(x, y, 1) +
         0.0722 * a.excess.at(x, y, 2);
}

TEST(SourceGroups, EveryExcessTexelInOneGroupWithItsPower)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  ASSERT_EQ(a.width, kW);
  // 11 sources (10 lamps, the window): 7 groups of their own and the rest together.
  ASSERT_EQ(groups.groups.size(), 8u);
  std::vector<double> power(8, 0.0);
  std::size_t excessTexels = 0;
  double total = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
    {
      const double l = excessLuminance(a, x, y);
      const int g = groups.group[std::size_t(y * kW + x)];
      if (l > 0.0)
      {
        ASSERT_GE(g, 0) << x << ", " << y;
        power[std::size_t(g)] += l * texelSolidAngle(y);
        total += l * texelSolidAngle(y);
        ++excessTexels;
      }
      else
      {
        EXPECT_EQ(g, -1) << x << ", " << y;
      }
    }
  EXPECT_EQ(groups.entryTexel.size(), excessTexels);
  EXPECT_NEAR(groups.power / total, 1.0, 1e-12);
  for (std::size_t g = 0; g < 8; ++g)
  {
    EXPECT_NEAR(groups.groups[g].power / power[g], 1.0, 1e-12);
    const aniso::SourceGroup& group = groups.groups[g];
    EXPECT_FLOAT_EQ(groups.rowCdf[std::size_t(group.firstRow + group.rowCount - 1)], 1.0f);
    int texels = 0;
    for (int r = group.firstRow; r < group.firstRow + group.rowCount; ++r)
    {
      const std::size_t row = std::size_t(r);
      EXPECT_FLOAT_EQ(groups.entryCdf[std::size_t(groups.rowFirst[row] + groups.rowCount[row] - 1)],
                      1.0f);
      for (int e = groups.rowFirst[row]; e < groups.rowFirst[row] + groups.rowCount[row]; ++e)
        EXPECT_EQ(int(groups.entryTexel[std::size_t(e)]) / kW, groups.rowY[row]);
      texels += groups.rowCount[row];
    }
    EXPECT_EQ(texels, group.texels);
  }
  for (std::size_t g = 0; g < 7; ++g)
  {
    const aniso::EnvSource& s = a.sources[g];
    EXPECT_GT(glm::dot(groups.groups[g].direction, s.direction), 1.0 - 1e-12);
    EXPECT_NEAR(groups.groups[g].power,
                0.2126 * s.power.x + 0.7152 * s.power.y + 0.0722 * s.power.z,
                1e-9 * groups.groups[g].power);
    // The cap reaches half a texel beyond the source's texels (its samples' tents).
    EXPECT_GT(groups.groups[g].angularRadius, s.angularRadius);
    EXPECT_LT(groups.groups[g].angularRadius, s.angularRadius + 2.0 * kPi / kW);
  }
  // The last group holds the four weakest lamps: 1500 ... 3000 less T, one texel each.
  EXPECT_EQ(groups.groups[7].texels, 4);
  EXPECT_EQ(groups.groups[7].rowCount, 1); // all in row 40
}

// The integral of f over texel (x, y) by the midpoint rule on k x k cells in (u, cos theta).
template <typename F>
double overTexel(int x, int y, int k, const F& f)
{
  const double zTop = std::cos(kPi * y / kH);
  const double zBottom = std::cos(kPi * (y + 1) / kH);
  const double cell = 2.0 * kPi / (kW * k) * (zTop - zBottom) / k;
  double sum = 0.0;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i)
    {
      const double z = zTop + (zBottom - zTop) * (j + 0.5) / k;
      const double phi = kPi - 2.0 * kPi * (x + (i + 0.5) / k) / kW;
      const double r = std::sqrt(1.0 - z * z);
      sum += f(glm::dvec3(r * std::cos(phi), r * std::sin(phi), z)) * cell;
    }
  return sum;
}

// Samples of a selection that is neither by power nor uniform: each inside its group's cap, and
// their histogram over texels follows pdf() integrated over each texel (cells expecting fewer
// than 5 pooled), with no sample where pdf() is zero over the whole texel.
TEST(SourceGroups, SamplesFollowTheirDensity)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  const std::vector<double> selection{0.05, 0.3, 0.05, 0.1, 0.1, 0.1, 0.2, 0.1};
  std::vector<double> count(std::size_t(kW * kH), 0.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const int n = 1 << 18;
  int outsideCap = 0;
  for (int i = 0; i < n; ++i)
  {
    const aniso::SourceGroupSample s = groups.sample(selection, {uniform(rng), uniform(rng)});
    ASSERT_GE(s.group, 0);
    ASSERT_GT(s.pdf, 0.0);
    const aniso::SourceGroup& group = groups.groups[std::size_t(s.group)];
    if (glm::dot(s.direction, group.direction) < std::cos(group.angularRadius) - 1e-12)
      ++outsideCap;
    const glm::dvec2 uv = aniso::directionToEquirect(s.direction);
    const int x = std::min(int(uv.x * kW), kW - 1);
    const int y = std::min(int((1.0 - uv.y) * kH), kH - 1);
    count[std::size_t(y * kW + x)] += 1.0;
  }
  EXPECT_EQ(outsideCap, 0);
  double chi2 = 0.0;
  int cells = 0;
  double pooledCount = 0.0;
  double pooledExpected = 0.0;
  double total = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
    {
      const std::size_t i = std::size_t(y * kW + x);
      const double expected =
          n * overTexel(x, y, 16, [&](const glm::dvec3& d) { return groups.pdf(selection, d); });
      total += expected;
      if (expected == 0.0)
      {
        EXPECT_EQ(count[i], 0.0) << x << ", " << y;
        continue;
      }
      if (expected < 5.0)
      {
        pooledCount += count[i];
        pooledExpected += expected;
        continue;
      }
      chi2 += (count[i] - expected) * (count[i] - expected) / expected;
      ++cells;
    }
  if (pooledExpected > 0.0)
  {
    chi2 += (pooledCount - pooledExpected) * (pooledCount - pooledExpected) / pooledExpected;
    ++cells;
  }
  // The density integrates to 1 (up to the quadrature), and chi-square with cells - 1 degrees
  // of freedom: mean cells - 1, sd sqrt(2 (cells - 1)).
  EXPECT_NEAR(total / n, 1.0, 1e-3);
  std::printf("chi-square %.1f over %d cells\n", chi2, cells);
  EXPECT_LT(chi2, cells + 6.0 * std::sqrt(2.0 * cells));
}

// excess(d) / pdf(d) stays near P_g / q_g over group g (one colour per source here), and its
// mean over samples is the integral of the excess as the image interpolates it (bilinear: the
// equirect environment's lookup), whatever the selection. That integral by quadrature over
// every texel, and the texels' sum (the groups' power) within the interpolation's
// second-order difference.
TEST(SourceGroups, ExcessOverDensityAveragesToThePower)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  const aniso::EquirectEnvironment excess(a.excess, "test:excess");
  auto excessAt = [&](const glm::dvec3& d) { return luminance(excess.radiance(d)); };
  double integral = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      integral += overTexel(x, y, 8, excessAt);
  EXPECT_NEAR(integral / groups.power, 1.0, 2e-3);
  const std::vector<double> selection{0.4, 0.01, 0.09, 0.1, 0.1, 0.1, 0.1, 0.1};
  const int n = 1 << 16;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const aniso::SourceGroupSample s =
        groups.sample(selection, {(i + 0.5) / n, std::fmod(0.618034 * i, 1.0)});
    // A point on the edge of its tent (the neighbour's centre) has density 0 unless the
    // neighbour is a source; the excess is 0 there too.
    if (s.pdf > 0.0)
      sum += excessAt(s.direction) / s.pdf;
    else
      EXPECT_EQ(excessAt(s.direction), 0.0) << i;
  }
  EXPECT_NEAR(sum / n / integral, 1.0, 1e-3);
}

// The points a frame's pixels share (sourcePoints): every point has the excess and the density
// the tables give at its direction (count x pdf under the selection); one frame's estimate of
// the sources' power, sum L / density, is the power to the noise of 16 points, and the frames'
// estimates of a peaked weight over the excess (a lobe of about 4 degrees across lamp 0 and its
// neighbourhood, where a 2 x 2 lamp is not flat) average to its integral by quadrature, closer
// after 64 frames than after 4 (the frames stratify as one set, no frame repeats another).
TEST(SourceGroups, SharedPointsIntegrateTheExcess)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  const aniso::EquirectEnvironment excess(a.excess, "test:excess");
  const std::vector<double> selection = aniso::pointSelection(groups);
  double sum = 0.0;
  for (double q : selection)
  {
    EXPECT_GT(q, aniso::kPointUniformShare / double(selection.size()) - 1e-12);
    sum += q;
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_EQ(aniso::sourcePointCount(1), 16);
  EXPECT_EQ(aniso::sourcePointCount(16), 128);
  EXPECT_EQ(aniso::sourcePointCount(64), aniso::kMaxSourcePoints);

  const glm::dvec3 axis = texelCentre(5, 41);
  auto weight = [&](const glm::dvec3& l) { return std::exp(400.0 * (glm::dot(axis, l) - 1.0)); };
  double integral = 0.0;
  for (int y = 30; y < 52; ++y)
    for (int x = 0; x < 20; ++x)
      integral += overTexel(
          x, y, 16, [&](const glm::dvec3& l) { return weight(l) * luminance(excess.radiance(l)); });
  ASSERT_GT(integral, 0.0);

  const int count = 16;
  double weighted = 0.0;
  double errorAt4 = 0.0;
  for (std::uint32_t frame = 0; frame < 64; ++frame)
  {
    const std::vector<aniso::SourcePoint> points =
        aniso::sourcePoints(groups, selection, excess, frame, count);
    ASSERT_EQ(points.size(), std::size_t(count));
    double power = 0.0;
    for (const aniso::SourcePoint& p : points)
    {
      EXPECT_NEAR(glm::length(p.direction), 1.0, 1e-12);
      if (!(p.density > 0.0))
      {
        EXPECT_EQ(luminance(p.radiance), 0.0) << frame;
        continue;
      }
      EXPECT_NEAR(p.density, count * groups.pdf(selection, p.direction), 1e-9 * p.density);
      EXPECT_NEAR(luminance(p.radiance), luminance(excess.radiance(p.direction)), 1e-9);
      power += luminance(p.radiance) / p.density;
      weighted += weight(p.direction) * luminance(p.radiance) / p.density;
    }
    EXPECT_NEAR(power / groups.power, 1.0, 0.25) << frame;
    if (frame == 3)
      errorAt4 = std::abs(weighted / 4.0 / integral - 1.0);
  }
  const double errorAt64 = std::abs(weighted / 64.0 / integral - 1.0);
  EXPECT_LT(errorAt64, 0.01);
  EXPECT_LT(errorAt64, errorAt4);
  std::printf("shared points: lamp 0 under a 4-degree lobe, %.4f of the integral off after 4 "
              "frames of 16, %.4f after 64\n",
              errorAt4, errorAt64);
}

// A lobe peaked on lamp 1 (the 5500 one): its group takes all but the defensive share; a lobe
// that sees no source leaves the selection by power; a mirror direction inside the window's
// cap reads the lobe there.
TEST(SourceGroups, SelectionFollowsTheLobe)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  const std::vector<double> byPower = groups.powerSelection();
  int lamp1 = -1;
  int window = -1;
  for (std::size_t g = 0; g < groups.groups.size(); ++g)
  {
    if (glm::dot(groups.groups[g].direction, texelCentre(16, 40)) > 1.0 - 1e-9)
      lamp1 = int(g);
    if (groups.groups[g].texels == 72)
      window = int(g);
  }
  ASSERT_GE(lamp1, 0);
  ASSERT_GE(window, 0);
  const glm::dvec3 target = texelCentre(16, 40);
  auto peaked = [&](const glm::dvec3& centre, double width)
  {
    return [centre, width](const glm::dvec3& l)
    { return std::exp((glm::dot(glm::normalize(l), centre) - 1.0) / (width * width)); };
  };
  const double defensive = 0.1;
  const std::vector<double> onLamp =
      aniso::lobeAwareSelection(groups, target, peaked(target, 0.02), defensive);
  double sum = 0.0;
  for (std::size_t g = 0; g < onLamp.size(); ++g)
  {
    sum += onLamp[g];
    EXPECT_GE(onLamp[g], defensive * byPower[g] * (1.0 - 1e-12));
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_GT(onLamp[std::size_t(lamp1)], 0.9 + 0.1 * byPower[std::size_t(lamp1)] - 1e-3);

  const std::vector<double> none = aniso::lobeAwareSelection(
      groups, target, [](const glm::dvec3&) { return 0.0; }, defensive);
  for (std::size_t g = 0; g < none.size(); ++g)
    EXPECT_DOUBLE_EQ(none[g], byPower[g]);

  // Inside the window's cap the lobe is read at the mirror direction itself.
  const glm::dvec3 inWindow = texelCentre(95, 14);
  glm::dvec3 seen(0.0);
  aniso::lobeAwareSelection(
      groups, inWindow,
      [&](const glm::dvec3& l)
      {
        if (glm::dot(l, inWindow) > 1.0 - 1e-12)
          seen = l;
        return 1.0;
      },
      defensive);
  EXPECT_GT(glm::dot(seen, inWindow), 1.0 - 1e-12);
}

// The pixel's source samples: four times the base where a sharp lobe sits on a lamp (a group
// smaller than the lobe that carries its light) and where a lobe over the whole sphere sees
// the lamps and the window; the base where the lobe sees no group and where it fits inside the
// window (its own samples find it); the ladder in between.
TEST(SourceGroups, SampleCountFollowsWhatTheLobeResolves)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  EXPECT_GT(groups.residualMean, 0.9); // the sky of 1, the window cut to T
  // A lobe of angular width s around its centre, normalised for small s (peak 1 / (2 pi s^2)).
  auto lobe = [](const glm::dvec3& centre, double s)
  {
    return [centre, s](const glm::dvec3& l) {
      return std::exp((glm::dot(glm::normalize(l), centre) - 1.0) / (s * s)) / (2.0 * kPi * s * s);
    };
  };
  const int base = 4;
  const glm::dvec3 lamp1 = texelCentre(16, 40);
  const double onLamp = aniso::smallSourceShare(groups, lamp1, lobe(lamp1, 0.02));
  EXPECT_GT(onLamp, 0.95);
  EXPECT_EQ(aniso::sourceSampleCount(onLamp, base, 2), 4 * base);

  EXPECT_EQ(aniso::smallSourceShare(groups, lamp1, [](const glm::dvec3&) { return 0.0; }), 0.0);
  // Uniform: every group seen at 1 / (4 pi), all smaller than the lobe, against the residual
  // (a sky of 1, the window at T = 16): share = P / (P + 4 pi residualMean).
  const double wide =
      aniso::smallSourceShare(groups, lamp1, [](const glm::dvec3&) { return 0.25 / kPi; });
  EXPECT_NEAR(wide, groups.power / (groups.power + 4.0 * kPi * groups.residualMean), 1e-12);
  EXPECT_EQ(aniso::sourceSampleCount(wide, base, 2), 4 * base);
  const glm::dvec3 inWindow = texelCentre(95, 14);
  const double window = aniso::smallSourceShare(groups, inWindow, lobe(inWindow, 0.02));
  EXPECT_LT(window, 0.05);
  EXPECT_EQ(aniso::sourceSampleCount(window, base, 2), base);

  EXPECT_EQ(aniso::sourceSampleCount(0.0, 3, 2), 3);
  EXPECT_EQ(aniso::sourceSampleCount(0.2, 3, 2), 6);
  EXPECT_EQ(aniso::sourceSampleCount(0.5, 3, 2), 6);
  EXPECT_EQ(aniso::sourceSampleCount(0.8, 3, 2), 12);
  EXPECT_EQ(aniso::sourceSampleCount(2.0, 3, 2), 12);
  EXPECT_EQ(aniso::sourceSampleCount(0.0, 0, 2), 1);
  // The steps allowed: no more source samples than lobe samples.
  EXPECT_EQ(aniso::sourceSampleCount(1.0, 3, 1), 6);
  EXPECT_EQ(aniso::sourceSampleSteps(4, 16), 2);
  EXPECT_EQ(aniso::sourceSampleSteps(4, 12), 1);
  EXPECT_EQ(aniso::sourceSampleSteps(1, 1), 0);
  EXPECT_EQ(aniso::sourceSampleSteps(1, 2), 1);
  EXPECT_EQ(aniso::sourceSampleSteps(16, 1024), 2);
}

// Where a pixel takes the sources by its lobe samples alone (lobeSamplesSuffice): the second
// moment of one lobe sample's estimate of the sources' light, the excess as the shader reads it
// (bilinear) times the sample's AS weight n.l / max(n.l, n.v) (F = 1), measured by 20 000
// samples of the AS lobe, against lobeSourceSecondMoment's bound with the lobe's own density at
// each cap's point nearest to the mirror direction (what the shader reads). Mirror directions
// within 0.3 rad of a lamp or the window, random normals and tangents, lobes (10, 10) to
// (20000, 70): the measured moment never above 1.3 times the bound. A sharp lobe on a lamp
// needs source samples; one facing away from every source does not; one whose broad axis
// reaches the window does.
TEST(SourceGroups, LobeSamplesAloneSufficeWhereTheirSecondMomentIsSmall)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  const aniso::EquirectEnvironment excess(a.excess, "test:excess");
  struct Frame
  {
    glm::dvec3 t, b, n, v;
  };
  auto toTangent = [](const Frame& f, const glm::dvec3& d)
  { return glm::dvec3(glm::dot(d, f.t), glm::dot(d, f.b), glm::dot(d, f.n)); };
  auto lobePdf = [&](const aniso::AsLobe& lobe, const Frame& f)
  {
    return [&, lobe, f](const glm::dvec3& l)
    { return aniso::pdfLight(lobe, toTangent(f, f.v), toTangent(f, glm::normalize(l))); };
  };
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto randomUnit = [&]()
  {
    const double z = 2.0 * uniform(rng) - 1.0;
    const double phi = 2.0 * kPi * uniform(rng);
    const double r = std::sqrt(1.0 - z * z);
    return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
  };
  const std::vector<glm::dvec3> targets{texelCentre(4, 40), texelCentre(16, 40),
                                        texelCentre(64, 40), texelCentre(95, 14)};
  const aniso::AsLobe lobes[] = {{10.0, 10.0}, {100.0, 10.0}, {1000.0, 100.0}, {20000.0, 70.0}};
  double worst = 0.0;
  int measured = 0;
  for (const aniso::AsLobe& lobe : lobes)
    for (int k = 0; k < 12; ++k)
    {
      // The mirror direction 0-0.3 rad from a source, then a normal 0-75 degrees from it.
      const glm::dvec3 target = targets[std::size_t(k) % targets.size()];
      const glm::dvec3 mirror = glm::normalize(
          target + 0.3 * uniform(rng) * glm::normalize(glm::cross(target, randomUnit())));
      glm::dvec3 n;
      do
        n = randomUnit();
      while (glm::dot(n, mirror) < 0.25);
      Frame f;
      f.n = n;
      f.v = 2.0 * glm::dot(n, mirror) * n - mirror;
      f.t = glm::normalize(glm::cross(n, randomUnit()));
      f.b = glm::cross(f.n, f.t);
      const glm::dvec3 vT = toTangent(f, f.v);
      const double bound = aniso::lobeSourceSecondMoment(groups, mirror, lobePdf(lobe, f));
      const int samples = 20000;
      double moment = 0.0;
      for (int i = 0; i < samples; ++i)
      {
        const glm::dvec3 h = aniso::sampleHalfVector(lobe, {uniform(rng), uniform(rng)});
        const glm::dvec3 lT = aniso::reflectAbout(vT, h);
        if (glm::dot(vT, h) <= 0.0 || lT.z <= 0.0)
          continue;
        const glm::dvec3 l = lT.x * f.t + lT.y * f.b + lT.z * f.n;
        const double x = luminance(excess.radiance(l)) * lT.z / std::max(lT.z, vT.z);
        moment += x * x;
      }
      moment /= samples;
      if (moment > 0.0)
        ++measured;
      EXPECT_LE(moment, 1.3 * bound) << "lobe (" << lobe.nu << ", " << lobe.nv << "), config " << k;
      if (bound > 0.0)
        worst = std::max(worst, moment / bound);
    }
  std::printf("second moment over its bound: at most %.3f (%d configurations seeing a source)\n",
              worst, measured);
  EXPECT_GT(measured, 24); // the configurations do see the sources

  // A sharp lobe on lamp 1, head on: source samples. Towards +Y, 40 degrees from the zenith
  // (the window is towards -Y, the lamps below the horizon): none needed. The same lobe
  // towards the zenith, its broad axis towards the window 34-48 degrees away, still sees it
  // (a sample hits it about once in 100, with 150 times the sky): source samples.
  const aniso::AsLobe sharp{1000.0, 100.0};
  Frame onLamp;
  onLamp.n = texelCentre(16, 40);
  onLamp.v = onLamp.n;
  onLamp.t = glm::normalize(glm::cross(onLamp.n, glm::dvec3(0.0, 0.0, 1.0)));
  onLamp.b = glm::cross(onLamp.n, onLamp.t);
  EXPECT_FALSE(aniso::lobeSamplesSuffice(groups, onLamp.n, lobePdf(sharp, onLamp),
                                         lobePdf(sharp, onLamp), 16, aniso::kLobeOnlySourceNoise));
  auto facing = [](const glm::dvec3& n)
  {
    Frame f;
    f.n = n;
    f.v = n;
    f.t = glm::normalize(glm::cross(n, glm::dvec3(1.0, 0.0, 0.0)));
    f.b = glm::cross(f.n, f.t);
    return f;
  };
  const double el = 40.0 * kPi / 180.0;
  const Frame away = facing(glm::dvec3(0.0, std::sin(el), std::cos(el)));
  EXPECT_TRUE(aniso::lobeSamplesSuffice(groups, away.n, lobePdf(sharp, away), lobePdf(sharp, away),
                                        16, aniso::kLobeOnlySourceNoise));
  Frame up; // the broad axis (b, n_v = 100) towards the window
  up.n = glm::dvec3(0.0, 0.0, 1.0);
  up.v = up.n;
  up.t = glm::dvec3(1.0, 0.0, 0.0);
  up.b = glm::dvec3(0.0, 1.0, 0.0);
  EXPECT_FALSE(aniso::lobeSamplesSuffice(groups, up.n, lobePdf(sharp, up), lobePdf(sharp, up), 16,
                                         aniso::kLobeOnlySourceNoise));
  // The same lobe with no lobe samples' worth of noise allowed: never.
  EXPECT_FALSE(aniso::lobeSamplesSuffice(groups, onLamp.n, lobePdf(sharp, onLamp),
                                         lobePdf(sharp, onLamp), 16, 0.0));
}

// The guided search finds what a bisection (std::upper_bound) finds in every row run and entry
// run, at random numbers, at every cumulative end itself, just below and just above it, and at
// the bins' edges k / count (where u count may round into the next bin).
TEST(SourceGroups, GuidedSearchFindsWhatABisectionFinds)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  ASSERT_EQ(groups.rowGuide.size(), groups.rowY.size());
  ASSERT_EQ(groups.entryGuide.size(), groups.entryTexel.size());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  int checked = 0;
  auto check = [&](const std::vector<float>& cdf, const std::vector<std::uint32_t>& guide,
                   int first, int count)
  {
    std::vector<float> us;
    for (int i = 0; i < 64; ++i)
      us.push_back(uniform(rng));
    for (int i = first; i < first + count; ++i)
    {
      const float c = cdf[std::size_t(i)];
      us.push_back(c);
      us.push_back(std::nextafter(c, 0.0f));
      us.push_back(std::min(std::nextafter(c, 1.0f), std::nextafter(1.0f, 0.0f)));
    }
    for (int k = 0; k <= count; ++k)
    {
      const float edge = float(k) / float(count);
      us.push_back(std::min(edge, std::nextafter(1.0f, 0.0f)));
      us.push_back(std::nextafter(edge, 0.0f));
    }
    us.push_back(0.0f);
    for (const float u : us)
    {
      const auto begin = cdf.begin() + first;
      const auto end = begin + count;
      auto it = std::upper_bound(begin, end, u);
      if (it == end)
        --it;
      ASSERT_EQ(aniso::guidedSearch(cdf, guide, first, count, u), std::size_t(it - cdf.begin()))
          << "run at " << first << " of " << count << ", u " << u;
      ++checked;
    }
  };
  for (const aniso::SourceGroup& group : groups.groups)
    check(groups.rowCdf, groups.rowGuide, group.firstRow, group.rowCount);
  for (std::size_t r = 0; r < groups.rowY.size(); ++r)
    check(groups.entryCdf, groups.entryGuide, groups.rowFirst[r], groups.rowCount[r]);
  EXPECT_GT(checked, 1000);
}

TEST(SourceGroups, AnAnalysisWithoutRanksIsRefused)
{
  aniso::EnvAnalysis a = scene();
  a.sourceRank.clear();
  try
  {
    aniso::buildSourceGroups(a);
    FAIL() << "expected an error";
  }
  catch (const aniso::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("test:lamps"), std::string::npos) << e.what();
  }
}
} // namespace
