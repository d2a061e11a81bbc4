// The shading model in the window (needs an X server: run under Xvfb, serially). Checks: a lit
// model replaces the environment material on screen and as-env brings it back; with no light
// and env-lights off a lit model reflects nothing (the sum over lights is empty), so the mesh is
// as black as a black background, while env-lights on (the environment's sources as lights,
// from the analysis the view's worker baked) or a light from the camera makes it visible; the
// comparison view has one viewport
// per lit model of the registry, all drawing the view's mesh through one camera, each showing
// the lit mesh at its centre. The surface models (LEADR, microstructure) replace the scene actor
// as well.
#include "app/gui/CompareWindow.h"
#include "app/gui/LitModelView.h"
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "core/models/models.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "widgets/LightsDock.h"

#include <QComboBox>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <algorithm>
#include <string>
#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>

using aniso::numberValue;
using aniso::textValue;

namespace
{
// The brightest channel over a small square at the centre of VIEWPORT (fractions of WINDOW).
int centreBrightness(vtkRenderWindow* window, const double viewport[4])
{
  const int* size = window->GetSize();
  const int cx = int((viewport[0] + viewport[2]) * 0.5 * size[0]);
  const int cy = int((viewport[1] + viewport[3]) * 0.5 * size[1]);
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(cx - 3, cy - 3, cx + 3, cy + 3, 0, pixels);
  int peak = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      peak = std::max(peak, int(pixels->GetComponent(i, c)));
    }
  }
  return peak;
}

// The brightest channel of any pixel of the window.
int peakBrightness(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels);
  int peak = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      peak = std::max(peak, int(pixels->GetComponent(i, c)));
    }
  }
  return peak;
}

// A directional light from the camera (the mesh's centre then holds the highlight), as text.
std::string headLight(vtkRenderer* renderer)
{
  double p[3];
  double f[3];
  renderer->GetActiveCamera()->GetPosition(p);
  renderer->GetActiveCamera()->GetFocalPoint(f);
  return "dir:" + std::to_string(p[0] - f[0]) + "," + std::to_string(p[1] - f[1]) + "," +
         std::to_string(p[2] - f[2]) + ":3";
}

vtkActor* firstActor(vtkRenderer* renderer)
{
  return aniso::firstActorOf(renderer);
}
} // namespace

class TestCompareModels : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void litModelReplacesTheEnvironmentMaterial()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.model()->setValues({{"mesh", textValue("builtin:sphere")},
                               {"samples", numberValue(1.0)},
                               {"target-samples", numberValue(1.0)},
                               {"nu", numberValue(20.0)},
                               {"nv", numberValue(20.0)},
                               {"background", textValue("color")},
                               {"background-color", aniso::colorValue(0.0, 0.0, 0.0)}});
    window.show();
    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    vtkActor* sceneActor = firstActor(view->renderer());
    QVERIFY(sceneActor->GetVisibility());
    QCOMPARE(window.lightsDock()->modelBox()->count(), int(aniso::shadingModels().size()));

    window.editor()->edit("model", textValue("banks"));
    window.editor()->edit("lights", textValue("none"));
    window.editor()->edit("env-lights", textValue("off"));
    QVERIFY(!sceneActor->GetVisibility());
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    const double whole[4] = {0.0, 0.0, 1.0, 1.0};
    vtkRenderWindow* rw = window.vtkWidget()->renderWindow();
    QCOMPARE(centreBrightness(rw, whole), 0);
    QCOMPARE(peakBrightness(rw), 0);

    // With env-lights, the environment's sources (the studio's soft boxes, from its analysis,
    // baked on the view's worker) light the lit model though the scene has no light.
    window.editor()->edit("env-lights", textValue("on"));
    QTRY_VERIFY_WITH_TIMEOUT(view->converged() && !view->lightingBusy(), 60000);
    QVERIFY(view->lighting()->bakedAnalysis());
    QVERIFY(!view->lighting()->bakedAnalysis()->sources.empty());
    QVERIFY(window.litView()->partMaterial(0));
    QCOMPARE(window.litView()->partMaterial(0)->settings().lights.size(),
             std::min<std::size_t>(view->lighting()->bakedAnalysis()->sources.size(),
                                   aniso::LitModelMaterial::kMaxLights));
    rw->Render();
    QTRY_VERIFY_WITH_TIMEOUT(peakBrightness(rw) > 20, 60000);
    window.editor()->edit("env-lights", textValue("off"));
    QCOMPARE(window.litView()->partMaterial(0)->settings().lights.size(), std::size_t(0));

    window.editor()->edit("lights", textValue(headLight(view->renderer())));
    QTRY_VERIFY_WITH_TIMEOUT(view->converged(), 60000);
    QVERIFY(centreBrightness(rw, whole) > 20);

    window.editor()->edit("model", textValue("as-env"));
    QVERIFY(sceneActor->GetVisibility());

    // The surface models draw in place of the scene actor too (test_surface_model_view checks
    // their pixels), silently.
    QSignalSpy notes(&window, &aniso::MainWindow::errorReported);
    window.editor()->edit("model", textValue("leadr"));
    window.editor()->edit("lights", textValue("dir:0,0,1:1"));
    QCOMPARE(notes.count(), 0);
    QVERIFY(!sceneActor->GetVisibility());
  }

  void comparisonHasOneViewportPerLitModel()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.model()->setValues({{"mesh", textValue("builtin:sphere")},
                               {"samples", numberValue(1.0)},
                               {"target-samples", numberValue(1.0)},
                               {"nu", numberValue(20.0)},
                               {"nv", numberValue(20.0)}});
    window.show();
    QTRY_VERIFY_WITH_TIMEOUT(window.view()->converged(), 60000);
    window.editor()->edit("lights", textValue(headLight(window.view()->renderer())));
    window.showCompareWindow();
    aniso::CompareWindow* compare = window.compareWindow();
    QVERIFY(compare);
    QVERIFY(QTest::qWaitForWindowExposed(compare));

    // The lit models of the registry, counted here from its rows.
    int lit = 0;
    for (const aniso::ShadingModelInfo& info : aniso::shadingModels())
    {
      aniso::LitModel model;
      lit += aniso::litModelFromName(info.name, model) ? 1 : 0;
    }
    QCOMPARE(compare->viewportCount(), lit);
    auto* sceneMapper =
        vtkPolyDataMapper::SafeDownCast(firstActor(window.view()->renderer())->GetMapper());
    vtkRenderWindow* rw = compare->vtkWidget()->renderWindow();
    rw->Render();
    for (int i = 0; i < lit; ++i)
    {
      vtkRenderer* r = compare->viewport(i);
      QCOMPARE(r->GetActiveCamera(), compare->viewport(0)->GetActiveCamera());
      auto* mapper = vtkPolyDataMapper::SafeDownCast(firstActor(r)->GetMapper());
      QCOMPARE(mapper->GetInput(), sceneMapper->GetInput());
      QVERIFY2(centreBrightness(rw, r->GetViewport()) > 20, std::to_string(i).c_str());
    }
  }
};

QTEST_MAIN(TestCompareModels)
#include "test_compare_window.moc"
