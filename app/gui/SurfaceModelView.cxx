#include "app/gui/SurfaceModelView.h"

#include "app/gui/LitModelView.h"
#include "app/gui/SceneAssets.h"
#include "app/gui/SceneView.h"
#include "core/error.h"
#include "core/leadr/leadr.h"
#include "core/parameters/choices.h"
#include "scene/SceneShading.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/SurfaceModelSettings.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <algorithm>
#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace aniso
{
namespace
{
// The built-in relief's moments are baked once per scale: moving a light reuses them.
std::shared_ptr<const LeadrMips> leadrMoments(double scale)
{
  static double cachedScale = -1.0;
  static std::shared_ptr<const LeadrMips> cached;
  if (!cached || scale != cachedScale)
  {
    cached = std::make_shared<const LeadrMips>(bakeLeadrFromHeight(builtinLeadrRelief(), scale));
    cachedScale = scale;
  }
  return cached;
}

// The installer of MODEL's surface model with the declared values PARAMETERS, F0, albedo and
// TPR map TPR (a pattern or a path).
MaterialInstaller surfaceInstaller(const SceneModel& model, const ParameterSet& parameters,
                                   const std::string& tpr, SceneAssets& assets)
{
  const DeclaredValues values = [&parameters](std::string_view key) -> const ParameterValue&
  { return parameters.value(key); };
  SurfaceModelInputs inputs;
  inputs.f0 = parameters.color("f0");
  inputs.albedo = parameters.color("albedo");
  inputs.lights = [&model] { return parseLightList(model.text("lights"), "lights"); };
  // The sources of the lighting on screen, when its worker baked them (LightingLoader).
  inputs.environmentLights = parseOnOff("env-lights", model.text("env-lights")) == OnOff::On;
  // As `aniso render --model leadr` without a map: the built-in relief.
  inputs.leadrMoments = [&parameters]
  { return leadrMoments(parameters.real("leadr-scale")); };
  inputs.tprMap = [&tpr, &assets] { return assets.map("tpr", tpr); };
  return surfaceModelInstaller(model.text("model"), values, inputs);
}
} // namespace

MaterialInstaller surfaceModelInstallerOf(const SceneModel& model, SceneAssets& assets)
{
  return surfaceInstaller(model, model.parameters(), model.text("tpr"), assets);
}

MaterialInstaller surfaceModelInstallerOf(const SceneModel& model, int part, SceneAssets& assets)
{
  return surfaceInstaller(model, model.partParameters(part),
                          model.partMaterial(part).value("tpr").text, assets);
}

// A drawn part's actor and the material it was given.
struct SurfaceModelView::Part
{
  int part = 0; // the view's part
  vtkSmartPointer<vtkActor> actor;
  std::shared_ptr<void> material; // owned by the actor it was applied to
};

SurfaceModelView::SurfaceModelView(SceneModel* model, SceneAssets* assets, SceneView* view,
                                   QObject* parent)
    : QObject(parent), model_(model), assets_(assets), view_(view), renderer_(view->renderer())
{
  // Connected after the view and the lit model's view, so their changes are in place first.
  connect(model_, &SceneModel::valueChanged, this, &SurfaceModelView::keyChanged);
  // A new environment: LEADR's material draws with the lighting it was made with.
  connect(view_, &SceneView::lightingBusyChanged, this,
          [this](bool busy)
          {
            if (!busy && view_->lighting() != lighting_ &&
                !surfaceModelKeys(model_->text("model")).empty())
            {
              update();
            }
          });
  // A part's material edited or replaced, or the parts drawn changed.
  const auto partsChanged = [this]
  {
    if (!surfaceModelKeys(model_->text("model")).empty())
    {
      update();
    }
  };
  connect(model_, &SceneModel::materialsChanged, this, partsChanged);
  connect(view_, &SceneView::partsDrawn, this, partsChanged);
  // The stand-ins of large surfaces while things move, the surfaces once still, as the view.
  connect(view_, &SceneView::interactionChanged, this,
          [this]
          {
            for (Part& part : parts_)
            {
              vtkMapper* mapper = part.actor->GetMapper();
              vtkPolyData* mesh =
                  part.part < view_->partCount() ? view_->partSurfaceToDraw(part.part) : nullptr;
              if (mapper && mesh && mesh != mapper->GetInputDataObject(0, 0))
              {
                mapper->SetInputDataObject(mesh);
              }
            }
          });
  update();
}

SurfaceModelView::~SurfaceModelView()
{
  for (Part& part : parts_)
  {
    part.material.reset();
    renderer_->RemoveActor(part.actor);
  }
}

bool SurfaceModelView::active() const
{
  return shown_;
}

vtkActor* SurfaceModelView::surfaceActor() const
{
  return parts_.empty() ? nullptr : parts_.front().actor.Get();
}

vtkActor* SurfaceModelView::partActor(int part) const
{
  for (const Part& p : parts_)
  {
    if (p.part == part)
    {
      return p.actor;
    }
  }
  return nullptr;
}

void SurfaceModelView::keyChanged(const QString& key)
{
  const std::string name = key.toStdString();
  if (isMaterialKey(name))
  {
    // The edited parts' materials: materialsChanged brings what changed, part by part.
    return;
  }
  const std::vector<std::string_view> keys = surfaceModelKeys(model_->text("model"));
  // The keys that change the picture of a surface model: the shared ones and its declared ones.
  if (sceneKeyAffects(name, Affects::SurfaceModels) ||
      std::find(keys.begin(), keys.end(), name) != keys.end())
  {
    update();
  }
  else if (active())
  {
    // The lit model's view shows the scene actors again for keys of its own.
    show(true);
  }
}

void SurfaceModelView::show(bool on)
{
  shown_ = on;
  for (Part& part : parts_)
  {
    part.actor->SetVisibility(on);
  }
  if (on)
  {
    view_->setPartsShown(false);
  }
}

void SurfaceModelView::update()
{
  const std::string& name = model_->text("model");
  if (surfaceModelKeys(name).empty())
  {
    // Another model: the lit model's view or the scene actors draw it.
    reported_.clear();
    if (active())
    {
      show(false);
      view_->requestRender();
    }
    return;
  }
  const std::shared_ptr<EnvironmentLighting> lighting = view_->lighting();
  if (!lighting)
  {
    return; // the first environment is still baking; lightingBusyChanged brings it
  }
  try
  {
    // Fresh actors, so a material that fails to apply leaves the previous ones untouched.
    std::vector<Part> made;
    const int count = std::min(view_->partCount(), int(model_->parts().size()));
    for (int i = 0; i < count; ++i)
    {
      if (!view_->partDrawn(i))
      {
        continue; // hidden parts are not drawn
      }
      const MaterialInstaller install = surfaceModelInstallerOf(*model_, i, *assets_);
      vtkNew<vtkAnisoPolyDataMapper> mapper;
      mapper->ScalarVisibilityOff();
      mapper->SetInputData(view_->partSurfaceToDraw(i));
      Part part;
      part.part = i;
      part.actor = vtkSmartPointer<vtkActor>::New();
      part.actor->SetMapper(mapper);
      setDrawingFrame(part.actor, view_->drawingFrame()); // the scene's parts, its point lights
      part.material = install(part.actor, renderer_, lighting);
      made.push_back(std::move(part));
    }
    for (Part& part : parts_)
    {
      renderer_->RemoveActor(part.actor);
    }
    parts_ = std::move(made);
    lighting_ = lighting;
    for (Part& part : parts_)
    {
      renderer_->AddActor(part.actor);
    }
    reported_.clear();
  }
  catch (const Error& e)
  {
    const std::string message = e.what();
    if (message != reported_)
    {
      reported_ = message;
      emit errorOccurred(QString::fromStdString(message));
    }
    // The previous picture stays: the surface model drawn before, or the other model's actors.
    if (active())
    {
      show(true);
    }
    return;
  }
  show(true);
  view_->requestRender();
}
} // namespace aniso
