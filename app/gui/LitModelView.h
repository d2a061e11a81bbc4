#pragma once
// Draws the scene with the lit model the scene chooses ("model" key, SceneShading.h) instead of
// the environment material: actors of its own in the view's renderer, one per drawn part, each
// drawing the part's surface (SceneView::partSurfaceToDraw) with a LitModelMaterial of that
// part's material (SceneView::partParameters) under the scene's lights, shown in place of the
// view's parts' actors while the model is a lit one (as `aniso render --model` does offscreen).
// Actors and materials are kept per part: edits, new materials, shown or hidden parts and the
// stand-ins while moving set their inputs and settings. The view's actors keep their
// environment materials, so going back to as-env costs nothing.
#include "core/lights/light.h"
#include "core/models/models.h"
#include "scene/SceneModel.h"

#include <QObject>
#include <memory>
#include <string>
#include <vector>

class vtkActor;
class vtkRenderer;

namespace aniso
{
class EnvironmentLighting;
class LitModelMaterial;
class SceneView;
struct LitModelSettings;

// The lit settings of MODEL's scene: its lit model (false when "model" is not one), lights and
// material (the sample material, or the uniform one of n_u, n_v, F0 and albedo). Throws
// aniso::Error "KEY: reason" for lights or a sample material that cannot be used.
bool litSettingsOf(const SceneModel& model, LitModelSettings& settings);
// The first actor added to RENDERER (the view's own), or null.
vtkActor* firstActorOf(vtkRenderer* renderer);
// The lights and material of MODEL's scene into SETTINGS, whatever its model (the comparison
// view draws them with every lit model). Throws as litSettingsOf.
void litSceneOf(const SceneModel& model, LitModelSettings& settings);
// The same for a part drawn with PARAMETERS (SceneModel::partParameters): the scene's lights, and
// the uniform material of the part's n_u, n_v, F0 and albedo (or the scene's sample material when
// it chooses one). With env-lights on, the lights are followed by the sources of LIGHTING's
// analysis (the lighting on screen) turned by env-rotation, up to LitModelMaterial::kMaxLights in
// all (core/lights/env_lights.h), when it has its analysis baked (LightingLoader bakes it on its
// worker; never made here): none until then. Throws as litSettingsOf.
void litSceneOf(const SceneModel& model, const ParameterSet& parameters,
                LitModelSettings& settings, const EnvironmentLighting* lighting = nullptr);

class LitModelView : public QObject
{
  Q_OBJECT

public:
  // VIEW must outlive this object; its parts' actors are the ones it replaces.
  LitModelView(SceneModel* model, SceneView* view, QObject* parent = nullptr);
  ~LitModelView() override;

  // True while the lit actors are the ones on screen.
  bool active() const;
  // The first drawn part's lit actor (null when no part is drawn).
  vtkActor* litActor() const;
  // Part PART's lit actor while it is in the renderer (the part drawn, the model a lit one, or
  // null).
  vtkActor* partActor(int part) const;
  // Part PART's lit material (null while it has no actor in the renderer).
  const LitModelMaterial* partMaterial(int part) const;

signals:
  void errorOccurred(const QString& message);

private:
  struct Part;
  void update();
  // The mappers' inputs: what the view's parts draw now (the stand-ins while moving).
  void followSurfaces();

  SceneModel* model_;
  SceneView* view_;
  vtkRenderer* renderer_;
  bool active_ = false;
  const EnvironmentLighting* lighting_ = nullptr; // whose sources the lights hold
  std::vector<std::unique_ptr<Part>> parts_; // parallel to the view's parts
};
} // namespace aniso
