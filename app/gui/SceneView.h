#pragma once
// Draws the scene of a SceneModel in a VTK render window with the anisotropic material, on
// demand only: a change of the model or the camera asks for one frame; while things move
// (a drag, a camera interaction) frames are cheap (one sample per pixel; the window draws them
// at reduced resolution, see interactionChanged); once still for a moment, frames accumulate
// (progressive refinement) until the quality's sample count is reached, then nothing is drawn
// until something changes. Each refinement frame takes as many of the material's samples as the
// frame budget allows by the measured cost of earlier frames (fewer frames of more samples when
// they are cheap), a count that divides the run's total, so the converged image is the same
// mean of the same number of samples. Lookup tables come from the LutScheduler's bakes, so a new
// n_u, n_v never bakes on the UI thread: until its tables are ready the material keeps the previous
// exponents. Likewise a new environment or cube size is baked (cubemap, SH9 and, with
// environment sampling on, its distribution) on a worker thread: the latest request wins, the
// previous lighting stays on screen until the new one is ready, and a failed bake is reported
// once and changes nothing. Switching environment sampling on bakes a lighting with its
// distribution the same way; until it is on screen the material samples its lobe only. A baked
// lighting reaches the screen over separate passes of the event loop, so their costs never add
// up in one stall: its textures are uploaded in one, the view switches to it in a later one with
// a cheap frame (as while moving: the new shader variant compiles then), and refinement under the
// frame budget follows once settled.
#include "core/quality/adaptive_quality.h"
#include "core/quality/frame_budget.h"
#include "scene/SceneModel.h"
#include "vtkpasses/render/DisplaySettings.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

class QThreadPool;
class QTimer;
class vtkActor;
class vtkAnisoAccumulationPass;
class vtkOpenGLPolyDataMapper;
class vtkOpenGLRenderer;
class vtkRenderStepsPass;
class vtkRenderWindow;
class vtkCallbackCommand;
class vtkObject;

namespace aniso
{
class AnisoMaterial;
class EnvironmentLighting;
class ErrorForwardingWindow;
class LutScheduler;
class SceneAssets;

class SceneView : public QObject
{
  Q_OBJECT

public:
  // Samples per pixel of the frames drawn while something moves.
  static constexpr int kInteractiveSamples = 1;
  static constexpr int kDefaultSettleMs = 300;
  static constexpr int kDefaultFrameBudgetMs = 70;
  // With a frame budget, the mean of a refinement run reaches the screen this often (and after
  // its first and last frames).
  static constexpr int kPresentIntervalMs = 250;
  static constexpr int kAfterPresentMs = 10;
  // A changing machine load: plans keep the largest measured/predicted cost ratio of the last
  // kLoadFrames frames in hand (at most kMaxLoadMargin, frame_budget.h's loadMargin), and a
  // refinement frame that overran the budget by more than kOverrunTolerance starts its run over
  // with a new plan (at most kMaxReplans times a run, the first frame's re-plan included).
  static constexpr int kLoadFrames = 8;
  static constexpr double kMaxLoadMargin = 1.25;
  static constexpr double kOverrunTolerance = 0.2;
  static constexpr int kMaxReplans = 4;
  // A refinement frame of one sample that still costs more than the budget is drawn in bands
  // (one per pass of the event loop, vtkAnisoAccumulationPass), at most this many.
  static constexpr int kMaxBands = 16;
  static constexpr double kUnmeasuredMargin = 2.0;
  // A still frame with nothing measured since the shading changed (a new mesh, maps, method) is
  // drawn in one band per this many triangles of the surface (at most kMaxBands): a render
  // costs about in proportion to its triangles on a software rasteriser (llvmpipe on the
  // development machine: some 140 ms for 320 000), and a band draws only the triangles in its
  // rows.
  static constexpr long long kTrianglesPerBand = 40000;

  SceneView(SceneModel* model, SceneAssets* assets, LutScheduler* luts, vtkRenderWindow* window,
            QObject* parent = nullptr);
  ~SceneView() override;

  vtkOpenGLRenderer* renderer() const;
  // Everything renderOffscreen needs to redraw the current view at WIDTH x HEIGHT with the full
  // quality (the target sample count).
  RenderSettings renderSettings(int width, int height) const;

  // Frames the current mesh from the default direction and forgets any stored camera.
  void resetCamera();
  // The window's camera as the model stores it.
  CameraState currentCamera() const;

  int accumulatedSamples() const;
  // Samples per pixel the still view accumulates: target-samples, or with quality-mode error
  // the fewest whose predicted error (quality()) meets error-target; rounded up to whole frames
  // of the material's samples.
  int targetSamples() const;
  // The quality of the still view by the error model of the material's lobe and filtering
  // (adaptive_quality.h): the total it asks for and that total's predicted error.
  QualityChoice quality() const;
  // Still, the target reached and on screen, and no frame asked for.
  bool converged() const;
  bool interacting() const { return interacting_; }
  // Triangles of what the view draws now: the surface, or while things move the surface's
  // stand-in when it has one (SceneAssets::interactiveSurface, LevelOfDetail.h).
  long long drawnTriangles() const;
  // The surface in the drawing frame (DrawingFrame.h) as drawn when still, never the stand-in
  // (the comparison window draws it).
  vtkPolyData* drawnSurface() const;
  // What the view draws now: the stand-in while things move (when the surface has one), else
  // drawnSurface(). Views of other models (lit, LEADR, microstructure) follow it, swapping their
  // mapper's input on interactionChanged.
  vtkPolyData* surfaceToDraw() const;
  void setSettleMs(int ms);
  // The longest a progressive frame should keep the UI thread (the window's render of it), by
  // which the samples per frame of a still view's refinement are chosen (frame_budget.h): at most
  // the material's samples, fewer when frames of that many would take longer, the run's total
  // unchanged. 0: frames of the material's samples whatever they cost.
  void setFrameBudgetMs(int ms);
  int frameBudgetMs() const { return frameBudgetMs_; }
  // Samples per pixel of each frame of the current refinement run.
  int frameSamples() const;
  // Bands each frame of the current refinement run is drawn in (1 while things move).
  int frameBands() const;
  // The cost model fitted to the frames of the window's current size drawn since the shading
  // last changed (a frame drawn in bands costing its bands together). With ANY_SIZE, to the frames
  // of every size: a guess for a size not measured yet (costs per pixel of smaller frames are
  // higher, so it errs on the side of cheaper frames).
  FrameCostModel frameCost(bool anySize = false) const;
  // True from a change of the environment or cube size until its lighting is on screen (or
  // its bake failed).
  bool lightingBusy() const
  {
    return lightingInFlight_ || lightingPending_ || nextLighting_ != nullptr;
  }
  // The lighting the view draws with.
  const std::shared_ptr<EnvironmentLighting>& lighting() const { return lighting_; }

public slots:
  // One frame soon (several requests before it make one frame).
  void requestRender();

signals:
  // A frame reached the screen, SAMPLES of targetSamples per pixel accumulated.
  void frameRendered(int samples, int targetSamples);
  void errorOccurred(const QString& message);
  void noteAdded(const QString& note);
  void lightingBusyChanged(bool busy);
  // Something started moving (cheap frames from now on) or settled (refinement).
  void interactionChanged(bool interacting);

private:
  void modelChanged(const QString& key);
  void applySurface();
  // The mapper's input: the stand-in while things move (when there is one), else the surface.
  void showDrawnSurface();
  void applyLighting();
  // Bakes the model's environment at its cube size on the worker (one bake at a time; a request
  // made meanwhile runs next, and the finished stale one is dropped).
  void requestLighting();
  void startLightingBake();
  void lightingBaked(int id, std::shared_ptr<EnvironmentLighting> lighting, bool sampled,
                     const QString& error);
  // Uploads LIGHTING's textures into the window's context (no drawing); false when it failed
  // (reported).
  bool uploadLighting(EnvironmentLighting& lighting, bool sampled);
  // Puts the uploaded nextLighting_ on screen with a cheap frame.
  void showLighting(int id);
  // lightingBusyChanged(false) once no lighting is baked or waiting to be shown.
  void updateLightingBusy();
  // Errors of the renderer (VTK's error output while drawing, glGetError after a frame), each
  // distinct message reported once.
  void reportRenderError(const std::string& message);
  void applyMaterial();
  void applyDisplay();
  void applyCameraFromModel();
  void renderNow();
  // Shows what the window drew last (a hidden frame's mean), without drawing.
  void presentFrame();
  // Window render start and end, the surface's draw in between: a frame's cost.
  void frameEvent(vtkObject* caller, unsigned long event);
  // The samples per frame of a still run and the bands its frames are drawn in (the frame
  // budget's choice).
  FramePlan planRun() const;
  // The budget a plan with the cost model COST meets: the frame budget less the load margin.
  double planBudgetSeconds(const FrameCostModel& cost) const;
  void beginInteraction();
  void settle();

  SceneModel* model_;
  SceneAssets* assets_;
  LutScheduler* luts_;
  vtkRenderWindow* window_;
  vtkNew<vtkOpenGLRenderer> renderer_;
  vtkNew<vtkActor> actor_;
  vtkNew<vtkOpenGLPolyDataMapper> mapper_;
  vtkNew<vtkRenderStepsPass> steps_;
  vtkNew<vtkAnisoAccumulationPass> pass_;
  vtkNew<vtkCallbackCommand> interactionObserver_;
  std::shared_ptr<EnvironmentLighting> lighting_;
  std::unique_ptr<AnisoMaterial> material_;
  MaterialSettings full_; // what the model asks for, LUT inputs held back until baked
  // The surface is drawn in the frame of its unit bounding sphere (DrawingFrame.h), so the
  // renderer's camera lives there too; the model's camera stays in the mesh's coordinates.
  DrawingFrame drawing_;
  vtkSmartPointer<vtkPolyData> surface_;      // in the mesh's coordinates, for offscreen renders
  vtkSmartPointer<vtkPolyData> drawnSurface_; // the surface in the drawing frame
  vtkSmartPointer<vtkPolyData> drawnInteractive_; // its stand-in while moving, or null
  QTimer* settle_;
  QTimer* frame_;
  bool interacting_ = false;
  bool applyingCamera_ = false;
  bool cameraMoved_ = false;
  int frameBudgetMs_ = kDefaultFrameBudgetMs;
  // Frame costs since the shading last changed (window render time of the renders that drew
  // the surface, a frame's bands together), a running mean per window size (pixels) and sample
  // count; the samples per frame of the current run, and how often that run was re-planned after
  // its first frame.
  struct FrameCost
  {
    double seconds = 0.0;
    int frames = 0; // measured
  };
  std::map<std::pair<long long, int>, FrameCost> frameCosts_;
  int runSamples_ = 1;
  int runReplans_ = 0;
  // Measured / predicted cost of the latest frames (the load margin's input), and the UI-thread
  // time of the last frame.
  std::vector<double> loadRatios_;
  double lastFrameSeconds_ = 0.0;
  vtkNew<vtkCallbackCommand> frameTiming_;
  qint64 frameStartNs_ = -1;
  bool frameDrewSurface_ = false;
  bool frameDrewStandIn_ = false; // the render drew the stand-in: its cost is not learnt
  int frameDrawnSamples_ = 1;
  int frameDrawnBands_ = 1;
  int frameDrawnBand_ = 0;
  double frameBandSeconds_ = 0.0; // the bands of the frame in progress so far
  // The lighting on screen has its environment-sampling distribution (baked on the worker).
  bool lightingSampled_ = false;
  QElapsedTimer presentClock_;  // since a frame last reached the screen
  bool presentPending_ = false; // presentFrame is queued
  QThreadPool* lightingPool_;
  int lightingRequest_ = 0; // sequence number of the latest lighting request
  bool lightingInFlight_ = false;
  bool lightingPending_ = false;   // a request arrived while a bake ran
  bool lightingBusyShown_ = false; // lightingBusyChanged(true) was the last sent
  // A baked lighting whose textures are uploaded, shown by the next pass of the event loop.
  std::shared_ptr<EnvironmentLighting> nextLighting_;
  bool nextLightingSampled_ = false;
  int nextLightingId_ = 0;
  bool contextReady_ = false; // the window has drawn once: its GL context exists
  QElapsedTimer clock_;
  std::set<std::string> reportedRenderErrors_;
  bool maxTextureSideKnown_ = false;
  vtkSmartPointer<ErrorForwardingWindow> errorOutput_;
};
} // namespace aniso
