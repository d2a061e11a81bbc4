#pragma once
// Draws the scene with the LEADR or the microstructure model when the scene chooses one ("model"
// key, SceneShading.h), as LitModelView does for the lit models: actors of its own in the view's
// renderer, one per drawn part, draw each part's surface (SceneView::partSurfaceToDraw) with a
// LeadrShadingMaterial or MicrostructureShadingMaterial (vtkpasses/render/LeadrMaterial.h,
// MicrostructureMaterial.h) of that part's material, and are shown in place of the view's own
// actors while the model is one of them. The settings come from the scene's declared keys
// (surfaceModelKeys) and lights, and the part's F0, albedo and TPR map, as `aniso render --model
// NAME` takes them from its options. These materials take no new settings once made, so each
// change of what they draw (a key, a part's material, the parts drawn) builds new actors and
// materials for the parts; one that fails leaves the previous picture on screen and is reported
// once. The stand-ins while moving are swapped into the actors' mappers.
#include "scene/SceneModel.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <QObject>
#include <memory>
#include <string>
#include <vector>

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
// The same for part PART (a valid index): its material's F0, albedo and TPR map over the scene's
// settings (SceneModel::partParameters).
MaterialInstaller surfaceModelInstallerOf(const SceneModel& model, int part, SceneAssets& assets);

class SurfaceModelView : public QObject
{
  Q_OBJECT

public:
  // VIEW and ASSETS must outlive this object; the renderer's first actor is the one it replaces.
  SurfaceModelView(SceneModel* model, SceneAssets* assets, SceneView* view,
                   QObject* parent = nullptr);
  ~SurfaceModelView() override;

  // True while the surface model's actors are the ones on screen.
  bool active() const;
  // The actor drawing the first drawn part with the surface model (null before the first
  // success).
  vtkActor* surfaceActor() const;
  // The actor drawing part PART with the surface model (null when it draws none).
  vtkActor* partActor(int part) const;

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
  struct Part;
  std::vector<Part> parts_; // the drawn parts' actors, in part order
  bool shown_ = false;      // the surface model's actors are on screen
  std::shared_ptr<EnvironmentLighting> lighting_; // what material_ draws with
  std::string reported_; // the last error reported, so a repeated failure says nothing new
};
} // namespace aniso
