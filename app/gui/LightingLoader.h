#pragma once
// The lighting a view draws with (EnvironmentLighting.h: cubemap, SH9 and, with environment
// sampling on, its distribution), baked from the model's environment at its cube size. A new one
// is baked on a worker thread, one bake at a time: the latest request wins (a request made while
// a bake runs bakes next, and the finished stale one is dropped), the previous lighting stays
// until the new one is ready, and a failed bake is reported once and changes nothing. A baked
// lighting reaches the view over separate passes of the event loop, so their costs never add up
// in one stall: its textures are uploaded into the view's window in one, the view switches to it
// (shown) in a later one.
#include "core/parameters/choices.h"
#include "vtkpasses/render/EnvironmentLighting.h"

#include <QObject>
#include <QString>
#include <memory>

class QThreadPool;
class vtkRenderWindow;

namespace aniso
{
class EnvironmentLighting;
class RenderErrorOutput;
class SceneAssets;
class SceneModel;

class LightingLoader : public QObject
{
  Q_OBJECT

public:
  // The wait between a lighting's upload and its showing: the events in between are handled.
  static constexpr int kShowAfterMs = 10;
  // Uploads go into WINDOW's GL context, VTK's errors meanwhile to ERRORS.
  LightingLoader(SceneModel* model, SceneAssets* assets, vtkRenderWindow* window,
                 RenderErrorOutput* errors, QObject* parent = nullptr);
  // Waits for a bake in flight (its result is dropped).
  ~LightingLoader() override;

  // Bakes the lighting the model names on this thread: the view's first.
  void loadNow();
  // The window has drawn once: its GL context exists, baked lightings are uploaded into it
  // (until then the first frame drawn with one uploads its textures).
  void setContextReady() { contextReady_ = true; }
  // Bakes the model's environment at its cube size (with what its env-sampling needs: the
  // analysis, the distribution or the sources' split; and the analysis with env-lights on) on
  // the worker. Back to the lighting shown (an undo, a change reverted while a bake ran):
  // nothing is baked.
  void request();

  // The lighting shown.
  const std::shared_ptr<EnvironmentLighting>& lighting() const { return lighting_; }
  // It has what a material sampling the environment by SAMPLING needs (its analysis,
  // distribution or sources' split), baked on the worker.
  bool prepared(EnvironmentSampling sampling) const
  {
    return lighting_ && sampled_ && lighting_->prepared(sampling);
  }
  // True from a request until its lighting is shown (or its bake failed).
  bool busy() const { return inFlight_ || pending_ || next_ != nullptr; }

signals:
  // A baked lighting is lighting() now (its textures were uploaded in an earlier pass).
  void shown();
  void busyChanged(bool busy);
  void failed(const QString& message);

private:
  void startBake();
  // env-lights is on: the analysis is baked with every lighting (its sources are the lit
  // models' and LEADR's lights), whatever env-sampling needs.
  bool environmentLightsOn() const;
  // LIGHTING's textures (SAMPLED: its distribution's too) into the window's context, drawing
  // nothing; false when that failed (reported).
  bool upload(EnvironmentLighting& lighting, bool sampled);
  void baked(int id, std::shared_ptr<EnvironmentLighting> lighting, bool sampled,
             const QString& error);
  // Makes the uploaded next_ lighting() unless a later request took its place.
  void show(int id);
  // busyChanged(false) once no lighting is baked or waiting to be shown.
  void updateBusy();

  SceneModel* model_;
  SceneAssets* assets_;
  vtkRenderWindow* window_;
  RenderErrorOutput* errors_;
  bool contextReady_ = false;
  QThreadPool* pool_;
  std::shared_ptr<EnvironmentLighting> lighting_;
  bool sampled_ = false;
  int request_ = 0; // sequence number of the latest request
  bool inFlight_ = false;
  bool pending_ = false;   // a request arrived while a bake ran
  bool busyShown_ = false; // busyChanged(true) was the last sent
  // A baked lighting whose textures are uploaded, shown by a later pass of the event loop.
  std::shared_ptr<EnvironmentLighting> next_;
  bool nextSampled_ = false;
  int nextId_ = 0;
};
} // namespace aniso
