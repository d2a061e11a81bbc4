#pragma once
// The frame planning of a still view's progressive refinement, frame_budget.h's rules applied to
// the frames a view draws: what frames cost, learnt per window size and sample count from the
// renders the view timed; the cost model fitted to them; the load margin; and the plan of each
// refinement run (samples per frame, bands per frame), re-planned when the run's first frame
// measured the plan wrong or a frame overran the budget. The view feeds it the renders it
// measured and asks it for plans. GL-free and Qt-free.
#include "core/quality/frame_budget.h"

#include <map>
#include <utility>
#include <vector>

namespace aniso
{
// A render that drew the surface (a frame, or one band of it), as the view timed it.
struct MeasuredRender
{
  long long pixels = 0; // the window's size, the whole frame's pixels (not the band's)
  double seconds = 0.0; // the render's time on the UI thread
  int samples = 1;      // per pixel, drawn by it
  int bands = 1;        // of its frame
  int band = 0;         // the band it drew, 0 the first
  bool standIn = false; // it drew the surface's stand-in (LevelOfDetail.h), not the surface
  // A refinement frame after its run's first (not while things move): only those measure the
  // load, as the first after a resize or a new shader variant also pays for those once.
  bool measuresLoad = false;
};

// What a run is planned for.
struct RunShape
{
  long long pixels = 0;    // the window's
  int materialSamples = 1; // the material's samples per pixel: the most a frame takes
  int total = 1;           // the run's samples per pixel (a multiple of materialSamples)
  long long triangles = 0; // of the surface drawn when still
};

// What follows a completed refinement frame: the run starts over with a new plan (REPLAN), or
// keeps its samples per frame, its frames drawn in BANDS.
struct RunStep
{
  bool replan = false;
  int bands = 1;
};

class RefinementPlanner
{
public:
  // A changing machine load: plans keep the largest measured/predicted cost ratio of the last
  // kLoadFrames frames in hand (at most kMaxLoadMargin, frame_budget.h's loadMargin), and a
  // refinement frame that overran the budget by more than kOverrunTolerance starts its run over
  // with a new plan (at most kMaxReplans times a run, the first frame's re-plan included).
  static constexpr int kLoadFrames = 8;
  static constexpr double kMaxLoadMargin = 1.25;
  // Plans aim at this share of the render budget, not at all of it: the bands of one frame cost
  // their equal share of it only on average (on the development machine's shared software
  // rasteriser, single bands took up to 1.47 times their share while the load margin was 1.0;
  // docs/BENCHMARKS.md, "The planner's headroom"), and the budget is a limit, not a target.
  static constexpr double kPlanHeadroom = 0.85;
  static constexpr double kOverrunTolerance = 0.2;
  static constexpr int kMaxReplans = 4;
  // A refinement frame of one sample that still costs more than the budget is drawn in bands
  // (one per pass of the event loop, vtkAnisoAccumulationPass), at most this many.
  static constexpr int kMaxBands = 16;
  // The first frame of a sample count never measured at a size is cut in bands for this many
  // times its predicted cost.
  static constexpr double kUnmeasuredMargin = 2.0;
  // A still frame with nothing measured since the shading changed (a new mesh, maps, method) is
  // drawn in one band per this many triangles of the surface (at most kMaxBands): a render
  // costs about in proportion to its triangles on a software rasteriser (llvmpipe on the
  // development machine: some 140 ms for 320 000), and a band draws only the triangles in its
  // rows.
  static constexpr long long kTrianglesPerBand = 40000;

  explicit RefinementPlanner(int budgetMs = 0) { setBudgetMs(budgetMs); }

  // The longest a refinement frame's render should take (at least 0; 0: no budget, frames of
  // the material's samples whatever they cost).
  void setBudgetMs(int ms);
  int budgetMs() const { return budgetMs_; }
  // What the pass of the event loop that renders costs besides the render (the window's own
  // work around it, measured by the view): taken off the budget the renders are planned for, at
  // most half of it, so the whole pass keeps within the budget. Negative or non-finite: 0.
  void setOverheadSeconds(double seconds);
  double overheadSeconds() const { return overheadSeconds_; }
  // The seconds a render may take: the budget less the overhead (0 without a budget).
  double renderBudgetSeconds() const;

  // The shading changed (a new mesh, maps, method, lighting): frames cost what they cost now,
  // every measured cost is forgotten.
  void forgetCosts() { costs_.clear(); }
  // A render starts: until learn() hears of it, the last render drew nothing.
  void renderStarted() { lastSeconds_ = 0.0; }
  // Learns from a render that drew the surface: the load margin (how far the fit was off for it,
  // when it measuresLoad), then, unless it drew the stand-in, the cost of its frame once its
  // last band is drawn (its bands together; a frame whose bands were interrupted is not
  // counted). Per size and sample count a running mean, 0.7 old + 0.3 new, except that the
  // second frame replaces the first (which may have paid for things done once: the targets'
  // allocation at a new size, a shader variant's compilation).
  void learn(const MeasuredRender& render);
  // The time of the latest render that drew the surface, 0 when the latest drew nothing.
  double lastRenderSeconds() const { return lastSeconds_; }
  // Whether whole frames of SAMPLES at PIXELS were measured since the costs were last forgotten.
  bool measured(long long pixels, int samples) const
  {
    return costs_.count(std::make_pair(pixels, samples)) != 0;
  }

  // The cost model fitted to the frames measured at PIXELS (a frame drawn in bands costing its
  // bands together). With ANY_SIZE, to the frames of every size: a guess for a size not measured
  // yet (costs per pixel of smaller frames are higher, so it errs on the side of cheaper frames).
  FrameCostModel cost(long long pixels, bool anySize = false) const;
  // The largest measured/predicted ratio of the latest kLoadFrames frames (frame_budget.h).
  double margin() const { return loadMargin(loadRatios_, kMaxLoadMargin); }
  // The budget a plan with the cost model COST meets: kPlanHeadroom of the render budget, less
  // the load margin.
  double budgetSeconds(const FrameCostModel& cost) const;
  // The samples per frame of a still run and the bands its frames are drawn in.
  FramePlan plan(const RunShape& shape) const;

  // The run takes PLAN's samples per frame; true when that is another count than the run's (its
  // frames start over, every frame with the same weight).
  bool beginRun(const FramePlan& plan);
  int runSamples() const { return runSamples_; }
  // A refinement frame of the run at SHAPE was completed (its last band drawn); FIRST_OF_RUN:
  // the run's first. Re-planned (and counted) when the first frame measured a plan of another
  // count (at most twice a run) or the frame overran the budget and the plan now takes fewer
  // samples, at most kMaxReplans times; else the run's frames are cut in as many bands as their
  // measured cost (and the load) now asks for.
  RunStep afterFrame(const RunShape& shape, bool firstOfRun);
  // The view settled: the runs from now on may be re-planned again.
  void settled() { runReplans_ = 0; }

private:
  struct FrameCost
  {
    double seconds = 0.0;
    int frames = 0; // measured
  };
  int budgetMs_ = 0;
  double overheadSeconds_ = 0.0;
  // Frame costs since the shading last changed, by window size (pixels) and sample count.
  std::map<std::pair<long long, int>, FrameCost> costs_;
  int runSamples_ = 1;
  int runReplans_ = 0; // how often the current run was re-planned
  // Measured / predicted cost of the latest frames (the load margin's input).
  std::vector<double> loadRatios_;
  double lastSeconds_ = 0.0;
  double bandSeconds_ = 0.0; // the bands of the frame in progress so far
};
} // namespace aniso
