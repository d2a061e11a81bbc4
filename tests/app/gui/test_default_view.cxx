// One default view everywhere: the window frames a part as `aniso render` does.
//  - The window's camera at start-up (in the drawing frame of the part's unit bounding sphere)
//    is the camera renderOffscreen places for `aniso render`'s default view, as the render
//    command parses it (renderViewSettings with no --view), for the window's own size: the same
//    position, focal point, view-up and view angle.
//  - That view sees a part lying flat in the XY plane from above: the camera is above the
//    plane at more than 30 degrees.
//  - Each entry of the View menu's Standard Views is a name `aniso render --view` takes and puts
//    the window's camera where the command line's view of that name would.
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "app/render_command.h"
#include "vtkpasses/render/ViewSettings.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <cmath>
#include <glm/geometric.hpp>
#include <vtkCamera.h>
#include <vtkOpenGLRenderer.h>
#include <vtkRenderWindow.h>

namespace
{
// The camera renderOffscreen would place for `aniso render ARGS` in a frame of the window's
// size (the drawing frame's unit sphere).
aniso::CameraPlacement renderCamera(aniso::SceneView* view, std::vector<std::string> args)
{
  args.insert(args.end(), {"--builtin", "plate", "-o", "out.png"});
  const int* size = view->renderer()->GetRenderWindow()->GetSize();
  return aniso::placeCamera(
      aniso::fittedToFrame(aniso::cli::renderViewSettings(args), size[0], size[1]), glm::dvec3(0.0),
      1.0);
}

void compareCameras(vtkCamera* camera, const aniso::CameraPlacement& expected, const char* what)
{
  double p[3], f[3], u[3];
  camera->GetPosition(p);
  camera->GetFocalPoint(f);
  camera->GetViewUp(u);
  const double tolerance = 1e-9;
  QVERIFY2(glm::length(glm::dvec3(p[0], p[1], p[2]) - expected.position) < tolerance, what);
  QVERIFY2(glm::length(glm::dvec3(f[0], f[1], f[2]) - expected.focalPoint) < tolerance, what);
  // The view-up as it shows on screen: its part across the direction of projection.
  const glm::dvec3 forward = glm::normalize(expected.focalPoint - expected.position);
  const auto across = [&](const glm::dvec3& v)
  { return glm::normalize(v - glm::dot(v, forward) * forward); };
  QVERIFY2(glm::length(across(glm::dvec3(u[0], u[1], u[2])) - across(expected.viewUp)) < 1e-6,
           what);
  QCOMPARE(camera->GetViewAngle(), expected.viewAngleDegrees);
  QCOMPARE(camera->GetParallelProjection() != 0, expected.parallel);
}
} // namespace

class TestDefaultView : public QObject
{
  Q_OBJECT

private slots:
  void windowAndRenderAgree()
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.model()->setValues({{"mesh", aniso::textValue("builtin:plate")},
                               {"samples", aniso::numberValue(1.0)},
                               {"target-samples", aniso::numberValue(1.0)}});
    window.resize(900, 600);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    aniso::SceneView* view = window.view();
    // The camera is placed for the view's size once it has one: reset it at the final size.
    view->resetCamera();
    vtkCamera* camera = view->renderer()->GetActiveCamera();
    compareCameras(camera, renderCamera(view, {}), "default view");

    // From above the XY plane, steeply enough to see a flat part's face.
    double p[3], f[3];
    camera->GetPosition(p);
    camera->GetFocalPoint(f);
    const glm::dvec3 toCamera = glm::normalize(glm::dvec3(p[0] - f[0], p[1] - f[1], p[2] - f[2]));
    QVERIFY(std::asin(toCamera.z) > 30.0 * M_PI / 180.0);

    // The View menu's standard views, each by the name the command line takes.
    QMenu* standard = nullptr;
    for (QMenu* menu : window.menuBar()->findChildren<QMenu*>())
    {
      if (menu->title().remove('&') == "Standard Views")
      {
        standard = menu;
      }
    }
    QVERIFY(standard);
    QCOMPARE(standard->actions().size(), int(aniso::viewPresets().size()));
    for (QAction* action : standard->actions())
    {
      const std::string name = action->data().toString().toStdString();
      action->trigger();
      compareCameras(camera, renderCamera(view, {"--view", name}), name.c_str());
    }
  }
};

int main(int argc, char** argv)
{
  // The VTK widget needs its OpenGL format before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  TestDefaultView test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_default_view.moc"
