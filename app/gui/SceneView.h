#pragma once
// Draws the scene of a SceneModel in a VTK render window with the anisotropic material, on
// demand only: a change of the model or the camera asks for one frame; while things move
// (a drag, a camera interaction) frames are cheap (one sample per pixel; the window draws them
// at reduced resolution, see interactionChanged); once still for a moment, frames accumulate
// (progressive refinement) until the quality's sample count is reached, then nothing is drawn
// until something changes. Lookup tables come from the LutScheduler's bakes, so a new n_u, n_v
// never bakes on the UI thread: until its tables are ready the material keeps the previous
// exponents. Likewise a new environment or cube size is baked (cubemap, SH9 and, with
// environment sampling on, its distribution) on a worker thread: the latest request wins, the
// previous lighting stays on screen until the new one is ready, and a failed bake is reported
// once and changes nothing.
#include "DisplaySettings.h"
#include "MaterialSettings.h"
#include "OffscreenRenderer.h"
#include "SceneModel.h"

#include <QObject>
#include <QString>
#include <memory>
#include <set>
#include <string>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

class QThreadPool;
class QTimer;
class vtkActor;
class vtkAnisoAccumulationPass;
class vtkOpenGLPolyDataMapper;
class vtkOpenGLRenderer;
class vtkRenderStepsPass;
class vtkRenderWindow;
class vtkCallbackCommand;

namespace aniso
{
class AnisoMaterial;
class EnvironmentLighting;
class ErrorForwardingWindow;
class LutScheduler;
class SceneAssets;

class SceneView : public QObject
{
  Q_OBJECT

public:
  // Samples per pixel of the frames drawn while something moves.
  static constexpr int kInteractiveSamples = 1;
  static constexpr int kDefaultSettleMs = 300;

  SceneView(SceneModel* model, SceneAssets* assets, LutScheduler* luts, vtkRenderWindow* window,
            QObject* parent = nullptr);
  ~SceneView() override;

  vtkOpenGLRenderer* renderer() const;
  // Everything renderOffscreen needs to redraw the current view at WIDTH x HEIGHT with the full
  // quality (the target sample count).
  RenderSettings renderSettings(int width, int height) const;

  // Frames the current mesh from the default direction and forgets any stored camera.
  void resetCamera();
  // The window's camera as the model stores it.
  CameraState currentCamera() const;

  int accumulatedSamples() const;
  int targetSamples() const;
  bool converged() const;
  bool interacting() const { return interacting_; }
  void setSettleMs(int ms);
  // True from a change of the environment or cube size until its lighting is on screen (or
  // its bake failed).
  bool lightingBusy() const { return lightingInFlight_ || lightingPending_; }
  // The lighting the view draws with.
  const std::shared_ptr<EnvironmentLighting>& lighting() const { return lighting_; }

public slots:
  // One frame soon (several requests before it make one frame).
  void requestRender();

signals:
  void frameRendered(int samples, int targetSamples);
  void errorOccurred(const QString& message);
  void noteAdded(const QString& note);
  void lightingBusyChanged(bool busy);
  // Something started moving (cheap frames from now on) or settled (refinement).
  void interactionChanged(bool interacting);

private:
  void modelChanged(const QString& key);
  void applySurface();
  void applyLighting();
  // Bakes the model's environment at its cube size on the worker (one bake at a time; a request
  // made meanwhile runs next, and the finished stale one is dropped).
  void requestLighting();
  void startLightingBake();
  void lightingBaked(int id, std::shared_ptr<EnvironmentLighting> lighting, const QString& error);
  // Errors of the renderer (VTK's error output while drawing, glGetError after a frame), each
  // distinct message reported once.
  void reportRenderError(const std::string& message);
  void applyMaterial();
  void applyDisplay();
  void applyCameraFromModel();
  void renderNow();
  void beginInteraction();
  void settle();

  SceneModel* model_;
  SceneAssets* assets_;
  LutScheduler* luts_;
  vtkRenderWindow* window_;
  vtkNew<vtkOpenGLRenderer> renderer_;
  vtkNew<vtkActor> actor_;
  vtkNew<vtkOpenGLPolyDataMapper> mapper_;
  vtkNew<vtkRenderStepsPass> steps_;
  vtkNew<vtkAnisoAccumulationPass> pass_;
  vtkNew<vtkCallbackCommand> interactionObserver_;
  std::shared_ptr<EnvironmentLighting> lighting_;
  std::unique_ptr<AnisoMaterial> material_;
  MaterialSettings full_; // what the model asks for, LUT inputs held back until baked
  double surfaceRadius_ = 1.0;
  double surfaceCentre_[3] = {0.0, 0.0, 0.0};
  QTimer* settle_;
  QTimer* frame_;
  bool interacting_ = false;
  bool applyingCamera_ = false;
  bool cameraMoved_ = false;
  QThreadPool* lightingPool_;
  int lightingRequest_ = 0; // sequence number of the latest lighting request
  bool lightingInFlight_ = false;
  bool lightingPending_ = false;   // a request arrived while a bake ran
  bool lightingBusyShown_ = false; // lightingBusyChanged(true) was the last sent
  std::set<std::string> reportedRenderErrors_;
  bool maxTextureSideKnown_ = false;
  vtkSmartPointer<ErrorForwardingWindow> errorOutput_;
};
} // namespace aniso
