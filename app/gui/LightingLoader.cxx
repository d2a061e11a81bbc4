#include "app/gui/LightingLoader.h"

#include "app/gui/Failure.h"
#include "app/gui/RenderErrorOutput.h"
#include "app/gui/SceneAssets.h"
#include "core/background_priority.h"
#include "core/error.h"
#include "core/parameters/choices.h"
#include "scene/SceneModel.h"
#include "vtkpasses/render/EnvironmentLighting.h"

#include <QThreadPool>
#include <QTimer>
#include <utility>
#include <vtkOpenGLRenderWindow.h>

namespace aniso
{
LightingLoader::LightingLoader(SceneModel* model, SceneAssets* assets, vtkRenderWindow* window,
                               RenderErrorOutput* errors, QObject* parent)
    : QObject(parent), model_(model), assets_(assets), window_(window), errors_(errors),
      pool_(new QThreadPool(this))
{
  // One bake at a time: a second would only compete for the cores with the first.
  pool_->setMaxThreadCount(1);
}

LightingLoader::~LightingLoader()
{
  // A bake in flight delivers to this loader; its queued result dies with it.
  pool_->waitForDone();
}

bool LightingLoader::environmentLightsOn() const
{
  return parseOnOff("env-lights", model_->text("env-lights")) == OnOff::On;
}

void LightingLoader::loadNow()
{
  lighting_ = std::make_shared<EnvironmentLighting>(assets_->environment(model_->text("env")),
                                                    model_->integer("cube-size"));
  lighting_->setRotationDegrees(model_->real("env-rotation"));
  sampled_ = true;
  if (!lighting_->prepared(parseEnvironmentSampling(model_->text("env-sampling"))) ||
      (environmentLightsOn() && !lighting_->bakedAnalysis()))
  {
    // The analysis (or what the sampling needs) comes from the worker; the lobe alone until then.
    request();
  }
}

void LightingLoader::request()
{
  ++request_;
  if (inFlight_)
  {
    pending_ = true;
  }
  else
  {
    startBake();
  }
  if (busy() && !busyShown_)
  {
    busyShown_ = true;
    emit busyChanged(true);
  }
}

void LightingLoader::startBake()
{
  pending_ = false;
  const int id = request_;
  const int cubeSize = model_->integer("cube-size");
  const EnvironmentSampling sampling = parseEnvironmentSampling(model_->text("env-sampling"));
  const bool analysed = environmentLightsOn();
  std::shared_ptr<const Environment> environment;
  try
  {
    // The model's validator loaded and checked it already: a hit of the assets' cache.
    environment = assets_->environment(model_->text("env"));
  }
  catch (const Error& e)
  {
    baked(id, nullptr, false, QString::fromStdString(e.what()));
    return;
  }
  const bool same = lighting_ && &lighting_->environment() == environment.get() &&
                    lighting_->cubeSize() == cubeSize;
  if (same && lighting_->prepared(sampling) && (!analysed || lighting_->bakedAnalysis()))
  {
    // Back to what is shown (an undo, or a change reverted while a bake ran).
    baked(id, lighting_, sampled_, QString());
    return;
  }
  // The same environment and cube, another sampling: its bakes are kept, the rest is added.
  std::shared_ptr<EnvironmentLighting> base = same ? lighting_->copyBakes() : nullptr;
  inFlight_ = true;
  pool_->start(
      [this, id, environment, cubeSize, sampling, analysed, base]
      {
        lowerThreadPriority(); // the window's renders first (background_priority.h)
        std::shared_ptr<EnvironmentLighting> lighting = base;
        const QString message = failureOf(
            [&]
            {
              if (!lighting)
              {
                lighting = std::make_shared<EnvironmentLighting>(environment, cubeSize);
              }
              // What the material's sampling needs (the analysis that resolves auto, the
              // distribution, the sources' split): never baked on the UI thread.
              lighting->prepare(sampling);
              // The sources the lit models and LEADR take as lights (env-lights).
              if (analysed)
              {
                lighting->analysis();
              }
            },
            tr("cube-size: %1 is too large for the memory available").arg(cubeSize));
        // Delivered on the UI thread; dropped with the loader if it is gone by then.
        QMetaObject::invokeMethod(
            this,
            [this, id, lighting, message] { baked(id, lighting, true, message); },
            Qt::QueuedConnection);
      });
}

void LightingLoader::baked(int id, std::shared_ptr<EnvironmentLighting> lighting, bool sampled,
                           const QString& error)
{
  inFlight_ = false;
  if (id != request_)
  {
    // Stale: the latest request bakes next.
    startBake();
    return;
  }
  if (!error.isEmpty())
  {
    // The lighting shown stays.
    emit failed(error);
  }
  else if (lighting != lighting_ && upload(*lighting, sampled))
  {
    // Its textures are in the GL now; the switch to it, with the first frame of the new shader
    // variant, comes in a later pass of the event loop (events in between are handled).
    next_ = std::move(lighting);
    nextSampled_ = sampled;
    nextId_ = id;
    QTimer::singleShot(kShowAfterMs, this, [this, id] { show(id); });
  }
  updateBusy();
}

bool LightingLoader::upload(EnvironmentLighting& lighting, bool sampled)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window_);
  if (!gl || !contextReady_)
  {
    return true; // no context yet: the first frame drawn with it uploads them
  }
  errors_->beginDrawing();
  const QString failure = failureOf(
      [&]
      {
        window_->MakeCurrent();
        lighting.cubeTexture(gl);
        if (sampled && lighting.prepared(EnvironmentSampling::Mis))
        {
          lighting.samplingCdfTexture(gl);
          lighting.samplingPdfTexture(gl);
          lighting.samplingGuideTexture(gl);
        }
        if (sampled && lighting.prepared(EnvironmentSampling::Sources))
        {
          lighting.residualCubeTexture(gl); // uploads every texture of the split
        }
      },
      tr("environment: its textures are too large for the memory available"));
  errors_->endDrawing();
  if (!failure.isEmpty())
  {
    // The lighting shown stays.
    emit failed(failure);
    return false;
  }
  return true;
}

void LightingLoader::show(int id)
{
  if (!next_ || id != nextId_)
  {
    return; // a later delivery took its place
  }
  std::shared_ptr<EnvironmentLighting> next = std::move(next_);
  next_.reset();
  if (id == request_)
  {
    next->setRotationDegrees(model_->real("env-rotation"));
    lighting_ = std::move(next);
    sampled_ = nextSampled_;
    emit shown();
  }
  updateBusy();
}

void LightingLoader::updateBusy()
{
  if (!busy() && busyShown_)
  {
    busyShown_ = false;
    emit busyChanged(false);
  }
}
} // namespace aniso
