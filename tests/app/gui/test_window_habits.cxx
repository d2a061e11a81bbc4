// The window's habits (needs an X server: run under Xvfb, serially). Checks: each standard
// shortcut triggers its action, seen by its effect (Undo and Redo take an edit back and forth;
// Ctrl+1..6 look from -Y, +Y, -X, +X, +Z, -Z at the parts' centre; Home frames the parts at the
// distance the field of view needs, the direction kept; Ctrl+R forgets the camera; Open, Save,
// Export Screenshot, Export Turntable and Preferences open their dialogs); the preferences
// round-trip through QSettings (a scope of the test's own), out-of-range values are clamped, and
// applied ones take effect (the recent files trimmed or cleared, screenshots offered in the chosen
// folder); the turntable writes N PNGs of the requested size whose first frame is the screenshot of
// the view at its azimuth and whose frames differ, and where ffmpeg is installed a video of those
// frames; a load running past 0.5 s shows progress, and Cancel drops it with the scene kept, while
// a quick one never shows; Cancel of an environment bake or of a lookup-table bake takes back the
// edit that started it.
#include "app/gui/BackgroundLoader.h"
#include "app/gui/MainWindow.h"
#include "app/gui/PreferencesDialog.h"
#include "app/gui/ProgressReporter.h"
#include "app/gui/SceneView.h"
#include "app/gui/StandardViews.h"
#include "app/gui/TurntableExport.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/render/ViewSettings.h"

#include <QApplication>
#include <QDateTime>
#include <QDialog>
#include <QDialogButtonBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QImage>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <memory>
#include <vtkRenderWindow.h>

using aniso::numberValue;
using aniso::textValue;

namespace
{
glm::dvec3 vec(const std::array<double, 3>& a)
{
  return {a[0], a[1], a[2]};
}

// From the focal point towards the camera, of unit length.
glm::dvec3 viewDirection(const aniso::CameraState& c)
{
  return glm::normalize(vec(c.position) - vec(c.focalPoint));
}

bool showCheapWindow(aniso::MainWindow& window)
{
  window.setErrorDialogs(false);
  window.model()->setValues({{"mesh", textValue("builtin:torus")},
                             {"samples", numberValue(1.0)},
                             {"target-samples", numberValue(1.0)}});
  window.resize(640, 480);
  window.show();
  // Shortcuts reach the active window only (no window manager under Xvfb activates it).
  window.activateWindow();
  QApplication::setActiveWindow(&window);
  return QTest::qWaitForWindowExposed(&window) && QTest::qWaitForWindowActive(&window);
}

// The title of the modal dialog KEYS open (closed again at once), or empty when none opened.
QString dialogOpenedBy(QWidget* window, const QKeySequence& keys)
{
  QString title;
  QTimer::singleShot(150,
                     [&title]
                     {
                       if (QWidget* modal = QApplication::activeModalWidget())
                       {
                         title = modal->windowTitle();
                         if (auto* dialog = qobject_cast<QDialog*>(modal))
                         {
                           dialog->reject();
                         }
                       }
                     });
  // The window active again after the last dialog (no window manager gives it back).
  window->activateWindow();
  QApplication::setActiveWindow(window);
  if (!QTest::qWaitForWindowActive(window))
  {
    return "the window is not active";
  }
  QTest::keySequence(window, keys);
  QTest::qWait(200);
  return title;
}

double meanDifference(const QImage& a, const QImage& b)
{
  double sum = 0.0;
  for (int y = 0; y < a.height(); ++y)
  {
    for (int x = 0; x < a.width(); ++x)
    {
      const QRgb p = a.pixel(x, y);
      const QRgb q = b.pixel(x, y);
      sum += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) +
             std::abs(qBlue(p) - qBlue(q));
    }
  }
  return sum / (3.0 * a.width() * a.height());
}
} // namespace

class TestWindowHabits : public QObject
{
  Q_OBJECT

  QTemporaryDir settingsDir_;
  // One window for every check: a window's start costs seconds here.
  std::unique_ptr<aniso::MainWindow> window_;

private slots:
  void initTestCase()
  {
    QStandardPaths::setTestModeEnabled(true);
    // Preferences of the test's own, never the user's.
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
    QCoreApplication::setOrganizationName("aniso-test-habits");
    QCoreApplication::setApplicationName("aniso-test-habits");
    window_ = std::make_unique<aniso::MainWindow>();
    QVERIFY(showCheapWindow(*window_));
  }

  void cleanupTestCase() { window_.reset(); }

  void undoRedoShortcuts()
  {
    aniso::MainWindow& window = *window_;
    const double before = window.model()->real("nu");
    window.editor()->edit("nu", numberValue(before + 17.0));
    QCOMPARE(window.model()->real("nu"), before + 17.0);
    QTest::keySequence(&window, QKeySequence::Undo);
    QCOMPARE(window.model()->real("nu"), before);
    QTest::keySequence(&window, QKeySequence::Redo);
    QCOMPARE(window.model()->real("nu"), before + 17.0);
  }

  void standardViewShortcuts()
  {
    aniso::MainWindow& window = *window_;
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->partCount() > 0, 30000);
    const glm::dvec3 centre = view->drawingFrame().centre;
    const glm::dvec3 expected[] = {{0, -1, 0}, {0, 1, 0}, {-1, 0, 0},
                                   {1, 0, 0},  {0, 0, 1}, {0, 0, -1}};
    for (int i = 0; i < 6; ++i)
    {
      QTest::keySequence(&window, QKeySequence(QString("Ctrl+%1").arg(i + 1)));
      const aniso::CameraState camera = window.model()->camera();
      QVERIFY(camera.set);
      QVERIFY2(glm::length(viewDirection(camera) - expected[i]) < 1e-9,
               qPrintable(QString("Ctrl+%1").arg(i + 1)));
      QVERIFY(glm::length(vec(camera.focalPoint) - centre) < 1e-9);
      // The view's own camera follows the model's.
      QVERIFY(glm::length(viewDirection(view->currentCamera()) - expected[i]) < 1e-6);
    }
  }

  void frameAllAndResetShortcuts()
  {
    aniso::MainWindow& window = *window_;
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->partCount() > 0, 30000);
    const aniso::DrawingFrame frame = view->drawingFrame();
    // Far off and aside, from a direction of its own.
    aniso::CameraState far;
    far.set = true;
    const glm::dvec3 direction = glm::normalize(glm::dvec3(1.0, -2.0, 0.5));
    const glm::dvec3 off = frame.centre + glm::dvec3(3.0, 1.0, 0.0) * frame.radius;
    const glm::dvec3 position = off + 40.0 * frame.radius * direction;
    far.position = {position.x, position.y, position.z};
    far.focalPoint = {off.x, off.y, off.z};
    far.viewUp = {0.0, 0.0, 1.0};
    far.viewAngle = 30.0;
    window.model()->setCamera(far);
    QTest::keySequence(&window, QKeySequence(Qt::Key_Home));
    const aniso::CameraState framed = window.model()->camera();
    QVERIFY(glm::length(viewDirection(framed) - direction) < 1e-9);
    QVERIFY(glm::length(vec(framed.focalPoint) - frame.centre) < 1e-9 * frame.radius);
    // The bounding sphere (times the 1.1 margin) fills the half height of a 30° field of view
    // (the view is wider than high: no widening).
    const int* size = window.vtkWidget()->renderWindow()->GetSize();
    QVERIFY(size[0] >= size[1]);
    const double distance = glm::length(vec(framed.position) - vec(framed.focalPoint));
    QVERIFY(std::abs(distance - 1.1 * frame.radius / std::sin(15.0 * M_PI / 180.0)) <
            1e-9 * frame.radius);

    QTest::keySequence(&window, QKeySequence(Qt::CTRL | Qt::Key_R));
    QVERIFY(!window.model()->camera().set);
    QVERIFY(glm::length(viewDirection(view->currentCamera()) - direction) > 0.1);
  }

  void dialogShortcuts()
  {
    aniso::MainWindow& window = *window_;
    QCOMPARE(dialogOpenedBy(&window, QKeySequence::Open), QString("Open a mesh"));
    const QString save = dialogOpenedBy(&window, QKeySequence::Save);
    QCOMPARE(save, QString("Save the session"));
    QCOMPARE(dialogOpenedBy(&window, QKeySequence(Qt::CTRL | Qt::Key_E)),
             QString("Export screenshot"));
    QCOMPARE(dialogOpenedBy(&window, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E)),
             QString("Export turntable"));
    const QList<QKeySequence> preferences = QKeySequence::keyBindings(QKeySequence::Preferences);
    QCOMPARE(dialogOpenedBy(&window, preferences.isEmpty() ? QKeySequence(Qt::CTRL | Qt::Key_Comma)
                                                           : preferences.front()),
             QString("Preferences"));
  }

  void preferencesRoundTrip()
  {
    aniso::Preferences p;
    p.screenshotFolder = "/tmp/shots";
    p.recentCount = 3;
    p.lutMemoryMiB = 100;
    p.lutDiskMiB = 50;
    p.restoreLayout = false;
    aniso::savePreferences(p);
    QCOMPARE(QSettings().value("recent/count").toInt(), 3);
    QVERIFY(aniso::loadPreferences() == p);
    // The dialog shows what it was given and gives back what was edited.
    aniso::PreferencesDialog dialog(p, QString());
    QVERIFY(dialog.preferences() == p);
    dialog.recentCountBox()->setValue(5);
    p.recentCount = 5;
    QVERIFY(dialog.preferences() == p);
    // Out of range in the file: clamped.
    QSettings().setValue("recent/count", 999);
    QSettings().setValue("lut/memoryMiB", "many");
    const aniso::Preferences loaded = aniso::loadPreferences();
    QCOMPARE(loaded.recentCount, 30);
    QCOMPARE(loaded.lutMemoryMiB, aniso::Preferences().lutMemoryMiB);
  }

  void preferencesTakeEffect()
  {
    QTemporaryDir dir;
    aniso::savePreferences(aniso::Preferences());
    QSettings().setValue("recentFiles", QStringList{"/a.ply", "/b.ply", "/c.ply", "/d.ply"});
    aniso::MainWindow& window = *window_;
    QCOMPARE(window.recentFiles().size(), 4);
    aniso::PreferencesDialog dialog(aniso::loadPreferences(), QString(), &window);
    connect(&dialog, &aniso::PreferencesDialog::applied, &window,
            &aniso::MainWindow::applyPreferences);
    dialog.recentCountBox()->setValue(2);
    dialog.screenshotFolderEdit()->setText(dir.path());
    QTest::mouseClick(dialog.buttons()->button(QDialogButtonBox::Apply), Qt::LeftButton);
    QCOMPARE(window.recentFiles(), (QStringList{"/a.ply", "/b.ply"}));
    QVERIFY(window.defaultScreenshotName("png").startsWith(dir.path() + "/"));
    // A file opened now joins a list of two.
    window.openMesh(dir.filePath("missing.ply")); // fails: not recent
    QCOMPARE(window.recentFiles().size(), 2);
    dialog.clearRecentButton()->setChecked(true);
    QTest::mouseClick(dialog.buttons()->button(QDialogButtonBox::Apply), Qt::LeftButton);
    QVERIFY(window.recentFiles().isEmpty());
    QVERIFY(!dialog.clearRecentButton()->isChecked());
    QCOMPARE(QSettings().value("recent/count").toInt(), 2);
  }

  void turntableFrames()
  {
    QTemporaryDir dir;
    aniso::MainWindow& window = *window_;
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    aniso::TurntableOptions options;
    options.frames = 4;
    options.elevationDegrees = 20.0;
    options.video = false;
    options.prefix = dir.filePath("turn");
    const qreal ratio = window.vtkWidget()->devicePixelRatioF();
    options.width = static_cast<int>(window.vtkWidget()->width() * ratio);
    options.height = static_cast<int>(window.vtkWidget()->height() * ratio);
    // The view put where the first frame looks from: the screenshot is the reference.
    const std::vector<aniso::CameraState> cameras = aniso::turntableCameras(
        view->currentCamera(), view->drawingFrame(), options.frames, options.elevationDegrees);
    QCOMPARE(int(cameras.size()), 4);
    window.model()->setCamera(cameras[0]);
    const QString shot = dir.filePath("shot.png");
    window.exportScreenshot(shot, aniso::ScreenshotOptions());

    const aniso::TurntableResult result = window.exportTurntableFrames(options);
    QVERIFY(!result.cancelled);
    QCOMPARE(result.frames.size(), 4);
    QImage frames[4];
    for (int k = 0; k < 4; ++k)
    {
      QCOMPARE(result.frames[k], dir.filePath(QString("turn_000%1.png").arg(k)));
      QVERIFY(frames[k].load(result.frames[k]));
      QCOMPARE(frames[k].size(), QSize(options.width, options.height));
    }
    QImage screenshot(shot);
    QCOMPARE(screenshot.size(), frames[0].size());
    QVERIFY2(meanDifference(frames[0], screenshot) < 0.05,
             qPrintable(QString::number(meanDifference(frames[0], screenshot))));
    // Each frame's camera is a quarter turn about +Z from the last, at the elevation asked.
    const aniso::DrawingFrame frame = view->drawingFrame();
    for (int k = 0; k < 4; ++k)
    {
      const glm::dvec3 d = vec(cameras[std::size_t(k)].position) - frame.centre;
      QVERIFY(std::abs(std::asin(d.z / glm::length(d)) * 180.0 / M_PI - 20.0) < 1e-9);
      if (k > 0)
      {
        const glm::dvec3 p = vec(cameras[std::size_t(k - 1)].position) - frame.centre;
        QVERIFY(std::abs(glm::dot(glm::dvec2(p), glm::dvec2(d))) < 1e-9 * glm::dot(d, d));
        QVERIFY(glm::cross(p, d).z > 0.0); // counter-clockwise seen from above
        QVERIFY2(meanDifference(frames[k], frames[k - 1]) > 0.5,
                 qPrintable(QString::number(meanDifference(frames[k], frames[k - 1]))));
      }
    }
    QVERIFY_EXCEPTION_THROWN(
        [&]
        {
          aniso::TurntableOptions bad = options;
          bad.frames = 0;
          window.exportTurntableFrames(bad);
        }(),
        aniso::Error);
  }

  void turntableVideo()
  {
    if (aniso::ffmpegExecutable().isEmpty())
    {
      QSKIP("ffmpeg is not installed: the turntable writes no video");
    }
    const QString ffprobe = QStandardPaths::findExecutable("ffprobe");
    if (ffprobe.isEmpty())
    {
      QSKIP("ffprobe is not installed: the video cannot be read back");
    }
    QTemporaryDir dir;
    aniso::MainWindow& window = *window_;
    aniso::TurntableOptions options;
    options.frames = 5;
    options.width = 63; // odd: padded to even for the encoder
    options.height = 40;
    options.prefix = dir.filePath("spin");
    const aniso::TurntableResult result = window.exportTurntableFrames(options);
    QVERIFY2(result.videoError.isEmpty(), qPrintable(result.videoError));
    QCOMPARE(result.video, dir.filePath("spin.mp4"));
    // What ffprobe, reading the file on its own, finds in it.
    QProcess probe;
    probe.start(ffprobe, {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                          "stream=nb_read_frames,width,height", "-of", "csv=p=0", result.video});
    QVERIFY(probe.waitForFinished(30000));
    QCOMPARE(QString::fromLocal8Bit(probe.readAllStandardOutput()).trimmed(), QString("64,40,5"));
  }

  void slowLoadShowsProgressAndCancelKeepsTheScene()
  {
    aniso::MainWindow& window = *window_;
    QTRY_VERIFY_WITH_TIMEOUT(!window.progress()->shown(), 30000);
    aniso::ProgressReporter* progress = window.progress();
    const std::string mesh = window.model()->text("mesh");
    const int steps = window.editor()->undoStack()->count();
    std::atomic<bool> workerDone{false};
    bool delivered = false;
    QElapsedTimer clock;
    clock.start();
    // A read that takes 1 s (the loader's seam: what it runs on the worker).
    window.loader()->load(
        "open mesh", "slow.ply",
        [&workerDone](aniso::SceneAssets&)
        {
          QThread::msleep(1000);
          workerDone = true;
        },
        [&] { delivered = window.openMesh("builtin:sphere"); });
    QTest::qWait(250);
    QVERIFY(!progress->shown());
    QTRY_VERIFY_WITH_TIMEOUT(progress->shown(), 1000);
    QVERIFY(clock.elapsed() >= aniso::ProgressReporter::kShowAfterMs);
    QVERIFY(progress->cancelButton()->isEnabled());
    QTest::mouseClick(progress->cancelButton(), Qt::LeftButton);
    QVERIFY(!window.meshLoading());
    QVERIFY(!progress->shown());
    QTRY_VERIFY_WITH_TIMEOUT(workerDone, 5000);
    QTest::qWait(100); // the worker's delivery, dropped
    QVERIFY(!delivered);
    QCOMPARE(window.model()->text("mesh"), mesh);
    QCOMPARE(window.editor()->undoStack()->count(), steps);

    // A quick load never shows progress.
    delivered = false;
    window.loader()->load(
        "open mesh", "quick.ply", [](aniso::SceneAssets&) {}, [&] { delivered = true; });
    QTRY_VERIFY_WITH_TIMEOUT(delivered, 5000);
    QVERIFY(!progress->shown());
    QTest::qWait(aniso::ProgressReporter::kShowAfterMs + 100);
    QVERIFY(!progress->shown());
  }

  void cancelledBakeTakesTheEditBack()
  {
    aniso::MainWindow& window = *window_;
    aniso::ProgressReporter* progress = window.progress();
    QTRY_VERIFY_WITH_TIMEOUT(!window.view()->lightingBusy(), 30000);
    const int cube = window.model()->integer("cube-size");
    const int steps = window.editor()->undoStack()->index();
    // Cancel as the bake starts, whether or not it is on screen yet.
    bool running = false;
    QString kind;
    connect(window.view(), &aniso::SceneView::lightingBusyChanged, this,
            [&](bool busy)
            {
              if (busy && !running)
              {
                // Once the edit's push is done (the edit on the undo stack).
                QTimer::singleShot(0, this,
                                   [&]
                                   {
                                     running = progress->running("environment bake");
                                     kind = progress->shownKind();
                                     progress->cancelButton()->click();
                                   });
              }
            });
    window.editor()->edit("cube-size", numberValue(cube * 4));
    QTRY_VERIFY_WITH_TIMEOUT(running, 5000);
    QCOMPARE(kind, QString("environment bake"));
    QCOMPARE(window.model()->integer("cube-size"), cube);
    QTRY_VERIFY_WITH_TIMEOUT(!progress->running("environment bake"), 10000);

    // The same for the lookup tables of new exponents (values no cache holds).
    const double nu = window.model()->real("nu");
    const double fresh = 1000.0 + std::fmod(double(QDateTime::currentMSecsSinceEpoch()), 9000.0);
    bool lutRunning = false;
    QString lutKind;
    connect(window.lutScheduler(), &aniso::LutScheduler::busyChanged, this,
            [&](bool busy)
            {
              if (busy && !lutRunning)
              {
                QTimer::singleShot(0, this,
                                   [&]
                                   {
                                     lutRunning = progress->running("lookup-table bake");
                                     lutKind = progress->shownKind();
                                     progress->cancelButton()->click();
                                   });
              }
            });
    window.editor()->edit("nu", numberValue(fresh));
    QTRY_VERIFY_WITH_TIMEOUT(lutRunning, 10000);
    QCOMPARE(lutKind, QString("lookup-table bake"));
    QCOMPARE(window.model()->real("nu"), nu);
    QTRY_VERIFY_WITH_TIMEOUT(!window.lutScheduler()->busy(), 10000);
    // One step back, which Redo brings back.
    QCOMPARE(window.editor()->undoStack()->index(), steps);
    QCOMPARE(window.editor()->undoStack()->count(), steps + 1);
  }
};

QTEST_MAIN(TestWindowHabits)
#include "test_window_habits.moc"
