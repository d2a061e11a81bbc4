#pragma once
// The frame-time budget of progressive refinement: how many samples per pixel one frame may take,
// and in how many bands (renders of a part of the rows each) it is drawn, so that every render
// keeps the UI thread free at least every budget, from the measured cost of earlier renders. A
// render's cost is modelled as perRender + pixels x (fixed + perSample x samples): what every
// render costs whatever it draws, then per pixel drawn the rasteriser's work that does not depend
// on the sample count, then the samples; fitted to recent renders by least squares. The total of a
// refinement run is left as it was: the chosen count divides the run's total, so frames x samples
// per frame is the same sample count and every frame weighs the same in the mean. GL-free and
// Qt-free.
#include <vector>

namespace aniso
{
struct FrameCostSample
{
  int samples = 1;      // per pixel, of that render
  double pixels = 0.0;  // drawn by it (a band's rows only)
  double seconds = 0.0; // taken on the UI thread
};

struct FrameCostModel
{
  // Seconds per render whatever it draws; 0 until renders of at least two pixel counts (whole
  // frames and bands) tell it from the per-pixel part, which holds it until then.
  double perRender = 0.0;
  double fixedPerPixel = 0.0;     // seconds
  double perSamplePerPixel = 0.0; // seconds
  bool known = false;             // false: no measurement yet
  // True when frames of at least two sample counts were measured; otherwise the split between
  // the fixed and the per-sample part is assumed: one sample costs as much as the fixed part,
  // which overestimates the cost of many samples (the budget errs on the side of shorter frames).
  bool separated = false;

  double predictSeconds(int samples, double pixels) const
  {
    return perRender + pixels * (fixedPerPixel + perSamplePerPixel * samples);
  }
};

// Least-squares fit of the model to the measurements (those with pixels > 0 and seconds >= 0):
// all three parts when at least three distinct (samples, pixels) pairs of two sample counts and
// two pixel counts were measured and none of the parts comes out negative; otherwise
// seconds / pixels = fixed + perSample x samples (perRender 0), where a fixed part that would be
// negative is kept at zero and the other refitted, and a per-sample part that would be negative
// (more samples measured cheaper) gives the one-count split (fixed = perSample) at the mean sample
// count instead.
FrameCostModel fitFrameCost(const std::vector<FrameCostSample>& measured);

// Bands a frame of SAMPLES per pixel over PIXELS is drawn in (horizontal strips, one render each,
// see vtkAnisoAccumulationPass) so that each band's predicted cost at PIXELS / bands stays within
// budgetSeconds: the fewest that do, maxBands when none does; 1 with an unknown model, no budget
// or no pixels.
int chooseFrameBands(const FrameCostModel& model, int samples, double pixels, double budgetSeconds,
                     int maxBands);

struct FramePlan
{
  int samples = 1; // per pixel and frame
  int bands = 1;   // renders per frame
};

// The frames of a refinement run over PIXELS: among the sample counts up to maxSamples that divide
// runTotal (and maxSamples itself), each drawn in the fewest bands (chooseFrameBands) whose
// renders meet budgetSeconds, the count with the most samples per second of predicted frame time
// (bands x perRender + pixels x (fixed + perSample x samples)); of equals, the fewer samples. When
// no count meets the budget in maxBands bands: 1 sample in maxBands bands. With an unknown model
// or no budget: maxSamples, whole.
FramePlan chooseFramePlan(const FrameCostModel& model, double pixels, double budgetSeconds,
                          int maxSamples, int runTotal, int maxBands);

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
