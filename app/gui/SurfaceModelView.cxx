#include "app/gui/SurfaceModelView.h"

#include "app/gui/LitModelView.h"
#include "app/gui/SceneAssets.h"
#include "app/gui/SceneView.h"
#include "core/error.h"
#include "core/leadr/leadr.h"
#include "scene/SceneShading.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/SurfaceModelSettings.h"

#include <algorithm>
#include <vtkActor.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
glm::dvec3 colourOf(const SceneModel& model, std::string_view key)
{
  const std::array<double, 3> c = model.color(key);
  return {c[0], c[1], c[2]};
}

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
} // namespace

MaterialInstaller surfaceModelInstallerOf(const SceneModel& model, SceneAssets& assets)
{
  const DeclaredValues values = [&model](std::string_view key) -> const ParameterValue&
  { return model.value(key); };
  SurfaceModelInputs inputs;
  inputs.f0 = colourOf(model, "f0");
  inputs.albedo = colourOf(model, "albedo");
  inputs.lights = [&model] { return parseLightList(model.text("lights"), "lights"); };
  // As `aniso render --model leadr` without a map: the built-in relief.
  inputs.leadrMoments = [&model] { return leadrMoments(model.real("leadr-scale")); };
  inputs.tprMap = [&model, &assets] { return assets.map("tpr", model.text("tpr")); };
  return surfaceModelInstaller(model.text("model"), values, inputs);
}

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
  // The stand-in of a large surface while things move, the surface once still, as the view.
  connect(view_, &SceneView::interactionChanged, this,
          [this]
          {
            vtkMapper* mapper = actor_ ? actor_->GetMapper() : nullptr;
            vtkPolyData* mesh = view_->surfaceToDraw();
            if (mapper && mesh && mesh != mapper->GetInputDataObject(0, 0))
            {
              mapper->SetInputDataObject(mesh);
            }
          });
  update();
}

SurfaceModelView::~SurfaceModelView()
{
  material_.reset();
  if (actor_)
  {
    renderer_->RemoveActor(actor_);
  }
}

bool SurfaceModelView::active() const
{
  return actor_ && actor_->GetVisibility() != 0;
}

vtkActor* SurfaceModelView::surfaceActor() const
{
  return actor_;
}

void SurfaceModelView::keyChanged(const QString& key)
{
  const std::string name = key.toStdString();
  const std::vector<std::string_view> keys = surfaceModelKeys(model_->text("model"));
  // The keys that change the picture of a surface model: the shared ones and its declared ones.
  if (sceneKeyAffects(name, Affects::SurfaceModels) ||
      std::find(keys.begin(), keys.end(), name) != keys.end())
  {
    update();
  }
  else if (active())
  {
    // The lit model's view shows the scene actor again for keys of its own.
    show(true);
  }
}

void SurfaceModelView::show(bool on)
{
  if (actor_)
  {
    actor_->SetVisibility(on);
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
    // Another model: the lit model's view or the scene actor draws it.
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
    const MaterialInstaller install = surfaceModelInstallerOf(*model_, *assets_);
    // A fresh actor, so a material that fails to apply leaves the previous one untouched.
    vtkNew<vtkOpenGLPolyDataMapper> mapper;
    mapper->ScalarVisibilityOff();
    mapper->SetInputData(view_->surfaceToDraw());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    setDrawingFrame(actor, view_->drawingFrame()); // the scene's parts, its point lights
    std::shared_ptr<void> material = install(actor, renderer_, lighting);
    if (actor_)
    {
      renderer_->RemoveActor(actor_);
    }
    material_ = std::move(material);
    actor_ = actor;
    lighting_ = lighting;
    renderer_->AddActor(actor_);
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
    // The previous picture stays: the surface model drawn before, or the other model's actor.
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
