#include "app/gui/SceneView.h"

#include "app/gui/RenderTimer.h"
#include "app/gui/SceneAssets.h"
#include "app/gui/ViewCamera.h"
#include "core/error.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"

#include <QTimer>
#include <algorithm>
#include <functional>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkInteractorObserver.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyData.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtk_glew.h> // before any other GL header

namespace aniso
{
namespace
{
bool isMaterialKey(const std::string& key)
{
  return sceneKeyAffects(key, Affects::Uniforms | Affects::Variant | Affects::Luts);
}

bool isDisplayKey(const std::string& key)
{
  return sceneKeyAffects(key, Affects::Display);
}

// Keys that leave the cost of a frame as it was: the measured frame costs stay valid.
bool keepsFrameCost(const std::string& key)
{
  return isSceneKey(key) && !sceneKeyAffects(key, Affects::FrameCost);
}

bool needsLuts(const MaterialSettings& s)
{
  return s.method == SpecularMethod::SplitSum || s.halfVectors == HalfVectorSource::Lut;
}
} // namespace

SceneView::SceneView(SceneModel* model, SceneAssets* assets, LutScheduler* luts,
                     vtkRenderWindow* window, QObject* parent)
    : QObject(parent), model_(model), assets_(assets), luts_(luts), window_(window),
      settle_(new QTimer(this)), frame_(new QTimer(this)),
      errors_(
          [this](const std::string& message)
          {
            // Queued: never re-enter the window from inside its own rendering.
            QMetaObject::invokeMethod(
                this, [this, message] { emit errorOccurred(QString::fromStdString(message)); },
                Qt::QueuedConnection);
          }),
      lightingLoader_(new LightingLoader(model, assets, window, &errors_, this))
{
  mapper_->ScalarVisibilityOff();
  actor_->SetMapper(mapper_);
  renderer_->AddActor(actor_);
  pass_->SetDelegatePass(steps_);
  renderer_->SetPass(pass_);
  window_->AddRenderer(renderer_);

  settle_->setObjectName("settle");
  frame_->setObjectName("frame");
  settle_->setSingleShot(true);
  settle_->setInterval(kDefaultSettleMs);
  connect(settle_, &QTimer::timeout, this, &SceneView::settle);
  frame_->setSingleShot(true);
  frame_->setInterval(0);
  connect(frame_, &QTimer::timeout, this, &SceneView::renderNow);

  // Camera interaction (rotate, zoom, pan): cheap frames while it lasts.
  interactionObserver_->SetClientData(this);
  interactionObserver_->SetCallback(
      [](vtkObject*, unsigned long event, void* self, void*)
      {
        auto* view = static_cast<SceneView*>(self);
        if (event == vtkCommand::StartInteractionEvent)
        {
          view->beginInteraction();
        }
        else if (event == vtkCommand::InteractionEvent)
        {
          view->cameraMoved_ = true;
          view->settle_->start();
        }
        else if (event == vtkCommand::EndInteractionEvent)
        {
          view->settle_->start();
        }
      });
  if (vtkRenderWindowInteractor* interactor = window_->GetInteractor())
  {
    if (vtkInteractorObserver* style = interactor->GetInteractorStyle())
    {
      for (unsigned long event : {vtkCommand::StartInteractionEvent, vtkCommand::InteractionEvent,
                                  vtkCommand::EndInteractionEvent})
      {
        style->AddObserver(event, interactionObserver_);
      }
    }
  }

  // Every frame the window draws is timed (progressive ones and the interactor's own); those
  // that drew the surface are what the frame budget learns from.
  renderTimer_ = std::make_unique<RenderTimer>(
      window_, mapper_, &planner_,
      [this](MeasuredRender& drawn)
      {
        drawn.standIn = drawnInteractive_ && mapper_->GetInput() == drawnInteractive_;
        drawn.samples = material_ ? material_->settings().samples : 1;
        drawn.bands = pass_->GetCurrentFrameBands();
        drawn.band = pass_->GetNextBand(); // the band being drawn (counted up after it)
      },
      // Only refinement frames after a run's first measure the load: the first after a resize
      // or a new shader variant also pays for those once, which says nothing of the load.
      [this](MeasuredRender& drawn)
      { drawn.measuresLoad = !interacting_ && pass_->GetAccumulatedFrames() > 1; });

  connect(model_, &SceneModel::valueChanged, this, &SceneView::modelChanged);
  connect(model_, &SceneModel::cameraChanged, this, &SceneView::applyCameraFromModel);
  connect(luts_, &LutScheduler::lutsReady, this, [this] { applyMaterial(); });
  connect(lightingLoader_, &LightingLoader::shown, this, &SceneView::lightingShown);
  connect(lightingLoader_, &LightingLoader::busyChanged, this, &SceneView::lightingBusyChanged);
  connect(lightingLoader_, &LightingLoader::failed, this, &SceneView::errorOccurred);

  lightingLoader_->loadNow();
  pass_->SetLighting(lighting());
  applySurface();
  applyDisplay();
  material_ = std::make_unique<AnisoMaterial>(lighting());
  applyMaterial();
  material_->apply(actor_, renderer_);
  luts_->requestNow();
  requestRender();
}

SceneView::~SceneView()
{
  // A bake in flight ends first; its upload and showing (queued) die with the loader.
  delete lightingLoader_;
  if (vtkRenderWindowInteractor* interactor = window_->GetInteractor())
  {
    if (vtkInteractorObserver* style = interactor->GetInteractorStyle())
    {
      style->RemoveObserver(interactionObserver_);
    }
  }
  renderTimer_.reset();
  material_.reset();
  window_->RemoveRenderer(renderer_);
}

void SceneView::attempt(const std::function<void()>& action)
{
  try
  {
    action();
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromStdString(e.what()));
  }
}

vtkOpenGLRenderer* SceneView::renderer() const
{
  return renderer_;
}

void SceneView::setSettleMs(int ms)
{
  settle_->setInterval(ms);
}

void SceneView::setFrameBudgetMs(int ms)
{
  planner_.setBudgetMs(ms);
  attempt([this] { applyMaterial(); });
  requestRender();
}

long long SceneView::windowPixels() const
{
  const int* size = window_->GetSize();
  return static_cast<long long>(size[0]) * size[1];
}

FrameCostModel SceneView::frameCost(bool anySize) const
{
  return planner_.cost(windowPixels(), anySize);
}

int SceneView::frameSamples() const
{
  return interacting_ ? std::min(full_.samples, kInteractiveSamples) : planner_.runSamples();
}

int SceneView::frameBands() const
{
  return interacting_ ? 1 : pass_->GetFrameBands();
}

RunShape SceneView::runShape() const
{
  RunShape shape;
  shape.total = targetSamples();
  shape.pixels = windowPixels();
  shape.materialSamples = full_.samples;
  shape.triangles = drawnSurface_ ? drawnSurface_->GetNumberOfPolys() : 0;
  return shape;
}

void SceneView::modelChanged(const QString& qkey)
{
  const std::string key = qkey.toStdString();
  try
  {
    if (key == "mesh" || key == "tangents")
    {
      applySurface();
    }
    else if (key == "env" || key == "cube-size")
    {
      lightingLoader_->request();
    }
    else if (key == "env-sampling" &&
             parseEnvironmentSampling(model_->text("env-sampling")) != EnvironmentSampling::Off &&
             !lightingSampled())
    {
      // The distribution is baked with a new lighting on the worker; until it is on screen the
      // material keeps sampling only its lobe.
      lightingLoader_->request();
    }
    if (!keepsFrameCost(key))
    {
      planner_.forgetCosts();
    }
    else if (key == "env-rotation")
    {
      lighting()->setRotationDegrees(model_->real("env-rotation"));
    }
    else if (isDisplayKey(key))
    {
      // Exposure and tone mapping apply to the accumulated image: no new frames needed.
      applyDisplay();
    }
    const bool qualityKey =
        key == "target-samples" || key == "quality-mode" || key == "error-target";
    if (!isDisplayKey(key) && !qualityKey)
    {
      beginInteraction();
    }
    if (isMaterialKey(key) || qualityKey || key == "env-sampling")
    {
      applyMaterial();
    }
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromStdString(e.what()));
  }
  requestRender();
}

void SceneView::applySurface()
{
  const std::string& mesh = model_->text("mesh");
  const std::string& tangents = model_->text("tangents");
  const std::shared_ptr<const PreparedSurface> surface = assets_->surface(mesh, tangents);
  surface_ = surface->polyData;
  drawing_ = drawingFrameOf(surface_);
  drawnSurface_ = inDrawingFrame(surface_, drawing_);
  // The stand-in in the surface's own drawing frame: the view does not jump when it is swapped.
  const vtkSmartPointer<vtkPolyData> standIn = assets_->interactiveSurface(mesh, tangents);
  drawnInteractive_ = standIn ? inDrawingFrame(standIn, drawing_) : nullptr;
  showDrawnSurface();
  setDrawingFrame(actor_, drawing_);
  for (const std::string& note : assets_->surfaceNotes(mesh, tangents))
  {
    emit noteAdded(QString::fromStdString(note));
  }
  if (model_->camera().set)
  {
    applyCameraFromModel();
  }
  else
  {
    resetCamera();
  }
}

vtkPolyData* SceneView::surfaceToDraw() const
{
  return interacting_ && drawnInteractive_ ? drawnInteractive_ : drawnSurface_;
}

void SceneView::showDrawnSurface()
{
  vtkPolyData* drawn = surfaceToDraw();
  if (drawn && mapper_->GetInput() != drawn)
  {
    // A new input: the mapper builds its buffers for it in the next render (a few ms even for
    // the largest surfaces; both stay in memory, so swapping reads nothing).
    mapper_->SetInputData(drawn);
  }
}

vtkPolyData* SceneView::drawnSurface() const
{
  return drawnSurface_;
}

long long SceneView::drawnTriangles() const
{
  vtkPolyData* drawn = vtkPolyData::SafeDownCast(mapper_->GetInput());
  return drawn ? static_cast<long long>(drawn->GetNumberOfPolys()) : 0;
}

void SceneView::lightingShown()
{
  pass_->SetLighting(lighting());
  material_->setLighting(lighting());
  // Frames with another lighting (and with environment sampling, another shader variant) cost
  // what they cost: measured anew.
  planner_.forgetCosts();
  // The first frame compiles the new variant: drawn as cheaply as while moving, refinement
  // under the frame budget once settled.
  beginInteraction();
  // Environment sampling held back for want of the distribution can start now.
  attempt([this] { applyMaterial(); });
  requestRender();
}

void SceneView::applyMaterial()
{
  if (!material_)
  {
    return;
  }
  MaterialSettings wanted = materialFromParameters(model_->parameters(), full_);
  assets_->addMaps(*model_, wanted);
  // Tables the variant reads must be baked already (by the scheduler, off the UI thread).
  // Until they are, a variant that needs none stays as it was, or a variant that needs them
  // keeps the exponents whose tables it has.
  const LutResult& ready = luts_->current();
  const bool baked = ready.halfVector && ready.request.lobe.nu == wanted.lobe.nu &&
                     ready.request.lobe.nv == wanted.lobe.nv &&
                     ready.request.size == wanted.lutSize &&
                     ready.request.samples == wanted.brdfLutSamples;
  if (needsLuts(wanted) && !baked)
  {
    if (needsLuts(full_))
    {
      wanted.lobe = full_.lobe;
      wanted.lutSize = full_.lutSize;
      wanted.brdfLutSamples = full_.brdfLutSamples;
    }
    else
    {
      wanted.method = full_.method;
      wanted.halfVectors = full_.halfVectors;
    }
  }
  if (wanted.environmentSampling != EnvironmentSampling::Off && !lightingSampled())
  {
    // Its distribution is being baked on the worker (LightingLoader); the lobe alone until then.
    wanted.environmentSampling = EnvironmentSampling::Off;
  }
  full_ = wanted;
  MaterialSettings shown = full_;
  int frames = 1;
  if (interacting_)
  {
    shown.samples = std::min(shown.samples, kInteractiveSamples);
    // Shown as drawn: whole frames.
    pass_->SetFrameBands(1);
  }
  else
  {
    const FramePlan plan = planner_.plan(runShape());
    if (planner_.beginRun(plan))
    {
      // Frames of another sample count: the run starts over, every frame with the same weight.
      pass_->Reset();
    }
    shown.samples = planner_.runSamples();
    frames = targetSamples() / planner_.runSamples();
    // Bands split a frame's drawing, not its samples: the mean is the same, so no restart (the
    // frame in progress keeps its bands).
    pass_->SetFrameBands(plan.bands);
  }
  // The scheduler's tables as its worker delivered them: nothing is read or baked here, even
  // when the cache has dropped them from memory since.
  material_->setSettings(shown, ready.halfVector, ready.brdf);
  pass_->SetTargetFrames(std::max(frames, 1));
  if (material_->mapsDropped())
  {
    emit noteAdded(tr("The mesh has no texture coordinates: its maps are not used."));
  }
}

void SceneView::applyDisplay()
{
  pass_->SetDisplaySettings(displayFromParameters(model_->parameters()));
}

void SceneView::applyCameraFromModel()
{
  const CameraState& c = model_->camera();
  if (!c.set || applyingCamera_)
  {
    if (!c.set && !applyingCamera_)
    {
      resetCamera();
    }
    return;
  }
  setCameraState(renderer_->GetActiveCamera(), c, drawing_);
  renderer_->ResetCameraClippingRange();
  requestRender();
}

void SceneView::resetCamera()
{
  const int* size = window_->GetSize();
  applyCamera(renderer_, defaultPlacement(size[0], size[1]));
  applyingCamera_ = true;
  model_->setCamera(CameraState{});
  applyingCamera_ = false;
  requestRender();
}

CameraState SceneView::currentCamera() const
{
  return cameraStateOf(renderer_->GetActiveCamera(), drawing_);
}

RenderSettings SceneView::renderSettings(int width, int height) const
{
  RenderSettings s;
  s.surface = surface_;
  s.environment = assets_->environment(model_->text("env"));
  s.cubeSize = model_->integer("cube-size");
  s.environmentRotationDegrees = model_->real("env-rotation");
  s.material = full_;
  s.display = displayFromParameters(model_->parameters());
  s.camera = placementOf(currentCamera());
  s.width = width;
  s.height = height;
  s.frames = targetSamples() / full_.samples;
  return s;
}

int SceneView::accumulatedSamples() const
{
  return pass_->GetAccumulatedFrames() * frameSamples();
}

QualityChoice SceneView::quality() const
{
  if (parseQualityMode(model_->text("quality-mode")) == QualityMode::Error)
  {
    // The largest total the samples mode allows bounds this one too.
    const int most = static_cast<int>(parameterSpec("target-samples").maximum);
    return chooseSamples(model_->real("error-target"), full_.lobe, full_.filtered, most);
  }
  QualityChoice choice;
  choice.samples = model_->integer("target-samples");
  choice.predictedError = predictedError(full_.lobe, full_.filtered, choice.samples);
  return choice;
}

int SceneView::targetSamples() const
{
  return runTotalSamples(quality().samples, full_.samples);
}

bool SceneView::converged() const
{
  // A frame asked for may find the mean stale (the window's size changed since the last one,
  // which the pass learns only as it draws): not converged until it is drawn.
  return !interacting_ && !lightingBusy() && pass_->IsConverged() && !presentPending_ &&
         !frame_->isActive();
}

void SceneView::requestRender()
{
  if (!frame_->isActive())
  {
    frame_->start();
  }
}

void SceneView::renderNow()
{
  frame_->setInterval(0);
  // With a frame budget a refinement frame goes into the mean without reaching the screen:
  // showing a frame (the widget's copy, the window's composition and buffer swap) costs about
  // as much as drawing one of few samples. The mean is shown by a step of its own
  // (presentFrame) after the first frame of a run, every kPresentIntervalMs and after the last,
  // so the two costs never add up in one stall. Frames while things move are shown as drawn.
  const bool hide = planner_.budgetMs() > 0 && !interacting_ && !pass_->IsConverged();
  errors_.beginDrawing();
  const bool swap = window_->GetSwapBuffers() != 0;
  if (hide)
  {
    window_->SwapBuffersOff();
  }
  window_->Render();
  if (hide && swap)
  {
    window_->SwapBuffersOn();
  }
  errors_.endDrawing();
  if (!hide)
  {
    presentClock_.start();
  }
  else if (!presentPending_ && pass_->GetNextBand() == 0 &&
           (pass_->GetAccumulatedFrames() <= 1 || pass_->IsConverged() ||
            !presentClock_.isValid() || presentClock_.elapsed() >= kPresentIntervalMs))
  {
    presentClock_.start();
    presentPending_ = true;
    QTimer::singleShot(kAfterPresentMs, this, &SceneView::presentFrame);
  }
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window_);
  if (gl && gl->IsCurrent())
  {
    lightingLoader_->setContextReady();
    if (!maxTextureSideKnown_)
    {
      // Map files the GL cannot hold are then refused before they reach the scene.
      GLint side = 0;
      glGetIntegerv(GL_MAX_TEXTURE_SIZE, &side);
      if (side > 0)
      {
        assets_->setMaxTextureSide(side);
        maxTextureSideKnown_ = true;
      }
    }
    // Errors VTK did not report itself.
    errors_.checkGlErrors();
  }
  // A refinement frame just completed (its last band drawn): the plan for the frames to come.
  const bool frameDone = pass_->GetNextBand() == 0;
  if (!interacting_ && frameDone && planner_.budgetMs() > 0 && !pass_->IsConverged())
  {
    attempt(
        [this]
        {
          const RunStep step = planner_.afterFrame(runShape(), pass_->GetAccumulatedFrames() == 1);
          if (step.replan)
          {
            // The run starts over with the corrected plan.
            applyMaterial();
            requestRender();
          }
          else
          {
            // The run's samples stay, its frames in the bands their measured cost asks for: no
            // restart.
            pass_->SetFrameBands(step.bands);
          }
        });
  }
  if (!hide)
  {
    emit frameRendered(accumulatedSamples(), targetSamples());
  }
  // Progressive refinement: one more frame once pending events are handled, so the window
  // stays responsive between frames.
  if (!interacting_ && !pass_->IsConverged())
  {
    requestRender();
  }
}

void SceneView::presentFrame()
{
  presentPending_ = false;
  // The window's last drawing (the mean after the latest hidden frame) to the screen.
  if (window_->GetSwapBuffers())
  {
    window_->MakeCurrent();
    window_->Frame();
    // The widget paints in the next pass of the event loop; the next frame waits a little, so
    // the two are not handled back to back without the events between them.
    if (frame_->isActive())
    {
      frame_->start(kAfterPresentMs);
    }
    emit frameRendered(accumulatedSamples(), targetSamples());
  }
}

void SceneView::beginInteraction()
{
  settle_->start();
  if (!interacting_)
  {
    interacting_ = true;
    showDrawnSurface();
    emit interactionChanged(true);
    attempt([this] { applyMaterial(); });
  }
}

void SceneView::settle()
{
  interacting_ = false;
  planner_.settled();
  showDrawnSurface();
  emit interactionChanged(false);
  if (cameraMoved_)
  {
    // The camera the user left is part of the scene (sessions save it).
    cameraMoved_ = false;
    applyingCamera_ = true;
    try
    {
      model_->setCamera(currentCamera());
    }
    catch (const Error&)
    {
      // A degenerate camera (zoomed onto its focal point) is simply not recorded.
    }
    applyingCamera_ = false;
  }
  attempt([this] { applyMaterial(); });
  requestRender();
}
} // namespace aniso
