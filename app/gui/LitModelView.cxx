#include "app/gui/LitModelView.h"

#include "app/gui/SceneView.h"
#include "core/error.h"
#include "scene/SceneShading.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/LitModelMaterial.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkOpenGLPolyDataMapper.h>
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
  settings.lights = parseLightList(model.text("lights"), "lights");
  const std::string& sample = model.text("sample-material");
  if (sample == kUniformSampleMaterial)
  {
    const std::array<double, 3> f0 = model.color("f0");
    const std::array<double, 3> albedo = model.color("albedo");
    settings.maps = std::make_shared<const SvMaps>(uniformSvMaps(
        uniformTexel(AsLobe{model.real("nu"), model.real("nv")}, glm::dvec3(f0[0], f0[1], f0[2]),
                     glm::dvec3(albedo[0], albedo[1], albedo[2]))));
  }
  else
  {
    settings.maps = sampleMaps(sample);
  }
}

LitModelView::LitModelView(SceneModel* model, SceneView* view, QObject* parent)
    : QObject(parent), model_(model), view_(view), renderer_(view->renderer())
{
  mapper_->ScalarVisibilityOff();
  actor_->SetMapper(mapper_);
  actor_->VisibilityOff();
  renderer_->AddActor(actor_);
  // Connected after the view, so the view's mesh is already in place when this runs.
  connect(model_, &SceneModel::valueChanged, this,
          [this](const QString& key)
          {
            // Only the keys the lit actor depends on: any other change leaves it as it is.
            if (sceneKeyAffects(key.toStdString(), Affects::LitModels))
            {
              update();
            }
          });
  // The stand-in of a large surface while things move, the surface once still, as the view.
  connect(view_, &SceneView::interactionChanged, this,
          [this]
          {
            vtkPolyData* mesh = view_->surfaceToDraw();
            if (mapper_->GetInput() && mesh && mesh != mapper_->GetInput())
            {
              mapper_->SetInputData(mesh);
            }
          });
  update();
}

LitModelView::~LitModelView()
{
  if (material_)
  {
    material_->detach();
  }
  renderer_->RemoveActor(actor_);
  view_->setPartsShown(true);
}

bool LitModelView::active() const
{
  return actor_->GetVisibility() != 0;
}

vtkActor* LitModelView::litActor() const
{
  return actor_;
}

void LitModelView::update()
{
  LitModelSettings settings;
  bool lit = false;
  try
  {
    lit = litSettingsOf(*model_, settings);
    // The surface models (LEADR, microstructure) are SurfaceModelView's.
    if (lit)
    {
      vtkPolyData* mesh = view_->surfaceToDraw();
      if (mesh != mapper_->GetInput())
      {
        mapper_->SetInputData(mesh);
      }
      setDrawingFrame(actor_, view_->drawingFrame()); // the scene's parts, its point lights
      if (!material_)
      {
        material_ = std::make_unique<LitModelMaterial>(settings);
        material_->apply(actor_, renderer_);
      }
      else
      {
        material_->setSettings(settings);
      }
    }
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromUtf8(e.what()));
    // The previous picture stays rather than a half-applied one.
    return;
  }
  actor_->SetVisibility(lit);
  view_->setPartsShown(!lit);
  view_->requestRender();
}
} // namespace aniso
