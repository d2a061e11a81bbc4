// The window's view while things change (needs an X server: run under Xvfb, serially).
// Checks: a new environment or cube size is baked off the UI thread (the previous lighting
// stays until the latest request is in); new exponents reach the material only with tables
// already baked off the UI thread; a renderer error reaches the user once; frames drawn while
// things move are at half resolution and show the same picture; a camera drag across the
// switch to half resolution turns at the trackball's rate; a map larger than the GL's texture
// limit is refused with its file's name.
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "core/env/environment.h"
#include "core/image/image.h"
#include "core/lut/lut_cache.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/render/EnvironmentLighting.h"

#include <QApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QImage>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderer.h>
#include <vtkOutputWindow.h>
#include <vtkRenderWindow.h>

using aniso::numberValue;
using aniso::textValue;

namespace
{
// One sample per frame and per pixel: the cheapest scene that still exercises everything.
void cheapScene(aniso::MainWindow& window, int target)
{
  window.model()->setValues({{"mesh", textValue("builtin:sphere")},
                             {"samples", numberValue(1.0)},
                             {"target-samples", numberValue(target)}});
}
} // namespace

class TestWindowRendering : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  // A new environment or cube size is baked off the UI thread: right after the edits the view
  // still draws with the lighting it had (the same object), and once the bake is in it shows
  // the latest request (a request made while another bakes runs after it, alone). The event
  // loop's longest stall while baking is printed (timings are not pass/fail).
  void environmentBakesOffTheUiThread()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    cheapScene(window, 1);
    window.show();
    // With environment sampling on, its distribution is part of the bake.
    window.model()->setValues({{"env-sampling", textValue("mis")}});
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    const std::shared_ptr<aniso::EnvironmentLighting> before = view->lighting();
    QCOMPARE(before->cubeSize(), 256);
    QSignalSpy busy(view, &aniso::SceneView::lightingBusyChanged);

    QElapsedTimer clock;
    clock.start();
    window.editor()->edit("cube-size", numberValue(512.0));
    window.editor()->edit("env", textValue("builtin:white"));
    const qint64 editMs = clock.elapsed();
    QVERIFY(view->lightingBusy());
    QVERIFY(view->lighting() == before);
    QVERIFY(!view->converged());

    // Frames themselves (llvmpipe draws on the CPU) are timed apart from the stalls.
    qint64 frameStart = 0;
    qint64 longestFrame = 0;
    vtkNew<vtkCallbackCommand> frameTimer;
    const auto onFrame = [&](unsigned long event)
    {
      if (event == vtkCommand::StartEvent)
      {
        frameStart = clock.elapsed();
      }
      else
      {
        longestFrame = std::max(longestFrame, clock.elapsed() - frameStart);
      }
    };
    std::function<void(unsigned long)> frameEvent = onFrame;
    frameTimer->SetClientData(&frameEvent);
    frameTimer->SetCallback([](vtkObject*, unsigned long event, void* data, void*)
                            { (*static_cast<std::function<void(unsigned long)>*>(data))(event); });
    view->renderer()->AddObserver(vtkCommand::StartEvent, frameTimer);
    view->renderer()->AddObserver(vtkCommand::EndEvent, frameTimer);
    qint64 last = clock.elapsed();
    qint64 worst = 0;
    QTimer tick;
    tick.setInterval(5);
    connect(&tick, &QTimer::timeout, this,
            [&]
            {
              worst = std::max(worst, clock.elapsed() - last);
              last = clock.elapsed();
            });
    tick.start();
    QTRY_VERIFY_WITH_TIMEOUT(!view->lightingBusy(), 60000);
    tick.stop();
    view->renderer()->RemoveObserver(frameTimer);
    qInfo("environment change: edits %lld ms, longest event-loop stall while baking %lld ms, "
          "longest frame %lld ms, bakes done after %lld ms",
          static_cast<long long>(editMs), static_cast<long long>(worst),
          static_cast<long long>(longestFrame), static_cast<long long>(clock.elapsed()));
    QCOMPARE(view->lighting()->cubeSize(), 512);
    QCOMPARE(view->lighting()->environment().key(), aniso::openEnvironment("builtin:white")->key());
    QCOMPARE(busy.count(), 2);
    QCOMPARE(busy.at(0).at(0).toBool(), true);
    QCOMPARE(busy.at(1).at(0).toBool(), false);
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
  }

  // n_u and n_v reach the material only with tables the scheduler baked on its worker: right
  // after the edit the view keeps the previous exponents, and taking the new ones costs the
  // shared cache nothing on the UI thread (the worker's tables are handed over as they are).
  void materialTakesOnlyBakedTables()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    cheapScene(window, 1);
    window.show();
    aniso::LutScheduler* luts = window.lutScheduler();
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(!luts->busy(), 60000);
    const double oldNu = view->renderSettings(1, 1).material.lobe.nu;
    // A value no earlier run has baked, so the worker really bakes.
    const double nu = 1000.0 + static_cast<double>(QDateTime::currentMSecsSinceEpoch() % 100000);
    QVERIFY(nu != oldNu);
    window.editor()->edit("nu", numberValue(nu));
    luts->requestNow();
    QCOMPARE(view->renderSettings(1, 1).material.lobe.nu, oldNu);
    luts->waitForIdle();
    const aniso::LutCacheStats worker = luts->cache().stats();
    QTRY_COMPARE_WITH_TIMEOUT(view->renderSettings(1, 1).material.lobe.nu, nu, 10000);
    const aniso::LutCacheStats ui = luts->cache().stats();
    QCOMPARE(ui.bakes, worker.bakes);
    QCOMPARE(ui.diskHits, worker.diskHits);
    QCOMPARE(ui.memoryHits, worker.memoryHits);
  }

  // While things move the view draws at half resolution, scaled up to the widget: the picture
  // during a slider move shows the same scene as the full-resolution one before it (a mean
  // difference far below that of the picture against its own background colour, which a picture
  // drawn into a corner would reach), and the full resolution comes back once still.
  void interactiveFramesAtReducedResolution()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    cheapScene(window, 1);
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    vtkRenderWindow* renderWindow = window.vtkWidget()->renderWindow();
    const int fullWidth = renderWindow->GetSize()[0];
    const int fullHeight = renderWindow->GetSize()[1];
    const QImage still =
        window.vtkWidget()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);

    view->setSettleMs(3000);
    QSignalSpy frames(view, &aniso::SceneView::frameRendered);
    window.editor()->edit("samples", numberValue(2.0)); // a material change: cheap frames
    QVERIFY(frames.wait(10000));
    QVERIFY(view->interacting());
    QCOMPARE(renderWindow->GetSize()[0], (fullWidth + 1) / 2);
    QVERIFY(std::abs(renderWindow->GetSize()[1] - fullHeight / 2) <= 1);
    const QImage moving =
        window.vtkWidget()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    QCOMPARE(moving.size(), still.size());

    const QRgb background = still.pixel(0, 0);
    double toMoving = 0.0;
    double toBackground = 0.0;
    for (int y = 0; y < still.height(); ++y)
    {
      for (int x = 0; x < still.width(); ++x)
      {
        const QRgb a = still.pixel(x, y);
        const QRgb b = moving.pixel(x, y);
        toMoving += std::abs(qGray(a) - qGray(b));
        toBackground += std::abs(qGray(a) - qGray(background));
      }
    }
    qInfo("mean grey difference: moving %.2f, background %.2f",
          toMoving / (still.width() * still.height()),
          toBackground / (still.width() * still.height()));
    QVERIFY(toMoving < 0.25 * toBackground);

    view->setSettleMs(50);
    QTRY_VERIFY_WITH_TIMEOUT(!view->interacting(), 10000);
    QCOMPARE(renderWindow->GetSize()[0], fullWidth);
    QCOMPARE(renderWindow->GetSize()[1], fullHeight);
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
  }

  // A camera drag rotates at the trackball's rate (azimuth = 200 degrees per view width:
  // vtkInteractorStyleTrackballCamera's motion factor 10 times 20 / width) although the view
  // switches to half resolution as the drag starts: the pointer's position carries over into
  // the new pixel units, so the camera does not jump.
  void dragRotatesWithoutAJump()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    cheapScene(window, 1);
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    vtkCamera* camera = view->renderer()->GetActiveCamera();
    // The drag turns the camera about its view-up made orthogonal to the view (what the screen
    // shows as up; the default view looks down at 35 degrees, so it is not the world's Z): the
    // turn is measured about that axis.
    camera->OrthogonalizeViewUp();
    const glm::dvec3 focal(camera->GetFocalPoint()[0], camera->GetFocalPoint()[1],
                           camera->GetFocalPoint()[2]);
    const glm::dvec3 up(camera->GetViewUp()[0], camera->GetViewUp()[1], camera->GetViewUp()[2]);
    const auto direction = [&]
    {
      const glm::dvec3 p(camera->GetPosition()[0], camera->GetPosition()[1],
                         camera->GetPosition()[2]);
      const glm::dvec3 d = p - focal;
      return glm::normalize(d - glm::dot(d, up) * up); // in the plane the azimuth turns
    };
    const glm::dvec3 before = direction();

    QWidget* widget = window.vtkWidget();
    const QPoint start(widget->width() / 2, widget->height() / 2);
    const int step = 10;
    const int steps = 4;
    QMouseEvent press(QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton,
                      Qt::NoModifier);
    QApplication::sendEvent(widget, &press);
    for (int i = 1; i <= steps; ++i)
    {
      QMouseEvent move(QEvent::MouseMove, start + QPoint(step * i, 0), Qt::NoButton, Qt::LeftButton,
                       Qt::NoModifier);
      QApplication::sendEvent(widget, &move);
    }
    QVERIFY(view->interacting());
    QMouseEvent release(QEvent::MouseButtonRelease, start + QPoint(step * steps, 0), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(widget, &release);

    const double turned =
        std::acos(std::clamp(glm::dot(before, direction()), -1.0, 1.0)) * 180.0 / M_PI;
    const double expected = 200.0 * step * steps / widget->width();
    QVERIFY2(std::abs(turned - expected) < 0.1 * expected,
             qPrintable(QString("turned %1 degrees, expected %2").arg(turned).arg(expected)));
  }

  // A map the GL cannot hold (wider than GL_MAX_TEXTURE_SIZE, 16384 on llvmpipe) is refused
  // with its file's name before it reaches the scene, at start-up (a session's map) and later.
  void oversizedMapIsRefused()
  {
    QTemporaryDir dir;
    const QString wide = dir.filePath("wide.png");
    aniso::Image image(20000, 1, 3);
    std::fill(image.data.begin(), image.data.end(), 0.5f);
    aniso::writeImage(wide.toStdString(), image);
    const auto refused = [&](const std::function<void()>& action)
    {
      try
      {
        action();
      }
      catch (const aniso::Error& e)
      {
        return QString(e.what()).startsWith(wide + ": 20000x1 texels, more than the ");
      }
      return false;
    };

    aniso::MainWindow window;
    window.setErrorDialogs(false);
    QVERIFY(refused(
        [&] {
          window.model()->setValues({{"albedo-map", textValue(wide.toStdString())}});
        }));
    cheapScene(window, 2);
    window.show();
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    QVERIFY(refused([&] { window.editor()->edit("ao-map", textValue(wide.toStdString())); }));
    QCOMPARE(window.model()->text("albedo-map"), std::string());
    QCOMPARE(window.model()->text("ao-map"), std::string());
    QVERIFY(!window.openAny(wide)); // as a normal map
    QCOMPARE(errors.count(), 1);
    QCOMPARE(window.model()->text("normal-map"), std::string());
  }

  // What VTK or OpenGL reports while the view draws (a shader that does not compile, a GL
  // error) reaches the user in words, once however many frames repeat it; VTK's source
  // location is not part of the words.
  void rendererErrorsReachTheUserOnce()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    cheapScene(window, 1);
    window.show();
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    // VTK's form of an error raised while drawing, as a failing shader compilation prints it.
    vtkNew<vtkCallbackCommand> failing;
    failing->SetCallback(
        [](vtkObject*, unsigned long, void*, void*)
        {
          vtkOutputWindow::GetInstance()->DisplayErrorText(
              "ERROR: In vtkShaderProgram.cxx, line 452\nvtkShaderProgram (0x55d0): 1: "
              "error: syntax error\n\n");
        });
    view->renderer()->AddObserver(vtkCommand::StartEvent, failing);
    QSignalSpy frames(view, &aniso::SceneView::frameRendered);
    for (double exposure : {0.9, 0.8})
    {
      window.editor()->edit("exposure", numberValue(exposure));
      view->requestRender();
      QVERIFY(frames.wait(10000));
    }
    QTest::qWait(100);
    QCOMPARE(errors.count(), 1);
    QCOMPARE(errors.at(0).at(0).toString(), QString("OpenGL: 1: error: syntax error"));
    view->renderer()->RemoveObserver(failing);
  }
};

int main(int argc, char** argv)
{
  // The VTK widget needs its OpenGL format before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  TestWindowRendering test;
  return QTest::qExec(&test, argc, argv);
}

#include "test_window_rendering.moc"
