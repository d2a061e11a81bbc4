#pragma once
// Draws the scene with the LEADR or the microstructure model when the scene chooses one ("model"
// key, SceneShading.h), as LitModelView does for the lit models: a second actor in the view's
// renderer draws the view's mesh with a LeadrShadingMaterial or MicrostructureShadingMaterial
// (vtkpasses/render/LeadrMaterial.h, MicrostructureMaterial.h) and is shown in place of the view's own
// actor while the model is one of them. The settings come from the scene's declared keys
// (surfaceModelKeys), lights, F0, albedo and TPR map, as `aniso render --model NAME` takes them
// from its options. Each change builds a new actor and material; one that fails leaves the
// previous picture on screen and is reported once.
#include "scene/SceneModel.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <QObject>
#include <memory>
#include <string>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkRenderer;

namespace aniso
{
class EnvironmentLighting;
class SceneAssets;
class SceneView;

// The installer (RenderSettings::installMaterial) of the surface model MODEL's scene chooses,
// or an empty one when its model is neither leadr nor microstructure. Maps come through
// ASSETS. Throws aniso::Error "KEY: reason" for settings the model refuses.
MaterialInstaller surfaceModelInstallerOf(const SceneModel& model, SceneAssets& assets);

class SurfaceModelView : public QObject
{
  Q_OBJECT

public:
  // VIEW and ASSETS must outlive this object; the renderer's first actor is the one it replaces.
  SurfaceModelView(SceneModel* model, SceneAssets* assets, SceneView* view,
                   QObject* parent = nullptr);
  ~SurfaceModelView() override;

  // True while the surface model's actor is the one on screen.
  bool active() const;
  // The actor drawing the surface model (null before the first success).
  vtkActor* surfaceActor() const;

signals:
  void errorOccurred(const QString& message);

private:
  void keyChanged(const QString& key);
  void update();
  void show(bool on);

  SceneModel* model_;
  SceneAssets* assets_;
  SceneView* view_;
  vtkRenderer* renderer_;
  vtkSmartPointer<vtkActor> actor_;
  std::shared_ptr<void> material_;                // owned by the actor it was applied to
  std::shared_ptr<EnvironmentLighting> lighting_; // what material_ draws with
  std::string reported_; // the last error reported, so a repeated failure says nothing new
};
} // namespace aniso
