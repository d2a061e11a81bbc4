// A data field in the window (needs an X server: Xvfb, serially). A plate (vtkPlaneSource, 8x8
// quads, normal +Z, x and y from -0.5 to 0.5) with the point array "temperature" = x, written by
// VTK's XML writer (an independent writer), is opened; with F0 0 and the field driving the albedo,
// `field` is set to "temperature" through the Maps dock's combo:
// (a) the combo lists "temperature" (what SceneAssets::fieldChoices found in the file);
// (b) the view's overlay holds one vtkScalarBarActor whose lookup table spans the array's range,
//     -0.5 to 0.5 (the values written), and the part's material has that range resolved;
// (c) the plate's pixels differ from the field-less image taken before the edit, and its low-x
//     side from its high-x side as viridis' ends do (dark purple, yellow: the high side greener);
//     a screenshot's settings (renderSettings) carry the resolved field and legend on;
// (d) legend off takes the bar away (undone, it is back), and a screenshot (File > Export
//     Screenshot) without it differs from one with it only at the right, where the bar is;
// (e) undo of the field edit brings the field-less state back: no field in the material, no
//     bar, and the pixels of the field-less image.
// A malformed field text typed into the combo is refused with the model's error, and the combo
// shows the scene's value again.
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "core/image/image.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "widgets/MapsDock.h"

#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <array>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarsToColors.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

using aniso::colorValue;
using aniso::numberValue;
using aniso::textValue;

namespace
{
// The plate with "temperature" = x at its points, written as PATH (VTP).
bool writePlate(const QString& path)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(8, 8);
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

// Where the mesh-space point P is shown, in display coordinates (origin bottom left).
std::array<int, 2> displayOf(aniso::SceneView* view, std::array<double, 3> p)
{
  const glm::dvec3 d = view->drawingFrame().pointToDrawing(glm::dvec3(p[0], p[1], p[2]));
  vtkRenderer* renderer = view->renderer();
  renderer->SetWorldPoint(d.x, d.y, d.z, 1.0);
  renderer->WorldToDisplay();
  const double* shown = renderer->GetDisplayPoint();
  return {int(shown[0] + 0.5), int(shown[1] + 0.5)};
}

// Mean RGB (0-255) over a 7x7 square around display position AT.
std::array<double, 3> meanAround(aniso::SceneView* view, std::array<int, 2> at)
{
  vtkRenderWindow* window = view->renderer()->GetRenderWindow();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(at[0] - 3, at[1] - 3, at[0] + 3, at[1] + 3, 0, pixels);
  std::array<double, 3> mean{0.0, 0.0, 0.0};
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      mean[std::size_t(c)] += pixels->GetComponent(i, c);
    }
  }
  for (double& m : mean)
  {
    m /= double(pixels->GetNumberOfTuples());
  }
  return mean;
}

double difference(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  double most = 0.0;
  for (std::size_t c = 0; c < 3; ++c)
  {
    most = std::max(most, std::abs(a[c] - b[c]));
  }
  return most;
}

QString text(const std::array<double, 3>& rgb)
{
  return QString("(%1, %2, %3)").arg(rgb[0]).arg(rgb[1]).arg(rgb[2]);
}

// The overlay's colour bars.
std::vector<vtkScalarBarActor*> scalarBars(aniso::SceneView* view)
{
  std::vector<vtkScalarBarActor*> bars;
  vtkPropCollection* props = view->overlay()->GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp())
  {
    if (auto* bar = vtkScalarBarActor::SafeDownCast(prop))
    {
      bars.push_back(bar);
    }
  }
  return bars;
}

bool settled(aniso::MainWindow& window)
{
  return window.view()->converged() && !window.lutScheduler()->busy();
}
} // namespace

class TestFieldsWindow : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void aFieldColoursThePlateWithALegend()
  {
    QTemporaryDir dir;
    const QString plate = dir.filePath("plate.vtp");
    QVERIFY(writePlate(plate));

    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.view()->setSettleMs(30);
    // Frames of the material's samples whatever they cost: every still view the same samples,
    // so the field-less image comes back exactly after the undo.
    window.view()->setFrameBudgetMs(0);
    window.resize(900, 820);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    QVERIFY(window.openMesh(plate));
    QCOMPARE(errors.count(), 0);
    aniso::SceneModel* model = window.model();
    aniso::SceneView* view = window.view();
    // The albedo shows the field's colours alone: no specular (F0 0), a white albedo.
    model->setValues({{"samples", numberValue(4.0)},
                      {"target-samples", numberValue(4.0)},
                      {"background", textValue("color")},
                      {"background-color", colorValue(0.0, 0.0, 0.0)},
                      {"f0", colorValue(0.0, 0.0, 0.0)},
                      {"albedo", colorValue(1.0, 1.0, 1.0)},
                      {"field-target", textValue("albedo")}});
    view->showView("+z"); // the plate face on
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    const auto lowAt = displayOf(view, {-0.35, 0.0, 0.0});
    const auto highAt = displayOf(view, {0.35, 0.0, 0.0});
    const auto lowBefore = meanAround(view, lowAt);
    const auto highBefore = meanAround(view, highAt);
    QVERIFY2(lowBefore[0] + lowBefore[1] > 20.0,
             qPrintable("the plate is not drawn: " + text(lowBefore)));
    QVERIFY(scalarBars(view).empty()); // no field, no legend

    // (a) The dock offers the file's array.
    auto* maps = window.findChild<aniso::MapsDock*>("MapsDock");
    QVERIFY(maps);
    QComboBox* field = maps->fieldBox();
    QCOMPARE(field->objectName(), QString("field"));
    const int temperature = field->findText("temperature");
    QVERIFY2(temperature >= 0, "the field combo does not list temperature");
    QCOMPARE(field->itemText(0), QString("none"));

    // A malformed text is refused with the model's error; the combo shows the scene's value.
    field->lineEdit()->setText("temperature:w");
    emit field->lineEdit()->editingFinished();
    QCOMPARE(errors.count(), 1);
    QVERIFY2(errors.front().front().toString().contains("field"),
             qPrintable(errors.front().front().toString()));
    QCOMPARE(model->text("field"), std::string("none"));
    QCOMPARE(field->currentText(), QString("none"));
    errors.clear();

    // The field chosen in the dock: one undoable edit.
    const int undoBefore = window.editor()->undoStack()->count();
    field->setCurrentIndex(temperature);
    emit field->activated(temperature);
    QCOMPARE(model->text("field"), std::string("temperature"));
    QCOMPARE(window.editor()->undoStack()->count(), undoBefore + 1);
    QCOMPARE(field->currentText(), QString("temperature"));
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    QCOMPARE(errors.count(), 0);

    // (b) One bar, over the array's range as written (x of the plate's points: -0.5 to 0.5),
    // the material's automatic range resolved to the same.
    const auto bars = scalarBars(view);
    QCOMPARE(bars.size(), std::size_t(1));
    const double* range = bars.front()->GetLookupTable()->GetRange();
    QVERIFY2(std::abs(range[0] + 0.5) < 1e-9 && std::abs(range[1] - 0.5) < 1e-9,
             qPrintable(QString("legend range %1..%2").arg(range[0]).arg(range[1])));
    QCOMPARE(QString(bars.front()->GetTitle()), QString("temperature"));
    const aniso::MaterialSettings& drawn = view->partMaterial(0)->settings();
    QVERIFY(drawn.field.has_value());
    QVERIFY(!drawn.field->range.automatic);
    QCOMPARE(drawn.field->range.min, -0.5);
    QCOMPARE(drawn.field->range.max, 0.5);

    // (c) The pixels against the field-less image: both sides changed, and the high side is
    // viridis' yellow end (much greener than the low side's dark purple).
    const auto lowField = meanAround(view, lowAt);
    const auto highField = meanAround(view, highAt);
    QVERIFY2(difference(lowField, lowBefore) > 20.0,
             qPrintable("low side " + text(lowBefore) + " -> " + text(lowField)));
    QVERIFY2(difference(highField, highBefore) > 20.0,
             qPrintable("high side " + text(highBefore) + " -> " + text(highField)));
    QVERIFY2(highField[1] > lowField[1] + 40.0,
             qPrintable("low " + text(lowField) + ", high " + text(highField)));
    // A screenshot (File > Export Screenshot, --screenshot) draws from these settings: the
    // resolved field, and the legend on.
    const int* size = view->renderer()->GetRenderWindow()->GetSize();
    const aniso::RenderSettings screenshot = view->renderSettings(size[0], size[1]);
    QVERIFY(screenshot.display.legend);
    QVERIFY(screenshot.material.field.has_value());
    QCOMPARE(screenshot.material.field->range.min, -0.5);
    QCOMPARE(screenshot.material.field->range.max, 0.5);

    const QString withLegend = dir.filePath("legend.png");
    window.exportScreenshot(withLegend, {});

    // (d) legend off takes the bar away; undone, the bar is back.
    window.editor()->edit("legend", textValue("off"));
    QVERIFY(scalarBars(view).empty());
    QVERIFY(!view->renderSettings(size[0], size[1]).display.legend);
    // The screenshots with and without the legend: the same plate (pixels of the left 80 % are
    // the same), the bar and its labels only in the one with the legend, at the right.
    const QString withoutLegend = dir.filePath("plain.png");
    window.exportScreenshot(withoutLegend, {});
    const aniso::Image on = aniso::readImage(withLegend.toStdString());
    const aniso::Image off = aniso::readImage(withoutLegend.toStdString());
    QCOMPARE(on.width, off.width);
    QCOMPARE(on.height, off.height);
    long long barPixels = 0;
    double leftMost = 0.0;
    for (int y = 0; y < on.height; ++y)
    {
      for (int x = 0; x < on.width; ++x)
      {
        double d = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          d = std::max(d, double(std::abs(on.at(x, y, c) - off.at(x, y, c))));
        }
        if (x < on.width * 8 / 10)
        {
          leftMost = std::max(leftMost, d);
        }
        else if (d > 0.1)
        {
          ++barPixels;
        }
      }
    }
    QVERIFY2(leftMost < 2.0 / 255.0, qPrintable(QString("left part differs by %1").arg(leftMost)));
    QVERIFY2(barPixels > 1000, qPrintable(QString("%1 pixels of the legend").arg(barPixels)));
    window.editor()->undoStack()->undo();
    QCOMPARE(model->text("legend"), std::string("on"));
    QCOMPARE(scalarBars(view).size(), std::size_t(1));

    // (e) Undo of the field edit: no field, no bar, the field-less pixels (the same samples of
    // the same material: within rounding).
    window.editor()->undoStack()->undo();
    QCOMPARE(model->text("field"), std::string("none"));
    QCOMPARE(field->currentText(), QString("none"));
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    QVERIFY(!view->partMaterial(0)->settings().field.has_value());
    QVERIFY(scalarBars(view).empty());
    const auto lowAfter = meanAround(view, lowAt);
    const auto highAfter = meanAround(view, highAt);
    QVERIFY2(difference(lowAfter, lowBefore) < 1.0,
             qPrintable("low side " + text(lowBefore) + " -> " + text(lowAfter)));
    QVERIFY2(difference(highAfter, highBefore) < 1.0,
             qPrintable("high side " + text(highBefore) + " -> " + text(highAfter)));
    QCOMPARE(errors.count(), 0);
  }
};

QTEST_MAIN(TestFieldsWindow)
#include "test_fields_window.moc"
