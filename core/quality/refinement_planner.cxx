#include "core/quality/refinement_planner.h"

#include <algorithm>
#include <cmath>

namespace aniso
{
void RefinementPlanner::setBudgetMs(int ms)
{
  budgetMs_ = std::max(ms, 0);
}

void RefinementPlanner::setOverheadSeconds(double seconds)
{
  overheadSeconds_ = std::isfinite(seconds) ? std::max(seconds, 0.0) : 0.0;
}

double RefinementPlanner::renderBudgetSeconds() const
{
  const double budget = budgetMs_ * 1e-3;
  return budget - std::min(overheadSeconds_, 0.5 * budget);
}

void RefinementPlanner::learn(const MeasuredRender& render)
{
  lastSeconds_ = render.seconds;
  // How far the fit was off for this render, before it learns from it: the load margin (a band
  // predicted as its share of the frame).
  const FrameCostModel before = cost(render.pixels);
  if (before.known && render.measuresLoad)
  {
    const double predicted =
        before.predictSeconds(render.samples, double(render.pixels)) / render.bands;
    if (predicted > 0.0)
    {
      loadRatios_.push_back(render.seconds / predicted);
      if (loadRatios_.size() > std::size_t(kLoadFrames))
      {
        loadRatios_.erase(loadRatios_.begin());
      }
    }
  }
  if (render.standIn)
  {
    return; // the stand-in's cost says nothing of the surface's
  }
  // What the model learns is the cost of whole frames: a frame drawn in bands costs its bands
  // together (bands differ from one another as the surface does across the rows; together they
  // are the frame). A frame whose bands were interrupted (the view changed) is not counted.
  bandSeconds_ = render.band == 0 ? render.seconds : bandSeconds_ + render.seconds;
  if (render.band != render.bands - 1)
  {
    return;
  }
  // A running mean that follows the view (how much of it the surface covers) within a few
  // frames. The first frame of a size and sample count may also have paid for things done once
  // (the targets' allocation at a new size, a new shader variant's compilation): the second
  // replaces it.
  FrameCost& frame = costs_[std::make_pair(render.pixels, render.samples)];
  frame.seconds = frame.frames < 2 ? bandSeconds_ : 0.7 * frame.seconds + 0.3 * bandSeconds_;
  ++frame.frames;
}

FrameCostModel RefinementPlanner::cost(long long pixels, bool anySize) const
{
  // Only frames of this size (unless asked otherwise): a frame also has costs that do not grow
  // with its pixels, so costs per pixel of other sizes would mislead.
  std::vector<FrameCostSample> measured;
  for (const auto& [key, frame] : costs_)
  {
    if (anySize || key.first == pixels)
    {
      measured.push_back({key.second, static_cast<double>(key.first), frame.seconds});
    }
  }
  return fitFrameCost(measured);
}

double RefinementPlanner::budgetSeconds(const FrameCostModel& cost) const
{
  // Planned for the machine as it ran the latest frames (the fit follows a change of load only
  // over several frames), except while the parts are not yet told apart: a margin on the
  // pessimistic split would keep every frame at 1 sample and the split unknown.
  return kPlanHeadroom * renderBudgetSeconds() / (cost.separated ? margin() : 1.0);
}

FramePlan RefinementPlanner::plan(const RunShape& shape) const
{
  if (budgetMs_ <= 0)
  {
    return {shape.materialSamples, 1};
  }
  const double pixels = double(shape.pixels);
  const FrameCostModel known = cost(shape.pixels);
  if (!known.known)
  {
    // Nothing measured at this size (the first still frame after moving at half resolution): a
    // first frame as cheap as can be, which measures it, in bands as the costs of the other sizes
    // suggest (costs per pixel of smaller frames are higher: it errs on the side of more bands).
    const FrameCostModel guess = cost(shape.pixels, true);
    if (!guess.known)
    {
      // Nothing measured at any size: bands by the surface's triangles.
      const long long bands = (shape.triangles + kTrianglesPerBand - 1) / kTrianglesPerBand;
      return {1, static_cast<int>(std::clamp<long long>(bands, 1, kMaxBands))};
    }
    return {1, chooseFrameBands(guess, 1, pixels, budgetSeconds(guess), kMaxBands)};
  }
  int largestMeasured = 1;
  for (const auto& entry : costs_)
  {
    if (entry.first.first == shape.pixels)
    {
      largestMeasured = std::max(largestMeasured, entry.first.second);
    }
  }
  if (!known.separated && largestMeasured != 1)
  {
    // One sample count measured, more than 1: a frame of 1 (the cheapest) tells the fixed cost
    // from the samples'.
    return {1, chooseFrameBands(known, 1, pixels, budgetSeconds(known), kMaxBands)};
  }
  // A fit from few, noisy renders is trusted up to 4 times the largest count measured (with one
  // count, 1, measured: its assumed split overestimates the cost of more samples, so a plan of up
  // to 4 stays within the budget and measures the split); a count beyond is reached over later
  // runs, each measuring the way there. Below the material's count, a divisor of the run's total.
  const int reach = 4 * largestMeasured;
  const int most = reach >= shape.materialSamples ? shape.materialSamples
                                                  : largestDivisorAtMost(shape.total, reach);
  FramePlan plan =
      chooseFramePlan(known, pixels, budgetSeconds(known), most, shape.total, kMaxBands);
  if (!measured(shape.pixels, plan.samples))
  {
    // A count never measured at this size is extrapolated: its first frame is cut in bands for
    // kUnmeasuredMargin times the predicted cost; the bands are re-planned from what it measured
    // once it is complete.
    plan.bands = chooseFrameBands(known, plan.samples, pixels,
                                  budgetSeconds(known) / kUnmeasuredMargin, kMaxBands);
  }
  return plan;
}

bool RefinementPlanner::beginRun(const FramePlan& plan)
{
  if (plan.samples == runSamples_)
  {
    return false;
  }
  runSamples_ = plan.samples;
  return true;
}

RunStep RefinementPlanner::afterFrame(const RunShape& shape, bool firstOfRun)
{
  const FramePlan next = plan(shape);
  const bool overran = frameOverran(lastSeconds_, renderBudgetSeconds(), kOverrunTolerance);
  if (runReplans_ < kMaxReplans &&
      ((firstOfRun && runReplans_ < 2 && next.samples != runSamples_) ||
       (overran && next.samples < runSamples_)))
  {
    // The run's first frame measured its own cost: if the plan was off (nothing measured at this
    // size yet, or one sample count only), the run starts over with the corrected count, at most
    // twice. A later frame that overran the budget (the load rose) does the same when the plan,
    // with the margin it measured, now takes fewer samples.
    ++runReplans_;
    return {true, next.bands};
  }
  // The run's samples stay; its frames are cut in as many bands as their measured cost (and the
  // load) now asks for. That changes no sample of the mean: no restart.
  const FrameCostModel known = cost(shape.pixels);
  return {false, chooseFrameBands(known, runSamples_, double(shape.pixels), budgetSeconds(known),
                                  kMaxBands)};
}
} // namespace aniso
