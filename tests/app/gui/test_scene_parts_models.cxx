// The other models' views draw a scene of parts each with its own material (needs an X server:
// Xvfb, serially). Two spheres side by side, written by VTK's PLY writer (an independent writer,
// with texture coordinates for the surface models), are opened as two parts, the left one
// aluminium with a grey albedo, the right one satin gold (F0 1, 0.78, 0.34: less blue than red)
// with a golden albedo (the lit models' colour), under a light from the camera. Checks: the lit
// model's view (Ward) draws one actor per part, and the right part's pixels have a lower blue to
// red ratio than the left part's; so does every viewport of the comparison window, each drawing two
// actors (the main view's part surfaces); so does the LEADR view. Editing the right part's material
// changes the right part's pixels in the lit view and leaves the left part's exactly as they were.
// Hiding the right part takes its actor out of the lit view's renderer, the comparison window's
// viewports and the LEADR view.
#include "app/gui/CompareWindow.h"
#include "app/gui/LitModelView.h"
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "app/gui/SurfaceModelView.h"
#include "core/image/image.h"
#include "scene/LutScheduler.h"
#include "widgets/SceneDock.h"

#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <array>
#include <string>
#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkSphereSource.h>
#include <vtkTextureMapToSphere.h>
#include <vtkUnsignedCharArray.h>

using aniso::numberValue;
using aniso::textValue;

namespace
{
// A sphere of radius 1 at (X, 0, 0) with spherical texture coordinates, written as binary PLY.
void writeSphere(const QString& path, double x)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(x, 0.0, 0.0);
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  vtkNew<vtkTextureMapToSphere> uv;
  uv->SetInputConnection(sphere->GetOutputPort());
  uv->PreventSeamOff();
  uv->Update();
  vtkNew<vtkPLYWriter> writer;
  writer->SetFileName(path.toStdString().c_str());
  writer->SetInputData(vtkPolyData::SafeDownCast(uv->GetOutput()));
  writer->SetFileTypeToBinary();
  writer->Write();
}

// Where the mesh-space point P is shown by RENDERER (drawing in VIEW's drawing frame), in display
// coordinates (origin bottom left).
std::array<int, 2> displayOf(aniso::SceneView* view, vtkRenderer* renderer, std::array<double, 3> p)
{
  const glm::dvec3 d = view->drawingFrame().pointToDrawing(glm::dvec3(p[0], p[1], p[2]));
  renderer->SetWorldPoint(d.x, d.y, d.z, 1.0);
  renderer->WorldToDisplay();
  const double* shown = renderer->GetDisplayPoint();
  return {int(shown[0] + 0.5), int(shown[1] + 0.5)};
}

// Mean RGB (0-255) of WINDOW over a 7x7 square around display position AT.
std::array<double, 3> meanAround(vtkRenderWindow* window, std::array<int, 2> at)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  window->MakeCurrent(); // the other window's context may be the current one
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

QString rgb(const std::array<double, 3>& c)
{
  return QString("%1 %2 %3").arg(c[0]).arg(c[1]).arg(c[2]);
}

// The right part is gold, the left aluminium: its blue to red ratio is clearly lower (and both
// are drawn: bright enough to tell).
bool rightIsGold(const std::array<double, 3>& left, const std::array<double, 3>& right)
{
  qInfo("left %.1f %.1f %.1f (blue/red %.3f), right %.1f %.1f %.1f (blue/red %.3f)", left[0],
        left[1], left[2], left[2] / left[0], right[0], right[1], right[2], right[2] / right[0]);
  return left[0] > 8.0 && right[0] > 8.0 && right[2] / right[0] < left[2] / left[0] - 0.05;
}

// A directional light from the camera (each sphere then has its highlight near its centre).
std::string headLight(vtkRenderer* renderer, double strength)
{
  double p[3];
  double f[3];
  renderer->GetActiveCamera()->GetPosition(p);
  renderer->GetActiveCamera()->GetFocalPoint(f);
  return "dir:" + std::to_string(p[0] - f[0]) + "," + std::to_string(p[1] - f[1]) + "," +
         std::to_string(p[2] - f[2]) + ":" + std::to_string(strength);
}

int actorsIn(vtkRenderer* renderer)
{
  return renderer->GetActors()->GetNumberOfItems();
}

bool settled(aniso::MainWindow& window)
{
  return window.view()->converged() && !window.view()->lightingBusy() &&
         !window.lutScheduler()->busy();
}
} // namespace

class TestScenePartsModels : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void otherModelsDrawEachPartWithItsMaterial()
  {
    QTemporaryDir dir;
    const QString left = dir.filePath("left.ply");
    const QString right = dir.filePath("right.ply");
    writeSphere(left, -1.5);
    writeSphere(right, 1.5);

    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.view()->setSettleMs(30);
    // Frames of the material's samples whatever they cost: the same frames every run, so a part
    // whose material did not change has the same pixels after another part's edit.
    window.view()->setFrameBudgetMs(0);
    // The scene's light alone (no environment source as a light, env-lights): the parts'
    // colours, not the studio's soft boxes, decide the pixels.
    window.model()->setValues({{"samples", numberValue(1.0)},
                               {"target-samples", numberValue(1.0)},
                               // The declared exposure, not the start-up scene's -1 EV: the
                               // LEADR step below sets it back to 0, and the lit view's pixels
                               // before and after are compared at one exposure.
                               {"exposure", numberValue(0.0)},
                               {"background", textValue("color")},
                               {"background-color", aniso::colorValue(0.0, 0.0, 0.0)},
                               {"env-lights", textValue("off")}});
    window.resize(900, 820);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    QVERIFY(window.openMesh(left));
    QVERIFY(window.addMeshes({right}));
    aniso::SceneModel* model = window.model();
    QCOMPARE(model->parts().size(), std::size_t(2));
    // Brushed aluminium for the left part (it kept the start-up scene's spun aluminium, whose
    // streaks from pole to pole would cross the measured points).
    model->setSelection({0});
    window.sceneDock()->assignToSelection(QString::fromUtf8(
        aniso::kDefaultMaterialName.data(), int(aniso::kDefaultMaterialName.size())));
    QCOMPARE(model->parts()[0].material, std::string(aniso::kDefaultMaterialName));
    model->setSelection({1});
    window.sceneDock()->assignToSelection("satin gold");
    QCOMPARE(model->parts()[1].material, std::string("satin gold"));
    // The lit models take F0's mean as their specular reflectance: the gold shows in its diffuse
    // colour there (the library's metals have none).
    window.editor()->edit("albedo", aniso::colorValue(0.8, 0.55, 0.15));
    // And a grey one for aluminium, so the left part shows away from its highlight too.
    model->setSelection({0});
    window.editor()->edit("albedo", aniso::colorValue(0.6, 0.6, 0.6));
    QCOMPARE(model->partMaterial(1).value("albedo"), aniso::colorValue(0.8, 0.55, 0.15));
    model->setSelection({});
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    vtkRenderer* renderer = view->renderer();
    vtkRenderWindow* rw = renderer->GetRenderWindow();
    // Above the spheres' centres, away from the highlights of a light from the camera.
    const std::array<double, 3> leftPoint{-1.5, 0.0, 0.6};
    const std::array<double, 3> rightPoint{1.5, 0.0, 0.6};
    // Where they are shown now (the docks of another model may change the view's size).
    const auto leftAt = [&] { return displayOf(view, renderer, leftPoint); };
    const auto rightAt = [&] { return displayOf(view, renderer, rightPoint); };

    // The lit model: one actor per part, each with its part's material.
    const std::string light = headLight(renderer, 0.5);
    window.editor()->edit("lights", textValue(light));
    window.editor()->edit("model", textValue("ward"));
    aniso::LitModelView* lit = window.litView();
    QVERIFY(lit->active());
    vtkActor* litLeft = lit->partActor(0);
    vtkActor* litRight = lit->partActor(1);
    QVERIFY(litLeft && litRight && litLeft != litRight);
    QVERIFY(renderer->HasViewProp(litLeft) && renderer->HasViewProp(litRight));
    QVERIFY(litLeft->GetVisibility() && litRight->GetVisibility());
    QVERIFY(!view->partActor(0)->GetVisibility() && !view->partActor(1)->GetVisibility());
    QCOMPARE(litRight->GetMapper()->GetInputDataObject(0, 0),
             static_cast<vtkDataObject*>(view->partSurfaceToDraw(1)));
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    const int wardRows = rw->GetSize()[1];
    const auto litLeftBefore = meanAround(rw, leftAt());
    const auto litRightBefore = meanAround(rw, rightAt());
    QVERIFY2(rightIsGold(litLeftBefore, litRightBefore),
             qPrintable("ward: left " + rgb(litLeftBefore) + ", right " + rgb(litRightBefore)));

    // A screenshot of the lit model draws each part with its own material, as the view does
    // (linear radiance: the same test of blue against red).
    {
      const QString shot = dir.filePath("ward.exr");
      window.exportScreenshot(shot, {});
      const aniso::Image image = aniso::readImage(shot.toStdString());
      QCOMPARE(image.width, rw->GetSize()[0]);
      QCOMPARE(image.height, rw->GetSize()[1]);
      const auto imageAround = [&](std::array<int, 2> at)
      {
        std::array<double, 3> mean{0.0, 0.0, 0.0};
        for (int dy = -3; dy <= 3; ++dy)
        {
          for (int dx = -3; dx <= 3; ++dx)
          {
            for (int c = 0; c < 3; ++c)
            {
              mean[std::size_t(c)] +=
                  255.0 * image.at(at[0] + dx, image.height - 1 - (at[1] + dy), c) / 49.0;
            }
          }
        }
        return mean;
      };
      const auto shotLeft = imageAround(leftAt());
      const auto shotRight = imageAround(rightAt());
      QVERIFY2(rightIsGold(shotLeft, shotRight),
               qPrintable("ward screenshot: left " + rgb(shotLeft) + ", right " + rgb(shotRight)));
    }

    // LEADR: one actor per part too, the right one gold.
    window.editor()->edit("model", textValue("leadr"));
    aniso::SurfaceModelView* surface = window.surfaceView();
    QVERIFY(surface->active());
    QVERIFY(!litLeft->GetVisibility() && !litRight->GetVisibility());
    vtkActor* leadrLeft = surface->partActor(0);
    vtkActor* leadrRight = surface->partActor(1);
    QVERIFY(leadrLeft && leadrRight && leadrLeft != leadrRight);
    QVERIFY(renderer->HasViewProp(leadrLeft) && renderer->HasViewProp(leadrRight));
    // LEADR reflects the environment too: a lower exposure keeps its pixels off white.
    window.editor()->edit("exposure", numberValue(-1.5));
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    const auto leadrLeftPixels = meanAround(rw, leftAt());
    const auto leadrRightPixels = meanAround(rw, rightAt());
    QVERIFY2(
        rightIsGold(leadrLeftPixels, leadrRightPixels),
        qPrintable("leadr: left " + rgb(leadrLeftPixels) + ", right " + rgb(leadrRightPixels)));
    window.editor()->edit("exposure", numberValue(0.0));

    // The comparison window: every viewport draws both parts, each with its material (its
    // pixels are linear, with no exposure: a stronger light).
    window.editor()->edit("lights", textValue(headLight(renderer, 3.0)));
    window.showCompareWindow();
    aniso::CompareWindow* compare = window.compareWindow();
    QVERIFY(compare);
    QVERIFY(QTest::qWaitForWindowExposed(compare));
    vtkRenderWindow* compareWindow = compare->vtkWidget()->renderWindow();
    compareWindow->Render();
    QVERIFY(compare->viewportCount() > 1);
    for (int i = 0; i < compare->viewportCount(); ++i)
    {
      vtkRenderer* pane = compare->viewport(i);
      QCOMPARE(actorsIn(pane), 2);
      for (int part = 0; part < 2; ++part)
      {
        QVERIFY(compare->partActor(i, part));
        QCOMPARE(compare->partActor(i, part)->GetMapper()->GetInputDataObject(0, 0),
                 static_cast<vtkDataObject*>(view->partDrawnSurface(part)));
      }
      const auto paneLeft = meanAround(compareWindow, displayOf(view, pane, leftPoint));
      const auto paneRight = meanAround(compareWindow, displayOf(view, pane, rightPoint));
      QVERIFY2(rightIsGold(paneLeft, paneRight),
               qPrintable(QString("viewport %1: left ").arg(i) + rgb(paneLeft) + ", right " +
                          rgb(paneRight)));
    }

    window.editor()->edit("lights", textValue(light));

    // Back to Ward: the same actors again. The right part's material edited (the selection's, a
    // blue albedo): only its pixels change.
    window.editor()->edit("model", textValue("ward"));
    QCOMPARE(lit->partActor(0), litLeft);
    QCOMPARE(lit->partActor(1), litRight);
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    // LEADR's parameters in the Lights dock made the bottom strip taller; back under Ward the
    // strip has its height again, and the view its rows (it stayed 75 rows shorter before).
    QTRY_COMPARE_WITH_TIMEOUT(rw->GetSize()[1], wardRows, 5000);
    // The baseline of the edit below is taken right before it: a part's mean around a point
    // moves by about half a level with the scale it is drawn at.
    const auto litLeftBeforeEdit = meanAround(rw, leftAt());
    const auto litRightBeforeEdit = meanAround(rw, rightAt());
    const aniso::ParameterValue leftAlbedo = model->partMaterial(0).value("albedo");
    model->setSelection({1});
    window.editor()->edit("albedo", aniso::colorValue(0.1, 0.3, 0.9));
    QVERIFY(model->partMaterial(0).value("albedo") == leftAlbedo);
    QCOMPARE(lit->partActor(1), litRight); // the same actor, its settings set
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    const auto litLeftAfter = meanAround(rw, leftAt());
    const auto litRightAfter = meanAround(rw, rightAt());
    for (std::size_t c = 0; c < 3; ++c)
    {
      QVERIFY2(std::abs(litLeftAfter[c] - litLeftBeforeEdit[c]) < 0.5,
               qPrintable("left before " + rgb(litLeftBeforeEdit) + ", after " +
                          rgb(litLeftAfter)));
    }
    QVERIFY2(litRightAfter[2] / litRightAfter[0] >
                 litRightBeforeEdit[2] / litRightBeforeEdit[0] + 0.2,
             qPrintable("right before " + rgb(litRightBeforeEdit) + ", after " +
                        rgb(litRightAfter)));

    // Hiding the right part takes its actor away everywhere.
    std::vector<aniso::ScenePart> parts = model->parts();
    parts[1].visible = false;
    model->setParts(parts, model->materials());
    QVERIFY(!lit->partActor(1));
    QVERIFY(!renderer->HasViewProp(litRight));
    QCOMPARE(lit->partActor(0), litLeft);
    QVERIFY(renderer->HasViewProp(litLeft));
    for (int i = 0; i < compare->viewportCount(); ++i)
    {
      QCOMPARE(actorsIn(compare->viewport(i)), 1);
      QVERIFY(!compare->partActor(i, 1));
    }
    window.editor()->edit("model", textValue("leadr"));
    QVERIFY(surface->active());
    QVERIFY(surface->partActor(0));
    QVERIFY(!surface->partActor(1));
    QVERIFY(!lit->partActor(1));
    QVERIFY2(errors.count() == 0, qPrintable(errors.count() ? errors.at(0).at(0).toString() : ""));
  }
};

QTEST_MAIN(TestScenePartsModels)
#include "test_scene_parts_models.moc"
