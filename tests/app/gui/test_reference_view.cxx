// View > Reference in the window (needs an X server: Xvfb, serially). The built-in sphere under
// the built-in studio with a broad lobe (n_u = n_v = 100: a pixel of the reference costs a few
// milliseconds) in a small window (the other docks hidden), its frames of the material's 16
// samples (no frame budget, as `aniso render` draws them); the integrator's tolerance 1e-2 instead
// of the window's 1e-3 keeps each reference to seconds (the pixels are the integrator's all the
// same), on a grid of every 4th pixel in x and y.
// (a) The reference the window shows is the integrator's, pixel for pixel: every pixel of the
//     grid (selectPixelGrid of the view's cast) is computed, and each equals referencePixel of the
//     same inputs (SceneView::referenceInputs: the drawn surface, the material, the unjittered
//     camera, the environment and its rotation) exactly; the dock shows each over its block, and
//     the view covers each whole.
// (b) The error the window reports is compareToReference of the view's linear image against that
//     reference, and the status bar says it in words against the reference's own bound; the
//     figure `aniso render --reference` gives for the same view (renderOffscreen of the view's
//     settings, through the same camera) is the same; the error map's scale is its 99th
//     percentile.
// (c) A change during a computation cancels it: n_u changed while the reference runs stops the run
//     early (its pixels below its grid's total) and, once the new reference is complete, every
//     pixel it shows is the new lobe's (none of the old run's); the progress showed a time
//     estimate while it ran.
// (d) Where the reference does not cover the view, View > Reference is disabled and its tip says
//     why: a lit model (Banks), a part with a map (a TPR pattern), a part showing a data field;
//     with the reference on, the dock says why instead of showing a comparison.
#include "app/gui/MainWindow.h"
#include "app/gui/ProgressiveReference.h"
#include "app/gui/ReferenceDock.h"
#include "app/gui/ReferenceView.h"
#include "app/gui/SceneView.h"
#include "core/reference/pixel_geometry.h"
#include "core/reference/reference_image.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "widgets/EnvironmentThumbnails.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <set>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

using aniso::numberValue;
using aniso::textValue;

namespace
{
// The scene every check starts from; the view is still and converged when it returns.
bool openSphere(aniso::MainWindow& window)
{
  window.setErrorDialogs(false);
  window.view()->setSettleMs(30);
  window.model()->setValues({{"mesh", textValue("builtin:sphere")},
                             {"env", textValue("builtin:studio")},
                             {"nu", numberValue(100.0)},
                             {"nv", numberValue(100.0)},
                             {"samples", numberValue(16.0)},
                             {"target-samples", numberValue(64.0)}});
  // A small view: the docks but the reference's hidden.
  for (QDockWidget* dock : window.findChildren<QDockWidget*>())
  {
    dock->hide();
  }
  window.view()->setFrameBudgetMs(0);
  window.resize(500, 300);
  window.show();
  if (!QTest::qWaitForWindowExposed(&window))
  {
    return false;
  }
  return QTest::qWaitFor(
      [&] { return !window.lutScheduler()->busy() && window.view()->converged(); }, 60000);
}

// The window's reference at every 4th or 2nd pixel, to the test's tolerance.
void chooseGrid(aniso::MainWindow& window, int stride)
{
  aniso::ReferenceOptions options = aniso::ReferenceView::defaultOptions();
  options.relativeTolerance = 1e-2;
  window.referenceView()->setOptions(options);
  QComboBox* grid = window.referenceDock()->gridBox();
  grid->setCurrentIndex(grid->findData(stride));
}

bool completeAndCompared(aniso::MainWindow& window, int ms)
{
  aniso::ReferenceView* reference = window.referenceView();
  if (QTest::qWaitFor([&] { return reference->complete() && reference->error(); }, ms))
  {
    return true;
  }
  aniso::SceneView* view = window.view();
  qWarning("the reference after %d ms: %s; %s (the view %s: %s, %s, %d of %d samples)", ms,
           qPrintable(reference->progressText()), qPrintable(reference->summary()),
           view->converged() ? "converged" : "refining",
           view->interacting() ? "interacting" : "still",
           view->lightingBusy() ? "lighting busy" : "lit", view->accumulatedSamples(),
           view->targetSamples());
  return false;
}

// The integrator's own reference at the pixels of REFERENCE, in its order, from the view's inputs
// now; COVERED gets selectPixelGrid's pixels of the view's cast.
aniso::ReferenceImage recomputed(aniso::SceneView* view, const aniso::ReferenceImage& reference,
                                 const aniso::ReferenceOptions& options, int stride,
                                 std::vector<int>& grid)
{
  const aniso::ReferenceInputs inputs = view->referenceInputs();
  const std::vector<aniso::PixelSample> geometry =
      aniso::castPixels(inputs.mesh, inputs.clipToWorld, inputs.width, inputs.height);
  grid = aniso::selectPixelGrid(geometry, inputs.width, inputs.height, stride);
  aniso::ReferenceImage image;
  image.width = inputs.width;
  image.height = inputs.height;
  for (const aniso::ReferencePixel& p : reference.pixels)
  {
    const aniso::PixelSample& s = geometry[std::size_t(p.y) * std::size_t(inputs.width) + p.x];
    image.pixels.push_back(
        aniso::referencePixel(s, p.x, p.y, inputs.materials.at(std::size_t(s.material)),
                              *inputs.environment, inputs.worldToEnvironment, options));
  }
  return image;
}

// Pixels of SHOWN whose value is not EXPECTED's at the same place (exactly), and whether both
// hold the same pixels; GRID must hold them all.
int mismatches(const aniso::ReferenceImage& shown, const aniso::ReferenceImage& expected,
               const std::vector<int>& grid)
{
  int wrong = 0;
  const std::set<int> onGrid(grid.begin(), grid.end());
  std::set<int> seen;
  for (std::size_t i = 0; i < shown.pixels.size(); ++i)
  {
    const aniso::ReferencePixel& p = shown.pixels[i];
    const aniso::ReferencePixel& q = expected.pixels.at(i);
    const int index = p.y * shown.width + p.x;
    if (p.x != q.x || p.y != q.y || p.value != q.value || p.errorEstimate != q.errorEstimate ||
        !onGrid.count(index) || !seen.insert(index).second)
    {
      ++wrong;
    }
  }
  return wrong + int(grid.size() - seen.size());
}

// The colour the dock shows a linear VALUE in (the view's display transform).
QRgb shownColour(const glm::dvec3& value, const aniso::DisplaySettings& display)
{
  aniso::Image pixel(1, 1, 4);
  for (int c = 0; c < 3; ++c)
  {
    pixel.at(0, 0, c) = static_cast<float>(value[c]);
  }
  pixel.at(0, 0, 3) = 1.0f;
  return aniso::toQImage(aniso::displayedImage(pixel, display)).pixel(0, 0);
}

// Pixels of the dock's reference picture that do not show REFERENCE's value at its place.
int wrongOnScreen(aniso::MainWindow& window, const aniso::ReferenceImage& reference)
{
  window.referenceDock()->refresh();
  const QImage& shown = window.referenceDock()->canvas()->referenceImage();
  if (shown.width() != reference.width || shown.height() != reference.height)
  {
    return -1;
  }
  const aniso::DisplaySettings display = window.referenceView()->display();
  int wrong = 0;
  for (const aniso::ReferencePixel& p : reference.pixels)
  {
    wrong += shown.pixel(p.x, p.y) == shownColour(p.value, display) ? 0 : 1;
  }
  return wrong;
}

// A plate with the point array "temperature" = x, written by VTK's XML writer.
bool writePlate(const QString& path)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(4, 4);
  plane->Update();
  vtkPolyData* plate = plane->GetOutput();
  vtkNew<vtkDoubleArray> temperature;
  temperature->SetName("temperature");
  temperature->SetNumberOfTuples(plate->GetNumberOfPoints());
  for (vtkIdType i = 0; i < plate->GetNumberOfPoints(); ++i)
  {
    temperature->SetValue(i, plate->GetPoint(i)[0]);
  }
  plate->GetPointData()->AddArray(temperature);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.toStdString().c_str());
  writer->SetInputData(plate);
  return writer->Write() == 1;
}
} // namespace

class TestReferenceView : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void theReferenceIsTheIntegratorsAndSoIsTheError()
  {
    aniso::MainWindow window;
    QVERIFY(openSphere(window));
    aniso::SceneView* view = window.view();
    aniso::ReferenceView* reference = window.referenceView();
    chooseGrid(window, 4);
    QVERIFY(window.referenceAction()->isEnabled());
    QCOMPARE(window.referenceAction()->shortcut(), QKeySequence("Ctrl+Shift+R"));
    QElapsedTimer clock;
    clock.start();
    window.referenceAction()->trigger(); // View > Reference
    QVERIFY(window.referenceAction()->isChecked());
    QVERIFY(window.referenceDock()->isVisible());
    QVERIFY(completeAndCompared(window, 60000));
    const double seconds = 1e-3 * double(clock.elapsed());

    // (a) Every pixel of the grid, each the integrator's for the view's inputs.
    const aniso::ReferenceImage& shown = reference->reference();
    std::vector<int> grid;
    const aniso::ReferenceImage expected = recomputed(view, shown, reference->options(), 4, grid);
    QVERIFY(grid.size() > 200);
    QCOMPARE(reference->pixelsTotal(), grid.size());
    QCOMPARE(mismatches(shown, expected, grid), 0);
    QCOMPARE(wrongOnScreen(window, shown), 0);
    // The view covers each compared pixel whole (the reference's rays go where the GL draws).
    const aniso::Image linear = view->linearImage();
    QCOMPARE(linear.width, shown.width);
    QCOMPARE(linear.height, shown.height);
    for (const aniso::ReferencePixel& p : shown.pixels)
    {
      QCOMPARE(linear.at(p.x, p.y, 3), 1.0f);
    }

    // (b) The window's error is the comparison of the view's image with that reference.
    const aniso::ImageError error = aniso::compareToReference(linear, expected);
    QCOMPARE(reference->error()->relativeL2, error.relativeL2);
    QCOMPARE(reference->error()->percentile99, error.percentile99);
    const QString words = window.findChild<QLabel*>("reference")->text();
    const bool within = error.relativeL2 <= shown.relativeErrorBound;
    QVERIFY2(words.contains(within ? "within its own" : "beyond its own") &&
                 words.contains(QString::number(100.0 * error.relativeL2, 'g', 2) + "%"),
             qPrintable(words));
    // `aniso render --reference`'s figure for the same view: the window's scene drawn offscreen
    // as a screenshot draws it (whole frames of the material's samples, as the view drew them
    // here), through the same camera, against the same reference.
    const aniso::RenderResult offscreen =
        aniso::renderOffscreen(view->renderSettings(linear.width, linear.height));
    const aniso::ImageError benchmark = aniso::compareToReference(offscreen.linear, expected);
    double cameraDifference = 0.0;
    const aniso::ReferenceInputs inputs = view->referenceInputs();
    for (int column = 0; column < 4; ++column)
    {
      for (int row = 0; row < 4; ++row)
      {
        cameraDifference = std::max(cameraDifference, std::abs(offscreen.clipToWorld[column][row] -
                                                               inputs.clipToWorld[column][row]));
      }
    }
    qInfo("the view %.12g from the reference, the offscreen render of its settings %.12g; their "
          "cameras differ by %.3g",
          error.relativeL2, benchmark.relativeL2, cameraDifference);
    // Measured: the same to 12 digits (the same frames of the same shader); the tolerance leaves
    // room for a GL that rounds the two contexts' frames differently.
    QCOMPARE(cameraDifference, 0.0);
    QVERIFY(std::abs(benchmark.relativeL2 - error.relativeL2) <= 1e-6 * error.relativeL2);
    // 64 samples of a broad lobe against its converged radiance: a few percent.
    QVERIFY2(error.relativeL2 < 0.1, qPrintable(words));
    qInfo("%zu pixels of a %dx%d view in %.1f s: relative L2 %.4f (99th percentile %.3f), the "
          "reference's own bound %.5f; \"%s\"",
          shown.pixels.size(), shown.width, shown.height, seconds, error.relativeL2,
          error.percentile99, shown.relativeErrorBound, qPrintable(words));

    // The error map: Viridis over its 99th percentile.
    window.referenceDock()->setMode(aniso::ReferenceCanvas::Mode::Error);
    window.referenceDock()->refresh();
    QCOMPARE(window.referenceDock()->canvas()->errorScale(), error.percentile99);
    QVERIFY(!window.referenceDock()->canvas()->errorImage().isNull());
  }

  void aChangeCancelsTheRunInFlight()
  {
    aniso::MainWindow window;
    QVERIFY(openSphere(window));
    aniso::ReferenceView* reference = window.referenceView();
    QCOMPARE(reference->stride(), 2); // a quarter of the pixels by default
    chooseGrid(window, 4);
    window.showReference(true);
    QVERIFY(QTest::qWaitFor([&] { return reference->pixelsDone() > 0; }, 60000));
    QVERIFY(!reference->complete());
    const QString progress = reference->progressText();
    QVERIFY2(progress.contains("left"), qPrintable(progress));
    const std::size_t runs = reference->finishedRuns().size();

    window.editor()->edit("nu", numberValue(140.0));
    // The run in flight ends early, cancelled.
    QVERIFY(QTest::qWaitFor([&] { return reference->finishedRuns().size() > runs; }, 30000));
    const aniso::ReferenceView::Run old = reference->finishedRuns()[runs];
    QVERIFY(old.cancelled);
    QVERIFY2(old.total > 0 && (long long)old.pixels < old.total,
             qPrintable(QString("%1 of %2 pixels").arg(old.pixels).arg(old.total)));
    QVERIFY(completeAndCompared(window, 60000));

    // What is shown is the new lobe's reference, every pixel of it.
    const aniso::ReferenceInputs inputs = window.view()->referenceInputs();
    QCOMPARE(inputs.materials.at(0).lobe.nu, 140.0);
    const aniso::ReferenceImage& shown = reference->reference();
    std::vector<int> grid;
    const aniso::ReferenceImage expected =
        recomputed(window.view(), shown, reference->options(), 4, grid);
    QCOMPARE(mismatches(shown, expected, grid), 0);
    QCOMPARE(wrongOnScreen(window, shown), 0);
    qInfo("the first run stopped at %zu of %lld pixels; the new one: %zu pixels, %s", old.pixels,
          old.total, shown.pixels.size(), qPrintable(reference->summary()));
  }

  void theActionSaysWhyWhereTheReferenceDoesNotCover()
  {
    QTemporaryDir dir;
    const QString plate = dir.filePath("plate.vtp");
    QVERIFY(writePlate(plate));
    aniso::MainWindow window;
    QVERIFY(openSphere(window));
    chooseGrid(window, 4);
    QAction* action = window.referenceAction();
    aniso::ReferenceView* reference = window.referenceView();
    QTRY_VERIFY(action->isEnabled());
    window.showReference(true);

    const auto refused = [&](const QString& why)
    {
      return QTest::qWaitFor(
          [&]
          {
            return !action->isEnabled() && action->toolTip().contains(why) &&
                   action->statusTip() == action->toolTip() && !reference->running() &&
                   window.referenceDock()
                       ->findChild<QLabel*>("referenceProgress")
                       ->text()
                       .contains(why);
          },
          30000);
    };
    window.model()->setValues({{"model", textValue("banks")}});
    QVERIFY2(refused("Banks"), qPrintable(action->toolTip()));
    window.model()->setValues({{"model", textValue("as-env")}});
    QTRY_VERIFY_WITH_TIMEOUT(action->isEnabled(), 30000);

    window.editor()->edit("tpr", textValue("circular"));
    QVERIFY2(refused("maps"), qPrintable(action->toolTip()));
    window.editor()->undoStack()->undo();
    QTRY_VERIFY_WITH_TIMEOUT(action->isEnabled(), 30000);

    QVERIFY(window.openMesh(plate));
    window.editor()->edit("field", textValue("temperature"));
    QVERIFY2(refused("data field"), qPrintable(action->toolTip()));
    qInfo("a field: \"%s\"", qPrintable(action->toolTip()));
  }

  // `aniso --session S --reference-view error --window-screenshot FILE --quit` turns the reference
  // on and writes the window once it is complete (here a sphere seen from afar: few pixels at the
  // window's own tolerance); a view name it does not know is a usage error.
  void scriptedWindowScreenshotWaitsForTheReference()
  {
    QTemporaryDir dir;
    const QString session = dir.filePath("far.json");
    QFile f(session);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "aniso-session", "version": 1,
      "parameters": {"nu": 100, "nv": 100, "samples": 16, "target-samples": 16},
      "assets": {"mesh": "builtin:sphere"},
      "view": {"position": [0, -20, 6], "focal-point": [0, 0, 0], "view-up": [0, 0, 1],
               "view-angle": 30, "parallel": false, "parallel-scale": 1}})");
    f.close();
    const QString out = dir.filePath("window.png");
    QProcess run;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("XDG_CONFIG_HOME", dir.path());
    env.insert("XDG_STATE_HOME", dir.path());
    run.setProcessEnvironment(env);
    QElapsedTimer clock;
    clock.start();
    run.start(ANISO_EXECUTABLE, {"--session", session, "--reference-view", "error",
                                 "--window-screenshot", out, "--quit"});
    QVERIFY(run.waitForFinished(100000));
    const QString said = QString::fromUtf8(run.readAllStandardOutput());
    QVERIFY2(run.exitCode() == 0, qPrintable(said + run.readAllStandardError()));
    QVERIFY2(said.contains("aniso: wrote " + out), qPrintable(said));
    const QImage window(out);
    QVERIFY(window.width() > 600 && window.height() > 400);
    qInfo("the window with its reference in %.1f s", 1e-3 * double(clock.elapsed()));

    run.start(ANISO_EXECUTABLE, {"builtin:sphere", "--reference-view", "side"});
    QVERIFY(run.waitForFinished(30000));
    QCOMPARE(run.exitCode(), 2);
    const QString err = QString::fromUtf8(run.readAllStandardError());
    QVERIFY2(err.contains("--reference-view") && err.contains("wipe, error"), qPrintable(err));
  }
};

QTEST_MAIN(TestReferenceView)
#include "test_reference_view.moc"
