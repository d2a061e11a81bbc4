// The LEADR and microstructure models in the window (needs an X server: run under Xvfb,
// serially). Checks: choosing each of them in the scene model puts its actor on screen in place
// of the view's own, and the window's pixels match the offscreen image of `aniso render --model
// NAME` with the same options (the command line's option handling, render_models.h, with the
// view's camera and size) within a stated bound; the exported screenshot is that image too. A
// setting the model refuses (a mesh without texture coordinates) leaves the previous model on
// screen and is reported once, however often the scene changes meanwhile. VTK reports no error
// and no warning (such as a texture left active or a texture unit never released when the
// window's context goes) from the window's creation to its destruction.
#include "app/gui/LitModelView.h"
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "app/gui/SurfaceModelView.h"
#include "app/render_models.h"
#include "core/image/image.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>
#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderer.h>
#include <vtkOutputWindow.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>

using aniso::numberValue;
using aniso::textValue;

// Records VTK's errors and warnings (and still prints them through the window it replaces), so
// a test can state that none was printed.
class RecordingOutputWindow : public vtkOutputWindow
{
public:
  static RecordingOutputWindow* New();
  vtkTypeMacro(RecordingOutputWindow, vtkOutputWindow)

      vtkSmartPointer<vtkOutputWindow> previous;
  QStringList messages;

  void DisplayText(const char* text) override { previous->DisplayText(text); }
  void DisplayErrorText(const char* text) override
  {
    messages << QString::fromUtf8(text).trimmed();
    previous->DisplayErrorText(text);
  }
  void DisplayWarningText(const char* text) override
  {
    messages << QString::fromUtf8(text).trimmed();
    previous->DisplayWarningText(text);
  }
  void DisplayGenericWarningText(const char* text) override
  {
    messages << QString::fromUtf8(text).trimmed();
    previous->DisplayGenericWarningText(text);
  }
  void DisplayDebugText(const char* text) override { previous->DisplayDebugText(text); }
};
vtkStandardNewMacro(RecordingOutputWindow);

namespace
{
constexpr const char* kLight = "dir:-1,-1.5,2:3";

// Mean absolute difference (in [0, 1]) between the window's RGB and DISPLAY (the offscreen
// image, row 0 at the top), and the share of pixels where the surface differs from black.
struct Comparison
{
  double meanDifference = 0.0;
  double covered = 0.0;
};

Comparison compareWithWindow(vtkRenderWindow* window, const aniso::Image& display)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(0, 0, display.width - 1, display.height - 1, 0, pixels);
  Comparison c;
  int lit = 0;
  for (int y = 0; y < display.height; ++y)
  {
    for (int x = 0; x < display.width; ++x)
    {
      // GL rows start at the bottom.
      const vtkIdType i = vtkIdType(display.height - 1 - y) * display.width + x;
      double brightest = 0.0;
      for (int ch = 0; ch < 3; ++ch)
      {
        const double shown = pixels->GetComponent(i, ch) / 255.0;
        c.meanDifference += std::abs(shown - double(display.at(x, y, ch)));
        brightest = std::max(brightest, shown);
      }
      lit += brightest > 0.05 ? 1 : 0;
    }
  }
  const double count = double(display.width) * display.height;
  c.meanDifference /= 3.0 * count;
  c.covered = lit / count;
  return c;
}

double meanDifference(const aniso::Image& a, const aniso::Image& b)
{
  double sum = 0.0;
  for (std::size_t i = 0; i < a.data.size(); ++i)
  {
    sum += std::abs(double(a.data[i]) - b.data[i]);
  }
  return sum / double(a.data.size());
}

// The options `aniso render` would be given for the scene of the test.
std::vector<std::string> commandLine(const std::string& model)
{
  std::vector<std::string> args = {"--model", model, "--light", kLight};
  if (model == "leadr")
  {
    args.insert(args.end(), {"--leadr-grid", "2", "--leadr-tiles", "4"});
  }
  else
  {
    args.insert(args.end(), {"--grid", "2", "--structure", "grooves", "--structure-tiles", "16",
                             "--micro-roughness", "0.2", "--tpr", "circular"});
  }
  return args;
}

// The messages a spy on errorReported caught, for the failure text.
QString messagesOf(const QSignalSpy& spy)
{
  QStringList messages;
  for (const QList<QVariant>& arguments : spy)
  {
    messages << arguments.at(0).toString();
  }
  return messages.join(" | ");
}
} // namespace

class TestSurfaceModelView : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void eachSurfaceModelDrawsAsTheCommandLine()
  {
    // Installed before the window, whose view forwards what VTK prints to the one it found.
    vtkNew<RecordingOutputWindow> output;
    output->previous = vtkOutputWindow::GetInstance();
    vtkOutputWindow::SetInstance(output);
    drawEachSurfaceModel();
    vtkOutputWindow::SetInstance(output->previous);
    if (QTest::currentTestFailed())
    {
      return;
    }
    // The window is gone: every texture the materials used was released in its own context.
    QVERIFY2(output->messages.isEmpty(), qPrintable(output->messages.join(" | ")));
  }

private:
  // The window of eachSurfaceModelDrawsAsTheCommandLine, destroyed on return.
  void drawEachSurfaceModel()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.model()->setValues({{"mesh", textValue("builtin:sphere")},
                               {"samples", numberValue(1.0)},
                               {"target-samples", numberValue(1.0)},
                               {"background", textValue("color")},
                               {"background-color", aniso::colorValue(0.0, 0.0, 0.0)},
                               {"lights", textValue(kLight)},
                               {"leadr-grid", numberValue(2.0)},
                               {"leadr-tiles", numberValue(4.0)},
                               {"micro-grid", numberValue(2.0)},
                               {"structure", textValue("grooves")},
                               {"structure-tiles", numberValue(16.0)},
                               {"micro-roughness", numberValue(0.2)},
                               {"tpr", textValue("circular")}});
    window.resize(640, 480);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged() && !view->lightingBusy(), 60000);
    vtkActor* sceneActor = aniso::firstActorOf(view->renderer());
    QVERIFY(sceneActor->GetVisibility());
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    QTemporaryDir folder;

    for (const std::string model : {"leadr", "microstructure"})
    {
      window.editor()->edit("model", textValue(model));
      QVERIFY2(window.surfaceView()->active(), model.c_str());
      QVERIFY(!sceneActor->GetVisibility());
      QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
      vtkRenderWindow* rw = window.vtkWidget()->renderWindow();
      rw->Render();
      const int* size = rw->GetSize();

      // `aniso render --model NAME ...` of the view's camera, size and material.
      aniso::cli::Command command;
      aniso::cli::addModelOptions(command);
      command.options.push_back(aniso::cli::textOption("--tpr", "PATTERN", "TPR map"));
      const aniso::cli::Arguments arguments =
          aniso::cli::parseArguments(command, commandLine(model));
      aniso::RenderSettings settings = view->renderSettings(size[0], size[1]);
      aniso::cli::applyModelOptions(arguments, settings);
      const aniso::RenderResult offscreen = aniso::renderOffscreen(settings);
      const Comparison c = compareWithWindow(rw, offscreen.display);
      std::printf("%s: window against the offscreen render, mean difference %.2e over %dx%d, "
                  "%.0f%% of the window lit\n",
                  model.c_str(), c.meanDifference, size[0], size[1], 100.0 * c.covered);
      // The sphere fills a good part of the view, so the comparison covers the model's shading.
      QVERIFY(c.covered > 0.1);
      // 8-bit window pixels against the offscreen display image (llvmpipe: 4e-9, the same frame).
      QVERIFY2(c.meanDifference < 0.01, model.c_str());
      // The bound tells the models apart: the environment material's image lies far outside it.
      aniso::RenderSettings plain = view->renderSettings(size[0], size[1]);
      const double asEnv = meanDifference(aniso::renderOffscreen(plain).display, offscreen.display);
      std::printf("%s: as-env differs from it by %.4f\n", model.c_str(), asEnv);
      QVERIFY(asEnv > 0.02);

      // The exported screenshot is what the window draws.
      const QString path = folder.filePath(QString::fromStdString(model + ".exr"));
      window.exportScreenshot(path, {});
      const aniso::Image exported = aniso::readImage(path.toStdString());
      QCOMPARE(exported.width, offscreen.linear.width);
      double difference = 0.0;
      double total = 0.0;
      for (std::size_t i = 0; i < exported.data.size(); ++i)
      {
        difference += std::abs(double(exported.data[i]) - offscreen.linear.data[i]);
        total += std::abs(double(offscreen.linear.data[i]));
      }
      QVERIFY(difference <= 1e-3 * total);
    }
    QVERIFY2(errors.count() == 0, qPrintable(messagesOf(errors)));

    window.editor()->edit("model", textValue("as-env"));
    QVERIFY(!window.surfaceView()->active());
    QVERIFY(sceneActor->GetVisibility());
  }

private slots:
  void refusedSettingKeepsThePreviousModel()
  {
    // A tetrahedron without texture coordinates: the surface models need them.
    QTemporaryDir folder;
    const std::string mesh = folder.filePath("tetrahedron.obj").toStdString();
    {
      std::ofstream obj(mesh);
      obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    }
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.model()->setValues({{"mesh", textValue("builtin:sphere")},
                               {"samples", numberValue(1.0)},
                               {"target-samples", numberValue(1.0)},
                               {"micro-grid", numberValue(1.0)}});
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged() && !view->lightingBusy(), 60000);
    vtkActor* sceneActor = aniso::firstActorOf(view->renderer());
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);

    window.editor()->edit("model", textValue("microstructure"));
    QVERIFY(window.surfaceView()->active());
    vtkActor* drawn = window.surfaceView()->surfaceActor();
    QVERIFY2(errors.count() == 0, qPrintable(messagesOf(errors)));

    // The mesh the model refuses: the microstructure drawn before stays, one message says why.
    window.editor()->edit("mesh", textValue(mesh));
    window.editor()->edit("lights", textValue("dir:0,0,1:2"));
    window.editor()->edit("micro-grid", numberValue(2.0));
    QVERIFY2(errors.count() == 1, qPrintable(messagesOf(errors)));
    QVERIFY2(errors.at(0).at(0).toString().contains("texture coordinates"),
             qPrintable(errors.at(0).at(0).toString()));
    QVERIFY(window.surfaceView()->active());
    QCOMPARE(window.surfaceView()->surfaceActor(), drawn);
    QVERIFY(!sceneActor->GetVisibility());

    // From the environment model, the refused choice leaves the environment material on screen.
    window.editor()->edit("model", textValue("as-env"));
    QVERIFY(sceneActor->GetVisibility());
    window.editor()->edit("model", textValue("leadr"));
    QVERIFY2(errors.count() == 2, qPrintable(messagesOf(errors)));
    QVERIFY(!window.surfaceView()->active());
    QVERIFY(sceneActor->GetVisibility());
  }
};

QTEST_MAIN(TestSurfaceModelView)
#include "test_surface_model_view.moc"
