// STEP files in the window (needs an X server: Xvfb, serially). The reference assembly of
// tests/vtkpasses/mesh/cad_test_documents.h (a plate and a pin placed twice, in a sub-assembly),
// written by OpenCASCADE's own STEP writer, is the reference: opened in the window (directly
// and on the worker) it gives one part per leaf instance named by its instance path, the file's
// colours as library materials assigned to those parts, and the file's placements. A finer
// cad-deflection set through the SceneEditor reads the parts again on the worker, the previous
// surfaces drawn meanwhile, and gives more triangles on the pins (a cylinder's chords shorten
// as the deflection does; the plate's box keeps its twelve); undo gives the old count back. A
// truncated STEP file leaves the scene as it was, with an error naming the file.
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "tests/vtkpasses/mesh/cad_test_documents.h"

#include <QFile>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <cmath>

using aniso::numberValue;
using aniso::ScenePart;
namespace cadtest = aniso::cadtest;

namespace
{
const std::vector<std::string> kPartNames{"rig/base", "rig/pins/pin-a", "rig/pins/pin-b"};

QString writeReference(const QTemporaryDir& dir)
{
  const QString path = dir.filePath("rig.step");
  if (!cadtest::writeStepFile(cadtest::referenceDocument(), path.toStdString()))
  {
    return {};
  }
  return path;
}

// Shown (the view draws only into a window on screen), with cheap frames: what is drawn is not
// what these tests look at.
void showSmall(aniso::MainWindow& window)
{
  window.setErrorDialogs(false);
  window.model()->setValues({{"samples", numberValue(1.0)}, {"target-samples", numberValue(1.0)}});
  window.resize(700, 600);
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
}

int partNamed(const aniso::SceneModel& model, const std::string& name)
{
  for (std::size_t i = 0; i < model.parts().size(); ++i)
  {
    if (model.parts()[i].name == name)
    {
      return int(i);
    }
  }
  return -1;
}

// The parts of the reference assembly, as the file gives them: names, colours as the parts'
// library materials (albedo the colour, as STEP keeps it: a few digits), placements.
void checkReferenceParts(aniso::MainWindow& window)
{
  const aniso::SceneModel& model = *window.model();
  std::vector<std::string> names;
  for (const ScenePart& part : model.parts())
  {
    names.push_back(part.name);
  }
  QCOMPARE(names, kPartNames);
  const cadtest::Reference r = cadtest::reference();
  const std::vector<aniso::PartMatrix> placements{
      aniso::kIdentityPlacement, cadtest::matrixOf(r.pins * r.pinA),
      cadtest::matrixOf(r.pins * r.pinB)};
  const std::vector<cadtest::Rgb> colours{cadtest::kPlateColour, cadtest::kPinColour,
                                          cadtest::kPinColour};
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    const ScenePart& part = model.parts()[i];
    for (std::size_t k = 0; k < 16; ++k)
    {
      QVERIFY2(std::abs(part.placement[k] - placements[i][k]) < 1e-9, part.name.c_str());
    }
    const aniso::Material* material = model.materials().find(part.material);
    QVERIFY2(material, part.material.c_str());
    const auto& albedo = material->value("albedo").number;
    QVERIFY2(std::abs(albedo[0] - colours[i].r) < 2e-3 && std::abs(albedo[1] - colours[i].g) < 2e-3 &&
                 std::abs(albedo[2] - colours[i].b) < 2e-3,
             part.name.c_str());
    QVERIFY(window.view()->partTriangles(int(i)) > 0);
  }
  // The two pins are one product: one material.
  QCOMPARE(model.parts()[1].material, model.parts()[2].material);
  QVERIFY(model.parts()[0].material != model.parts()[1].material);
}
} // namespace

class TestCadWindow : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void aStepAssemblyOpensAsItsParts()
  {
    QTemporaryDir dir;
    const QString step = writeReference(dir);
    QVERIFY(!step.isEmpty());
    {
      aniso::MainWindow window;
      showSmall(window);
      QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
      QVERIFY(window.openMesh(step));
      QCOMPARE(errors.count(), 0);
      checkReferenceParts(window);
      // The status bar tells the tessellation's triangles.
      const QString message = window.statusBar()->currentMessage();
      QVERIFY2(message.startsWith("STEP: ") && message.contains("triangles at deflection 0.001"),
               qPrintable(message));
    }
    {
      aniso::MainWindow window;
      showSmall(window);
      QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
      window.openMeshInBackground(step);
      QVERIFY(window.meshLoading());
      QCOMPARE(window.statusBar()->currentMessage(), QString("Loading %1").arg(step));
      QTRY_VERIFY_WITH_TIMEOUT(!window.meshLoading(), 60000);
      QCOMPARE(errors.count(), 0);
      checkReferenceParts(window);
    }
  }

  void aFinerDeflectionGivesMoreTrianglesAndUndoTheOldOnes()
  {
    QTemporaryDir dir;
    const QString step = writeReference(dir);
    QVERIFY(!step.isEmpty());
    aniso::MainWindow window;
    showSmall(window);
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    QVERIFY(window.openMesh(step));
    aniso::SceneView* view = window.view();
    const int plate = partNamed(*window.model(), "rig/base");
    const int pin = partNamed(*window.model(), "rig/pins/pin-a");
    const long long plateTriangles = view->partTriangles(plate);
    const long long pinTriangles = view->partTriangles(pin);
    QCOMPARE(plateTriangles, 12LL); // a box: two triangles a face, whatever the deflection
    QVERIFY(pinTriangles > 0);

    QSignalSpy outdated(view, &aniso::SceneView::surfacesOutdated);
    window.editor()->edit("cad-deflection", numberValue(0.0001));
    // Read on the worker: until then the previous surfaces are drawn.
    QVERIFY(outdated.count() >= 1);
    QCOMPARE(view->partTriangles(pin), pinTriangles);
    QTRY_VERIFY_WITH_TIMEOUT(view->partTriangles(pin) > pinTriangles, 60000);
    const long long finer = view->partTriangles(pin);
    QCOMPARE(view->partTriangles(partNamed(*window.model(), "rig/pins/pin-b")), finer);
    QCOMPARE(view->partTriangles(plate), plateTriangles);
    const QString message = window.statusBar()->currentMessage();
    QVERIFY2(message.contains("at deflection 0.0001"), qPrintable(message));
    QCOMPARE(errors.count(), 0);

    // Undo: the old tessellation, still held by the assets (read nothing again).
    window.editor()->undoStack()->undo();
    QCOMPARE(window.model()->real("cad-deflection"), 0.001);
    QTRY_COMPARE_WITH_TIMEOUT(view->partTriangles(pin), pinTriangles, 60000);
    window.editor()->undoStack()->redo();
    QTRY_COMPARE_WITH_TIMEOUT(view->partTriangles(pin), finer, 60000);

    // A coarse deflection: fewer triangles than at first (the 20 degrees angle now sets the
    // chords), again read on the worker.
    window.editor()->edit("cad-deflection", numberValue(0.05));
    QTRY_VERIFY_WITH_TIMEOUT(view->partTriangles(pin) < pinTriangles, 60000);
    QCOMPARE(errors.count(), 0);
  }

  void aTruncatedStepLeavesTheScene()
  {
    QTemporaryDir dir;
    const QString step = writeReference(dir);
    QVERIFY(!step.isEmpty());
    const QString cut = dir.filePath("cut.step");
    {
      QFile whole(step);
      QVERIFY(whole.open(QIODevice::ReadOnly));
      const QByteArray bytes = whole.readAll();
      QFile part(cut);
      QVERIFY(part.open(QIODevice::WriteOnly));
      part.write(bytes.left(bytes.size() * 2 / 3));
    }
    aniso::MainWindow window;
    showSmall(window);
    QVERIFY(window.openMesh(step));
    const std::vector<ScenePart> before = window.model()->parts();
    const int undoSteps = window.editor()->undoStack()->count();
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);

    QVERIFY(!window.openMesh(cut));
    QCOMPARE(errors.count(), 1);
    QVERIFY2(errors.at(0).at(0).toString().contains(cut), qPrintable(errors.at(0).at(0).toString()));
    QCOMPARE(window.model()->parts(), before);
    QCOMPARE(window.editor()->undoStack()->count(), undoSteps);

    window.openMeshInBackground(cut);
    QTRY_VERIFY_WITH_TIMEOUT(!window.meshLoading(), 60000);
    QCOMPARE(errors.count(), 2);
    QVERIFY2(errors.at(1).at(0).toString().contains(cut), qPrintable(errors.at(1).at(0).toString()));
    QCOMPARE(window.model()->parts(), before);
    QCOMPARE(window.editor()->undoStack()->count(), undoSteps);
    for (int i = 0; i < window.view()->partCount(); ++i)
    {
      QVERIFY(window.view()->partTriangles(i) > 0);
    }
  }
};

QTEST_MAIN(TestCadWindow)
#include "test_cad_window.moc"
