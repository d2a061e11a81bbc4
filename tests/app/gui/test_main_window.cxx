// The application window with its VTK view (needs an X server: run under Xvfb, serially).
// Checks: a corrupt or missing mesh, image, environment or session is reported and leaves the scene
// as it was; an idle window stops drawing once the view reaches its sample count and starts again
// on a change; screenshots are written in each format with the requested size and alpha
// (sizes from the widget, the PNG as the view shows it, alpha 0 on the background and 1 on the
// sphere's centre, which the framed sphere covers); a session's camera reaches the view; the
// scripted command line writes a screenshot or fails with the file's name; dropped files open by
// kind; meshes, environments, maps and sessions opened in the background (menus, drops, the
// docks) change the scene only when loaded, the latest request winning, a corrupt one reported;
// screenshot file names follow the mesh.
#include "app/gui/MainWindow.h"
#include "app/gui/SceneAssets.h"
#include "app/gui/SceneView.h"
#include "core/error.h"
#include "core/image/image.h"
#include "scene/Autosave.h"
#include "scene/LutScheduler.h"
#include "widgets/AssetControls.h"
#include "widgets/EnvironmentDock.h"
#include "widgets/MapsDock.h"

#include <QApplication>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QListWidget>
#include <QMimeData>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QUrl>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <ctime>
#include <vtkCamera.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyData.h>

using aniso::numberValue;
using aniso::textValue;

namespace
{
void writeGarbage(const QString& path)
{
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write("solid broken\n this is not a mesh nor an image \x01\x02\x03");
}

// An RGB image of one value, written by its extension.
void writeUniformImage(const QString& path, int width, int height, float value)
{
  aniso::Image image(width, height, 3);
  std::fill(image.data.begin(), image.data.end(), value);
  aniso::writeImage(path.toStdString(), image);
}

// One sample per frame and per pixel: the cheapest scene that still exercises everything.
void cheapScene(aniso::MainWindow& window, int target)
{
  window.model()->setValues({{"mesh", textValue("builtin:sphere")},
                             {"samples", numberValue(1.0)},
                             {"target-samples", numberValue(target)}});
}

// The window with the cheapest scene, shown, its dialogs off; false if it was not shown.
bool showCheapWindow(aniso::MainWindow& window)
{
  window.setErrorDialogs(false);
  cheapScene(window, 1);
  window.show();
  return QTest::qWaitForWindowExposed(&window);
}
} // namespace

class TestMainWindow : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void badFilesKeepTheScene()
  {
    QTemporaryDir dir;
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.show();
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    const aniso::SceneModel::Values before = window.model()->values();
    const QString mesh = dir.filePath("broken.stl");
    const QString image = dir.filePath("broken.png");
    const QString hdr = dir.filePath("broken.hdr");
    const QString session = dir.filePath("broken.json");
    for (const QString& path : {mesh, image, hdr, session})
    {
      writeGarbage(path);
    }
    QVERIFY(!window.openMesh(mesh));
    QVERIFY(!window.openMesh(dir.filePath("missing.obj")));
    QVERIFY(!window.openAny(image));
    QVERIFY(!window.openEnvironment(hdr));
    QVERIFY(!window.openAny(session));
    QCOMPARE(errors.count(), 5);
    QVERIFY(errors.at(0).at(0).toString().startsWith(mesh));
    QVERIFY(errors.at(1).at(0).toString().contains("missing.obj"));
    QVERIFY(errors.at(2).at(0).toString().startsWith(image));
    QVERIFY(errors.at(3).at(0).toString().startsWith(hdr));
    QVERIFY(errors.at(4).at(0).toString().startsWith(session));
    QVERIFY(window.model()->values() == before);
    QCOMPARE(window.editor()->undoStack()->count(), 0);
  }

  void idleWindowStopsDrawing()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.view()->setSettleMs(50);
    cheapScene(window, 3);
    window.show();
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    QCOMPARE(view->accumulatedSamples(), 3);
    QSignalSpy frames(view, &aniso::SceneView::frameRendered);
    QTRY_VERIFY_WITH_TIMEOUT(!window.lutScheduler()->busy(), 60000);
    const std::clock_t cpuBefore = std::clock();
    {
      // A plain event loop (QTest::qWait polls): the process sleeps unless something is due.
      QEventLoop loop;
      QTimer::singleShot(1000, &loop, &QEventLoop::quit);
      loop.exec();
    }
    QCOMPARE(frames.count(), 0); // still: nothing is drawn
    qInfo("idle window: %.1f ms of CPU in 1000 ms",
          1000.0 * static_cast<double>(std::clock() - cpuBefore) / CLOCKS_PER_SEC);
    // Nothing is scheduled either: no timer of the window runs (a status bar message's own
    // timeout aside, which ends with the message).
    for (const QTimer* timer : window.findChildren<QTimer*>())
    {
      if (!qobject_cast<const QStatusBar*>(timer->parent()))
      {
        QVERIFY2(!timer->isActive(), timer->parent()->metaObject()->className());
      }
    }
    window.editor()->edit("nu", numberValue(20000.0));
    QVERIFY(frames.wait(10000));
    // The new lobe's tables are baked on the worker: the view may converge before they land and
    // then draws again with them. Still is after both.
    QTRY_VERIFY_WITH_TIMEOUT(!window.lutScheduler()->busy() && view->converged(), 60000);
    const int afterChange = frames.count();
    QVERIFY(afterChange >= 3);
    QTest::qWait(300);
    QCOMPARE(frames.count(), afterChange);
  }

  void screenshotsHaveTheRequestedSizeAndAlpha()
  {
    QTemporaryDir dir;
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    cheapScene(window, 1);
    window.resize(900, 640);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const int w = window.vtkWidget()->width();
    const int h = window.vtkWidget()->height();

    const QString png = dir.filePath("view.png");
    window.exportScreenshot(png, {});
    const aniso::Image opaque = aniso::readImage(png.toStdString());
    QCOMPARE(opaque.width, w);
    QCOMPARE(opaque.height, h);
    QCOMPARE(opaque.channels, 3);
    // As displayed: the PNG's mean grey is the view's (the same scene through the same display
    // transform; per-pixel noise of one sample differs, the mean hardly).
    QTRY_VERIFY_WITH_TIMEOUT(window.view()->converged(), 60000);
    const QImage shown =
        window.vtkWidget()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    QCOMPARE(shown.width(), w);
    double shownGrey = 0.0;
    double pngGrey = 0.0;
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        shownGrey += qGray(shown.pixel(x, y));
        pngGrey += qGray(static_cast<int>(std::lround(255.0f * opaque.at(x, y, 0))),
                         static_cast<int>(std::lround(255.0f * opaque.at(x, y, 1))),
                         static_cast<int>(std::lround(255.0f * opaque.at(x, y, 2))));
      }
    }
    QVERIFY2(std::abs(shownGrey - pngGrey) / (w * h) < 2.0,
             qPrintable(QString("%1 %2").arg(shownGrey / (w * h)).arg(pngGrey / (w * h))));

    const QString clear = dir.filePath("clear.png");
    window.exportScreenshot(clear, {2, true});
    const aniso::Image transparent = aniso::readImage(clear.toStdString());
    QCOMPARE(transparent.width, 2 * w);
    QCOMPARE(transparent.height, 2 * h);
    QCOMPARE(transparent.channels, 4);
    QCOMPARE(transparent.at(0, 0, 3), 0.0f);
    QCOMPARE(transparent.at(w, h, 3), 1.0f);

    const QString exr = dir.filePath("view.exr");
    window.exportScreenshot(exr, {});
    const aniso::Image linear = aniso::readImage(exr.toStdString());
    QCOMPARE(linear.width, w);
    QCOMPARE(linear.channels, 4);
    QCOMPARE(linear.at(w / 2, h / 2, 3), 1.0f);
    for (float v : linear.data)
    {
      QVERIFY(std::isfinite(v));
    }
    QVERIFY(linear.at(w / 2, h / 2, 0) > 0.0f);

    const QString tif = dir.filePath("view.tif");
    window.exportScreenshot(tif, {3, false});
    const aniso::Image tiff = aniso::readImage(tif.toStdString());
    QCOMPARE(tiff.width, 3 * w);
    QCOMPARE(tiff.height, 3 * h);

    const auto refused = [&](const QString& path, int scale)
    {
      aniso::ScreenshotOptions options;
      options.scale = scale;
      try
      {
        window.exportScreenshot(path, options);
      }
      catch (const aniso::Error& e)
      {
        return QString(e.what()).startsWith(path + ": ");
      }
      return false;
    };
    QVERIFY(refused(dir.filePath("view.bmp"), 1));
    QVERIFY(refused(png, 5));

    // Default names: the mesh's name, a time stamp, the extension, in the last used folder.
    const QFileInfo name(window.defaultScreenshotName("exr"));
    QCOMPARE(name.absolutePath(), QFileInfo(dir.path()).absoluteFilePath());
    QVERIFY2(name.fileName().startsWith("sphere-"), qPrintable(name.fileName()));
    QCOMPARE(name.suffix(), QString("exr"));
  }

  // Dropped files open by kind: a mesh, an environment (2:1 .hdr), an image as the normal map,
  // a session's parameters.
  void droppedFilesOpenByKind()
  {
    QTemporaryDir dir;
    const QString mesh = dir.filePath("tetra.obj");
    {
      QFile f(mesh);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    }
    const QString env = dir.filePath("sky.hdr");
    writeUniformImage(env, 16, 8, 0.5f);
    const QString normals = dir.filePath("normals.png");
    aniso::Image flat(8, 8, 3);
    for (int y = 0; y < 8; ++y)
    {
      for (int x = 0; x < 8; ++x)
      {
        flat.at(x, y, 0) = 0.5f;
        flat.at(x, y, 1) = 0.5f;
        flat.at(x, y, 2) = 1.0f;
      }
    }
    aniso::writeImage(normals.toStdString(), flat);
    const QString session = dir.filePath("nu.json");
    {
      QFile f(session);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(R"({"format": "aniso-session", "version": 1,
        "parameters": {"nu": 321, "samples": 1, "target-samples": 1}})");
    }

    aniso::MainWindow window;
    window.setErrorDialogs(false);
    cheapScene(window, 1);
    window.show();
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    const auto drop = [&](const QString& path)
    {
      QMimeData data;
      data.setUrls({QUrl::fromLocalFile(path)});
      QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
      QApplication::sendEvent(&window, &enter);
      QVERIFY(enter.isAccepted());
      QDropEvent dropped(QPointF(10, 10), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
      QApplication::sendEvent(&window, &dropped);
    };
    drop(mesh);
    // Dropped files load on a worker: the scene changes once it delivers.
    QTRY_COMPARE_WITH_TIMEOUT(QString::fromStdString(window.model()->text("mesh")), mesh, 30000);
    drop(env);
    QTRY_COMPARE_WITH_TIMEOUT(QString::fromStdString(window.model()->text("env")), env, 30000);
    drop(normals);
    QTRY_COMPARE_WITH_TIMEOUT(QString::fromStdString(window.model()->text("normal-map")), normals,
                              30000);
    QVERIFY(window.model()->text("bump") != "none");
    drop(session);
    QTRY_COMPARE_WITH_TIMEOUT(window.model()->real("nu"), 321.0, 30000);
    QCOMPARE(errors.count(), 0);
  }

  // A mesh opened in the background (the File menu, drops, recent files) changes nothing until
  // the worker delivers it: right after the request the scene is as it was and the window says
  // it is loading; then the mesh is the scene's, the same surface openMesh gives. Of two
  // requests the later wins, whichever finishes last; a corrupt file is reported once with its
  // name and the scene stays.
  void meshesOpenInTheBackground()
  {
    QTemporaryDir dir;
    const QString first = dir.filePath("first.obj");
    const QString second = dir.filePath("second.obj");
    const QString broken = dir.filePath("broken.stl");
    {
      QFile f(first);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    }
    {
      QFile f(second);
      QVERIFY(f.open(QIODevice::WriteOnly));
      // A square pyramid: 5 points, 6 triangles.
      f.write("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
              "f 1 3 2\nf 1 4 3\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n");
    }
    writeGarbage(broken);

    aniso::MainWindow window;
    QVERIFY(showCheapWindow(window));
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    const std::string before = window.model()->text("mesh");
    const int edits = window.editor()->undoStack()->count();

    window.openMeshInBackground(first);
    QVERIFY(window.meshLoading());
    QCOMPARE(window.model()->text("mesh"), before);
    window.openMeshInBackground(second);
    QTRY_VERIFY_WITH_TIMEOUT(!window.meshLoading(), 30000);
    QCOMPARE(QString::fromStdString(window.model()->text("mesh")), second);
    // The first request's delivery, if it comes later, changes nothing.
    QTest::qWait(200);
    QCOMPARE(QString::fromStdString(window.model()->text("mesh")), second);
    QCOMPARE(errors.count(), 0);
    // The first never reached the scene: one edit, the second mesh.
    QCOMPARE(window.editor()->undoStack()->count(), edits + 1);
    // The view draws the pyramid: what the synchronous path prepares from the same file.
    aniso::SceneModel scratch;
    aniso::SceneAssets reference(&scratch);
    const auto expected = reference.surface(second.toStdString(), window.model()->text("tangents"));
    QCOMPARE(window.view()->renderSettings(8, 8).surface->GetNumberOfCells(),
             expected->polyData->GetNumberOfCells());
    QCOMPARE(window.view()->renderSettings(8, 8).surface->GetNumberOfPoints(),
             expected->polyData->GetNumberOfPoints());

    const aniso::SceneModel::Values kept = window.model()->values();
    window.openMeshInBackground(broken);
    QTRY_VERIFY_WITH_TIMEOUT(!window.meshLoading(), 30000);
    QCOMPARE(errors.count(), 1);
    QVERIFY(errors.at(0).at(0).toString().startsWith(broken));
    QVERIFY(window.model()->values() == kept);
  }

  // Environments too: a file opened in the background reaches the scene only once read, as does
  // a choice in the environment dock; a corrupt file is reported once and the scene stays.
  void environmentsOpenInTheBackground()
  {
    QTemporaryDir dir;
    const QString sky = dir.filePath("sky.hdr");
    writeUniformImage(sky, 16, 8, 0.25f);
    const QString broken = dir.filePath("broken.hdr");
    writeGarbage(broken);

    aniso::MainWindow window;
    QVERIFY(showCheapWindow(window));
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    const std::string before = window.model()->text("env");
    QVERIFY(before != sky.toStdString());

    QVERIFY(window.openAny(sky, true));
    QVERIFY(window.environmentLoading());
    QCOMPARE(window.model()->text("env"), before);
    QTRY_VERIFY_WITH_TIMEOUT(!window.environmentLoading(), 30000);
    QCOMPARE(QString::fromStdString(window.model()->text("env")), sky);
    QVERIFY(window.recentFiles().contains(sky));

    // The dock's built-in white environment, chosen in its list.
    auto* dock = window.findChild<aniso::EnvironmentDock*>();
    QVERIFY(dock);
    QListWidgetItem* white = nullptr;
    for (int i = 0; i < dock->list()->count(); ++i)
    {
      if (dock->list()->item(i)->text().startsWith("White"))
      {
        white = dock->list()->item(i);
      }
    }
    QVERIFY(white);
    emit dock->list()->itemClicked(white);
    QVERIFY(window.environmentLoading());
    QTRY_VERIFY_WITH_TIMEOUT(!window.environmentLoading(), 30000);
    QCOMPARE(window.model()->text("env"), std::string("builtin:white"));

    const aniso::SceneModel::Values kept = window.model()->values();
    QVERIFY(window.openAny(broken, true));
    QTRY_VERIFY_WITH_TIMEOUT(!window.environmentLoading(), 30000);
    QCOMPARE(errors.count(), 1);
    QVERIFY(errors.at(0).at(0).toString().startsWith(broken));
    QVERIFY(window.model()->values() == kept);
  }

  // A map chosen in the Maps dock and a session opened from the menus also reach the scene only
  // once what they name is read on a worker; a corrupt session is reported once by the session
  // reader, with its name, and the scene stays.
  void mapsAndSessionsOpenInTheBackground()
  {
    QTemporaryDir dir;
    const QString albedo = dir.filePath("albedo.png");
    writeUniformImage(albedo, 8, 8, 0.5f);
    const QString session = dir.filePath("nu.json");
    {
      QFile f(session);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(R"({"format": "aniso-session", "version": 1,
        "parameters": {"nu": 321, "samples": 1, "target-samples": 1}})");
    }
    const QString broken = dir.filePath("broken.json");
    writeGarbage(broken);

    aniso::MainWindow window;
    QVERIFY(showCheapWindow(window));
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);

    auto* maps = window.findChild<aniso::MapsDock*>();
    QVERIFY(maps);
    emit maps->fileRow("albedo-map")->edited(albedo);
    QVERIFY(window.assetLoading("albedo-map"));
    QCOMPARE(window.model()->text("albedo-map"), std::string());
    QTRY_VERIFY_WITH_TIMEOUT(!window.assetLoading("albedo-map"), 30000);
    QCOMPARE(QString::fromStdString(window.model()->text("albedo-map")), albedo);

    QVERIFY(window.openAny(session, true));
    QVERIFY(window.sessionLoading());
    QVERIFY(window.model()->real("nu") != 321.0);
    QTRY_VERIFY_WITH_TIMEOUT(!window.sessionLoading(), 30000);
    QCOMPARE(window.model()->real("nu"), 321.0);

    const aniso::SceneModel::Values kept = window.model()->values();
    QVERIFY(window.openAny(broken, true));
    QTRY_VERIFY_WITH_TIMEOUT(!window.sessionLoading(), 30000);
    QCOMPARE(errors.count(), 1);
    QVERIFY(errors.at(0).at(0).toString().startsWith(broken));
    QVERIFY(window.model()->values() == kept);
  }

  // An earlier run's autosave (a marker of a process that is gone, its session) comes back into
  // the window as one undoable step, is then dropped from the state directory, and the window
  // autosaves its own scene there; with Keep it stays for a later start.
  void aDeadRunsAutosaveIsRestored()
  {
    QTemporaryDir dir;
    QProcess gone;
    gone.start("sleep", {"0.2"});
    QVERIFY(gone.waitForStarted(5000));
    const QString pid = QString::number(gone.processId());
    QVERIFY(gone.waitForFinished(5000));
    const auto writeDeadRun = [&]
    {
      QFile marker(QDir(dir.path()).filePath("running-" + pid));
      QVERIFY(marker.open(QIODevice::WriteOnly));
      QFile f(QDir(dir.path()).filePath("autosave-" + pid + ".aniso"));
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(R"({"format": "aniso-session", "version": 1,
        "parameters": {"nu": 555, "samples": 1, "target-samples": 1}})");
    };
    writeDeadRun();
    {
      aniso::MainWindow window;
      QVERIFY(showCheapWindow(window));
      window.enableAutosave(dir.path(), aniso::AutosaveRestore::Keep);
      QVERIFY(window.model()->real("nu") != 555.0);
      QCOMPARE(aniso::Autosave::crashedSessions(dir.path()).size(), std::size_t(1));
    }
    aniso::MainWindow window;
    QVERIFY(showCheapWindow(window));
    const int undoSteps = window.editor()->undoStack()->count();
    window.enableAutosave(dir.path(), aniso::AutosaveRestore::Always);
    QCOMPARE(window.model()->real("nu"), 555.0);
    QCOMPARE(window.editor()->undoStack()->count(), undoSteps + 1);
    QVERIFY(aniso::Autosave::crashedSessions(dir.path()).empty());
    QVERIFY(!QFile::exists(QDir(dir.path()).filePath("autosave-" + pid + ".aniso")));
    QVERIFY(window.autosave());
    QVERIFY(window.autosave()->saveNow());
    QCOMPARE(aniso::readSessionFile(window.autosave()->path()).values.at("nu").number[0], 555.0);
  }

  // The camera a session stores is the one the view shows.
  void sessionCameraReachesTheView()
  {
    QTemporaryDir dir;
    const QString path = dir.filePath("camera.json");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "aniso-session", "version": 1,
      "parameters": {"samples": 1, "target-samples": 1},
      "assets": {"mesh": "builtin:plate"},
      "view": {"position": [0, -5, 2], "focal-point": [0, 0, 0.5], "view-up": [0, 0, 1],
               "view-angle": 25, "parallel": false, "parallel-scale": 1}})");
    f.close();
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.show();
    QVERIFY(window.openSession(path));
    // The view draws in the frame of the mesh's unit bounding sphere (DrawingFrame.h); the
    // camera it reports is mapped back to the mesh's coordinates, where sessions keep it.
    const aniso::CameraState c = window.view()->currentCamera();
    QCOMPARE(c.position[1], -5.0);
    QCOMPARE(c.focalPoint[2], 0.5);
    QCOMPARE(window.view()->renderer()->GetActiveCamera()->GetViewAngle(), 25.0);
    QCOMPARE(window.model()->text("mesh"), std::string("builtin:plate"));
  }

  // `aniso MESH --screenshot FILE --quit` writes the view and exits 0; a missing mesh exits 1
  // with one line naming it.
  void scriptedScreenshot()
  {
    QTemporaryDir dir;
    const QString session = dir.filePath("cheap.json");
    QFile f(session);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "aniso-session", "version": 1,
      "parameters": {"samples": 1, "target-samples": 1}, "assets": {"mesh": "builtin:sphere"}})");
    f.close();
    const QString out = dir.filePath("shot.png");
    QProcess run;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("XDG_CONFIG_HOME", dir.path());
    run.setProcessEnvironment(env);
    run.start(ANISO_EXECUTABLE,
              {"builtin:sphere", "--session", session, "--screenshot", out, "--quit"});
    QVERIFY(run.waitForFinished(60000));
    QCOMPARE(run.exitCode(), 0);
    QCOMPARE(aniso::readImage(out.toStdString()).channels, 3);

    const QString missing = dir.filePath("missing.stl");
    run.start(ANISO_EXECUTABLE, {missing, "--screenshot", out, "--quit"});
    QVERIFY(run.waitForFinished(60000));
    QCOMPARE(run.exitCode(), 1);
    const QString err = QString::fromUtf8(run.readAllStandardError()).trimmed();
    QVERIFY2(err.contains("aniso: " + missing + ": "), qPrintable(err));
  }
};

int main(int argc, char** argv)
{
  // The VTK widget needs its OpenGL format before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  TestMainWindow test;
  return QTest::qExec(&test, argc, argv);
}

#include "test_main_window.moc"
