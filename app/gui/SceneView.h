#pragma once
// Draws the scene of a SceneModel in a VTK render window with the anisotropic material, on
// demand only: a change of the model or the camera asks for one frame; while things move
// (a drag, a camera interaction) frames are cheap (one sample per pixel; the window draws them
// at reduced resolution, see interactionChanged); once still for a moment, frames accumulate
// (progressive refinement) until the quality's sample count is reached, then nothing is drawn
// until something changes. Each refinement frame takes as many of the material's samples as the
// frame budget allows by the measured cost of earlier frames (fewer frames of more samples when
// they are cheap), a count that divides the run's total, so the converged image is the same
// mean of the same number of samples: the view times its renders, a RefinementPlanner
// (refinement_planner.h) learns from them and plans. Lookup tables come from the LutScheduler's
// bakes, so a new n_u, n_v never bakes on the UI thread: until its tables are ready the material
// keeps the previous exponents. Likewise a new environment or cube size is baked (cubemap, SH9
// and, with environment sampling on, its distribution) on a worker thread by a LightingLoader:
// the latest request wins, the previous lighting stays on screen until the new one is ready, and
// a failed bake is reported once and changes nothing. Switching environment sampling on bakes a
// lighting with its distribution the same way; until it is on screen the material samples its
// lobe only. A baked lighting reaches the screen over separate passes of the event loop, so
// their costs never add up in one stall: its textures are uploaded in one, the view switches to
// it in a later one with a cheap frame (as while moving: the new shader variant compiles then),
// and refinement under the frame budget follows once settled.
#include "app/gui/LightingLoader.h"
#include "app/gui/ProgressiveReference.h"
#include "app/gui/RenderErrorOutput.h"
#include "core/quality/adaptive_quality.h"
#include "core/quality/frame_budget.h"
#include "core/quality/refinement_planner.h"
#include "scene/SceneModel.h"
#include "vtkpasses/render/DisplaySettings.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/FieldValues.h"
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <functional>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>

class QStringList;
class QTimer;
class vtkActor;
class vtkAnisoAccumulationPass;
class vtkOpenGLPolyDataMapper;
class vtkOpenGLRenderer;
class vtkRenderStepsPass;
class vtkRenderWindow;
class vtkRenderer;
class vtkScalarBarActor;
class vtkCallbackCommand;

namespace aniso
{
class AnisoMaterial;
class EnvironmentLighting;
class LutScheduler;
class RenderTimer;
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

  SceneView(SceneModel* model, SceneAssets* assets, LutScheduler* luts, vtkRenderWindow* window,
            QObject* parent = nullptr);
  ~SceneView() override;

  vtkOpenGLRenderer* renderer() const;
  // The renderer drawn over the scene's (its layer 1, sharing its camera): the selected parts'
  // outline and the colour legends of the fields the drawn parts show (FieldValues.h), with
  // legend on, one vtkScalarBarActor a distinct array, colour map and range.
  vtkRenderer* overlay() const;

  // The scene's parts as drawn: one actor each, with its own material (the part's library
  // material over the scene's parameters). Parts whose surface did not load or prepare are
  // skipped (reported once with the file and the part) and, like hidden parts, are not in the
  // renderer at all.
  int partCount() const { return int(parts_.size()); }
  // Part I's actor (a valid index), in the renderer when the part is drawn.
  vtkActor* partActor(int part) const;
  // Part I's material (null until the part was first drawn).
  const AnisoMaterial* partMaterial(int part) const;
  // Whether part I is drawn (visible and loaded).
  bool partDrawn(int part) const;
  // Triangles of part I's surface (-1 when it did not load).
  long long partTriangles(int part) const;
  // Part I's surface in the drawing frame as drawn when still, never the stand-in (null while
  // the part is not drawn): the same polydata its actor draws once still. The comparison window
  // draws it.
  vtkPolyData* partDrawnSurface(int part) const;
  // What part I's actor draws now: its stand-in while things move (when it has one), else
  // partDrawnSurface(I). The views of other models (lit, LEADR, microstructure) draw it, one actor
  // per drawn part, following partsDrawn and interactionChanged.
  vtkPolyData* partSurfaceToDraw(int part) const;
  // The declared parameters part I is drawn with (SceneModel::partParameters: the scene's, with
  // the part's library material over the material keys).
  ParameterSet partParameters(int part) const;
  // The part drawn at display position (X, Y) (VTK's convention: origin bottom left), or -1.
  int partAt(int x, int y);
  // What a click at (X, Y) does: selects the part there (EXTEND: adds it to the selection, or
  // takes it out), or clears the selection on nothing.
  void clickedAt(int x, int y, bool extend);
  // Shows or hides the parts' actors together (the other models' views draw in their place).
  void setPartsShown(bool shown);
  bool partsShown() const { return partsShown_; }
  // The frame the visible parts are drawn in (their common bounding sphere).
  const DrawingFrame& drawingFrame() const { return drawing_; }
  // Everything renderOffscreen needs to redraw the current view at WIDTH x HEIGHT with the full
  // quality (the target sample count).
  RenderSettings renderSettings(int width, int height) const;

  // Brings the parts' surfaces in line with the model, reading on this thread what the assets
  // do not hold yet (or reporting it skipped): after a worker read them with new read options.
  void refreshSurfaces();

  // Frames the current mesh from the default direction and forgets any stored camera.
  void resetCamera();
  // Frames the current mesh from the named view NAME (viewPresets, `aniso render --view`'s
  // names), kept as the scene's camera; throws aniso::Error for an unknown name.
  void showView(const std::string& name);
  // The window's camera as the model stores it.
  CameraState currentCamera() const;

  int accumulatedSamples() const;
  // Samples per pixel the still view accumulates: target-samples rounded up to whole frames of
  // the material's samples. With quality-mode error the most it accumulates: it stops before
  // once the error estimated from its own frames (estimatedError()) is at most error-target.
  int targetSamples() const;
  // With quality-mode error: whether the view stops by the estimated error.
  bool byError() const;
  // The relative L2 error of the still view's image as estimated from its own frames (the mean
  // against the mean of its first half, core/quality/error_estimate.h) at the latest checkpoint
  // of the estimate (4, 6, 8, 12, ... frames) under quality-mode error; negative before the
  // first and in samples mode.
  double estimatedError() const;
  // The error model's prediction (adaptive_quality.h, fitted under the built-in studio) for the
  // target's samples: what the window shows before a measured estimate exists.
  QualityChoice quality() const;
  // Still, the target reached and on screen, and no frame asked for.
  bool converged() const;
  bool interacting() const { return interacting_; }
  // Triangles of what the view draws now: the surface, or while things move the surface's
  // stand-in when it has one (SceneAssets::interactiveSurface, LevelOfDetail.h).
  long long drawnTriangles() const;
  // The drawn parts' surfaces together in the drawing frame (DrawingFrame.h) as drawn when
  // still, never the stand-in (null when no part is drawn). The views of other models draw the
  // parts one by one instead (partDrawnSurface, partSurfaceToDraw).
  vtkPolyData* drawnSurface() const;
  // What the view draws now, together: the stand-ins while things move (when a part has one),
  // else drawnSurface().
  vtkPolyData* surfaceToDraw() const;
  void setSettleMs(int ms);
  // The longest a progressive frame should keep the UI thread (the window's render of it), by
  // which the samples per frame of a still view's refinement are chosen (frame_budget.h): at most
  // the material's samples, fewer when frames of that many would take longer, the run's total
  // unchanged. 0: frames of the material's samples whatever they cost.
  void setFrameBudgetMs(int ms);
  int frameBudgetMs() const { return planner_.budgetMs(); }
  // A repaint of the window around the view begins and ends (its widgets painted and the window
  // composed with the view's picture: on a software rasteriser some 10-20 ms for a large window).
  // A repaint may fall in the same pass of the event loop as a refinement render, so renders are
  // planned for the budget less what repaints cost (repaintSeconds: the latest repaint's time
  // less the view's renders during it, or the previous ones', decayed, when larger).
  void beginWindowRepaint();
  void endWindowRepaint();
  double repaintSeconds() const { return repaintSeconds_; }
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
  bool lightingBusy() const { return lightingLoader_->busy(); }
  // The lighting the view draws with.
  const std::shared_ptr<EnvironmentLighting>& lighting() const
  {
    return lightingLoader_->lighting();
  }

  // The CPU reference of the view (View > Reference, app/gui/ReferenceView.h). Why it does not
  // cover what the view draws now, or empty: another shading model than the anisotropic
  // environment material, a drawn part with maps or a data field (referenceMaterialOf), a line
  // part, or no part drawn.
  std::string referenceUnsupported() const;
  // What it integrates (ReferenceInputs): the drawn parts' surfaces as their actors draw them when
  // still (in the drawing frame, never the stand-in), each triangle with its part's material as
  // drawn, the camera without the accumulation's jitter (the pass restores it after each frame),
  // the lighting's environment on screen (kept alive by the inputs) and its rotation, the window's
  // size in pixels. Throws aniso::Error "reference: WHY" with referenceUnsupported()'s reason.
  ReferenceInputs referenceInputs() const;
  // What referenceInputs depends on, without copying a triangle: equal keys, equal inputs.
  struct ReferenceKey
  {
    int width = 0;
    int height = 0;
    glm::dmat4 clipToWorld{1.0};
    glm::dmat3 worldToEnvironment{1.0};
    const Environment* environment = nullptr;
    struct Part
    {
      const vtkPolyData* surface = nullptr;
      vtkMTimeType time = 0;
      ReferenceMaterial material;
    };
    std::vector<Part> parts;
    std::string unsupported;
    bool operator==(const ReferenceKey& o) const;
    bool operator!=(const ReferenceKey& o) const { return !(*this == o); }
  };
  ReferenceKey referenceKey() const;
  // The view's running mean (linear RGBA, row 0 at the top; the accumulation pass's
  // ReadAccumulation), empty before the first frame.
  Image linearImage();

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
  // The drawn parts changed (a part added, removed, shown, hidden, or its surface replaced), or
  // the drawing frame with them: the views of other models take the parts' surfaces anew.
  void partsDrawn();
  // Parts whose file is read anew with other read options (a STEP or IGES file's tessellation,
  // SceneAssets::readOptionsKey) keep their previous surfaces, since the assets do not hold the
  // new ones: those are to be read (on a worker), then refreshSurfaces().
  void surfacesOutdated();

private:
  void modelChanged(const QString& key);
  // Brings the part actors in line with the model's parts (surfaces loaded for new meshes,
  // blocks, tangents, placements or read options (unless only those changed and the assets do
  // not hold the surface: surfacesOutdated), visibility); returns whether what is drawn changed.
  bool syncParts();
  // A library material's values of the keys that change what a frame costs
  // (Affects::FrameCost); none for a material not in the library.
  Material::Values frameCostValues(const std::string& material) const;
  // Whether any of the named materials that parts were drawn with at the last applyMaterial
  // differs in those values from what they were then.
  bool frameCostChanged(const QStringList& names) const;
  // The drawing frame, the surfaces in it and the camera after the drawn parts changed.
  void applySurfaces();
  void materialsChanged(const QStringList& names);
  // The selected parts' outline.
  void applySelection();
  // The mapper's input: the stand-in while things move (when there is one), else the surface.
  void showDrawnSurface();
  // The loader's new lighting to the pass and the material, drawn with a cheap frame.
  void lightingShown();
  // The lighting on screen has its environment-sampling distribution (baked on the worker).
  bool lightingPrepared(EnvironmentSampling sampling) const
  {
    return lightingLoader_->prepared(sampling);
  }
  // Runs ACTION; an aniso::Error it throws is reported (errorOccurred).
  void attempt(const std::function<void()>& action);
  void applyMaterial();
  // The drawn parts' fields with an automatic range (MaterialSettings::field) take the joint
  // range of their array over the drawn parts that show it (resolveFieldRanges), in their
  // settings (PartView::full), before these reach the materials.
  void resolveFields();
  // The overlay's colour legends as the drawn parts' settings and the legend key ask.
  void applyLegends();
  void applyDisplay();
  void applyCameraFromModel();
  void renderNow();
  // Shows what the window drew last (a hidden frame's mean), without drawing.
  void presentFrame();
  // The window's pixels.
  long long windowPixels() const;
  // What the planner plans the still view's run for.
  RunShape runShape() const;
  void beginInteraction();
  void settle();

  SceneModel* model_;
  SceneAssets* assets_;
  LutScheduler* luts_;
  vtkRenderWindow* window_;
  vtkNew<vtkOpenGLRenderer> renderer_;
  struct PartView;
  std::vector<std::unique_ptr<PartView>> parts_; // parallel to the model's parts
  // frameCostValues of the parts' materials at the last applyMaterial.
  std::map<std::string, Material::Values> drawnFrameCostValues_;
  bool partsShown_ = true;
  // The selected parts' bounding boxes, drawn by a renderer of their own over the scene's (its
  // layer 1, sharing its camera): selecting a part leaves the accumulated image as it is.
  vtkNew<vtkRenderer> overlay_;
  vtkNew<vtkActor> outline_;
  // The fields' colour legends in the overlay, and what they show.
  std::vector<FieldLegend> legends_;
  std::vector<vtkSmartPointer<vtkScalarBarActor>> legendActors_;
  // The last resolution of automatic field ranges (resolveFields), one entry a drawn part that
  // shows a field, in part order.
  struct ResolvedField
  {
    vtkPolyData* surface = nullptr;
    vtkMTimeType surfaceTime = 0;
    FieldSpec spec;
    bool automatic = true;
    FieldRange range; // as resolved
  };
  std::vector<ResolvedField> resolvedFields_;
  vtkNew<vtkRenderStepsPass> steps_;
  vtkNew<vtkAnisoAccumulationPass> pass_;
  vtkNew<vtkCallbackCommand> interactionObserver_;
  vtkNew<vtkCallbackCommand> clickObserver_;
  // A new window size restarts the mean (the pass learns it as the widget draws): refinement
  // resumes with a frame asked for.
  vtkNew<vtkCallbackCommand> resizeObserver_;
  int pressAt_[2] = {0, 0};
  bool pressed_ = false;
  MaterialSettings full_; // the first drawn part's settings, LUT inputs held back until baked
  // The surface is drawn in the frame of its unit bounding sphere (DrawingFrame.h), so the
  // renderer's camera lives there too; the model's camera stays in the mesh's coordinates.
  DrawingFrame drawing_;
  // The drawn parts together in the drawing frame, and their stand-ins while moving (null when
  // no part has one).
  vtkSmartPointer<vtkPolyData> drawnSurface_;
  vtkSmartPointer<vtkPolyData> drawnInteractive_;
  QTimer* settle_;
  QTimer* frame_;
  bool interacting_ = false;
  bool applyingCamera_ = false;
  bool cameraMoved_ = false;
  // Frame costs learnt, the cost model, the load margin and the run's plan.
  RefinementPlanner planner_{kDefaultFrameBudgetMs};
  double overheadSeconds_ = 0.0; // a pass of renderNow besides its render, running mean
  double repaintSeconds_ = 0.0;  // the window's repaints (endWindowRepaint)
  QElapsedTimer repaintClock_;   // since the repaint in progress began
  double renderedAtRepaint_ = 0.0; // renderTimer_'s renderedSeconds then
  // Times the window's renders for the planner.
  std::unique_ptr<RenderTimer> renderTimer_;
  QElapsedTimer presentClock_;  // since a frame last reached the screen
  bool presentPending_ = false; // presentFrame is queued
  bool maxTextureSideKnown_ = false;
  bool changedSettings_ = false; // applyMaterial gave a part other settings
  bool readNow_ = false;         // syncParts reads outdated surfaces (refreshSurfaces)
  // Errors of the renderer (VTK's error output while drawing, glGetError after a frame), each
  // distinct message reported once, queued as errorOccurred.
  RenderErrorOutput errors_;
  LightingLoader* lightingLoader_; // after errors_: its uploads report there
};
} // namespace aniso
