#include "app/gui/LitModelView.h"

#include "app/gui/SceneView.h"
#include "core/error.h"
#include "core/parameters/choices.h"
#include "scene/SceneShading.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/LineStyle.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <algorithm>
#include <utility>
#include <vector>
#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>

namespace aniso
{
namespace
{
// Sample materials are baked once per name: switching models or moving lights reuses them.
std::shared_ptr<const SvMaps> sampleMaps(const std::string& name)
{
  static std::string cachedName;
  static std::shared_ptr<const SvMaps> cached;
  if (name != cachedName || !cached)
  {
    cached = std::make_shared<const SvMaps>(makeSampleMaterial(name, "sample-material"));
    cachedName = name;
  }
  return cached;
}
} // namespace

vtkActor* firstActorOf(vtkRenderer* renderer)
{
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp())
  {
    if (vtkActor* actor = vtkActor::SafeDownCast(prop))
    {
      return actor;
    }
  }
  return nullptr;
}

bool litSettingsOf(const SceneModel& model, LitModelSettings& settings)
{
  LitModel lit;
  if (!litModelFromName(model.text("model"), lit))
  {
    return false;
  }
  settings.model = lit;
  litSceneOf(model, settings);
  return true;
}

void litSceneOf(const SceneModel& model, LitModelSettings& settings)
{
  litSceneOf(model, model.parameters(), settings);
}

void litSceneOf(const SceneModel& model, const ParameterSet& parameters,
                LitModelSettings& settings, const EnvironmentLighting* lighting)
{
  settings.lights = parseLightList(model.text("lights"), "lights");
  if (lighting && parseOnOff("env-lights", model.text("env-lights")) == OnOff::On)
  {
    settings.lights = withEnvironmentLights(settings.lights, lighting->bakedAnalysis().get(),
                                            model.real("env-rotation"));
  }
  const std::string& sample = model.text("sample-material");
  if (sample == kUniformSampleMaterial)
  {
    settings.maps = std::make_shared<const SvMaps>(uniformSvMaps(uniformTexel(
        parameters.lobe(), parameters.color("f0"), parameters.color("albedo"))));
  }
  else
  {
    settings.maps = sampleMaps(sample);
  }
}

// A part as the lit model draws it: its actor, mapper and material, kept across updates.
struct LitModelView::Part
{
  vtkNew<vtkActor> actor;
  vtkNew<vtkAnisoPolyDataMapper> mapper;
  std::unique_ptr<LitModelMaterial> material;
  bool inRenderer = false;
};

LitModelView::LitModelView(SceneModel* model, SceneView* view, QObject* parent)
    : QObject(parent), model_(model), view_(view), renderer_(view->renderer())
{
  // Connected after the view, so the view's parts are already in place when these run.
  connect(model_, &SceneModel::valueChanged, this,
          [this](const QString& key)
          {
            // Only the keys the lit actors depend on: any other change leaves them as they are.
            // The material keys' values are the edited parts' materials: materialsChanged brings
            // what changed, part by part.
            const std::string name = key.toStdString();
            if (!isMaterialKey(name) && sceneKeyAffects(name, Affects::LitModels))
            {
              update();
            }
          });
  // A part's material edited or replaced (also one not edited through the scene's keys).
  connect(model_, &SceneModel::materialsChanged, this,
          [this]
          {
            if (active_)
            {
              update();
            }
          });
  // Parts added, removed, shown, hidden or given other surfaces (the drawing frame with them).
  connect(view_, &SceneView::partsDrawn, this,
          [this]
          {
            if (active_)
            {
              update();
            }
          });
  // The stand-ins of large surfaces while things move, the surfaces once still, as the view.
  connect(view_, &SceneView::interactionChanged, this, &LitModelView::followSurfaces);
  // A new lighting on screen: its environment's sources (env-lights).
  connect(view_, &SceneView::lightingBusyChanged, this,
          [this](bool busy)
          {
            if (!busy && active_ && view_->lighting().get() != lighting_)
            {
              update();
            }
          });
  update();
}

LitModelView::~LitModelView()
{
  for (auto& part : parts_)
  {
    if (part->material)
    {
      part->material->detach();
    }
    if (part->inRenderer)
    {
      renderer_->RemoveActor(part->actor);
    }
  }
  view_->setPartsShown(true);
}

bool LitModelView::active() const
{
  return active_;
}

vtkActor* LitModelView::litActor() const
{
  for (const auto& part : parts_)
  {
    if (part->inRenderer)
    {
      return part->actor;
    }
  }
  return nullptr;
}

vtkActor* LitModelView::partActor(int part) const
{
  if (part < 0 || part >= int(parts_.size()) || !parts_[std::size_t(part)]->inRenderer)
  {
    return nullptr;
  }
  return parts_[std::size_t(part)]->actor;
}

const LitModelMaterial* LitModelView::partMaterial(int part) const
{
  return partActor(part) ? parts_[std::size_t(part)]->material.get() : nullptr;
}

void LitModelView::followSurfaces()
{
  for (std::size_t i = 0; i < parts_.size(); ++i)
  {
    Part& part = *parts_[i];
    vtkPolyData* mesh = part.inRenderer && int(i) < view_->partCount()
                            ? view_->partSurfaceToDraw(int(i))
                            : nullptr;
    if (mesh && mesh != part.mapper->GetInput())
    {
      part.mapper->SetInputData(mesh);
    }
  }
}

void LitModelView::update()
{
  LitModelSettings scene;
  bool lit = false;
  // Each drawn part's settings (the scene's model and lights, the part's material), all made
  // and checked before any is applied.
  std::vector<std::pair<int, LitModelSettings>> drawn;
  try
  {
    lit = litSettingsOf(*model_, scene);
    // The surface models (LEADR, microstructure) are SurfaceModelView's.
    const int count = std::min(view_->partCount(), int(model_->parts().size()));
    for (int i = 0; lit && i < count; ++i)
    {
      if (!view_->partDrawn(i))
      {
        continue;
      }
      LitModelSettings settings = scene;
      litSceneOf(*model_, view_->partParameters(i), settings, view_->lighting().get());
      LitModelMaterial::validate(settings);
      drawn.emplace_back(i, std::move(settings));
    }
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromUtf8(e.what()));
    // The previous picture stays rather than a half-applied one.
    return;
  }
  if (lit)
  {
    while (int(parts_.size()) > view_->partCount())
    {
      Part& gone = *parts_.back();
      if (gone.material)
      {
        gone.material->detach();
      }
      if (gone.inRenderer)
      {
        renderer_->RemoveActor(gone.actor);
      }
      parts_.pop_back();
    }
    while (int(parts_.size()) < view_->partCount())
    {
      auto part = std::make_unique<Part>();
      part->mapper->ScalarVisibilityOff();
      part->actor->SetMapper(part->mapper);
      parts_.push_back(std::move(part));
    }
    std::vector<bool> draws(parts_.size(), false);
    for (auto& [i, settings] : drawn)
    {
      Part& part = *parts_[std::size_t(i)];
      draws[std::size_t(i)] = true;
      vtkPolyData* mesh = view_->partSurfaceToDraw(i);
      if (mesh != part.mapper->GetInput())
      {
        part.mapper->SetInputData(mesh);
      }
      setDrawingFrame(part.actor, view_->drawingFrame()); // the scene's parts, its point lights
      setLineStyle(part.actor, lineStyleFromParameters(view_->partParameters(i))); // line parts
      try
      {
        if (!part.material)
        {
          part.material = std::make_unique<LitModelMaterial>(settings);
          part.material->apply(part.actor, renderer_);
        }
        else
        {
          part.material->setSettings(settings);
        }
      }
      catch (const Error& e)
      {
        // Validated above: only a mapper that is no OpenGL one gets here.
        emit errorOccurred(QString::fromUtf8(e.what()));
      }
    }
    // Hidden parts (and those that did not load) are not in the renderer: they cost nothing.
    for (std::size_t i = 0; i < parts_.size(); ++i)
    {
      Part& part = *parts_[i];
      if (draws[i] && !part.inRenderer)
      {
        renderer_->AddActor(part.actor);
        part.inRenderer = true;
      }
      else if (!draws[i] && part.inRenderer)
      {
        renderer_->RemoveActor(part.actor);
        part.inRenderer = false;
      }
    }
  }
  for (auto& part : parts_)
  {
    part->actor->SetVisibility(lit);
  }
  if (lit || surfaceModelKeys(model_->text("model")).empty())
  {
    // The lit actors in place of the view's parts, or the parts back for the environment
    // material (a surface model's actors are SurfaceModelView's to show).
    view_->setPartsShown(!lit);
  }
  active_ = lit;
  lighting_ = view_->lighting().get();
  view_->requestRender();
}
} // namespace aniso
