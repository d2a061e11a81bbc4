#include "app/gui/BackgroundLoader.h"

#include "app/gui/Failure.h"
#include "app/gui/SceneAssets.h"
#include "core/background_priority.h"

#include <QThreadPool>
#include <memory>

namespace aniso
{
BackgroundLoader::BackgroundLoader(SceneAssets* assets, QObject* parent)
    : QObject(parent), assets_(assets), pool_(new QThreadPool(this))
{
  // A mesh and an environment may load at once; more would only compete for the two cores.
  pool_->setMaxThreadCount(2);
}

BackgroundLoader::~BackgroundLoader()
{
  pool_->waitForDone();
}

bool BackgroundLoader::loading(const std::string& kind) const
{
  const auto it = requests_.find(kind);
  return it != requests_.end() && it->second.loading;
}

void BackgroundLoader::cancel(const std::string& kind)
{
  const auto it = requests_.find(kind);
  if (it == requests_.end() || !it->second.loading)
  {
    return;
  }
  // The worker's delivery finds a later number and drops what it read.
  ++it->second.latest;
  it->second.loading = false;
  emit finished();
  emit ended(QString::fromStdString(kind));
}

void BackgroundLoader::load(const std::string& kind, const QString& name, const Load& load,
                            const Deliver& deliver, bool prefetch)
{
  Requests& requests = requests_[kind];
  const int id = ++requests.latest;
  requests.loading = true;
  emit started(name);
  emit began(QString::fromStdString(kind), name);
  // The worker loads into assets of its own; this thread takes them over on delivery.
  auto staged = std::make_shared<SceneAssets>();
  staged->setMaxTextureSide(assets_->maxTextureSide());
  // Read as the scene's assets read (a CAD file's tessellation), so that what it reads is found
  // there under the same keys.
  staged->setMeshReadOptions(assets_->meshReadOptions());
  pool_->start(
      [this, kind, id, name, staged, load, deliver, prefetch]
      {
        lowerThreadPriority(); // the window's renders first (background_priority.h)
        const QString error = failureOf([&] { load(*staged); },
                                        tr("%1: too large for the memory available").arg(name));
        // Delivered on the UI thread (the loader waits for its workers before it goes).
        QMetaObject::invokeMethod(
            this,
            [this, kind, id, staged, error, deliver, prefetch]
            {
              Requests& latest = requests_[kind];
              if (id != latest.latest)
              {
                return; // a later request took its place
              }
              latest.loading = false;
              emit finished();
              emit ended(QString::fromStdString(kind));
              assets_->adopt(*staged);
              if (!error.isEmpty() && !prefetch)
              {
                // The scene stays as it was.
                emit failed(error);
                return;
              }
              // A prefetch that failed leaves the failure to DELIVER's own reading, which
              // reports it in its words.
              deliver();
            },
            Qt::QueuedConnection);
      });
}
} // namespace aniso
