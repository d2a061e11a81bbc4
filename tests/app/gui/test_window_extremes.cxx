// The window's view of meshes at the edges of the number range (needs an X server: run under
// Xvfb, serially). A tetrahedron scaled by 1e30 or 1e-30, or moved 1e7 from the origin, is shown
// as the same tetrahedron at unit size at the origin: the view frames the object and the
// environment lighting depends on directions only, so the unit mesh's window image is the
// reference. Bound: the mean 8-bit difference below 0.5/255 and the largest below 2/255, every
// pixel of the frame read back. And the camera the view reports (and a session saves) is in the
// mesh's own coordinates: it looks at the scaled or moved tetrahedron's centre.
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"

#include <QStandardPaths>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>

using aniso::numberValue;
using aniso::textValue;

namespace
{
// The corner at the origin and the three unit points, scaled and moved; faces wound outwards.
std::string tetrahedronOff(double scale, double offset)
{
  const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::ostringstream text;
  text.precision(17);
  text << "OFF\n4 4 0\n";
  for (const auto& c : corners)
    text << offset + scale * c[0] << ' ' << offset + scale * c[1] << ' ' << offset + scale * c[2]
         << '\n';
  text << "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  return text.str();
}

std::vector<unsigned char> windowPixels(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels);
  std::vector<unsigned char> rgb;
  for (vtkIdType i = 0; i < vtkIdType(size[0]) * size[1]; ++i)
    for (int c = 0; c < 3; ++c)
      rgb.push_back(static_cast<unsigned char>(pixels->GetComponent(i, c)));
  return rgb;
}
} // namespace

class TestWindowExtremes : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void tinyHugeAndFarMeshesShowAsTheUnitOne()
  {
    QTemporaryDir dir;
    struct Case
    {
      const char* name;
      double scale;
      double offset;
    };
    const Case cases[] = {{"unit.off", 1.0, 0.0},
                          {"huge.off", 1e30, 0.0},
                          {"tiny.off", 1e-30, 0.0},
                          {"far.off", 1.0, 1e7}};
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    // Frames of the material's samples whatever they cost: every mesh is refined by the same
    // frames (under a budget the plan follows the machine's load, and frames of other sample
    // counts give other noise: 1.1/255 apart in one loaded run).
    window.view()->setFrameBudgetMs(0);
    window.model()->setValues(
        {{"samples", numberValue(4.0)}, {"target-samples", numberValue(4.0)}});
    window.resize(400, 300);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    aniso::SceneView* view = window.view();
    vtkRenderWindow* rw = window.vtkWidget()->renderWindow();
    std::vector<unsigned char> reference;
    for (const Case& c : cases)
    {
      const QString path = dir.filePath(c.name);
      std::ofstream(path.toStdString()) << tetrahedronOff(c.scale, c.offset);
      window.editor()->edit("mesh", textValue(path.toStdString()));
      QTRY_VERIFY_WITH_TIMEOUT(view->converged() && !view->lightingBusy(), 60000);
      rw->Render();

      // The reported camera looks at the tetrahedron's centre in its own coordinates.
      const aniso::CameraState camera = view->currentCamera();
      const double centre = c.offset + 0.5 * c.scale;
      for (int i = 0; i < 3; ++i)
        QVERIFY2(std::abs(camera.focalPoint[std::size_t(i)] - centre) <= 1e-9 * std::abs(centre),
                 c.name);

      const std::vector<unsigned char> shown = windowPixels(rw);
      if (reference.empty())
      {
        reference = shown;
        QVERIFY(*std::max_element(shown.begin(), shown.end()) > 0);
        continue;
      }
      QCOMPARE(shown.size(), reference.size());
      double sum = 0.0;
      int largest = 0;
      for (std::size_t i = 0; i < shown.size(); ++i)
      {
        const int d = std::abs(int(shown[i]) - int(reference[i]));
        sum += d;
        largest = std::max(largest, d);
      }
      const double mean = sum / double(shown.size());
      std::printf("%s: window against the unit mesh's, mean difference %.3g/255, largest %d/255\n",
                  c.name, mean, largest);
      QVERIFY2(mean < 0.5, c.name);
      QVERIFY2(largest <= 2, c.name);
    }
  }
};

QTEST_MAIN(TestWindowExtremes)
#include "test_window_extremes.moc"
