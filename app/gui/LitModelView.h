#pragma once
// Draws the scene with the lit model the scene chooses ("model" key, SceneShading.h) instead of
// the environment material: a second actor in the view's renderer, drawing the same mesh with a
// LitModelMaterial under the scene's lights and sample material, shown in place of the view's
// parts' actors while the model is a lit one (as `aniso render --model` does offscreen). The view's
// actor keeps its environment material, so going back to as-env costs nothing.
#include "core/lights/light.h"
#include "core/models/models.h"
#include "scene/SceneModel.h"

#include <QObject>
#include <memory>
#include <string>
#include <vtkNew.h>

class vtkActor;
class vtkOpenGLPolyDataMapper;
class vtkRenderer;

namespace aniso
{
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

class LitModelView : public QObject
{
  Q_OBJECT

public:
  // VIEW must outlive this object; its parts' actors are the ones it replaces.
  LitModelView(SceneModel* model, SceneView* view, QObject* parent = nullptr);
  ~LitModelView() override;

  // True while the lit actor is the one on screen.
  bool active() const;
  vtkActor* litActor() const;

signals:
  void errorOccurred(const QString& message);

private:
  void update();

  SceneModel* model_;
  SceneView* view_;
  vtkRenderer* renderer_;
  vtkNew<vtkActor> actor_;
  vtkNew<vtkOpenGLPolyDataMapper> mapper_;
  std::unique_ptr<LitModelMaterial> material_;
};
} // namespace aniso
