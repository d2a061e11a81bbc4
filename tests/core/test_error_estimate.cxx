// The error a progressive mean estimates from its own frames (quality/error_estimate.h):
//   - the frame counts kept and checked are 2^k and 3 x 2^k (listed by hand), each checkpoint
//     twice a snapshot;
//   - with independent frames (pixels of known mean and noise), the estimate from the mean and
//     the mean of its first half matches the mean's actual relative L2 error, and the analytic
//     one sqrt(sum sigma^2 / F / sum mu^2), within a few percent over many pixels;
//   - pixels are weighed by their coverage: uncovered ones (the background) count for nothing, a
//     half-covered one for half (a value worked out by hand);
//   - a view stops at an estimate of 3/4 of its target, from 256 samples a pixel on (worked out
//     by hand);
//   - nothing covered or not finite gives a negative estimate; mismatched images are an error;
//   - pixels freeze in whole tiles, aligned in GL's rows, where every pixel and its eight
//     neighbours are fully covered and the neighbourhood's squared difference is below the
//     level (a scene worked out by hand: a noisy patch, a half-covered column, the border); a
//     frozen pixel keeps the error it froze with, and the estimate then counts it by that error,
//     not by its unchanged mean (a value worked out by hand).
#include "core/error.h"
#include "core/quality/error_estimate.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace aniso
{
namespace
{
TEST(ErrorEstimate, SnapshotsAndCheckpoints)
{
  std::vector<int> snapshots;
  std::vector<int> checkpoints;
  for (int f = 0; f <= 200; ++f)
  {
    if (isErrorSnapshot(f))
    {
      snapshots.push_back(f);
    }
    if (isErrorCheckpoint(f))
    {
      checkpoints.push_back(f);
      EXPECT_TRUE(isErrorSnapshot(f / 2)) << f;
      EXPECT_EQ(f % 2, 0) << f;
    }
  }
  EXPECT_EQ(snapshots, (std::vector<int>{2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192}));
  EXPECT_EQ(checkpoints, (std::vector<int>{4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192}));
}

TEST(ErrorEstimate, IndependentFramesGiveTheMeansError)
{
  constexpr int kPixels = 40000;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> level(0.2, 3.0);
  std::vector<double> mu(kPixels);
  std::vector<double> sigma(kPixels);
  for (int p = 0; p < kPixels; ++p)
  {
    mu[p] = level(random);
    sigma[p] = 0.5 * level(random);
  }
  for (int frames : {4, 16, 48})
  {
    Image mean(kPixels, 1, 4);
    Image half(kPixels, 1, 4);
    double signal = 0.0;
    double actual = 0.0;
    double variance = 0.0;
    for (int p = 0; p < kPixels; ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        std::normal_distribution<double> noise(mu[p], sigma[p]);
        double sum = 0.0;
        for (int f = 0; f < frames; ++f)
        {
          sum += noise(random);
          if (f + 1 == frames / 2)
          {
            half.at(p, 0, c) = static_cast<float>(sum / (frames / 2));
          }
        }
        const double m = sum / frames;
        mean.at(p, 0, c) = static_cast<float>(m);
        signal += m * m;
        actual += (m - mu[p]) * (m - mu[p]);
        variance += sigma[p] * sigma[p] / frames;
      }
      mean.at(p, 0, 3) = 1.0f;
      half.at(p, 0, 3) = 1.0f;
    }
    const double estimate = estimatedRelativeError(mean, half);
    const double actualError = std::sqrt(actual / signal);
    const double analytic = std::sqrt(variance / signal);
    EXPECT_NEAR(estimate / actualError, 1.0, 0.03) << frames;
    EXPECT_NEAR(estimate / analytic, 1.0, 0.03) << frames;
  }
}

TEST(ErrorEstimate, PixelsWeighByCoverage)
{
  Image mean(3, 1, 4);
  Image half(3, 1, 4);
  // Pixel 0: covered, mean (1, 1, 1), half (0.9, 1, 1.1). Pixel 1: background, a difference of 5
  // that must not count. Pixel 2: half covered, mean (2, 0, 0), half (1.8, 0, 0).
  const float m[3][4] = {{1, 1, 1, 1}, {4, 4, 4, 0}, {2, 0, 0, 0.5f}};
  const float h[3][4] = {{0.9f, 1, 1.1f, 1}, {-1, -1, -1, 0}, {1.8f, 0, 0, 0.5f}};
  for (int p = 0; p < 3; ++p)
  {
    for (int c = 0; c < 4; ++c)
    {
      mean.at(p, 0, c) = m[p][c];
      half.at(p, 0, c) = h[p][c];
    }
  }
  // Error: 0.01 + 0.01 + 0.5 x 0.04 = 0.04; signal: 3 + 0.5 x 4 = 5.
  EXPECT_NEAR(estimatedRelativeError(mean, half), std::sqrt(0.04 / 5.0), 1e-6);
}

TEST(ErrorEstimate, AViewStopsAtThreeQuartersOfItsTarget)
{
  EXPECT_DOUBLE_EQ(kErrorStopShare, 0.75);
  EXPECT_TRUE(errorTargetReached(0.0075, 0.01));
  EXPECT_TRUE(errorTargetReached(0.0, 0.01));
  EXPECT_FALSE(errorTargetReached(0.0076, 0.01));
  EXPECT_FALSE(errorTargetReached(-1.0, 0.01)); // no estimate
  EXPECT_FALSE(errorTargetReached(0.001, 0.0)); // no target
  EXPECT_EQ(minimumErrorStopFrames(16), 16);
  EXPECT_EQ(minimumErrorStopFrames(1), 256);
  EXPECT_EQ(minimumErrorStopFrames(3), 86);
  EXPECT_EQ(minimumErrorStopFrames(0), 256);
}

TEST(ErrorEstimate, NothingToEstimateAndMismatches)
{
  Image mean(2, 2, 4);
  Image half(2, 2, 4);
  EXPECT_LT(estimatedRelativeError(mean, half), 0.0); // nothing covered
  mean.at(0, 0, 3) = 1.0f;
  EXPECT_LT(estimatedRelativeError(mean, half), 0.0); // covered but black
  mean.at(0, 0, 0) = 1.0f;
  EXPECT_NEAR(estimatedRelativeError(mean, half), 1.0, 1e-12);
  half.at(0, 0, 1) = std::nanf("");
  EXPECT_LT(estimatedRelativeError(mean, half), 0.0);
  EXPECT_THROW(estimatedRelativeError(mean, Image(2, 3, 4)), Error);
  EXPECT_THROW(estimatedRelativeError(Image(2, 2, 3), Image(2, 2, 3)), Error);
}
// A W x H scene of mean 1 (RGB) whose first half differs by D per channel everywhere but in a
// noisy patch (differing by 0.5); column 13 is half covered.
struct FreezeScene
{
  static constexpr int kW = 20;
  static constexpr int kH = 14; // not a multiple of the tile: GL's rows and the image's differ
  Image mean{kW, kH, 4};
  Image half{kW, kH, 4};
  explicit FreezeScene(float d)
  {
    for (int y = 0; y < kH; ++y)
    {
      for (int x = 0; x < kW; ++x)
      {
        const bool noisy = x >= 2 && x < 5 && y >= 2 && y < 4; // image rows (from the top)
        for (int c = 0; c < 3; ++c)
        {
          mean.at(x, y, c) = 1.0f;
          half.at(x, y, c) = 1.0f + (noisy ? 0.5f : d);
        }
        mean.at(x, y, 3) = x == 13 ? 0.5f : 1.0f;
        half.at(x, y, 3) = mean.at(x, y, 3);
      }
    }
  }
};

// The freezing level of FreezeScene for TARGET, per pixel (its squared difference over RGB).
double freezeLevel(const FreezeScene& scene, double target)
{
  double signal = 0.0;
  int covered = 0;
  for (int y = 0; y < FreezeScene::kH; ++y)
  {
    for (int x = 0; x < FreezeScene::kW; ++x)
    {
      signal += 3.0 * scene.mean.at(x, y, 3);
      ++covered;
    }
  }
  const double level = kErrorStopShare * target;
  return kFreezeShare * level * level * signal / covered;
}

// The difference per channel whose squared sum over RGB is SHARE x the level for TARGET.
float differenceAt(double share, double target)
{
  return static_cast<float>(std::sqrt(share * freezeLevel(FreezeScene(0.0f), target) / 3.0));
}

TEST(ErrorEstimate, PixelsFreezeInTilesWhereTheirNeighbourhoodConverged)
{
  const double target = 0.01;
  const float d = differenceAt(0.5, target); // below the level
  const FreezeScene scene(d);
  FrozenPixels frozen;
  const int now = freezeConvergedPixels(scene.mean, scene.half, target, frozen);
  ASSERT_EQ(frozen.width, FreezeScene::kW);
  ASSERT_EQ(frozen.height, FreezeScene::kH);
  // Which pixels may freeze: fully covered with their eight neighbours, not on the border, the
  // neighbourhood away from the noisy patch (rows 2-3, columns 2-4) and the half-covered column.
  const auto eligible = [](int x, int y)
  {
    if (x < 1 || y < 1 || x + 1 >= FreezeScene::kW || y + 1 >= FreezeScene::kH)
    {
      return false;
    }
    const bool nearNoise = x >= 1 && x <= 5 && y >= 1 && y <= 4;
    const bool nearHalf = x >= 12 && x <= 14;
    return !nearNoise && !nearHalf;
  };
  // Tiles in GL's rows: GL row g is image row H - 1 - g.
  int expected = 0;
  for (int ty = 0; ty * kFreezeTile < FreezeScene::kH; ++ty)
  {
    for (int tx = 0; tx * kFreezeTile < FreezeScene::kW; ++tx)
    {
      bool all = true;
      for (int g = ty * kFreezeTile; g < std::min(FreezeScene::kH, (ty + 1) * kFreezeTile); ++g)
      {
        for (int x = tx * kFreezeTile; x < std::min(FreezeScene::kW, (tx + 1) * kFreezeTile); ++x)
        {
          all = all && eligible(x, FreezeScene::kH - 1 - g);
        }
      }
      for (int g = ty * kFreezeTile; g < std::min(FreezeScene::kH, (ty + 1) * kFreezeTile); ++g)
      {
        for (int x = tx * kFreezeTile; x < std::min(FreezeScene::kW, (tx + 1) * kFreezeTile); ++x)
        {
          const int y = FreezeScene::kH - 1 - g;
          EXPECT_EQ(frozen.frozen(x, y), all) << "pixel (" << x << ", " << y << ")";
          if (all)
          {
            ++expected;
            // Its error: the neighbourhood's mean squared difference, 3 d^2.
            EXPECT_NEAR(frozen.error[std::size_t(y) * FreezeScene::kW + x], 3.0 * d * d,
                        1e-3 * 3.0 * d * d); // d is read back from 1 + d in floats
          }
        }
      }
    }
  }
  EXPECT_GT(expected, 0);
  EXPECT_EQ(now, expected);
  EXPECT_EQ(frozen.count, expected);
  // Frozen pixels stay frozen; nothing more freezes from the same means.
  EXPECT_EQ(freezeConvergedPixels(scene.mean, scene.half, target, frozen), 0);
  EXPECT_EQ(frozen.count, expected);

  // Twice the level: nothing freezes.
  const FreezeScene above(differenceAt(2.0, target));
  FrozenPixels none;
  EXPECT_EQ(freezeConvergedPixels(above.mean, above.half, target, none), 0);
  EXPECT_EQ(none.count, 0);
  // No target: nothing freezes.
  EXPECT_EQ(freezeConvergedPixels(scene.mean, scene.half, 0.0, none), 0);
}

TEST(ErrorEstimate, FrozenPixelsCountByTheirErrorAtFreezing)
{
  const double target = 0.01;
  const float d = differenceAt(0.5, target);
  const FreezeScene scene(d);
  FrozenPixels frozen;
  ASSERT_GT(freezeConvergedPixels(scene.mean, scene.half, target, frozen), 0);
  // A later checkpoint: the frozen pixels' means no longer change (their half is their mean),
  // the others still differ by d (the patch by 0.5).
  Image later = scene.half;
  for (int y = 0; y < FreezeScene::kH; ++y)
  {
    for (int x = 0; x < FreezeScene::kW; ++x)
    {
      if (frozen.frozen(x, y))
      {
        for (int c = 0; c < 3; ++c)
        {
          later.at(x, y, c) = scene.mean.at(x, y, c);
        }
      }
    }
  }
  double error = 0.0;
  double signal = 0.0;
  for (int y = 0; y < FreezeScene::kH; ++y)
  {
    for (int x = 0; x < FreezeScene::kW; ++x)
    {
      const double c = scene.mean.at(x, y, 3);
      signal += 3.0 * c;
      if (frozen.frozen(x, y))
      {
        error += 3.0 * d * d; // as it froze
      }
      else
      {
        for (int k = 0; k < 3; ++k)
        {
          const double diff = scene.mean.at(x, y, k) - later.at(x, y, k);
          error += c * diff * diff;
        }
      }
    }
  }
  EXPECT_NEAR(estimatedRelativeError(scene.mean, later, frozen), std::sqrt(error / signal), 1e-9);
  // Without the frozen pixels' errors the unchanged means would say less.
  EXPECT_LT(estimatedRelativeError(scene.mean, later), std::sqrt(error / signal));
  // Nothing frozen: the estimate as before.
  EXPECT_DOUBLE_EQ(estimatedRelativeError(scene.mean, scene.half, FrozenPixels{}),
                   estimatedRelativeError(scene.mean, scene.half));
}
} // namespace
} // namespace aniso
