#include "scene/Autosave.h"

#include "core/error.h"
#include "scene/SceneModel.h"
#include "scene/Session.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTimer>
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <sys/types.h>
#include <unistd.h>

namespace aniso
{
namespace
{
const QString kMarkerPrefix = QStringLiteral("running-");
const QString kSessionPrefix = QStringLiteral("autosave-");

QString markerName(qint64 pid)
{
  return kMarkerPrefix + QString::number(pid);
}

QString sessionName(qint64 pid)
{
  return kSessionPrefix + QString::number(pid) + QStringLiteral(".aniso");
}

// The process PID exists (kill with signal 0 checks without sending; EPERM: it exists but
// belongs to someone else).
bool processExists(qint64 pid)
{
  return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
}
} // namespace

Autosave::Autosave(const SceneModel* model, const SessionFile* session, const QString& directory,
                   int delayMs, QObject* parent)
    : QObject(parent), model_(model), session_(session),
      directory_(directory.isEmpty() ? stateDirectory() : directory), timer_(new QTimer(this))
{
  const qint64 pid = QCoreApplication::applicationPid();
  QDir().mkpath(directory_);
  path_ = QDir(directory_).filePath(sessionName(pid));
  marker_ = QDir(directory_).filePath(markerName(pid));
  QFile marker(marker_);
  if (!marker.open(QIODevice::WriteOnly | QIODevice::Truncate))
  {
    // Without a marker a crash would not be noticed; saving still happens.
    failing_ = true;
    QTimer::singleShot(0, this, [this] {
      emit failed(tr("%1: cannot write the autosave marker (%2)").arg(marker_, directory_));
    });
  }
  timer_->setSingleShot(true);
  timer_->setInterval(delayMs);
  connect(timer_, &QTimer::timeout, this, [this] { saveNow(); });
  connect(model_, &SceneModel::valueChanged, timer_, qOverload<>(&QTimer::start));
  connect(model_, &SceneModel::cameraChanged, timer_, qOverload<>(&QTimer::start));
  connect(model_, &SceneModel::partsChanged, timer_, qOverload<>(&QTimer::start));
  connect(model_, &SceneModel::materialsChanged, timer_, qOverload<>(&QTimer::start));
}

Autosave::~Autosave()
{
  QFile::remove(path_);
  QFile::remove(marker_);
}

QString Autosave::stateDirectory()
{
  const QByteArray state = qgetenv("XDG_STATE_HOME");
  const QString base = !state.isEmpty() && QDir::isAbsolutePath(QString::fromLocal8Bit(state))
                           ? QString::fromLocal8Bit(state)
                           : QDir::homePath() + QStringLiteral("/.local/state");
  return base + QStringLiteral("/aniso");
}

std::vector<CrashedSession> Autosave::crashedSessions(const QString& directory)
{
  std::vector<CrashedSession> found;
  const QDir dir(directory);
  const qint64 self = QCoreApplication::applicationPid();
  for (const QString& name : dir.entryList({kMarkerPrefix + QStringLiteral("*")}, QDir::Files))
  {
    bool ok = false;
    const qint64 pid = name.mid(kMarkerPrefix.size()).toLongLong(&ok);
    if (!ok || pid == self || processExists(pid))
    {
      continue; // another instance still running, or not a marker of ours
    }
    CrashedSession crashed;
    crashed.marker = dir.filePath(name);
    crashed.path = dir.filePath(sessionName(pid));
    const QFileInfo info(crashed.path);
    if (!info.isFile())
    {
      QFile::remove(crashed.marker); // it ended before its first autosave: nothing to offer
      continue;
    }
    crashed.savedAt = info.lastModified();
    found.push_back(crashed);
  }
  std::sort(found.begin(), found.end(), [](const CrashedSession& a, const CrashedSession& b)
            { return a.savedAt > b.savedAt; });
  return found;
}

void Autosave::forget(const CrashedSession& session)
{
  QFile::remove(session.path);
  QFile::remove(session.marker);
}

bool Autosave::saveNow()
{
  timer_->stop();
  try
  {
    if (session_)
    {
      session_->save(*model_, path_);
    }
    else
    {
      SessionFile().save(*model_, path_);
    }
  }
  catch (const Error& e)
  {
    if (!failing_)
    {
      failing_ = true;
      emit failed(tr("Autosave: %1").arg(QString::fromStdString(e.what())));
    }
    return false;
  }
  failing_ = false;
  emit saved(path_);
  return true;
}
} // namespace aniso
