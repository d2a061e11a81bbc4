// The refinement planner (quality/refinement_planner.h), fed renders by hand, no window:
//   - what it learns: the second frame of a size and sample count replaces the first, later ones
//     a running mean (0.7 old + 0.3 new); a frame in bands costs its bands together, an
//     interrupted one is not counted; stand-in renders are not learnt; costs are kept per size
//     (another size is a guess from all sizes) and forgotten on request;
//   - the load margin: the largest measured/predicted ratio of the last 8 refinement frames after
//     their run's first, at most 1.25, kept in hand only by a fit that tells the parts apart;
//   - the run plan: the material's count whole without a budget; nothing measured: one band per
//     40 000 triangles; another size measured: 1 sample in the bands its costs suggest; one count
//     above 1 measured: a 1-sample frame; trusted up to 4 times the largest count measured; a count
//     never measured cut for twice its predicted cost;
//   - re-plans after a frame: the run's first measuring another plan (at most twice a run), a frame
//     overrunning the budget by more than 20 % with a plan of fewer samples, at most 4 a run until
//     the view settles; else the run's frames in the bands their cost asks for.
// Every frame is at P = 1e5 pixels with a budget of 70 ms unless said otherwise, of which plans
// aim at kPlanHeadroom = 85 %: 59.5 ms; expected values are worked out by hand in the comments.
#include "core/quality/refinement_planner.h"

#include <gtest/gtest.h>
#include <utility>

namespace aniso
{
namespace
{
constexpr long long P = 100000;

// A whole frame (one band) of SAMPLES at PIXELS that took SECONDS.
MeasuredRender frame(int samples, double seconds, long long pixels = P)
{
  MeasuredRender r;
  r.pixels = pixels;
  r.seconds = seconds;
  r.samples = samples;
  return r;
}

// Band BAND of BANDS of a frame of SAMPLES at P.
MeasuredRender band(int samples, int band, int bands, double seconds)
{
  MeasuredRender r = frame(samples, seconds);
  r.band = band;
  r.bands = bands;
  return r;
}

// A refinement frame after its run's first: it measures the load.
MeasuredRender loaded(MeasuredRender r)
{
  r.measuresLoad = true;
  return r;
}

// A run at P of the material's 16 samples, 64 in all.
RunShape shape(int materialSamples = 16, long long triangles = 0)
{
  RunShape s;
  s.pixels = P;
  s.materialSamples = materialSamples;
  s.total = 64;
  s.triangles = triangles;
  return s;
}

void expectPlan(const FramePlan& plan, int samples, int bands)
{
  EXPECT_EQ(plan.samples, samples);
  EXPECT_EQ(plan.bands, bands);
}

double predicted(const RefinementPlanner& planner, int samples)
{
  return planner.cost(P).predictSeconds(samples, double(P));
}

TEST(RefinementPlanner, TheSecondFrameReplacesTheFirstThenARunningMean)
{
  RefinementPlanner planner(70);
  // One count measured: the fit splits a frame's cost evenly, so it predicts the frame's own
  // cost for its count.
  planner.learn(frame(4, 0.5)); // a first frame that paid for a shader compile
  EXPECT_NEAR(predicted(planner, 4), 0.5, 1e-12);
  planner.learn(frame(4, 0.1));
  EXPECT_NEAR(predicted(planner, 4), 0.1, 1e-12);
  // 0.7 x 0.1 + 0.3 x 0.2 = 0.13.
  planner.learn(frame(4, 0.2));
  EXPECT_NEAR(predicted(planner, 4), 0.13, 1e-12);
  EXPECT_TRUE(planner.measured(P, 4));
  EXPECT_FALSE(planner.measured(P, 1));
  EXPECT_EQ(planner.lastRenderSeconds(), 0.2);
  planner.renderStarted();
  EXPECT_EQ(planner.lastRenderSeconds(), 0.0);
}

TEST(RefinementPlanner, AFrameInBandsCostsItsBandsTogether)
{
  RefinementPlanner planner(70);
  planner.learn(band(1, 0, 2, 0.03));
  EXPECT_FALSE(planner.cost(P).known); // not complete
  // The view changed: the frame starts over at band 0, so the interrupted one is not counted;
  // this one costs 0.035 + 0.04 = 0.075.
  planner.learn(band(1, 0, 2, 0.035));
  planner.learn(band(1, 1, 2, 0.04));
  EXPECT_NEAR(predicted(planner, 1), 0.075, 1e-12);
}

TEST(RefinementPlanner, StandInRendersAreNotLearnt)
{
  RefinementPlanner planner(70);
  MeasuredRender standIn = frame(1, 0.02);
  standIn.standIn = true;
  planner.learn(standIn);
  EXPECT_FALSE(planner.cost(P).known);
  EXPECT_FALSE(planner.cost(P, true).known);
  // Its time is the last render's all the same (an overrun is an overrun).
  EXPECT_EQ(planner.lastRenderSeconds(), 0.02);
}

TEST(RefinementPlanner, CostsArePerSizeAndForgottenOnRequest)
{
  RefinementPlanner planner(70);
  planner.learn(frame(1, 0.02, 25000));
  EXPECT_FALSE(planner.cost(P).known);
  // Any size: 0.02 s over 25 000 pixels, split evenly: 4e-7 s per pixel and sample, so 1 sample
  // at P predicts 1e5 x 8e-7 = 0.08 s.
  EXPECT_NEAR(planner.cost(P, true).predictSeconds(1, double(P)), 0.08, 1e-12);
  planner.forgetCosts();
  EXPECT_FALSE(planner.cost(P, true).known);
}

TEST(RefinementPlanner, TheLoadMarginKeepsTheWorstOfTheLastEightFrames)
{
  RefinementPlanner planner(70);
  planner.learn(frame(1, 0.02));
  planner.learn(frame(1, 0.02));
  // A frame that measures no load (moving, or its run's first) leaves the margin at 1.
  planner.learn(frame(1, 0.05));
  planner.learn(frame(1, 0.02)); // the mean: 0.7 x (0.7 x 0.02 + 0.3 x 0.05) + 0.3 x 0.02 = 0.0263
  EXPECT_EQ(planner.margin(), 1.0);
  planner.forgetCosts();
  planner.learn(frame(1, 0.02));
  planner.learn(frame(1, 0.02));
  // Predicted 0.02, measured 0.024: 1.2, ahead of what it learns (0.7 x 0.02 + 0.3 x 0.024 =
  // 0.0212).
  planner.learn(loaded(frame(1, 0.024)));
  EXPECT_NEAR(planner.margin(), 1.2, 1e-12);
  // Seven frames as predicted (ratio 1, the mean stays 0.0212): 1.2 is still one of the last 8.
  for (int i = 0; i < 7; ++i)
  {
    planner.learn(loaded(frame(1, 0.0212)));
  }
  EXPECT_NEAR(predicted(planner, 1), 0.0212, 1e-12);
  EXPECT_NEAR(planner.margin(), 1.2, 1e-12);
  // The eighth pushes it out.
  planner.learn(loaded(frame(1, 0.0212)));
  EXPECT_NEAR(planner.margin(), 1.0, 1e-12);
  // Twice the prediction: at most 1.25.
  planner.learn(loaded(frame(1, 2 * 0.0212)));
  EXPECT_NEAR(planner.margin(), RefinementPlanner::kMaxLoadMargin, 0.0);
}

TEST(RefinementPlanner, ABandIsPredictedAsItsShareOfTheFrame)
{
  RefinementPlanner planner(70);
  planner.learn(frame(1, 0.02));
  planner.learn(frame(1, 0.02));
  // Band 1 of 2 predicted 0.01 s, measured 0.012: 1.2 (as a whole frame it would be 0.6).
  planner.learn(loaded(band(1, 0, 2, 0.012)));
  EXPECT_NEAR(planner.margin(), 1.2, 1e-12);
}

TEST(RefinementPlanner, TheMarginIsKeptOnlyByAFitThatTellsThePartsApart)
{
  RefinementPlanner planner(70);
  planner.learn(frame(1, 0.02));
  planner.learn(frame(1, 0.02));
  planner.learn(loaded(frame(1, 0.024))); // margin 1.2
  // One count: the parts are an assumed split, the budget whole (less the headroom).
  const double h = RefinementPlanner::kPlanHeadroom;
  FrameCostModel model = planner.cost(P);
  EXPECT_FALSE(model.separated);
  EXPECT_NEAR(planner.budgetSeconds(model), 0.07 * h, 1e-15);
  model.separated = true;
  EXPECT_NEAR(planner.budgetSeconds(model), 0.07 * h / 1.2, 1e-12);
}

TEST(RefinementPlanner, WithoutABudgetFramesOfTheMaterialsSamplesWhole)
{
  RefinementPlanner planner(-5); // negative: no budget
  EXPECT_EQ(planner.budgetMs(), 0);
  planner.learn(frame(1, 10.0));
  expectPlan(planner.plan(shape()), 16, 1);
}

TEST(RefinementPlanner, NothingMeasuredBandsByTriangles)
{
  const RefinementPlanner planner(70);
  // One band per 40 000 triangles, rounded up, 1 to 16: 320 000 -> 8, 40 001 -> 2, none -> 1,
  // 10^6 -> 25, at most 16; always 1 sample.
  EXPECT_EQ(planner.plan(shape(16, 320000)).bands, 8);
  EXPECT_EQ(planner.plan(shape(16, 320000)).samples, 1);
  EXPECT_EQ(planner.plan(shape(16, 40001)).bands, 2);
  EXPECT_EQ(planner.plan(shape(16, 0)).bands, 1);
  EXPECT_EQ(planner.plan(shape(16, 1000000)).bands, 16);
}

TEST(RefinementPlanner, AnotherSizeMeasuredGuessesTheBands)
{
  RefinementPlanner planner(70);
  // 25 000 pixels at 0.02 s: 1 sample at P predicts 0.08 s (see CostsArePerSize), over the
  // 70 ms budget in one band, within it in two (0.04 s).
  planner.learn(frame(1, 0.02, 25000));
  expectPlan(planner.plan(shape(16, 320000)), 1, 2);
}

TEST(RefinementPlanner, OneCountAboveOneMeasuredProbesWithOneSample)
{
  RefinementPlanner planner(70);
  // 16 samples at 0.17 s, split evenly: 1e-7 s per pixel and part, 1 sample 0.02 s: one band.
  planner.learn(frame(16, 0.17));
  expectPlan(planner.plan(shape()), 1, 1);
}

TEST(RefinementPlanner, TrustsTheFitUpToFourTimesTheLargestCountMeasured)
{
  RefinementPlanner planner(70);
  // 1 sample at 0.02 s: S samples predict 0.01 (1 + S) s. Up to 4 (the largest divisor of 64 at
  // most 4 x 1): 1, 2 and 4 each fit one band (0.02, 0.03, 0.05 s); samples per second 50, 67,
  // 80: 4. Never measured: bands for 0.07 / 2 = 0.035 s: 0.05 / 2 = 0.025, 2 bands.
  planner.learn(frame(1, 0.02));
  expectPlan(planner.plan(shape()), 4, 2);
}

TEST(RefinementPlanner, TwoCountsPlanUpToTheMaterialsCount)
{
  RefinementPlanner planner(70);
  // 1 sample 0.02 s, 4 samples 0.05 s: 1e-7 s per pixel fixed and per sample, S samples
  // 0.01 (1 + S) s. Largest measured 4, reach 16 = the material's: 1, 2, 4, 8, 16, samples per
  // second S / 0.01 (1 + S) rising with S: 16 (0.17 s). Never measured: bands for half the
  // 59.5 ms, 0.02975 s: 0.17 / 6 = 0.0283 (5 would be 0.034).
  planner.learn(frame(1, 0.02));
  planner.learn(frame(4, 0.05));
  expectPlan(planner.plan(shape()), 16, 6);
  // Measured: bands for the whole 59.5 ms, 0.17 / 3 = 0.057.
  planner.learn(frame(16, 0.17));
  EXPECT_EQ(planner.plan(shape()).bands, 3);
}

// The window's work around a render comes off the budget the renders are planned for: the same
// measured frame (16 samples 0.17 s) takes 3 bands of 0.057 s under 70 ms (59.5 planned), 4 of
// 0.043 s once 15 ms of each pass are the window's own (55 ms left, 46.75 planned), and the
// overhead never takes more than half the budget (100 ms of it leaves 35 ms, 29.75 planned:
// 6 bands of 0.028 s).
TEST(RefinementPlanner, TheWindowsOverheadComesOffTheRendersBudget)
{
  RefinementPlanner planner(70);
  planner.learn(frame(1, 0.02));
  planner.learn(frame(4, 0.05));
  planner.learn(frame(16, 0.17));
  EXPECT_EQ(planner.plan(shape()).bands, 3);
  planner.setOverheadSeconds(0.015);
  EXPECT_DOUBLE_EQ(planner.renderBudgetSeconds(), 0.055);
  EXPECT_EQ(planner.plan(shape()).bands, 4);
  planner.setOverheadSeconds(0.100);
  EXPECT_DOUBLE_EQ(planner.renderBudgetSeconds(), 0.035);
  EXPECT_EQ(planner.plan(shape()).bands, 6);
  planner.setOverheadSeconds(-1.0);
  EXPECT_DOUBLE_EQ(planner.overheadSeconds(), 0.0);
  EXPECT_EQ(planner.plan(shape()).bands, 3);
}

TEST(RefinementPlanner, ARunTakesItsPlansSamples)
{
  RefinementPlanner planner(70);
  EXPECT_EQ(planner.runSamples(), 1);
  EXPECT_FALSE(planner.beginRun({1, 4})); // the same count: no restart
  EXPECT_TRUE(planner.beginRun({4, 1}));
  EXPECT_EQ(planner.runSamples(), 4);
}

TEST(RefinementPlanner, TheFirstFrameOfARunReplansAtMostTwice)
{
  RefinementPlanner planner(70);
  // Nothing measured (no triangles): 1 sample, 1 band.
  FramePlan plan = planner.plan(shape());
  EXPECT_EQ(plan.samples, 1);
  planner.beginRun(plan);
  // Its first frame measured 0.02 s: the plan is now 4 samples in 2 bands
  // (TrustsTheFitUpToFourTimes...): re-planned.
  planner.learn(frame(1, 0.02));
  RunStep step = planner.afterFrame(shape(), true);
  EXPECT_TRUE(step.replan);
  EXPECT_EQ(step.bands, 2);
  EXPECT_TRUE(planner.beginRun(planner.plan(shape())));
  EXPECT_EQ(planner.runSamples(), 4);
  // Its first frame measured 0.05 s: the plan is now 16 (TwoCountsPlan...): re-planned again.
  planner.learn(frame(4, 0.05));
  step = planner.afterFrame(shape(), true);
  EXPECT_TRUE(step.replan);
  EXPECT_EQ(step.bands, 6);
  planner.beginRun(planner.plan(shape()));
  EXPECT_EQ(planner.runSamples(), 16);
  // 16 samples at 0.17 s, as planned: the run stays, its frames in 3 bands.
  planner.learn(frame(16, 0.17));
  planner.renderStarted(); // a render that drew nothing: no overrun either
  step = planner.afterFrame(shape(), true);
  EXPECT_FALSE(step.replan);
  EXPECT_EQ(step.bands, 3);
  // The material's count down to 8: a plan of 8 (0.09 s), but twice is the most for first
  // frames: the run keeps 16, in 3 bands.
  step = planner.afterFrame(shape(8), true);
  EXPECT_FALSE(step.replan);
  EXPECT_EQ(step.bands, 3);
  EXPECT_EQ(planner.runSamples(), 16);
  // Once the view settled, runs may re-plan again.
  planner.settled();
  EXPECT_TRUE(planner.afterFrame(shape(8), true).replan);
}

// 1, 4 and 8 samples measured at 0.2, 0.5 and 0.9 s: 1e-6 s per pixel fixed and per sample,
// S samples 0.1 (1 + S) s. Within the 59.5 ms planned in at most 16 bands (0.0595 x 16 =
// 0.952 s): up to 8 (in 16 bands: 0.9 / 16 = 0.05625), 8 / 0.9 = 8.9 samples per second of frame
// against 8 for 4 (in 9 bands), 6.7 for 2 and 5 for 1: 8 in 16.
void learnSlowFrames(RefinementPlanner& planner)
{
  const std::pair<int, double> measured[] = {{1, 0.2}, {4, 0.5}, {8, 0.9}};
  for (const auto& [samples, seconds] : measured)
  {
    planner.learn(frame(samples, seconds));
    planner.learn(frame(samples, seconds));
  }
}

TEST(RefinementPlanner, AnOverrunWithAPlanOfFewerSamplesReplans)
{
  RefinementPlanner planner(70);
  learnSlowFrames(planner);
  expectPlan(planner.plan(shape()), 8, 16);
  planner.beginRun(planner.plan(shape()));
  // A band took 87.5 ms where 0.9 / 16 = 56.25 ms were predicted: ratio 1.56, margin 1.25 (the
  // most), and over the 70 ms budget by more than 20 % (84 ms). The 59.5 ms less the margin,
  // 47.6 ms, hold 8 samples no longer (56.25 ms in 16 bands) and 4 in 11 bands (0.5 / 11 =
  // 45.5 ms; 2 in 7 bands, 0.3 / 7 = 42.9 ms, give fewer samples per second): re-planned.
  planner.learn(loaded(band(8, 0, 16, 0.0875)));
  EXPECT_NEAR(planner.margin(), 1.25, 0.0);
  RunStep step = planner.afterFrame(shape(), false);
  EXPECT_TRUE(step.replan);
  EXPECT_EQ(step.bands, 11);
  EXPECT_EQ(planner.plan(shape()).samples, 4);
  // Without the run taking the plan, each further overrun re-plans again, 4 times a run in all.
  EXPECT_TRUE(planner.afterFrame(shape(), false).replan);
  EXPECT_TRUE(planner.afterFrame(shape(), false).replan);
  EXPECT_TRUE(planner.afterFrame(shape(), false).replan);
  step = planner.afterFrame(shape(), false);
  EXPECT_FALSE(step.replan);
  // Then its 8 samples stay, in as many bands as the budget less the margin asks: 16 at most.
  EXPECT_EQ(step.bands, 16);
  planner.settled();
  EXPECT_TRUE(planner.afterFrame(shape(), false).replan);
}

TEST(RefinementPlanner, AFrameWithinTheToleranceDoesNotReplan)
{
  RefinementPlanner planner(70);
  learnSlowFrames(planner);
  planner.beginRun(planner.plan(shape()));
  planner.learn(loaded(band(8, 0, 16, 0.0875))); // margin 1.25
  // The next band 80 ms: over the budget by less than 20 % (84 ms). The run stays, its frames
  // in the most bands, 16 (0.9 / 16 = 56.25 ms: more than the 47.6 ms planned less the margin).
  planner.learn(band(8, 1, 16, 0.08));
  const RunStep step = planner.afterFrame(shape(), false);
  EXPECT_FALSE(step.replan);
  EXPECT_EQ(step.bands, 16);
  EXPECT_EQ(planner.runSamples(), 8);
}
} // namespace
} // namespace aniso
