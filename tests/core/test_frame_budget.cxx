// The frame-time budget of progressive refinement (quality/frame_budget.h):
//   - the cost fit recovers fixed and per-sample costs that generated the measurements exactly
//     (a known line), falls back to the stated assumption with one sample count or when more
//     samples measured cheaper, and keeps both parts non-negative;
//   - with whole frames only (one band), the plan's samples per frame are the largest divisor of
//     the run's total whose predicted cost meets the budget (values worked out by hand below),
//     the material's own count when it fits or nothing is known, and 1 at worst; frames x
//     samples per frame stay the run's total;
//   - with renders of two sizes (whole frames and bands) the fit also recovers what every render
//     costs whatever its pixels;
//   - a frame is drawn in the fewest bands whose predicted cost each meets the budget (worked
//     out by hand), at most the given count, in one band when nothing is known or there is no
//     budget; a run's plan takes the sample count and bands with the most samples per second
//     of predicted frame time among those that meet the budget (worked out by hand);
//   - under a changing load the plan keeps the largest recent measured/predicted ratio in hand
//     (bounded), which shrinks the chosen count to what the slower machine meets (worked out by
//     hand), and a frame overruns only beyond the budget's tolerance.
#include "core/quality/frame_budget.h"

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

// A model with both parts told apart (as if fitted to two sample counts).
FrameCostModel knownModel(double perRender, double fixedPerPixel, double perSamplePerPixel)
{
  FrameCostModel m;
  m.known = true;
  m.separated = true;
  m.perRender = perRender;
  m.fixedPerPixel = fixedPerPixel;
  m.perSamplePerPixel = perSamplePerPixel;
  return m;
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

TEST(FrameBudget, FitRecoversWhatEveryRenderCosts)
{
  // 5 ms per render, 40 ms fixed and 8 ms per sample at 300 000 pixels, measured whole at 1 and
  // 4 samples, in 2 bands (150 000 pixels) at 4 and in 4 bands at 16.
  const double fixed = 40e-3 / 3e5;
  const double perSample = 8e-3 / 3e5;
  const auto render = [&](int samples, double pixels) {
    return FrameCostSample{samples, pixels, 5e-3 + pixels * (fixed + perSample * samples)};
  };
  const FrameCostModel m =
      fitFrameCost({render(1, 3e5), render(4, 3e5), render(4, 1.5e5), render(16, 7.5e4)});
  ASSERT_TRUE(m.known);
  EXPECT_TRUE(m.separated);
  EXPECT_NEAR(m.perRender, 5e-3, 1e-9);
  EXPECT_NEAR(m.fixedPerPixel, fixed, 1e-6 * fixed);
  EXPECT_NEAR(m.perSamplePerPixel, perSample, 1e-6 * perSample);
  // One size only: what every render costs cannot be told from the pixels' part.
  const FrameCostModel oneSize = fitFrameCost({render(1, 3e5), render(4, 3e5)});
  EXPECT_EQ(oneSize.perRender, 0.0);
  EXPECT_NEAR(oneSize.predictSeconds(4, 3e5), render(4, 3e5).seconds, 1e-12);
  // Two sizes, one count: neither.
  const FrameCostModel oneCount = fitFrameCost({render(4, 3e5), render(4, 1.5e5)});
  EXPECT_EQ(oneCount.perRender, 0.0);
  EXPECT_FALSE(oneCount.separated);
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
  // More samples measured cheaper: the one-count split at the mean count 4.5 and the mean cost
  // 0.03 s: fixed = perSample = 0.03 / 100 / 5.5 per pixel, so more samples predict more cost.
  const FrameCostModel cheaper = fitFrameCost({{1, 100.0, 0.04}, {8, 100.0, 0.02}});
  EXPECT_NEAR(cheaper.perSamplePerPixel, 0.03 / 100.0 / 5.5, 1e-15);
  EXPECT_NEAR(cheaper.fixedPerPixel, 0.03 / 100.0 / 5.5, 1e-15);
  EXPECT_GT(cheaper.predictSeconds(16, 100.0), cheaper.predictSeconds(8, 100.0));
  // A line through below the origin: everything per sample, the fit through the origin
  // b = sum(x y) / sum(x^2) = (1 x 1e-4 + 4 x 1e-3) / 17.
  const FrameCostModel steep = fitFrameCost({{1, 100.0, 0.01}, {4, 100.0, 0.1}});
  EXPECT_EQ(steep.fixedPerPixel, 0.0);
  EXPECT_NEAR(steep.perSamplePerPixel, (1e-4 + 4e-3) / 17.0, 1e-15);
}

TEST(FrameBudget, ChoosesTheLargestDivisorWithinTheBudget)
{
  // 38 ms fixed and 7.8 ms per sample at 1e5 pixels; budget 60 ms: (60 - 38) / 7.8 = 2.8 -> 2.
  const FrameCostModel m = knownModel(0.0, 38e-3 / 1e5, 7.8e-3 / 1e5);
  EXPECT_EQ(chooseFramePlan(m, 1e5, 0.060, 16, 256, 1).samples, 2);
  // Budget 80 ms: (80 - 38) / 7.8 = 5.4 -> 5, which does not divide 256: 4.
  EXPECT_EQ(chooseFramePlan(m, 1e5, 0.080, 16, 256, 1).samples, 4);
  // A total of 300: 5 divides it.
  EXPECT_EQ(chooseFramePlan(m, 1e5, 0.080, 16, 300, 1).samples, 5);
  // A prime total below the affordable count: 1.
  EXPECT_EQ(chooseFramePlan(m, 1e5, 0.080, 16, 257, 1).samples, 1);
  // Everything fits (38 + 16 x 7.8 = 162.8 ms): the material's count.
  EXPECT_EQ(chooseFramePlan(m, 1e5, 0.163, 16, 256, 1).samples, 16);
  // Half the pixels: (60 / 0.5 - 38) / 7.8 = 10.5 -> 10, divisor of 256 at most 10: 8.
  EXPECT_EQ(chooseFramePlan(m, 5e4, 0.060, 16, 256, 1).samples, 8);
  // Not even the fixed part fits: 1 sample per frame.
  EXPECT_EQ(chooseFramePlan(m, 1e5, 0.020, 16, 256, 1).samples, 1);
  // No budget, or nothing measured: the material's count.
  EXPECT_EQ(chooseFramePlan(m, 1e5, 0.0, 16, 256, 1).samples, 16);
  EXPECT_EQ(chooseFramePlan(FrameCostModel{}, 1e5, 0.060, 16, 256, 1).samples, 16);
}

TEST(FrameBudget, BandsSplitAFrameTheBudgetCannotHold)
{
  // 38 ms fixed and 7.8 ms per sample at 1e5 pixels: one sample costs 45.8 ms.
  const FrameCostModel m = knownModel(0.0, 38e-3 / 1e5, 7.8e-3 / 1e5);
  // It fits a 70 ms budget whole.
  EXPECT_EQ(chooseFrameBands(m, 1, 1e5, 0.070, 8), 1);
  // 45.8 / 30 = 1.53 -> 2 bands of 22.9 ms.
  EXPECT_EQ(chooseFrameBands(m, 1, 1e5, 0.030, 8), 2);
  // Four samples: 38 + 31.2 = 69.2 ms; budget 20 ms: 3.46 -> 4 bands.
  EXPECT_EQ(chooseFrameBands(m, 4, 1e5, 0.020, 8), 4);
  // Twice the pixels, twice the cost: 91.6 / 30 = 3.05 -> 4.
  EXPECT_EQ(chooseFrameBands(m, 1, 2e5, 0.030, 8), 4);
  // At most the given count: 45.8 / 1 = 45.8 -> 8.
  EXPECT_EQ(chooseFrameBands(m, 1, 1e5, 0.001, 8), 8);
  // Nothing known, no budget, or no pixels: whole frames.
  EXPECT_EQ(chooseFrameBands(FrameCostModel{}, 1, 1e5, 0.030, 8), 1);
  EXPECT_EQ(chooseFrameBands(m, 1, 1e5, 0.0, 8), 1);
  EXPECT_EQ(chooseFrameBands(m, 1, 0.0, 0.030, 8), 1);
}

TEST(FrameBudget, PlanTakesTheMostSamplesPerSecondWithinTheBudget)
{
  // 4 ms per render; a whole frame of 3.6e5 pixels costs 30 ms + 10 ms per sample besides.
  const FrameCostModel m = knownModel(4e-3, 30e-3 / 3.6e5, 10e-3 / 3.6e5);
  const double pixels = 3.6e5;
  // Budget 60 ms. Band cost 4 + (30 + 10 s) / n ms:
  //   s = 1: 1 band, 44 ms a frame: 0.023 samples/ms;  s = 2: 1 band, 54 ms: 0.037;
  //   s = 4: 2 bands (39 ms each), 78 ms: 0.051;       s = 8: 2 bands (59), 118 ms: 0.068;
  //   s = 16: 4 bands (51.5; 3 would be 67.3), 206 ms: 0.078, the most.
  FramePlan plan = chooseFramePlan(m, pixels, 0.060, 16, 256, 8);
  EXPECT_EQ(plan.samples, 16);
  EXPECT_EQ(plan.bands, 4);
  // Budget 20 ms: s = 16 needs 12 bands (more than 8); s = 8 in 7 bands (19.7 ms each), 138 ms:
  // 0.058, more than s = 4 in 5 (90 ms: 0.044) or s = 2 in 4 (66 ms: 0.030).
  plan = chooseFramePlan(m, pixels, 0.020, 16, 256, 8);
  EXPECT_EQ(plan.samples, 8);
  EXPECT_EQ(plan.bands, 7);
  // Budget 10 ms: only s = 1 fits, in 7 bands (9.7 ms each; s = 2 would need 9).
  plan = chooseFramePlan(m, pixels, 0.010, 16, 256, 8);
  EXPECT_EQ(plan.samples, 1);
  EXPECT_EQ(plan.bands, 7);
  // Budget 5 ms: nothing fits (1 sample needs 40 bands): 1 sample in the most bands.
  plan = chooseFramePlan(m, pixels, 0.005, 16, 256, 8);
  EXPECT_EQ(plan.samples, 1);
  EXPECT_EQ(plan.bands, 8);
  // Below the most, only divisors of the run's total: with at most 12 of a total of 24, 12
  // itself in 3 bands (54 ms each, 162 ms: 0.074) beats 8 (0.068) and 6 (2 bands, 98 ms: 0.061).
  plan = chooseFramePlan(m, pixels, 0.060, 12, 24, 8);
  EXPECT_EQ(plan.samples, 12);
  EXPECT_EQ(plan.bands, 3);
  // Nothing known or no budget: the most samples, whole.
  plan = chooseFramePlan(FrameCostModel{}, pixels, 0.060, 16, 256, 8);
  EXPECT_EQ(plan.samples, 16);
  EXPECT_EQ(plan.bands, 1);
  plan = chooseFramePlan(m, pixels, 0.0, 16, 256, 8);
  EXPECT_EQ(plan.samples, 16);
  EXPECT_EQ(plan.bands, 1);
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
  const FrameCostModel m = knownModel(0.0, 38e-3 / 1e5, 7.8e-3 / 1e5);
  EXPECT_EQ(chooseFramePlan(m, 1e5, 0.080 / loadMargin({1.0, 1.25}, 1.5), 16, 256, 1).samples, 2);
  EXPECT_EQ(chooseFramePlan(m, 1e5, 0.080 / loadMargin({1.0, 0.9}, 1.5), 16, 256, 1).samples, 4);
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
      const int s = chooseFramePlan(m, 1e5, budget, 16, total, 1).samples;
      EXPECT_EQ(total % s, 0) << target << " " << budget;
    }
  }
}
} // namespace
} // namespace aniso
