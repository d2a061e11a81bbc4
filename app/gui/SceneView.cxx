#include "app/gui/SceneView.h"

#include "app/gui/RenderTimer.h"
#include "app/gui/SceneAssets.h"
#include "app/gui/ViewCamera.h"
#include "core/error.h"
#include "core/models/models.h"
#include "core/parameters/choices.h"
#include "core/quality/error_estimate.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/mesh/LineSet.h"
#include "vtkpasses/mesh/PartPlacement.h"
#include "vtkpasses/mesh/TriangleArrays.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/FieldValues.h"
#include "vtkpasses/render/LineStyle.h"
#include "vtkpasses/render/PickCuller.h"
#include "vtkpasses/render/RendererMatrices.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <QStringList>
#include <QTimer>
#include <algorithm>
#include <cstdlib>
#include <functional>
#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataObject.h>
#include <vtkHardwareSelector.h>
#include <vtkInteractorObserver.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkOutlineSource.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkScalarBarActor.h>
#include <vtk_glew.h> // before any other GL header

namespace aniso
{
namespace
{
// Keys the materials' settings follow.
bool isShadingKey(const std::string& key)
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

// The surfaces together, as one polydata (SURFACES has at least one).
vtkSmartPointer<vtkPolyData> appended(const std::vector<vtkPolyData*>& surfaces)
{
  if (surfaces.size() == 1)
  {
    return surfaces.front();
  }
  vtkNew<vtkAppendPolyData> append;
  for (vtkPolyData* surface : surfaces)
  {
    append->AddInputData(surface);
  }
  append->Update();
  return append->GetOutput();
}
} // namespace

// One part as drawn: its actor, mapper and material, and its surface in the mesh's coordinates
// and in the drawing frame.
struct SceneView::PartView
{
  std::string surfaceKey; // mesh, block, tangents, read options and placement of the surface
  std::string sourceKey;  // the same without the read options
  std::string name;
  std::string material; // its library material
  bool visible = false; // the part's visibility
  bool loaded = false;  // its surface loaded and prepared
  bool inRenderer = false;
  vtkNew<vtkActor> actor;
  vtkNew<vtkAnisoPolyDataMapper> mapper;
  // Draws the stand-in while things move, swapped in on the actor: each mapper keeps its own
  // buffers and shader programs, so the swap rebuilds nothing (a new input would rebuild both,
  // for every part of a scene).
  vtkNew<vtkAnisoPolyDataMapper> standInMapper;
  std::unique_ptr<AnisoMaterial> shading;
  MaterialSettings full;
  vtkSmartPointer<vtkPolyData> surface;          // in the mesh's coordinates
  vtkSmartPointer<vtkPolyData> drawn;            // in the drawing frame
  vtkSmartPointer<vtkPolyData> drawnInteractive; // its stand-in while moving, or null

  bool drawnNow() const { return visible && loaded; }
};

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
  // No multisampled framebuffer: the accumulation pass draws into targets of its own and
  // antialiases by its jittered samples, so the window's samples (8 as VTK's Qt widget sets them)
  // would only multiply what showing a frame costs, and the hardware selector, which draws ids
  // without them, would make the window's framebuffers anew at every pick and again after it
  // (some 20-60 ms each on llvmpipe).
  window_->SetMultiSamples(0);
  pass_->SetDelegatePass(steps_);
  renderer_->SetPass(pass_);
  window_->AddRenderer(renderer_);
  window_->SetNumberOfLayers(std::max(2, window_->GetNumberOfLayers()));
  overlay_->SetLayer(1);
  overlay_->InteractiveOff();
  overlay_->SetActiveCamera(renderer_->GetActiveCamera());
  window_->AddRenderer(overlay_);

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
    // A click (press and release in one place, the camera not moved) picks a part: it becomes
    // the selection, or with Ctrl or Shift joins it (or leaves it); a click on nothing clears it.
    clickObserver_->SetClientData(this);
    clickObserver_->SetCallback(
        [](vtkObject* caller, unsigned long event, void* self, void*)
        {
          auto* view = static_cast<SceneView*>(self);
          auto* source = static_cast<vtkRenderWindowInteractor*>(caller);
          const int* at = source->GetEventPosition();
          if (event == vtkCommand::LeftButtonPressEvent)
          {
            view->pressAt_[0] = at[0];
            view->pressAt_[1] = at[1];
            view->pressed_ = true;
            return;
          }
          if (!view->pressed_)
          {
            return;
          }
          view->pressed_ = false;
          if (std::abs(at[0] - view->pressAt_[0]) > 3 || std::abs(at[1] - view->pressAt_[1]) > 3)
          {
            return; // a drag: the camera moved
          }
          const bool extend = source->GetControlKey() || source->GetShiftKey();
          view->clickedAt(at[0], at[1], extend);
        });
    // Before the interactor style (higher priority): the style still rotates on a drag.
    interactor->AddObserver(vtkCommand::LeftButtonPressEvent, clickObserver_, 1.0f);
    interactor->AddObserver(vtkCommand::LeftButtonReleaseEvent, clickObserver_, 1.0f);
  }

  resizeObserver_->SetClientData(this);
  resizeObserver_->SetCallback([](vtkObject*, unsigned long, void* self, void*)
                               { static_cast<SceneView*>(self)->requestRender(); });
  window_->AddObserver(vtkCommand::WindowResizeEvent, resizeObserver_);

  // Every frame the window draws is timed (progressive ones and the interactor's own); those
  // that drew the surface are what the frame budget learns from.
  renderTimer_ = std::make_unique<RenderTimer>(
      window_, &planner_,
      [this](MeasuredRender& drawn)
      {
        drawn.standIn = false;
        for (const auto& part : parts_)
        {
          drawn.standIn = drawn.standIn || (part->drawnInteractive && part->inRenderer &&
                                            part->actor->GetMapper() == part->standInMapper);
        }
        // The samples each part draws in this frame (every part the same: the run's).
        drawn.samples = 1;
        for (const auto& part : parts_)
        {
          if (part->inRenderer && part->shading)
          {
            drawn.samples = part->shading->settings().samples;
            break;
          }
        }
        drawn.bands = pass_->GetCurrentFrameBands();
        drawn.band = pass_->GetNextBand(); // the band being drawn (counted up after it)
      },
      // Only refinement frames after a run's first measure the load: the first after a resize
      // or a new shader variant also pays for those once, which says nothing of the load.
      [this](MeasuredRender& drawn)
      { drawn.measuresLoad = !interacting_ && pass_->GetAccumulatedFrames() > 1; });

  connect(model_, &SceneModel::valueChanged, this, &SceneView::modelChanged);
  connect(model_, &SceneModel::cameraChanged, this, &SceneView::applyCameraFromModel);
  connect(model_, &SceneModel::partsChanged, this,
          [this]
          {
            attempt(
                [this]
                {
                  if (syncParts())
                  {
                    applySurfaces();
                  }
                  beginInteraction();
                  applyMaterial();
                  applySelection();
                });
            requestRender();
          });
  connect(model_, &SceneModel::materialsChanged, this, &SceneView::materialsChanged);
  connect(model_, &SceneModel::selectionChanged, this, [this] { applySelection(); });
  // New tables reach the parts that waited for them, and those draw anew (a still view may
  // have converged with the tables it had).
  connect(luts_, &LutScheduler::lutsReady, this,
          [this]
          {
            changedSettings_ = false;
            attempt([this] { applyMaterial(); });
            if (changedSettings_)
            {
              requestRender();
            }
          });
  connect(lightingLoader_, &LightingLoader::shown, this, &SceneView::lightingShown);
  connect(lightingLoader_, &LightingLoader::busyChanged, this, &SceneView::lightingBusyChanged);
  connect(lightingLoader_, &LightingLoader::failed, this, &SceneView::errorOccurred);

  lightingLoader_->loadNow();
  pass_->SetLighting(lighting());
  outline_->VisibilityOff();
  outline_->PickableOff();
  outline_->GetProperty()->SetColor(1.0, 0.8, 0.2);
  outline_->GetProperty()->SetLineWidth(2.0);
  outline_->GetProperty()->LightingOff();
  syncParts();
  applySurfaces();
  applyDisplay();
  applyMaterial();
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
    interactor->RemoveObserver(clickObserver_);
  }
  window_->RemoveObserver(resizeObserver_);
  renderTimer_.reset();
  parts_.clear();
  window_->RemoveRenderer(overlay_);
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

vtkRenderer* SceneView::overlay() const
{
  return overlay_;
}

void SceneView::setSettleMs(int ms)
{
  settle_->setInterval(ms);
}

void SceneView::beginWindowRepaint()
{
  repaintClock_.start();
  renderedAtRepaint_ = renderTimer_->renderedSeconds();
}

void SceneView::endWindowRepaint()
{
  if (!repaintClock_.isValid())
  {
    return;
  }
  // A repaint may render the view (the widget's paint, when VTK asks for a render): that is a
  // render, timed and planned as such, not the repaint's own cost.
  const double seconds = double(repaintClock_.nsecsElapsed()) * 1e-9 -
                         (renderTimer_->renderedSeconds() - renderedAtRepaint_);
  repaintClock_.invalidate();
  // The larger of this repaint and the earlier ones decayed by a tenth a repaint: one slow
  // repaint holds for some tens of them, and a window made smaller is planned for within as many.
  repaintSeconds_ = std::max(std::max(seconds, 0.0), 0.9 * repaintSeconds_);
  planner_.setOverheadSeconds(overheadSeconds_ + repaintSeconds_);
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
  shape.triangles = 0;
  for (const auto& part : parts_)
  {
    shape.triangles += part->drawnNow() && part->drawn ? part->drawn->GetNumberOfPolys() : 0;
  }
  return shape;
}

void SceneView::modelChanged(const QString& qkey)
{
  const std::string key = qkey.toStdString();
  if (isMaterialKey(key))
  {
    // The edited parts' materials: materialsChanged brings what changed (a new selection only
    // shows another material in the docks).
    return;
  }
  try
  {
    if (key == "mesh" || sceneKeyAffects(key, Affects::Meshes))
    {
      // The parts follow (partsChanged); the mesh key is the first part's file. A key of how
      // files are read (cad-deflection, ...) reads the parts of STEP and IGES files again: from
      // the assets when they hold them (an undo), else on a worker (surfacesOutdated).
      if (syncParts())
      {
        applySurfaces();
      }
    }
    else if (key == "env" || key == "cube-size")
    {
      lightingLoader_->request();
    }
    else if (key == "env-sampling" &&
             !lightingPrepared(parseEnvironmentSampling(model_->text("env-sampling"))))
    {
      // The distribution is baked with a new lighting on the worker; until it is on screen the
      // material keeps sampling only its lobe.
      lightingLoader_->request();
    }
    else if (key == "env-lights" && model_->text("env-lights") == "on" && lighting() &&
             !lighting()->bakedAnalysis())
    {
      // The sources of the lit models and LEADR come with the analysis, baked on the worker.
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
    if (isShadingKey(key) || qualityKey || key == "env-sampling")
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

void SceneView::materialsChanged(const QStringList& names)
{
  attempt(
      [&]
      {
        // A material's tangent model is part of its parts' surfaces.
        if (syncParts())
        {
          applySurfaces();
        }
        bool used = false;
        for (const auto& part : parts_)
        {
          used = used || names.contains(QString::fromStdString(part->material));
        }
        if (used)
        {
          // Exponents, F0 or albedo are uniforms and tables: frames cost what they cost before,
          // and what the planner measured still holds (a new count's first frames are not
          // extrapolated from nothing at every slider step).
          if (frameCostChanged(names))
          {
            planner_.forgetCosts();
          }
          beginInteraction();
          applyMaterial();
        }
      });
  requestRender();
}

bool SceneView::syncParts()
{
  const std::vector<ScenePart>& parts = model_->parts();
  bool changed = false;
  bool outdated = false;
  if (parts_.size() > parts.size())
  {
    renderTimer_->setMappers({}); // the mappers about to go (applySurfaces sets them anew)
  }
  while (parts_.size() > parts.size())
  {
    PartView& gone = *parts_.back();
    if (gone.inRenderer)
    {
      renderer_->RemoveActor(gone.actor);
    }
    parts_.pop_back();
    changed = true;
  }
  while (parts_.size() < parts.size())
  {
    auto part = std::make_unique<PartView>();
    part->mapper->ScalarVisibilityOff();
    part->standInMapper->ScalarVisibilityOff();
    part->actor->SetMapper(part->mapper);
    parts_.push_back(std::move(part));
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    const ScenePart& wanted = parts[i];
    PartView& part = *parts_[i];
    const std::string tangents = model_->partMaterial(int(i)).value("tangents").text;
    std::string source = wanted.mesh + "\n" + wanted.block + "\n" + tangents;
    for (double v : wanted.placement)
    {
      source += "\n" + formatNumber(v);
    }
    const std::string key = source + assets_->readOptionsKey(wanted.mesh);
    part.name = wanted.name;
    part.material = wanted.material;
    if (part.surfaceKey != key && part.loaded && part.sourceKey == source && !readNow_ &&
        !assets_->hasSurface(wanted.mesh, wanted.block, tangents))
    {
      // Only the read options changed (a CAD file's tessellation) and the surface they give is
      // not read yet: the previous one stays on screen while the window reads it on a worker.
      outdated = true;
    }
    else if (part.surfaceKey != key)
    {
      part.sourceKey = source;
      part.surfaceKey = key;
      part.loaded = false;
      changed = true;
      try
      {
        // Prepared in the part's own frame (its tangent model's axes are there), then placed.
        part.surface = assets_->surface(wanted.mesh, wanted.block, tangents)->polyData;
        if (wanted.placement != kIdentityPlacement)
        {
          part.surface = placedSurface(part.surface, wanted.placement);
        }
        part.loaded = true;
        model_->setPartArrays(wanted.name, assets_->vectorArrays(wanted.mesh, wanted.block));
        model_->setPartFields(wanted.name, assets_->fieldChoices(wanted.mesh, wanted.block));
        for (const std::string& note : assets_->surfaceNotes(wanted.mesh, wanted.block, tangents))
        {
          emit noteAdded(QString::fromStdString(note));
        }
      }
      catch (const Error& e)
      {
        // Skipped with one warning; the other parts are drawn.
        part.surface = nullptr;
        try
        {
          // The mesh may have loaded and its tangent model failed (array:NAME of an array it
          // lacks): its arrays are still offered.
          model_->setPartArrays(wanted.name, assets_->vectorArrays(wanted.mesh, wanted.block));
          model_->setPartFields(wanted.name, assets_->fieldChoices(wanted.mesh, wanted.block));
        }
        catch (const Error&)
        {
          model_->setPartArrays(wanted.name, {});
          model_->setPartFields(wanted.name, {});
        }
        emit errorOccurred(tr("Part %1 skipped: %2")
                               .arg(QString::fromStdString(wanted.name),
                                    QString::fromStdString(e.what())));
      }
    }
    if (part.visible != wanted.visible)
    {
      part.visible = wanted.visible;
      changed = true;
    }
  }
  if (outdated)
  {
    emit surfacesOutdated();
  }
  return changed;
}

Material::Values SceneView::frameCostValues(const std::string& material) const
{
  Material::Values costs;
  if (const Material* m = model_->materials().find(material))
  {
    for (const auto& [key, value] : m->values)
    {
      if (sceneKeyAffects(key, Affects::FrameCost))
      {
        costs.emplace(key, value);
      }
    }
  }
  return costs;
}

bool SceneView::frameCostChanged(const QStringList& names) const
{
  for (const QString& name : names)
  {
    const auto drawn = drawnFrameCostValues_.find(name.toStdString());
    if (drawn != drawnFrameCostValues_.end() &&
        drawn->second != frameCostValues(name.toStdString()))
    {
      return true;
    }
  }
  return false;
}

void SceneView::refreshSurfaces()
{
  readNow_ = true;
  attempt(
      [this]
      {
        if (syncParts())
        {
          planner_.forgetCosts();
          applySurfaces();
          beginInteraction();
          applyMaterial();
          applySelection();
        }
      });
  readNow_ = false;
  requestRender();
}

void SceneView::applySurfaces()
{
  std::vector<vtkPolyData*> surfaces;
  for (const auto& part : parts_)
  {
    if (part->drawnNow())
    {
      surfaces.push_back(part->surface);
    }
  }
  if (!surfaces.empty())
  {
    // The visible parts' common bounding sphere: framing fits them, hidden parts do not count.
    drawing_ = drawingFrameOf(surfaces);
  }
  std::vector<vtkPolyData*> drawn;
  std::vector<vtkPolyData*> interactive;
  bool anyStandIn = false;
  for (std::size_t i = 0; i < parts_.size(); ++i)
  {
    PartView& part = *parts_[i];
    const bool draw = part.drawnNow();
    if (draw)
    {
      const ScenePart& p = model_->parts()[i];
      const std::string tangents = model_->partMaterial(int(i)).value("tangents").text;
      part.drawn = inDrawingFrame(part.surface, drawing_);
      // The stand-in in the scene's drawing frame: the view does not jump when it is swapped.
      vtkSmartPointer<vtkPolyData> standIn =
          assets_->interactiveSurface(p.mesh, p.block, tangents);
      if (standIn && p.placement != kIdentityPlacement)
      {
        standIn = placedSurface(standIn, p.placement);
      }
      part.drawnInteractive = standIn ? inDrawingFrame(standIn, drawing_) : nullptr;
      setDrawingFrame(part.actor, drawing_);
      if (!part.shading)
      {
        part.shading = std::make_unique<AnisoMaterial>(lighting(), part.full);
        part.shading->apply(part.actor, renderer_);
        part.shading->addMapper(part.standInMapper);
      }
      drawn.push_back(part.drawn);
      interactive.push_back(part.drawnInteractive ? part.drawnInteractive.Get() : part.drawn.Get());
      anyStandIn = anyStandIn || part.drawnInteractive;
    }
    else
    {
      part.drawn = nullptr;
      part.drawnInteractive = nullptr;
    }
    // Hidden parts are not in the renderer: they cost nothing.
    if (draw && !part.inRenderer)
    {
      renderer_->AddActor(part.actor);
      part.inRenderer = true;
    }
    else if (!draw && part.inRenderer)
    {
      renderer_->RemoveActor(part.actor);
      part.inRenderer = false;
    }
    part.actor->SetVisibility(partsShown_);
  }
  drawnSurface_ = drawn.empty() ? nullptr : appended(drawn);
  drawnInteractive_ = anyStandIn ? appended(interactive) : nullptr;
  showDrawnSurface();
  std::vector<vtkMapper*> mappers;
  for (auto& part : parts_)
  {
    if (part->inRenderer)
    {
      mappers.push_back(part->mapper);
      mappers.push_back(part->standInMapper);
    }
  }
  renderTimer_->setMappers(mappers);
  if (model_->camera().set)
  {
    applyCameraFromModel();
  }
  else
  {
    resetCamera();
  }
  applySelection();
  emit partsDrawn();
}

vtkPolyData* SceneView::surfaceToDraw() const
{
  return interacting_ && drawnInteractive_ ? drawnInteractive_ : drawnSurface_;
}

void SceneView::showDrawnSurface()
{
  for (auto& part : parts_)
  {
    if (!part->inRenderer)
    {
      continue;
    }
    // Each mapper keeps its input (a new input: buffers built in the next render), and the actor
    // draws with the stand-in's while things move.
    if (part->drawn && part->mapper->GetInput() != part->drawn)
    {
      part->mapper->SetInputData(part->drawn);
    }
    if (part->drawnInteractive && part->standInMapper->GetInput() != part->drawnInteractive)
    {
      part->standInMapper->SetInputData(part->drawnInteractive);
    }
    vtkMapper* wanted = interacting_ && part->drawnInteractive
                            ? static_cast<vtkMapper*>(part->standInMapper)
                            : static_cast<vtkMapper*>(part->mapper);
    if (part->drawn && part->actor->GetMapper() != wanted)
    {
      part->actor->SetMapper(wanted);
    }
  }
}

vtkPolyData* SceneView::drawnSurface() const
{
  return drawnSurface_;
}

long long SceneView::drawnTriangles() const
{
  long long triangles = 0;
  for (const auto& part : parts_)
  {
    vtkMapper* mapper = part->actor->GetMapper();
    vtkPolyData* drawn = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
    triangles += part->inRenderer && drawn ? drawn->GetNumberOfPolys() : 0;
  }
  return triangles;
}

vtkActor* SceneView::partActor(int part) const
{
  return parts_.at(std::size_t(part))->actor;
}

const AnisoMaterial* SceneView::partMaterial(int part) const
{
  return parts_.at(std::size_t(part))->shading.get();
}

bool SceneView::partDrawn(int part) const
{
  return parts_.at(std::size_t(part))->inRenderer;
}

long long SceneView::partTriangles(int part) const
{
  const PartView& p = *parts_.at(std::size_t(part));
  return p.surface ? p.surface->GetNumberOfPolys() : -1;
}

vtkPolyData* SceneView::partDrawnSurface(int part) const
{
  const PartView& p = *parts_.at(std::size_t(part));
  return p.inRenderer ? p.drawn.Get() : nullptr;
}

vtkPolyData* SceneView::partSurfaceToDraw(int part) const
{
  const PartView& p = *parts_.at(std::size_t(part));
  if (!p.inRenderer)
  {
    return nullptr;
  }
  return interacting_ && p.drawnInteractive ? p.drawnInteractive.Get() : p.drawn.Get();
}

ParameterSet SceneView::partParameters(int part) const
{
  return model_->partParameters(part);
}

int SceneView::partAt(int x, int y)
{
  // VTK's hardware selector: the renderer draws each visible part's id into the window's back
  // buffer (one render, the props' pass only) and the pixel under (x, y) names the part. The
  // selector's renders go through the renderer's own drawing, which a render pass replaces, so
  // the accumulation pass steps aside for them; it keeps its mean, and the window shows that mean
  // again (nothing added to it: the view did not change). The overlay (the selection's outline)
  // is not drawn into the ids, and the id renders are not timed (the planner learns frames only).
  if (x < 0 || y < 0 || !renderer_->GetRenderWindow())
  {
    return -1;
  }
  bool anyShown = false;
  for (const auto& part : parts_)
  {
    anyShown = anyShown || (part->inRenderer && part->actor->GetVisibility());
  }
  if (!anyShown)
  {
    return -1;
  }
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer_);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  selector->SetActorPassOnly(true);
  const unsigned int at[2] = {static_cast<unsigned int>(x), static_cast<unsigned int>(y)};
  selector->SetArea(at[0], at[1], at[0], at[1]);
  // Only the parts whose screen rectangles hold the pixel draw their ids: the id render costs
  // what those few cost, and only their mappers switch to their picking shaders (and back at the
  // next frame) instead of every part's.
  vtkNew<PickCuller> culler;
  culler->SetPixel(x, y);
  renderer_->AddCuller(culler);
  const int overlayDrawn = overlay_->GetDraw();
  overlay_->DrawOff();
  renderer_->SetPass(nullptr);
  renderTimer_->setIgnoring(true);
  const bool captured = selector->CaptureBuffers();
  renderTimer_->setIgnoring(false);
  renderer_->SetPass(pass_);
  overlay_->SetDraw(overlayDrawn);
  renderer_->RemoveCuller(culler);
  const vtkHardwareSelector::PixelInformation info =
      captured ? selector->GetPixelInformation(at) : vtkHardwareSelector::PixelInformation{};
  vtkProp* prop = captured && info.Valid ? info.Prop : nullptr;
  selector->ClearBuffers();
  // The ids are in the back buffer: the mean again (timed as any render: a still view that is
  // refining draws its next frame here, a converged one only shows its mean).
  window_->Render();
  if (!prop)
  {
    return -1;
  }
  for (std::size_t i = 0; i < parts_.size(); ++i)
  {
    if (parts_[i]->actor.Get() == prop)
    {
      return int(i);
    }
  }
  return -1;
}

void SceneView::clickedAt(int x, int y, bool extend)
{
  const int part = partAt(x, y);
  std::vector<int> selection = extend ? model_->selection() : std::vector<int>{};
  if (part >= 0)
  {
    const auto it = std::find(selection.begin(), selection.end(), part);
    if (extend && it != selection.end())
    {
      selection.erase(it);
    }
    else if (it == selection.end())
    {
      selection.push_back(part);
    }
  }
  model_->setSelection(selection);
}

void SceneView::setPartsShown(bool shown)
{
  partsShown_ = shown;
  for (auto& part : parts_)
  {
    part->actor->SetVisibility(shown);
  }
  applySelection();
  applyLegends();
}

void SceneView::applySelection()
{
  // The selected parts' bounding boxes in the drawing frame, drawn over the surfaces; a scene of
  // one part shows none (there is nothing to tell apart).
  const std::vector<int>& selection = model_->selection();
  double bounds[6] = {1.0, -1.0, 1.0, -1.0, 1.0, -1.0};
  for (int i : selection)
  {
    if (i < 0 || i >= int(parts_.size()) || !parts_[std::size_t(i)]->inRenderer)
    {
      continue;
    }
    double b[6];
    parts_[std::size_t(i)]->drawn->GetBounds(b);
    for (int axis = 0; axis < 3; ++axis)
    {
      bounds[2 * axis] = bounds[2 * axis] <= bounds[2 * axis + 1]
                             ? std::min(bounds[2 * axis], b[2 * axis])
                             : b[2 * axis];
      bounds[2 * axis + 1] = std::max(bounds[2 * axis + 1], b[2 * axis + 1]);
    }
  }
  const bool show = partsShown_ && parts_.size() > 1 && bounds[0] <= bounds[1];
  if (show)
  {
    vtkNew<vtkOutlineSource> box;
    box->SetBounds(bounds);
    box->Update();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(box->GetOutput());
    outline_->SetMapper(mapper);
    if (!overlay_->HasViewProp(outline_))
    {
      overlay_->AddActor(outline_);
    }
  }
  else if (overlay_->HasViewProp(outline_))
  {
    overlay_->RemoveActor(outline_);
  }
  outline_->SetVisibility(show);
  requestRender();
}

void SceneView::lightingShown()
{
  pass_->SetLighting(lighting());
  for (auto& part : parts_)
  {
    if (part->shading)
    {
      part->shading->setLighting(lighting());
    }
  }
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
  // The values the frames from now on are drawn with, against which frameCostChanged tells
  // whether an edit changes what they cost.
  drawnFrameCostValues_.clear();
  for (const auto& part : parts_)
  {
    drawnFrameCostValues_[part->material] = frameCostValues(part->material);
  }
  if (parts_.empty())
  {
    applyLegends();
    return;
  }
  // The LUT scheduler bakes the tables of the edited material (the docks' n_u, n_v): its parts
  // keep the exponents whose tables they have until the new ones are ready, so a slider drag
  // never bakes on the UI thread. Parts of other materials take their tables from the cache
  // (LutCache: shared by every part of the same lobe, read from disk or baked when missing).
  const LutResult& ready = luts_->current();
  const std::vector<std::string> edited = model_->editedMaterials();
  int frames = 1;
  bool first = true;
  bool mapsDropped = false;
  // Each drawn part's settings first, then their fields' automatic ranges resolved over the
  // drawn parts together, then the settings to the materials.
  std::vector<char> bakedFor(parts_.size(), 0);
  for (std::size_t i = 0; i < parts_.size(); ++i)
  {
    PartView& part = *parts_[i];
    if (!part.inRenderer || !part.shading)
    {
      continue;
    }
    const ParameterSet partValues = model_->partParameters(int(i));
    MaterialSettings wanted = materialFromParameters(partValues, part.full);
    // A line set's width (LineStyle.h); a surface has no lines to widen.
    const LineStyle style = lineStyleFromParameters(partValues);
    if (style.width != lineStyle(part.actor).width || style.unit != lineStyle(part.actor).unit)
    {
      setLineStyle(part.actor, style);
      changedSettings_ = true;
    }
    assets_->addMaps(model_->partMaterial(int(i)), wanted);
    const bool baked = ready.halfVector && ready.request.lobe.nu == wanted.lobe.nu &&
                       ready.request.lobe.nv == wanted.lobe.nv &&
                       ready.request.size == wanted.lutSize &&
                       ready.request.samples == wanted.brdfLutSamples;
    bakedFor[i] = baked;
    const bool editedPart =
        std::find(edited.begin(), edited.end(), part.material) != edited.end();
    if (editedPart && needsLuts(wanted) && !baked)
    {
      if (needsLuts(part.full))
      {
        wanted.lobe = part.full.lobe;
        wanted.lutSize = part.full.lutSize;
        wanted.brdfLutSamples = part.full.brdfLutSamples;
      }
      else
      {
        wanted.method = part.full.method;
        wanted.halfVectors = part.full.halfVectors;
      }
    }
    if (!lightingPrepared(wanted.environmentSampling))
    {
      // What it needs is being baked on the worker (LightingLoader); the lobe alone until then.
      wanted.environmentSampling = EnvironmentSampling::Off;
    }
    part.full = wanted;
  }
  resolveFields();
  for (std::size_t i = 0; i < parts_.size(); ++i)
  {
    PartView& part = *parts_[i];
    if (!part.inRenderer || !part.shading)
    {
      continue;
    }
    if (first)
    {
      // What the planner and the quality follow: the first drawn part's settings (the samples
      // per frame and the quality are the scene's, the same for every part).
      full_ = part.full;
    }
    MaterialSettings shown = part.full;
    if (interacting_)
    {
      shown.samples = std::min(shown.samples, kInteractiveSamples);
      if (first)
      {
        // Shown as drawn: whole frames.
        pass_->SetFrameBands(1);
      }
    }
    else
    {
      if (first)
      {
        const FramePlan plan = planner_.plan(runShape());
        if (planner_.beginRun(plan))
        {
          // Frames of another sample count: the run starts over, every frame with the same
          // weight.
          pass_->Reset();
        }
        frames = targetSamples() / planner_.runSamples();
        // Bands split a frame's drawing, not its samples: the mean is the same, so no restart
        // (the frame in progress keeps its bands).
        pass_->SetFrameBands(plan.bands);
      }
      shown.samples = planner_.runSamples();
    }
    first = false;
    // The scheduler's tables when they are this part's: nothing is read or baked here for the
    // edited parts, even when the cache has dropped them from memory since.
    changedSettings_ = changedSettings_ || shown != part.shading->settings();
    if (bakedFor[i])
    {
      part.shading->setSettings(shown, ready.halfVector, ready.brdf);
    }
    else
    {
      part.shading->setSettings(shown);
    }
    mapsDropped = mapsDropped || part.shading->mapsDropped();
  }
  pass_->SetTargetFrames(std::max(frames, 1));
  // With quality-mode error the still view stops once the error its own frames show is at the
  // target, from 256 samples a pixel on (error_estimate.h), target-samples then the most it
  // accumulates.
  pass_->SetErrorTarget(byError() ? model_->real("error-target") : 0.0,
                        minimumErrorStopFrames(frameSamples()));
  applyLegends();
  if (mapsDropped)
  {
    emit noteAdded(tr("The mesh has no texture coordinates: its maps are not used."));
  }
}

void SceneView::resolveFields()
{
  // What the resolution depends on: each drawn part's surface (and its modification time) and
  // its field. applyMaterial runs often (each settle, each replanned run) and the statistics
  // read every value, so an unchanged scene keeps the ranges it resolved.
  std::vector<ResolvedField> wanted;
  std::vector<vtkPolyData*> surfaces;
  std::vector<MaterialSettings*> materials;
  for (auto& part : parts_)
  {
    if (!part->inRenderer || !part->shading || !part->full.field)
    {
      continue;
    }
    ResolvedField f;
    f.surface = part->surface;
    f.surfaceTime = part->surface ? part->surface->GetMTime() : 0;
    f.spec = part->full.field->spec;
    f.automatic = part->full.field->range.automatic;
    wanted.push_back(f);
    surfaces.push_back(part->surface);
    materials.push_back(&part->full);
  }
  const bool same = wanted.size() == resolvedFields_.size() &&
                    std::equal(wanted.begin(), wanted.end(), resolvedFields_.begin(),
                               [](const ResolvedField& a, const ResolvedField& b)
                               {
                                 return a.surface == b.surface && a.surfaceTime == b.surfaceTime &&
                                        a.spec == b.spec && a.automatic == b.automatic;
                               });
  if (same)
  {
    for (std::size_t k = 0; k < materials.size(); ++k)
    {
      materials[k]->field->range = resolvedFields_[k].range;
    }
    return;
  }
  // Parts that show one array share one colour scale, as ParaView colours a multiblock
  // dataset (FieldValues.h).
  resolveFieldRanges(surfaces, materials);
  for (std::size_t k = 0; k < materials.size(); ++k)
  {
    wanted[k].range = materials[k]->field->range;
  }
  resolvedFields_ = std::move(wanted);
}

void SceneView::applyLegends()
{
  // The colour legends of the fields the drawn parts show through a colour map (their ranges
  // resolved), over the image in the overlay (the accumulated image stays as it is); none while
  // another model's view draws in the parts' place, or with legend off.
  std::vector<FieldLegend> wanted;
  if (partsShown_ && parseOnOff("legend", model_->text("legend")) == OnOff::On)
  {
    std::vector<const MaterialSettings*> shown;
    for (const auto& part : parts_)
    {
      if (part->inRenderer && part->shading)
      {
        shown.push_back(&part->full);
      }
    }
    wanted = fieldLegends(shown);
  }
  if (wanted == legends_)
  {
    return;
  }
  for (const auto& actor : legendActors_)
  {
    overlay_->RemoveViewProp(actor);
  }
  legendActors_.clear();
  for (std::size_t k = 0; k < wanted.size(); ++k)
  {
    legendActors_.push_back(makeFieldLegendActor(wanted[k], int(k)));
    overlay_->AddViewProp(legendActors_.back());
  }
  legends_ = std::move(wanted);
  requestRender();
}

void SceneView::applyDisplay()
{
  pass_->SetDisplaySettings(displayFromParameters(model_->parameters()));
  applyLegends();
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

void SceneView::showView(const std::string& name)
{
  ViewSettings view = defaultViewSettings();
  view.direction = viewDirectionFromName(name, "view");
  const int* size = window_->GetSize();
  applyCamera(renderer_, viewPlacement(view, size[0], size[1]));
  applyingCamera_ = true;
  model_->setCamera(name == defaultViewName() ? CameraState{} : currentCamera());
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
  if (parts_.size() == 1)
  {
    s.surface = parts_.front()->surface;
  }
  else
  {
    for (const auto& part : parts_)
    {
      RenderPart p;
      p.name = part->name;
      p.surface = part->surface;
      p.material = part->full;
      p.visible = part->inRenderer;
      s.parts.push_back(std::move(p));
    }
  }
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

bool SceneView::byError() const
{
  return parseQualityMode(model_->text("quality-mode")) == QualityMode::Error;
}

QualityChoice SceneView::quality() const
{
  QualityChoice choice;
  choice.samples = targetSamples();
  choice.predictedError = predictedError(full_.lobe, full_.filtered, choice.samples);
  return choice;
}

int SceneView::targetSamples() const
{
  return runTotalSamples(model_->integer("target-samples"), full_.samples);
}

double SceneView::estimatedError() const
{
  return pass_->GetEstimatedError();
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
  QElapsedTimer pass;
  pass.start();
  qint64 renderNs = 0;
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
  const qint64 renderStart = pass.nsecsElapsed();
  window_->Render();
  renderNs = pass.nsecsElapsed() - renderStart;
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
  // What this pass cost besides the render (errors checked, the plan, the signals' receivers):
  // the renders are planned for the budget less its running mean and the window's repaint
  // (endWindowRepaint), so the pass keeps within it.
  const double overhead = double(pass.nsecsElapsed() - renderNs) * 1e-9;
  overheadSeconds_ =
      overheadSeconds_ > 0.0 ? 0.8 * overheadSeconds_ + 0.2 * overhead : overhead;
  planner_.setOverheadSeconds(overheadSeconds_ + repaintSeconds_);
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

bool SceneView::ReferenceKey::operator==(const ReferenceKey& o) const
{
  const auto sameMaterial = [](const ReferenceMaterial& a, const ReferenceMaterial& b)
  {
    return a.lobe.nu == b.lobe.nu && a.lobe.nv == b.lobe.nv && a.f0 == b.f0 && a.albedo == b.albedo;
  };
  return width == o.width && height == o.height && clipToWorld == o.clipToWorld &&
         worldToEnvironment == o.worldToEnvironment && environment == o.environment &&
         unsupported == o.unsupported && parts.size() == o.parts.size() &&
         std::equal(parts.begin(), parts.end(), o.parts.begin(),
                    [&](const Part& a, const Part& b)
                    {
                      return a.surface == b.surface && a.time == b.time &&
                             sameMaterial(a.material, b.material);
                    });
}

std::string SceneView::referenceUnsupported() const
{
  if (!lighting())
  {
    return "no environment is loaded";
  }
  const std::string name = model_->text("model");
  if (name != kEnvironmentModel)
  {
    const ShadingModelInfo* info = findShadingModel(name);
    return "the reference is of the anisotropic environment material, not of " +
           (info ? std::string(info->title) : name);
  }
  bool drawn = false;
  for (const auto& part : parts_)
  {
    if (!part->inRenderer || !part->drawn)
    {
      continue;
    }
    drawn = true;
    const std::string prefix = parts_.size() > 1 ? "part " + part->name + ": " : "";
    if (isLineSet(part->drawn))
    {
      return prefix + "the reference does not cover line parts (illuminated lines)";
    }
    std::string why;
    if (!referenceMaterialOf(part->full, why))
    {
      return prefix + why;
    }
  }
  return drawn ? std::string() : "no part is drawn";
}

SceneView::ReferenceKey SceneView::referenceKey() const
{
  ReferenceKey key;
  key.unsupported = referenceUnsupported();
  const int* size = window_->GetSize();
  key.width = size[0];
  key.height = size[1];
  // The camera as the mappers draw with it between frames: the pass jitters the window centre
  // only while it draws a frame, and restores it after.
  key.clipToWorld = clipToWorld(renderer_);
  if (const std::shared_ptr<EnvironmentLighting>& light = lighting())
  {
    key.environment = &light->environment();
    key.worldToEnvironment = light->worldToEnvironment();
  }
  if (!key.unsupported.empty())
  {
    return key;
  }
  for (const auto& part : parts_)
  {
    if (part->inRenderer && part->drawn)
    {
      std::string why;
      key.parts.push_back({part->drawn, part->drawn->GetMTime(),
                           referenceMaterialOf(part->full, why).value_or(ReferenceMaterial{})});
    }
  }
  return key;
}

ReferenceInputs SceneView::referenceInputs() const
{
  const ReferenceKey key = referenceKey();
  if (!key.unsupported.empty())
  {
    throw errorAbout("reference", key.unsupported);
  }
  ReferenceInputs inputs;
  for (const auto& part : parts_)
  {
    if (part->inRenderer && part->drawn)
    {
      std::string why;
      // The surface the actor draws, already in the drawing frame (as floats, as the GL has it).
      appendTriangles(inputs.mesh, triangleMesh(part->drawn), int(inputs.materials.size()));
      inputs.materials.push_back(*referenceMaterialOf(part->full, why));
    }
  }
  inputs.clipToWorld = key.clipToWorld;
  inputs.worldToEnvironment = key.worldToEnvironment;
  // Shares the lighting's ownership: a new lighting on screen leaves this one's environment alive
  // for the run that integrates it.
  const std::shared_ptr<EnvironmentLighting>& light = lighting();
  inputs.environment = std::shared_ptr<const Environment>(light, &light->environment());
  inputs.width = key.width;
  inputs.height = key.height;
  return inputs;
}

Image SceneView::linearImage()
{
  return pass_->ReadAccumulation();
}
} // namespace aniso
