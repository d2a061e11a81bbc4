// The source groups (core/env/env_source_groups.h) of an image built here: ten lamps of known
// texels and a window on a grey sky. Checked against what the test computes from the grid
// itself: every texel above T in exactly one group, the groups' powers and directions (the
// analysis' listed sources for the first seven), the sampled directions' histogram against the
// stated density, the density sample() returns against pdf() at the same direction, the
// estimator excess / pdf averaging to the source part's power (an identity), and the per-pixel
// selection following the lobe (its bound) with the defensive share kept.
#include "core/env/env_source_groups.h"
#include "core/env/env_sources.h"
#include "core/error.h"

#include <cmath>
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
    EXPECT_NEAR(groups.groups[g].angularRadius, s.angularRadius, 1e-12);
  }
  // The last group holds the four weakest lamps: 1500 ... 3000 less T, one texel each.
  EXPECT_EQ(groups.groups[7].texels, 4);
  EXPECT_EQ(groups.groups[7].rowCount, 1); // all in row 40
}

// Samples of a selection that is neither by power nor uniform: their histogram over texels
// follows q_g x excess / P_g x the texel's solid angle, and sample()'s density is pdf()'s.
TEST(SourceGroups, SamplesFollowTheirDensity)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  const std::vector<double> selection{0.05, 0.3, 0.05, 0.1, 0.1, 0.1, 0.2, 0.1};
  std::vector<double> count(std::size_t(kW * kH), 0.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const int n = 1 << 18;
  int mismatched = 0;
  for (int i = 0; i < n; ++i)
  {
    const aniso::SourceGroupSample s = groups.sample(selection, {uniform(rng), uniform(rng)});
    ASSERT_GE(s.group, 0);
    const double pdf = groups.pdf(selection, s.direction);
    if (std::abs(pdf - s.pdf) > 1e-6 * s.pdf)
      ++mismatched; // a point on a texel's edge may round into the neighbour
    const glm::dvec2 uv = aniso::directionToEquirect(s.direction);
    const int x = std::min(int(uv.x * kW), kW - 1);
    const int y = std::min(int((1.0 - uv.y) * kH), kH - 1);
    count[std::size_t(y * kW + x)] += 1.0;
  }
  EXPECT_LT(mismatched, n / 1000);
  double chi2 = 0.0;
  int cells = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
    {
      const std::size_t i = std::size_t(y * kW + x);
      const int g = groups.group[i];
      const double expected = g < 0 ? 0.0
                                    : n * selection[std::size_t(g)] * excessLuminance(a, x, y) /
                                          groups.groups[std::size_t(g)].power * texelSolidAngle(y);
      if (expected == 0.0)
      {
        EXPECT_EQ(count[i], 0.0) << x << ", " << y;
        continue;
      }
      chi2 += (count[i] - expected) * (count[i] - expected) / expected;
      ++cells;
    }
  // chi-square with cells - 1 degrees of freedom: mean cells - 1, sd sqrt(2 (cells - 1)).
  std::printf("chi-square %.1f over %d texels\n", chi2, cells);
  EXPECT_LT(chi2, cells + 6.0 * std::sqrt(2.0 * cells));
}

// excess(d) / pdf(d) = P_g / q_g over group g (one colour per source here), so its mean over
// stratified samples is sum_g q_g P_g / q_g = the source part's power, whatever the selection.
TEST(SourceGroups, ExcessOverDensityAveragesToThePower)
{
  const aniso::EnvAnalysis a = scene();
  const aniso::SourceGroups groups = aniso::buildSourceGroups(a);
  const std::vector<double> selection{0.4, 0.01, 0.09, 0.1, 0.1, 0.1, 0.1, 0.1};
  const int n = 4096;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const aniso::SourceGroupSample s =
        groups.sample(selection, {(i + 0.5) / n, std::fmod(0.618034 * i, 1.0)});
    const glm::dvec2 uv = aniso::directionToEquirect(s.direction);
    const int x = std::min(int(uv.x * kW), kW - 1);
    const int y = std::min(int((1.0 - uv.y) * kH), kH - 1);
    sum += excessLuminance(a, x, y) / s.pdf;
  }
  EXPECT_NEAR(sum / n / groups.power, 1.0, 1e-3);
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
