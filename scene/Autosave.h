#pragma once
// Nothing of the user's tuning is lost when the application does not exit normally: the scene
// is saved as a session, a moment after the last edit (debounced, so a slider drag writes once),
// atomically (SessionFile::save: a temporary file renamed), to a file of this process's own in
// the state directory ($XDG_STATE_HOME/aniso, else ~/.local/state/aniso). A marker file says the
// process is running; a normal exit (the destructor) removes both. At the next start, a marker
// whose process is gone means that process ended abnormally, and its last autosave is offered
// (crashedSessions); once dealt with (restored or declined), forget() removes it.
#include <QDateTime>
#include <QObject>
#include <QString>
#include <vector>

class QTimer;

namespace aniso
{
class SceneModel;
class SessionFile;

// An autosave left by a process that did not exit normally.
struct CrashedSession
{
  QString path;        // the autosaved session
  QString marker;      // that process's marker
  QDateTime savedAt;   // when it was last written
};

class Autosave : public QObject
{
  Q_OBJECT

public:
  static constexpr int kDefaultDelayMs = 2000;

  // Saves MODEL's scene (with SESSION's kept unknown keys, when given) into DIRECTORY (made if
  // missing; empty: stateDirectory()) DELAY_MS after the last of a series of edits.
  Autosave(const SceneModel* model, const SessionFile* session, const QString& directory = {},
           int delayMs = kDefaultDelayMs, QObject* parent = nullptr);
  // A normal exit: the autosave and the marker are removed.
  ~Autosave() override;

  // $XDG_STATE_HOME/aniso, or ~/.local/state/aniso.
  static QString stateDirectory();
  // The autosaves in DIRECTORY of processes that are gone without exiting normally, the newest
  // first (this process's own never among them).
  static std::vector<CrashedSession> crashedSessions(const QString& directory);
  // Removes a crashed session's files.
  static void forget(const CrashedSession& session);

  const QString& path() const { return path_; }
  // Writes now (what the timer would do); false when it failed (reported by failed()).
  bool saveNow();

signals:
  void saved(const QString& path);
  // The autosave could not be written: its file and the reason, once per run of failures.
  void failed(const QString& message);

private:
  const SceneModel* model_;
  const SessionFile* session_;
  QString directory_;
  QString path_;
  QString marker_;
  QTimer* timer_;
  bool failing_ = false;
};
} // namespace aniso
