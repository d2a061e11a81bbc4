#pragma once
// The window's background loads: what a file names (a mesh, an environment, a map, what a
// session names) is read on a worker thread into assets of its own (a staging SceneAssets),
// read as the scene's assets read (SceneAssets::meshReadOptions), which the scene's assets then
// take over on the UI thread before what opens it runs, reading
// nothing again. Of each kind of request the latest wins (an earlier one that finishes later is
// dropped); a failure is reported once, in the loader's words (with the file's name), and
// leaves the scene as it was.
#include <QObject>
#include <QString>
#include <functional>
#include <map>
#include <string>

class QThreadPool;

namespace aniso
{
class SceneAssets;

class BackgroundLoader : public QObject
{
  Q_OBJECT

public:
  using Load = std::function<void(SceneAssets& staged)>;
  using Deliver = std::function<void()>;

  // Loads into staging assets handed over to ASSETS.
  explicit BackgroundLoader(SceneAssets* assets, QObject* parent = nullptr);
  // Waits for the loads in flight (their results are dropped).
  ~BackgroundLoader() override;

  // Runs LOAD on a worker (started(NAME), loading(KIND) true), then on this thread, unless a
  // later request of KIND took its place: finished(), the staged assets taken into the scene's,
  // and DELIVER, unless LOAD threw: then failed(message) and DELIVER does not run, or with
  // PREFETCH, DELIVER runs all the same (and reports the failure itself, in its words).
  void load(const std::string& kind, const QString& name, const Load& load, const Deliver& deliver,
            bool prefetch = false);
  // A request of KIND is loading.
  bool loading(const std::string& kind) const;
  // The request of KIND in flight is dropped: its result never reaches the scene (the worker's
  // read runs out, its result is discarded); ended(KIND) follows. Nothing when none loads.
  void cancel(const std::string& kind);

signals:
  void started(const QString& name);
  // A request of KIND (named NAME) loads; the same until ended(KIND), a later request of KIND
  // taking its place.
  void began(const QString& kind, const QString& name);
  // No request of KIND loads any longer (delivered, failed or cancelled).
  void ended(const QString& kind);
  // The latest request of a kind is done loading (before it is delivered or fails).
  void finished();
  void failed(const QString& message);

private:
  struct Requests
  {
    int latest = 0; // sequence number of the latest request
    bool loading = false;
  };
  SceneAssets* assets_;
  QThreadPool* pool_;
  std::map<std::string, Requests> requests_;
};
} // namespace aniso
