#include "app/gui/SceneView.h"

#include "app/gui/SceneAssets.h"
#include "core/error.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/ViewSettings.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"

#include <QThreadPool>
#include <QTimer>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <new>
#include <sstream>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkInteractorObserver.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkOutputWindow.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtk_glew.h> // before any other GL header

namespace aniso
{
// VTK's error text (a shader that does not compile, a failed GL call) and generic warnings (the
// material's failures) go to SINK while the view draws; everything goes where it went before
// too.
class ErrorForwardingWindow : public vtkOutputWindow
{
public:
  static ErrorForwardingWindow* New();
  vtkSmartPointer<vtkOutputWindow> previous;
  std::function<void(const std::string&)> sink;
  bool drawing = false;
  bool spoke = false; // something went to SINK since the flag was cleared

  void DisplayText(const char* text) override { previous->DisplayText(text); }
  void DisplayErrorText(const char* text) override
  {
    previous->DisplayErrorText(text);
    if (drawing && sink && text)
    {
      spoke = true;
      sink(text);
    }
  }
  void DisplayWarningText(const char* text) override { previous->DisplayWarningText(text); }
  void DisplayGenericWarningText(const char* text) override
  {
    previous->DisplayGenericWarningText(text);
    // The material reports what failed while drawing (a texture that could not be made) so.
    if (drawing && sink && text)
    {
      spoke = true;
      sink(text);
    }
  }
  void DisplayDebugText(const char* text) override { previous->DisplayDebugText(text); }

  vtkTypeMacro(ErrorForwardingWindow, vtkOutputWindow)
};
vtkStandardNewMacro(ErrorForwardingWindow);

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

// "ERROR: In FILE, line N\nvtkClass (0x...): what\n" -> "what": the words, not the source.
std::string plainVtkError(std::string text)
{
  if ((text.rfind("ERROR: In ", 0) == 0 || text.rfind("Generic Warning: In ", 0) == 0) &&
      text.find('\n') != std::string::npos)
  {
    text = text.substr(text.find('\n') + 1);
  }
  const std::size_t object = text.find("): ");
  if (text.rfind("vtk", 0) == 0 && object != std::string::npos)
  {
    text = text.substr(object + 3);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
  {
    text.pop_back();
  }
  return text;
}

// Default view: a three-quarter view from the front, slightly above (Z up).
glm::dvec3 defaultViewDirection()
{
  return viewDirectionFromAngles(-35.0, 25.0);
}
} // namespace

SceneView::SceneView(SceneModel* model, SceneAssets* assets, LutScheduler* luts,
                     vtkRenderWindow* window, QObject* parent)
    : QObject(parent), model_(model), assets_(assets), luts_(luts), window_(window),
      settle_(new QTimer(this)), frame_(new QTimer(this)), lightingPool_(new QThreadPool(this)),
      errorOutput_(vtkSmartPointer<ErrorForwardingWindow>::New())
{
  errorOutput_->previous = vtkOutputWindow::GetInstance();
  errorOutput_->sink = [this](const std::string& text)
  {
    const std::string plain = plainVtkError(text);
    const std::string material = "anisotropic material: ";
    // The material's messages name their subject already.
    reportRenderError(plain.rfind(material, 0) == 0 ? plain.substr(material.size())
                                                    : "OpenGL: " + plain);
  };
  vtkOutputWindow::SetInstance(errorOutput_);

  // One lighting bake at a time: a second would only compete for the cores with the first.
  lightingPool_->setMaxThreadCount(1);
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
  clock_.start();
  frameTiming_->SetClientData(this);
  frameTiming_->SetCallback([](vtkObject* caller, unsigned long event, void* self, void*)
                            { static_cast<SceneView*>(self)->frameEvent(caller, event); });
  window_->AddObserver(vtkCommand::StartEvent, frameTiming_);
  window_->AddObserver(vtkCommand::EndEvent, frameTiming_);
  mapper_->AddObserver(vtkCommand::StartEvent, frameTiming_);

  connect(model_, &SceneModel::valueChanged, this, &SceneView::modelChanged);
  connect(model_, &SceneModel::cameraChanged, this, &SceneView::applyCameraFromModel);
  connect(luts_, &LutScheduler::lutsReady, this, [this] { applyMaterial(); });

  applyLighting();
  applySurface();
  applyDisplay();
  material_ = std::make_unique<AnisoMaterial>(lighting_);
  applyMaterial();
  material_->apply(actor_, renderer_);
  luts_->requestNow();
  requestRender();
}

SceneView::~SceneView()
{
  // A bake in flight refers to this view; its queued result dies with it.
  lightingPool_->waitForDone();
  if (vtkRenderWindowInteractor* interactor = window_->GetInteractor())
  {
    if (vtkInteractorObserver* style = interactor->GetInteractorStyle())
    {
      style->RemoveObserver(interactionObserver_);
    }
  }
  window_->RemoveObserver(frameTiming_);
  mapper_->RemoveObserver(frameTiming_);
  material_.reset();
  window_->RemoveRenderer(renderer_);
  vtkOutputWindow::SetInstance(errorOutput_->previous);
}

void SceneView::reportRenderError(const std::string& message)
{
  // A failure repeats with every frame: the user hears of it once.
  if (!reportedRenderErrors_.insert(message).second)
  {
    return;
  }
  // Queued: never re-enter the window from inside its own rendering.
  QMetaObject::invokeMethod(
      this, [this, message] { emit errorOccurred(QString::fromStdString(message)); },
      Qt::QueuedConnection);
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
  frameBudgetMs_ = std::max(ms, 0);
  try
  {
    applyMaterial();
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromStdString(e.what()));
  }
  requestRender();
}

FrameCostModel SceneView::frameCost(bool anySize) const
{
  const int* size = window_->GetSize();
  const long long pixels = static_cast<long long>(size[0]) * size[1];
  // Only frames of this size (unless asked otherwise): a frame also has costs that do not grow
  // with its pixels, so costs per pixel of other sizes would mislead.
  std::vector<FrameCostSample> measured;
  for (const auto& [key, cost] : frameCosts_)
  {
    if (anySize || key.first == pixels)
    {
      measured.push_back({key.second, static_cast<double>(key.first), cost.seconds});
    }
  }
  return fitFrameCost(measured);
}

int SceneView::frameSamples() const
{
  return interacting_ ? std::min(full_.samples, kInteractiveSamples) : runSamples_;
}

int SceneView::frameBands() const
{
  return interacting_ ? 1 : pass_->GetFrameBands();
}

FramePlan SceneView::planRun() const
{
  const int total = targetSamples();
  if (frameBudgetMs_ <= 0)
  {
    return {full_.samples, 1};
  }
  const int* size = window_->GetSize();
  const long long pixels = static_cast<long long>(size[0]) * size[1];
  const FrameCostModel cost = frameCost();
  if (!cost.known)
  {
    // Nothing measured at this size (the first still frame after moving at half resolution): a
    // first frame as cheap as can be, which measures it, in bands as the costs of the other sizes
    // suggest (costs per pixel of smaller frames are higher: it errs on the side of more bands).
    const FrameCostModel guess = frameCost(true);
    if (!guess.known)
    {
      // Nothing measured at any size: bands by the surface's triangles.
      const long long triangles = drawnSurface_ ? drawnSurface_->GetNumberOfPolys() : 0;
      const long long bands = (triangles + kTrianglesPerBand - 1) / kTrianglesPerBand;
      return {1, static_cast<int>(std::clamp<long long>(bands, 1, kMaxBands))};
    }
    return {1, chooseFrameBands(guess, 1, double(pixels), planBudgetSeconds(guess), kMaxBands)};
  }
  int largestMeasured = 1;
  for (const auto& entry : frameCosts_)
  {
    if (entry.first.first == pixels)
    {
      largestMeasured = std::max(largestMeasured, entry.first.second);
    }
  }
  if (!cost.separated && largestMeasured != 1)
  {
    // One sample count measured, more than 1: a frame of 1 (the cheapest) tells the fixed cost
    // from the samples'.
    return {1, chooseFrameBands(cost, 1, double(pixels), planBudgetSeconds(cost), kMaxBands)};
  }
  // A fit from few, noisy renders is trusted up to 4 times the largest count measured (with one
  // count, 1, measured: its assumed split overestimates the cost of more samples, so a plan of up
  // to 4 stays within the budget and measures the split); a count beyond is reached over later
  // runs, each measuring the way there. Below the material's count, a divisor of the run's total.
  const int reach = 4 * largestMeasured;
  const int most = reach >= full_.samples ? full_.samples : largestDivisorAtMost(total, reach);
  FramePlan plan =
      chooseFramePlan(cost, double(pixels), planBudgetSeconds(cost), most, total, kMaxBands);
  if (frameCosts_.count(std::make_pair(pixels, plan.samples)) == 0)
  {
    // A count never measured at this size is extrapolated: its first frame is cut in bands for
    // kUnmeasuredMargin times the predicted cost; the bands are re-planned from what it measured
    // once it is complete.
    plan.bands = chooseFrameBands(cost, plan.samples, double(pixels),
                                  planBudgetSeconds(cost) / kUnmeasuredMargin, kMaxBands);
  }
  return plan;
}

double SceneView::planBudgetSeconds(const FrameCostModel& cost) const
{
  // Planned for the machine as it ran the latest frames (the fit follows a change of load only
  // over several frames), except while the parts are not yet told apart: a margin on the
  // pessimistic split would keep every frame at 1 sample and the split unknown.
  return frameBudgetMs_ * 1e-3 / (cost.separated ? loadMargin(loadRatios_, kMaxLoadMargin) : 1.0);
}

void SceneView::frameEvent(vtkObject* caller, unsigned long event)
{
  if (caller == window_ && event == vtkCommand::StartEvent)
  {
    frameStartNs_ = clock_.nsecsElapsed();
    frameDrewSurface_ = false;
    lastFrameSeconds_ = 0.0;
    return;
  }
  if (caller != window_)
  {
    // The surface's mapper starts drawing: this render adds (a band of) a frame to the mean.
    frameDrewSurface_ = true;
    frameDrewStandIn_ = drawnInteractive_ && mapper_->GetInput() == drawnInteractive_;
    frameDrawnSamples_ = material_ ? material_->settings().samples : 1;
    frameDrawnBands_ = pass_->GetCurrentFrameBands();
    frameDrawnBand_ = pass_->GetNextBand(); // the band being drawn (counted up after it)
    return;
  }
  if (frameStartNs_ < 0)
  {
    return;
  }
  if (frameDrewSurface_)
  {
    // The GL may still be drawing what it was given (a software rasteriser works on its own
    // threads until something needs the result): the render is measured, and its cost paid,
    // here, not in whichever later call waits for it.
    glFinish();
  }
  const double seconds = double(clock_.nsecsElapsed() - frameStartNs_) * 1e-9;
  frameStartNs_ = -1;
  if (!frameDrewSurface_)
  {
    return; // a converged view shown again, or nothing to draw
  }
  lastFrameSeconds_ = seconds;
  const int* size = window_->GetSize();
  const long long pixels = static_cast<long long>(size[0]) * size[1];
  // How far the fit was off for this render, before it learns from it: the load margin (a band
  // predicted as its share of the frame). Only refinement frames after a run's first: the first
  // after a resize or a new shader variant also pays for those once, which says nothing of the
  // load.
  const FrameCostModel before = frameCost();
  if (before.known && !interacting_ && pass_->GetAccumulatedFrames() > 1)
  {
    const double predicted =
        before.predictSeconds(frameDrawnSamples_, double(pixels)) / frameDrawnBands_;
    if (predicted > 0.0)
    {
      loadRatios_.push_back(seconds / predicted);
      if (loadRatios_.size() > std::size_t(kLoadFrames))
      {
        loadRatios_.erase(loadRatios_.begin());
      }
    }
  }
  if (frameDrewStandIn_)
  {
    return; // the stand-in's cost says nothing of the surface's
  }
  // What the model learns is the cost of whole frames: a frame drawn in bands costs its bands
  // together (bands differ from one another as the surface does across the rows; together they
  // are the frame). A frame whose bands were interrupted (the view changed) is not counted.
  frameBandSeconds_ = frameDrawnBand_ == 0 ? seconds : frameBandSeconds_ + seconds;
  if (frameDrawnBand_ != frameDrawnBands_ - 1)
  {
    return;
  }
  // A running mean that follows the view (how much of it the surface covers) within a few
  // frames. The first frame of a size and sample count may also have paid for things done once
  // (the targets' allocation at a new size, a new shader variant's compilation): the second
  // replaces it.
  FrameCost& cost = frameCosts_[std::make_pair(pixels, frameDrawnSamples_)];
  cost.seconds = cost.frames < 2 ? frameBandSeconds_ : 0.7 * cost.seconds + 0.3 * frameBandSeconds_;
  ++cost.frames;
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
      requestLighting();
    }
    else if (key == "env-sampling" &&
             parseEnvironmentSampling(model_->text("env-sampling")) != EnvironmentSampling::Off &&
             !lightingSampled_)
    {
      // The distribution is baked with a new lighting on the worker; until it is on screen the
      // material keeps sampling only its lobe.
      requestLighting();
    }
    if (!keepsFrameCost(key))
    {
      frameCosts_.clear();
    }
    else if (key == "env-rotation")
    {
      lighting_->setRotationDegrees(model_->real("env-rotation"));
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

void SceneView::applyLighting()
{
  lighting_ = std::make_shared<EnvironmentLighting>(assets_->environment(model_->text("env")),
                                                    model_->integer("cube-size"));
  lighting_->setRotationDegrees(model_->real("env-rotation"));
  pass_->SetLighting(lighting_);
}

void SceneView::requestLighting()
{
  ++lightingRequest_;
  if (lightingInFlight_)
  {
    lightingPending_ = true;
  }
  else
  {
    startLightingBake();
  }
  if (lightingBusy() && !lightingBusyShown_)
  {
    lightingBusyShown_ = true;
    emit lightingBusyChanged(true);
  }
}

void SceneView::startLightingBake()
{
  lightingPending_ = false;
  const int id = lightingRequest_;
  const int cubeSize = model_->integer("cube-size");
  const bool sampling =
      parseEnvironmentSampling(model_->text("env-sampling")) != EnvironmentSampling::Off;
  std::shared_ptr<const Environment> environment;
  try
  {
    // The model's validator loaded and checked it already: a hit of the assets' cache.
    environment = assets_->environment(model_->text("env"));
  }
  catch (const Error& e)
  {
    lightingBaked(id, nullptr, false, QString::fromStdString(e.what()));
    return;
  }
  if (lighting_ && &lighting_->environment() == environment.get() &&
      lighting_->cubeSize() == cubeSize && (!sampling || lightingSampled_))
  {
    // Back to what is on screen (an undo, or a change reverted while a bake ran).
    lightingBaked(id, lighting_, lightingSampled_, QString());
    return;
  }
  lightingInFlight_ = true;
  lightingPool_->start(
      [this, id, environment, cubeSize, sampling]
      {
        std::shared_ptr<EnvironmentLighting> baked;
        QString message;
        try
        {
          baked = std::make_shared<EnvironmentLighting>(environment, cubeSize);
          if (sampling)
          {
            // The material samples the environment only with a lighting baked so: never
            // baked on the UI thread.
            baked->samplingDistribution();
          }
        }
        catch (const Error& e)
        {
          message = QString::fromStdString(e.what());
        }
        catch (const std::bad_alloc&)
        {
          message = tr("cube-size: %1 is too large for the memory available").arg(cubeSize);
        }
        // Delivered on the UI thread; dropped with the view if it is gone by then.
        QMetaObject::invokeMethod(
            this,
            [this, id, baked, sampling, message] { lightingBaked(id, baked, sampling, message); },
            Qt::QueuedConnection);
      });
}

void SceneView::lightingBaked(int id, std::shared_ptr<EnvironmentLighting> baked, bool sampled,
                              const QString& error)
{
  lightingInFlight_ = false;
  if (id != lightingRequest_)
  {
    // Stale: the latest request bakes next.
    startLightingBake();
    return;
  }
  if (!error.isEmpty())
  {
    // The lighting on screen stays.
    emit errorOccurred(error);
  }
  else if (baked != lighting_ && uploadLighting(*baked, sampled))
  {
    // Its textures are in the GL now; the switch to it, with the first frame of the new shader
    // variant, comes in a later pass of the event loop (events in between are handled).
    nextLighting_ = std::move(baked);
    nextLightingSampled_ = sampled;
    nextLightingId_ = id;
    QTimer::singleShot(kAfterPresentMs, this, [this, id] { showLighting(id); });
  }
  updateLightingBusy();
}

bool SceneView::uploadLighting(EnvironmentLighting& lighting, bool sampled)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window_);
  if (!gl || !contextReady_)
  {
    return true; // no context yet: the first frame drawn with it uploads them
  }
  errorOutput_->drawing = true;
  QString failure;
  try
  {
    window_->MakeCurrent();
    lighting.cubeTexture(gl);
    if (sampled)
    {
      lighting.samplingCdfTexture(gl);
      lighting.samplingPdfTexture(gl);
      lighting.samplingGuideTexture(gl);
    }
  }
  catch (const Error& e)
  {
    failure = QString::fromStdString(e.what());
  }
  catch (const std::bad_alloc&)
  {
    failure = tr("environment: its textures are too large for the memory available");
  }
  errorOutput_->drawing = false;
  if (!failure.isEmpty())
  {
    // The lighting on screen stays.
    emit errorOccurred(failure);
    return false;
  }
  return true;
}

void SceneView::showLighting(int id)
{
  if (!nextLighting_ || id != nextLightingId_)
  {
    return; // a later delivery took its place
  }
  std::shared_ptr<EnvironmentLighting> next = std::move(nextLighting_);
  nextLighting_.reset();
  if (id == lightingRequest_)
  {
    next->setRotationDegrees(model_->real("env-rotation"));
    lighting_ = std::move(next);
    lightingSampled_ = nextLightingSampled_;
    pass_->SetLighting(lighting_);
    material_->setLighting(lighting_);
    // Frames with another lighting (and with environment sampling, another shader variant) cost
    // what they cost: measured anew.
    frameCosts_.clear();
    // The first frame compiles the new variant: drawn as cheaply as while moving, refinement
    // under the frame budget once settled.
    beginInteraction();
    // Environment sampling held back for want of the distribution can start now.
    try
    {
      applyMaterial();
    }
    catch (const Error& e)
    {
      emit errorOccurred(QString::fromStdString(e.what()));
    }
    requestRender();
  }
  updateLightingBusy();
}

void SceneView::updateLightingBusy()
{
  if (!lightingBusy() && lightingBusyShown_)
  {
    lightingBusyShown_ = false;
    emit lightingBusyChanged(false);
  }
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
  if (wanted.environmentSampling != EnvironmentSampling::Off && !lightingSampled_)
  {
    // Its distribution is being baked on the worker (requestLighting); the lobe alone until then.
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
    const FramePlan plan = planRun();
    if (plan.samples != runSamples_)
    {
      // Frames of another sample count: the run starts over, every frame with the same weight.
      runSamples_ = plan.samples;
      pass_->Reset();
    }
    shown.samples = runSamples_;
    frames = targetSamples() / runSamples_;
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
  const glm::dvec3 position =
      drawing_.pointToDrawing({c.position[0], c.position[1], c.position[2]});
  const glm::dvec3 focalPoint =
      drawing_.pointToDrawing({c.focalPoint[0], c.focalPoint[1], c.focalPoint[2]});
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetPosition(position.x, position.y, position.z);
  camera->SetFocalPoint(focalPoint.x, focalPoint.y, focalPoint.z);
  camera->SetViewUp(c.viewUp.data());
  camera->SetViewAngle(c.viewAngle);
  camera->SetParallelProjection(c.parallel);
  camera->SetParallelScale(c.parallelScale / drawing_.radius);
  renderer_->ResetCameraClippingRange();
  requestRender();
}

void SceneView::resetCamera()
{
  ViewSettings view;
  view.direction = defaultViewDirection();
  // placeCamera fits the object's height; a window narrower than high needs more room.
  const int* size = window_->GetSize();
  if (size[0] > 0 && size[1] > 0 && size[0] < size[1])
  {
    view.margin *= static_cast<double>(size[1]) / size[0];
  }
  const CameraPlacement p = placeCamera(view, glm::dvec3(0.0), 1.0); // the drawing frame
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetFocalPoint(p.focalPoint.x, p.focalPoint.y, p.focalPoint.z);
  camera->SetPosition(p.position.x, p.position.y, p.position.z);
  camera->SetViewUp(p.viewUp.x, p.viewUp.y, p.viewUp.z);
  camera->SetViewAngle(p.viewAngleDegrees);
  camera->SetParallelScale(p.parallelScale);
  camera->SetParallelProjection(p.parallel);
  renderer_->ResetCameraClippingRange();
  applyingCamera_ = true;
  model_->setCamera(CameraState{});
  applyingCamera_ = false;
  requestRender();
}

CameraState SceneView::currentCamera() const
{
  vtkCamera* camera = renderer_->GetActiveCamera();
  CameraState c;
  c.set = true;
  camera->GetPosition(c.position.data());
  camera->GetFocalPoint(c.focalPoint.data());
  camera->GetViewUp(c.viewUp.data());
  c.viewAngle = camera->GetViewAngle();
  c.parallel = camera->GetParallelProjection() != 0;
  // From the drawing frame back to the mesh's coordinates.
  for (std::size_t i = 0; i < 3; ++i)
  {
    c.position[i] = c.position[i] * drawing_.radius + drawing_.centre[int(i)];
    c.focalPoint[i] = c.focalPoint[i] * drawing_.radius + drawing_.centre[int(i)];
  }
  c.parallelScale = camera->GetParallelScale() * drawing_.radius;
  return c;
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
  const CameraState c = currentCamera();
  CameraPlacement p;
  p.position = {c.position[0], c.position[1], c.position[2]};
  p.focalPoint = {c.focalPoint[0], c.focalPoint[1], c.focalPoint[2]};
  p.viewUp = {c.viewUp[0], c.viewUp[1], c.viewUp[2]};
  p.viewAngleDegrees = c.viewAngle;
  p.parallel = c.parallel;
  p.parallelScale = c.parallelScale;
  s.camera = p;
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
  const bool hide = frameBudgetMs_ > 0 && !interacting_ && !pass_->IsConverged();
  errorOutput_->drawing = true;
  errorOutput_->spoke = false;
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
  errorOutput_->drawing = false;
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
    contextReady_ = true;
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
    // Errors VTK did not report itself (it checks only in debug builds); a few at most, as
    // glGetError returns one per call. When VTK or the material said what failed, the GL's
    // code for the same failure adds nothing.
    for (int i = 0; i < 4; ++i)
    {
      const GLenum code = glGetError();
      if (code == GL_NO_ERROR)
      {
        break;
      }
      if (errorOutput_->spoke)
      {
        continue;
      }
      std::ostringstream message;
      message << "OpenGL: error 0x" << std::hex << code
              << " while drawing the view (the image may be wrong)";
      reportRenderError(message.str());
    }
  }
  // A refinement frame just completed (its last band drawn): the plan for the frames to come.
  const bool frameDone = pass_->GetNextBand() == 0;
  if (!interacting_ && frameDone && frameBudgetMs_ > 0 && !pass_->IsConverged())
  {
    try
    {
      const FramePlan plan = planRun();
      const bool firstOfRun = pass_->GetAccumulatedFrames() == 1;
      const bool overran =
          frameOverran(lastFrameSeconds_, frameBudgetMs_ * 1e-3, kOverrunTolerance);
      if (runReplans_ < kMaxReplans &&
          ((firstOfRun && runReplans_ < 2 && plan.samples != runSamples_) ||
           (overran && plan.samples < runSamples_)))
      {
        // The run's first frame measured its own cost: if the plan was off (nothing measured at
        // this size yet, or one sample count only), the run starts over with the corrected
        // count, at most twice. A later frame that overran the budget (the load rose) does the
        // same when the plan, with the margin it measured, now takes fewer samples.
        ++runReplans_;
        applyMaterial();
        requestRender();
      }
      else
      {
        // The run's samples stay; its frames are cut in as many bands as their measured cost
        // (and the load) now asks for. That changes no sample of the mean: no restart.
        const FrameCostModel cost = frameCost();
        const int* size = window_->GetSize();
        pass_->SetFrameBands(chooseFrameBands(cost, runSamples_, double(size[0]) * double(size[1]),
                                              planBudgetSeconds(cost), kMaxBands));
      }
    }
    catch (const Error& e)
    {
      emit errorOccurred(QString::fromStdString(e.what()));
    }
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
    try
    {
      applyMaterial();
    }
    catch (const Error& e)
    {
      emit errorOccurred(QString::fromStdString(e.what()));
    }
  }
}

void SceneView::settle()
{
  interacting_ = false;
  runReplans_ = 0;
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
  try
  {
    applyMaterial();
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromStdString(e.what()));
  }
  requestRender();
}
} // namespace aniso
