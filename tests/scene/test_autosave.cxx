// The autosave (scene/Autosave.h): a process killed with SIGKILL in the middle of its edits
// leaves its last autosave, which the next start finds and which opens to the values edited
// before it (the reference: the values the killed process set); a normal exit leaves nothing;
// a drag's series of edits writes once; running instances and processes that never autosaved
// are not offered; a directory that cannot be written is reported once, naming it.
#include "scene/Autosave.h"
#include "scene/SceneEditor.h"
#include "scene/Session.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <csignal>
#include <cstring>

using aniso::Autosave;
using aniso::SceneModel;

namespace
{
constexpr double kSavedNu = 1234.0;   // set, then autosaved, before the kill
constexpr double kUnsavedNu = 4321.0; // set just before the kill, inside the autosave's delay

// The child: edits, waits for the autosave, edits again and is killed before that one is saved.
int runChild(const QString& directory)
{
  SceneModel model;
  aniso::SceneEditor editor(&model);
  aniso::SessionFile session;
  Autosave autosave(&model, &session, directory, 50);
  editor.edit("nu", aniso::numberValue(kSavedNu));
  QSignalSpy saved(&autosave, &Autosave::saved);
  if (!saved.wait(5000))
  {
    return 3;
  }
  editor.edit("nu", aniso::numberValue(kUnsavedNu));
  std::raise(SIGKILL);
  return 4;
}
} // namespace

class TestAutosave : public QObject
{
  Q_OBJECT

private slots:
  void aKilledProcessLeavesItsLastAutosave()
  {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QProcess child;
    child.start(QCoreApplication::applicationFilePath(), {"--autosave-child", dir.path()});
    QVERIFY(child.waitForFinished(20000));
    QCOMPARE(child.exitStatus(), QProcess::CrashExit); // killed, not returned
    const std::vector<aniso::CrashedSession> crashed = Autosave::crashedSessions(dir.path());
    QCOMPARE(crashed.size(), std::size_t(1));
    // The next start restores it as a session: the value set before the autosave comes back.
    SceneModel restored;
    aniso::SceneEditor editor(&restored);
    aniso::SessionFile session;
    session.open(editor, crashed[0].path);
    QCOMPARE(restored.real("nu"), kSavedNu);
    Autosave::forget(crashed[0]);
    QVERIFY(Autosave::crashedSessions(dir.path()).empty());
    QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
  }

  void aNormalExitLeavesNothing()
  {
    QTemporaryDir dir;
    SceneModel model;
    aniso::SceneEditor editor(&model);
    {
      Autosave autosave(&model, nullptr, dir.path(), 10);
      editor.edit("nu", aniso::numberValue(77.0));
      QVERIFY(autosave.saveNow());
      QVERIFY(QFile::exists(autosave.path()));
      QCOMPARE(aniso::readSessionFile(autosave.path()).values.at("nu").number[0], 77.0);
    }
    QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    QVERIFY(Autosave::crashedSessions(dir.path()).empty());
  }

  void aSeriesOfEditsWritesOnce()
  {
    QTemporaryDir dir;
    SceneModel model;
    aniso::SceneEditor editor(&model);
    Autosave autosave(&model, nullptr, dir.path(), 200);
    QSignalSpy saved(&autosave, &Autosave::saved);
    for (int i = 1; i <= 5; ++i)
    {
      editor.edit("nu", aniso::numberValue(100.0 * i), 1); // one drag
      QTest::qWait(20);
    }
    QVERIFY(saved.wait(3000));
    QTest::qWait(300);
    QCOMPARE(saved.count(), 1);
    QCOMPARE(aniso::readSessionFile(autosave.path()).values.at("nu").number[0], 500.0);
  }

  void runningOrUnsavedProcessesAreNotOffered()
  {
    QTemporaryDir dir;
    const auto touch = [&](const QString& name)
    {
      QFile file(QDir(dir.path()).filePath(name));
      QVERIFY(file.open(QIODevice::WriteOnly));
      file.write("{}");
    };
    // PID 1 is running: another instance's files stay.
    touch("running-1");
    touch("autosave-1.aniso");
    // A process that is gone but never autosaved: its marker is cleared, nothing offered.
    QProcess gone;
    gone.start("sleep", {"0.2"});
    QVERIFY(gone.waitForStarted(5000));
    const QString deadPid = QString::number(gone.processId());
    QVERIFY(gone.waitForFinished(5000));
    touch("running-" + deadPid);
    // This process's own marker (an Autosave of its own) is never offered.
    SceneModel model;
    Autosave own(&model, nullptr, dir.path(), 10);
    QVERIFY(Autosave::crashedSessions(dir.path()).empty());
    QVERIFY(QFile::exists(QDir(dir.path()).filePath("running-1")));
    QVERIFY(!QFile::exists(QDir(dir.path()).filePath("running-" + deadPid)));
  }

  void anUnwritableDirectoryIsReportedOnce()
  {
    QTemporaryDir dir;
    const QString file = QDir(dir.path()).filePath("not-a-folder");
    QFile blocker(file);
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    SceneModel model;
    Autosave autosave(&model, nullptr, file, 10);
    QSignalSpy failed(&autosave, &Autosave::failed);
    QVERIFY(!autosave.saveNow());
    QVERIFY(!autosave.saveNow());
    QTest::qWait(20);
    QCOMPARE(failed.count(), 1);
    QVERIFY(failed.at(0).at(0).toString().contains(file));
  }
};

int main(int argc, char** argv)
{
  if (argc == 3 && std::strcmp(argv[1], "--autosave-child") == 0)
  {
    QCoreApplication app(argc, argv);
    return runChild(QString::fromLocal8Bit(argv[2]));
  }
  QCoreApplication app(argc, argv);
  TestAutosave test;
  return QTest::qExec(&test, argc, argv);
}

#include "test_autosave.moc"
