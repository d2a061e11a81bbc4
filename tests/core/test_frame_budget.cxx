// The frame-time budget of progressive refinement (quality/frame_budget.h):
//   - the cost fit recovers fixed and per-sample costs that generated the measurements exactly
//     (a known line), falls back to the stated assumption with one sample count, and keeps
//     both parts non-negative;
//   - the chosen samples per frame are the largest divisor of the run's total whose predicted
//     cost meets the budget (values worked out by hand below), the material's own count when it
//     fits or nothing is known, and 1 at worst; frames x samples per frame stay the run's total;
//   - under a changing load the plan keeps the largest recent measured/predicted ratio in hand
//     (bounded), which shrinks the chosen count to what the slower machine meets (worked out by
//     hand), and a frame overruns only beyond the budget's tolerance.
#include "quality/frame_budget.h"

#include <gtest/gtest.h>
#include <limits>
#include <vector>

namespace aniso
{
namespace
{
// A frame of S samples at P pixels costing P (fixed + perSample S) seconds.
FrameCostSample frame(int samples, double pixels, double fixed, double perSample)
{
  return {samples, pixels, pixels * (fixed + perSample * samples)};
}

TEST(FrameBudget, FitRecoversALine)
{
  // 40 ms fixed and 8 ms per sample at 300 000 pixels, measured at 1, 4 and 16 samples and at
  // two sizes: per pixel, 40e-3 / 3e5 and 8e-3 / 3e5 seconds.
  const double fixed = 40e-3 / 3e5;
  const double perSample = 8e-3 / 3e5;
  const FrameCostModel m =
      fitFrameCost({frame(1, 75000.0, fixed, perSample), frame(4, 3e5, fixed, perSample),
                    frame(16, 3e5, fixed, perSample)});
  ASSERT_TRUE(m.known);
  EXPECT_TRUE(m.separated);
  EXPECT_NEAR(m.fixedPerPixel, fixed, 1e-9 * fixed);
  EXPECT_NEAR(m.perSamplePerPixel, perSample, 1e-9 * perSample);
  EXPECT_NEAR(m.predictSeconds(16, 3e5), 40e-3 + 16 * 8e-3, 1e-12);
}

TEST(FrameBudget, OneSampleCountSplitsEvenly)
{
  // Only 1-sample frames of 46 ms at 3e5 pixels: fixed = per sample = 23 ms / 3e5.
  const FrameCostModel m = fitFrameCost({{1, 3e5, 0.046}, {1, 3e5, 0.046}});
  ASSERT_TRUE(m.known);
  EXPECT_FALSE(m.separated);
  EXPECT_NEAR(m.fixedPerPixel, 0.023 / 3e5, 1e-15);
  EXPECT_NEAR(m.perSamplePerPixel, 0.023 / 3e5, 1e-15);
  EXPECT_FALSE(fitFrameCost({}).known);
  // Unusable measurements are ignored.
  EXPECT_FALSE(fitFrameCost({{1, 0.0, 0.01}, {0, 100.0, 0.01}}).known);
}

TEST(FrameBudget, FitKeepsBothPartsNonNegative)
{
  // More samples measured cheaper: everything fixed (the mean, 0.03 / 100 per pixel).
  const FrameCostModel cheaper = fitFrameCost({{1, 100.0, 0.04}, {8, 100.0, 0.02}});
  EXPECT_EQ(cheaper.perSamplePerPixel, 0.0);
  EXPECT_NEAR(cheaper.fixedPerPixel, 0.03 / 100.0, 1e-15);
  // A line through below the origin: everything per sample, the fit through the origin
  // b = sum(x y) / sum(x^2) = (1 x 1e-4 + 4 x 1e-3) / 17.
  const FrameCostModel steep = fitFrameCost({{1, 100.0, 0.01}, {4, 100.0, 0.1}});
  EXPECT_EQ(steep.fixedPerPixel, 0.0);
  EXPECT_NEAR(steep.perSamplePerPixel, (1e-4 + 4e-3) / 17.0, 1e-15);
}

TEST(FrameBudget, ChoosesTheLargestDivisorWithinTheBudget)
{
  // 38 ms fixed and 7.8 ms per sample at 1e5 pixels; budget 60 ms: (60 - 38) / 7.8 = 2.8 -> 2.
  FrameCostModel m;
  m.known = true;
  m.separated = true;
  m.fixedPerPixel = 38e-3 / 1e5;
  m.perSamplePerPixel = 7.8e-3 / 1e5;
  EXPECT_EQ(chooseFrameSamples(m, 1e5, 0.060, 16, 256), 2);
  // Budget 80 ms: (80 - 38) / 7.8 = 5.4 -> 5, which does not divide 256: 4.
  EXPECT_EQ(chooseFrameSamples(m, 1e5, 0.080, 16, 256), 4);
  // A total of 300: 5 divides it.
  EXPECT_EQ(chooseFrameSamples(m, 1e5, 0.080, 16, 300), 5);
  // A prime total below the affordable count: 1.
  EXPECT_EQ(chooseFrameSamples(m, 1e5, 0.080, 16, 257), 1);
  // Everything fits (38 + 16 x 7.8 = 162.8 ms): the material's count.
  EXPECT_EQ(chooseFrameSamples(m, 1e5, 0.163, 16, 256), 16);
  // Half the pixels: (60 / 0.5 - 38) / 7.8 = 10.5 -> 10, divisor of 256 at most 10: 8.
  EXPECT_EQ(chooseFrameSamples(m, 5e4, 0.060, 16, 256), 8);
  // Not even the fixed part fits: 1 sample per frame.
  EXPECT_EQ(chooseFrameSamples(m, 1e5, 0.020, 16, 256), 1);
  // No budget, or nothing measured: the material's count.
  EXPECT_EQ(chooseFrameSamples(m, 1e5, 0.0, 16, 256), 16);
  EXPECT_EQ(chooseFrameSamples(FrameCostModel{}, 1e5, 0.060, 16, 256), 16);
}

TEST(FrameBudget, LoadMarginIsTheLargestRecentOverrun)
{
  // Frames that came in under or at their prediction leave the budget whole.
  EXPECT_EQ(loadMargin({}, 1.5), 1.0);
  EXPECT_EQ(loadMargin({0.8, 1.0, 0.95}, 1.5), 1.0);
  // The largest ratio, whatever its position.
  EXPECT_EQ(loadMargin({1.1, 1.25, 0.9}, 1.5), 1.25);
  // Bounded: one frame stalled five times over keeps 1.5 in hand.
  EXPECT_EQ(loadMargin({1.2, 5.0}, 1.5), 1.5);
  // Ratios that are no measurement (not finite, not above 0) are ignored.
  EXPECT_EQ(loadMargin({std::numeric_limits<double>::infinity(),
                        std::numeric_limits<double>::quiet_NaN(), -2.0, 1.125},
                       1.5),
            1.125);
  // A bound below 1 never makes the budget larger.
  EXPECT_EQ(loadMargin({1.3}, 0.5), 1.0);
}

TEST(FrameBudget, MarginShrinksThePlanUnderLoad)
{
  // The model of ChoosesTheLargestDivisorWithinTheBudget (38 ms + 7.8 ms per sample at 1e5
  // pixels), budget 80 ms: unloaded (80 - 38) / 7.8 = 5.4 -> 4 of 256. Recent frames took 1.25
  // times their prediction: planned with 80 / 1.25 = 64 ms, (64 - 38) / 7.8 = 3.3 -> 2; the
  // frame then costs 1.25 x (38 + 2 x 7.8) = 67 ms, within the budget where 4 samples would
  // cost 1.25 x 69.2 = 86.5 ms.
  FrameCostModel m;
  m.known = true;
  m.separated = true;
  m.fixedPerPixel = 38e-3 / 1e5;
  m.perSamplePerPixel = 7.8e-3 / 1e5;
  EXPECT_EQ(chooseFrameSamples(m, 1e5, 0.080 / loadMargin({1.0, 1.25}, 1.5), 16, 256), 2);
  EXPECT_EQ(chooseFrameSamples(m, 1e5, 0.080 / loadMargin({1.0, 0.9}, 1.5), 16, 256), 4);
}

TEST(FrameBudget, OverrunBeyondTheTolerance)
{
  // Budget 70 ms, tolerance 20 %: the limit is 84 ms.
  EXPECT_FALSE(frameOverran(0.070, 0.070, 0.2));
  EXPECT_FALSE(frameOverran(0.083, 0.070, 0.2));
  EXPECT_TRUE(frameOverran(0.085, 0.070, 0.2));
  // No budget: nothing overruns it; a negative tolerance counts as none.
  EXPECT_FALSE(frameOverran(1.0, 0.0, 0.2));
  EXPECT_TRUE(frameOverran(0.071, 0.070, -1.0));
}

TEST(FrameBudget, LargestDivisor)
{
  EXPECT_EQ(largestDivisorAtMost(256, 5), 4);
  EXPECT_EQ(largestDivisorAtMost(300, 7), 6);
  EXPECT_EQ(largestDivisorAtMost(257, 100), 1);
  EXPECT_EQ(largestDivisorAtMost(257, 257), 257);
  EXPECT_EQ(largestDivisorAtMost(12, 100), 12);
  EXPECT_EQ(largestDivisorAtMost(12, 0), 1);
}

TEST(FrameBudget, RunTotalIsWholeFrames)
{
  EXPECT_EQ(runTotalSamples(256, 16), 256);
  EXPECT_EQ(runTotalSamples(100, 16), 112); // 7 frames of 16
  EXPECT_EQ(runTotalSamples(1, 16), 16);
  EXPECT_EQ(runTotalSamples(0, 0), 1);
  // Every choice divides the run's total, so frames x samples per frame = total.
  FrameCostModel m;
  m.known = true;
  m.fixedPerPixel = 1e-7;
  m.perSamplePerPixel = 1e-7;
  for (int target : {1, 7, 100, 256, 1000, 65536})
  {
    const int total = runTotalSamples(target, 16);
    for (double budget : {0.001, 0.02, 0.05, 0.1})
    {
      const int s = chooseFrameSamples(m, 1e5, budget, 16, total);
      EXPECT_EQ(total % s, 0) << target << " " << budget;
    }
  }
}
} // namespace
} // namespace aniso
