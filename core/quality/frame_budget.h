#pragma once
// The frame-time budget of progressive refinement: how many samples per pixel one frame may take
// so that drawing it keeps the UI thread free at least every budget, from the measured cost of
// earlier frames. A frame's cost is modelled per pixel as fixed + perSample x samples (the
// rasteriser's per-pixel work that does not depend on the sample count, then the samples), fitted
// to recent frames by least squares. The total of a refinement run is left as it was: the chosen
// count divides the run's total, so frames x samples per frame is the same sample count and every
// frame weighs the same in the mean. GL-free and Qt-free.
#include <vector>

namespace aniso
{
struct FrameCostSample
{
  int samples = 1;      // per pixel, of that frame
  double pixels = 0.0;  // drawn
  double seconds = 0.0; // taken on the UI thread
};

struct FrameCostModel
{
  double fixedPerPixel = 0.0;     // seconds
  double perSamplePerPixel = 0.0; // seconds
  bool known = false;             // false: no measurement yet
  // True when frames of at least two sample counts were measured; otherwise the split between
  // the fixed and the per-sample part is assumed: one sample costs as much as the fixed part,
  // which overestimates the cost of many samples (the budget errs on the side of shorter frames).
  bool separated = false;

  double predictSeconds(int samples, double pixels) const
  {
    return pixels * (fixedPerPixel + perSamplePerPixel * samples);
  }
};

// Least-squares fit of seconds / pixels = fixed + perSample x samples to the measurements
// (those with pixels > 0 and seconds >= 0). A fit that would make either part negative keeps it at
// zero and refits the other.
FrameCostModel fitFrameCost(const std::vector<FrameCostSample>& measured);

// The samples per pixel and frame of a refinement run: the largest count whose predicted frame
// cost at PIXELS stays within budgetSeconds, at most maxSamples (the material's own count, used
// as is with no budget, an unknown model or a cost it meets), at least 1, and a divisor of
// runTotal (frames x count = runTotal, see runTotalSamples) when below maxSamples.
int chooseFrameSamples(const FrameCostModel& model, double pixels, double budgetSeconds,
                       int maxSamples, int runTotal);

// The factor a plan keeps in hand for a changing machine load (other programs taking the cores):
// the largest ratio of a recent frame's measured cost to the cost the fit predicted for it, at
// least 1 (frames that came in under their prediction leave the budget whole) and at most
// maxMargin (one frame stalled by something else does not shrink every frame without bound).
// Ratios that are not finite and above 0 are ignored. A run plans with budget / margin.
double loadMargin(const std::vector<double>& measuredOverPredicted, double maxMargin);

// True when a frame that took measuredSeconds overran the budget by more than tolerance (a
// fraction of the budget): the load rose since the run was planned, which starts it over with a
// new plan.
bool frameOverran(double measuredSeconds, double budgetSeconds, double tolerance);

// The largest divisor of total (>= 1) that is at most limit (at least 1).
int largestDivisorAtMost(int total, int limit);

// The samples per pixel a run accumulates for a target of targetSamples at samplesPerFrame per
// frame: whole frames, so targetSamples rounded up to a multiple of samplesPerFrame.
int runTotalSamples(int targetSamples, int samplesPerFrame);
} // namespace aniso
