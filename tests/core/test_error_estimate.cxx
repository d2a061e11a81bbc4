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
//   - nothing covered or not finite gives a negative estimate; mismatched images are an error.
#include "core/error.h"
#include "core/quality/error_estimate.h"

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
} // namespace
} // namespace aniso
