// A scene of several parts in the window (needs an X server: Xvfb, serially). Two spheres side by
// side, written by VTK's PLY writer (an independent writer), are opened and added as two parts:
// the scene dock lists them with the triangle counts of the written spheres; a click on the right
// sphere (the view's pick, a ray cast against the drawn parts) selects that part in the model
// and the dock; a library material assigned to the selection reaches only that part (its pixels
// turn gold, the left part's pixels stay as they were, pixel checks against the image before the
// edit); hiding a part takes its pixels away (the background shows there) and frames the visible
// part alone; undo brings the part back; a session of the scene reopens with the same parts and
// materials.
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "core/lut/lut_cache.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "widgets/SceneDock.h"

#include <QFile>
#include <QListWidget>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>
#include <array>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkMapper.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLMultiBlockDataWriter.h>

using aniso::numberValue;
using aniso::ScenePart;
using aniso::textValue;

namespace
{
// A sphere of radius 1 at (X, 0, 0) written as binary PLY; returns its triangle count.
long long writeSphere(const QString& path, double x)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(x, 0.0, 0.0);
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  sphere->Update();
  vtkNew<vtkPLYWriter> writer;
  writer->SetFileName(path.toStdString().c_str());
  writer->SetInputData(sphere->GetOutput());
  writer->SetFileTypeToBinary();
  writer->Write();
  return sphere->GetOutput()->GetNumberOfPolys();
}

// Two spheres written into DIR as left.ply (x = -1.5) and right.ply (x = 1.5), with their
// triangle counts.
struct TwoSpheres
{
  QString left;
  QString right;
  long long leftTriangles = 0;
  long long rightTriangles = 0;
};

TwoSpheres writeTwoSpheres(const QTemporaryDir& dir)
{
  TwoSpheres spheres;
  spheres.left = dir.filePath("left.ply");
  spheres.right = dir.filePath("right.ply");
  spheres.leftTriangles = writeSphere(spheres.left, -1.5);
  spheres.rightTriangles = writeSphere(spheres.right, 1.5);
  return spheres;
}

// Where the mesh-space point P is shown, in display coordinates (origin bottom left).
std::array<int, 2> displayOf(aniso::SceneView* view, std::array<double, 3> p)
{
  const aniso::DrawingFrame& frame = view->drawingFrame();
  const glm::dvec3 d = frame.pointToDrawing(glm::dvec3(p[0], p[1], p[2]));
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

bool settled(aniso::MainWindow& window)
{
  return window.view()->converged() && !window.lutScheduler()->busy();
}
} // namespace

class TestScenePartsWindow : public QObject
{
  Q_OBJECT

private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void partsAreListedPickedEditedAndHidden()
  {
    QTemporaryDir dir;
    const auto [left, right, leftTriangles, rightTriangles] = writeTwoSpheres(dir);

    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.view()->setSettleMs(30);
    // Frames of the material's samples whatever they cost: every refinement run draws the same
    // samples (a budget would plan by measured costs, which vary with the machine's load), so a
    // part whose material did not change has the same pixels after another part's edit.
    window.view()->setFrameBudgetMs(0);
    window.model()->setValues({{"samples", numberValue(4.0)},
                               {"target-samples", numberValue(4.0)},
                               {"background", textValue("color")},
                               {"background-color", aniso::colorValue(0.0, 0.0, 0.0)}});
    // Taller than the docks' least height: the view keeps its size when a dock's content grows
    // (at its least size the window grows, and the view with it, moving every part's pixels).
    window.resize(900, 820);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    QVERIFY(window.openMesh(left));
    QVERIFY(window.addMeshes({right}));
    QCOMPARE(errors.count(), 0);
    aniso::SceneModel* model = window.model();
    QCOMPARE(model->parts().size(), std::size_t(2));
    QCOMPARE(model->parts()[0].name, std::string("left"));
    QCOMPARE(model->parts()[1].name, std::string("right"));

    // The dock lists both with the triangles of the spheres written.
    aniso::SceneDock* dock = window.sceneDock();
    QCOMPARE(dock->partItem(0)->text(0), QString("left"));
    QCOMPARE(dock->partItem(1)->text(2), QString::number(rightTriangles));
    QCOMPARE(dock->partItem(0)->text(2), QString::number(leftTriangles));

    aniso::SceneView* view = window.view();
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    const auto leftAt = displayOf(view, {-1.5, 0.0, 0.0});
    const auto rightAt = displayOf(view, {1.5, 0.0, 0.0});
    const auto leftBefore = meanAround(view, leftAt);
    const auto rightBefore = meanAround(view, rightAt);
    const int samplesBefore = view->accumulatedSamples();
    const std::array<int, 2> viewSize{view->renderer()->GetRenderWindow()->GetSize()[0],
                                      view->renderer()->GetRenderWindow()->GetSize()[1]};
    QVERIFY2(leftBefore[0] + leftBefore[1] > 20.0, "the left sphere is not drawn");
    QVERIFY2(rightBefore[0] + rightBefore[1] > 20.0, "the right sphere is not drawn");

    // A click on the right sphere selects it, in the model and in the dock.
    view->clickedAt(rightAt[0], rightAt[1], false);
    QCOMPARE(model->selection(), std::vector<int>{1});
    QVERIFY(dock->partItem(1)->isSelected());
    QVERIFY(!dock->partItem(0)->isSelected());
    // A click beside both clears it.
    view->clickedAt(5, 5, false);
    QVERIFY(model->selection().empty());
    // Picking draws the parts' ids into the window (VTK's hardware selector) and shows the mean
    // again at once: the mean keeps the samples it had (nothing started over), and the window's
    // pixels are those it had before.
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    QCOMPARE(view->partAt(leftAt[0], leftAt[1]), 0);
    QCOMPARE(view->partAt(rightAt[0], rightAt[1]), 1);
    QCOMPARE(view->partAt(5, 5), -1);
    QCOMPARE(view->accumulatedSamples(), samplesBefore);
    const auto leftPicked = meanAround(view, leftAt);
    const auto rightPicked = meanAround(view, rightAt);
    for (std::size_t c = 0; c < 3; ++c)
    {
      QVERIFY2(std::abs(leftPicked[c] - leftBefore[c]) < 0.5 &&
                   std::abs(rightPicked[c] - rightBefore[c]) < 0.5,
               qPrintable(QString("channel %1 after picking: left %2 (before %3), right %4 "
                                  "(before %5)")
                              .arg(c)
                              .arg(leftPicked[c])
                              .arg(leftBefore[c])
                              .arg(rightPicked[c])
                              .arg(rightBefore[c])));
    }
    view->clickedAt(rightAt[0], rightAt[1], false);

    // Another material (copper) for the right part leaves the left part's pixels exactly as they
    // were.
    dock->assignToSelection("brushed copper");
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    const auto leftBesideCopper = meanAround(view, leftAt);
    for (int c = 0; c < 3; ++c)
    {
      QVERIFY2(std::abs(leftBesideCopper[std::size_t(c)] - leftBefore[std::size_t(c)]) < 0.5,
               "the left part changed with the right part's material");
    }

    // Gold for the selected part only.
    dock->assignToSelection("satin gold");
    QCOMPARE(model->parts()[1].material, std::string("satin gold"));
    QCOMPARE(model->parts()[0].material, std::string(aniso::kStartMaterialName));
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    // The selection's outline (drawn over the parts) out of the measured squares.
    model->setSelection({});
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    QCOMPARE(view->renderer()->GetRenderWindow()->GetSize()[0], viewSize[0]);
    QCOMPARE(view->renderer()->GetRenderWindow()->GetSize()[1], viewSize[1]);
    const auto leftAfter = meanAround(view, leftAt);
    const auto rightAfter = meanAround(view, rightAt);
    // The left part's pixels are those it had before the right part's edits.
    for (std::size_t c = 0; c < 3; ++c)
    {
      QVERIFY2(std::abs(leftAfter[c] - leftBefore[c]) < 0.5,
               qPrintable(QString("left, channel %1: %2 before the right part turned gold, %3 "
                                  "after")
                              .arg(c)
                              .arg(leftBefore[c])
                              .arg(leftAfter[c])));
    }
    // Aluminium is nearly neutral, gold (F0 1, 0.78, 0.34) has less blue than red (tone mapping
    // near white takes much of the difference away).
    QVERIFY2(rightAfter[2] / rightAfter[0] < leftAfter[2] / leftAfter[0] - 0.05,
             qPrintable(QString("right %1 %2 %3, left %4 %5 %6")
                            .arg(rightAfter[0])
                            .arg(rightAfter[1])
                            .arg(rightAfter[2])
                            .arg(leftAfter[0])
                            .arg(leftAfter[1])
                            .arg(leftAfter[2])));
    // The window's pixels of both parts are those of the offscreen renderer drawing the same
    // parts, camera and samples (an independent path: renderOffscreen's parts), and the left
    // part's are the same as when the right part is aluminium too.
    const int* size = view->renderer()->GetRenderWindow()->GetSize();
    aniso::RenderSettings settings = view->renderSettings(size[0], size[1]);
    settings.jitter = false; // the window's single frame has no jitter either
    QCOMPARE(settings.parts.size(), std::size_t(2));
    const auto offscreenAround = [&](const aniso::RenderResult& r, std::array<int, 2> at)
    {
      std::array<double, 3> mean{0.0, 0.0, 0.0};
      for (int dy = -3; dy <= 3; ++dy)
      {
        for (int dx = -3; dx <= 3; ++dx)
        {
          for (int c = 0; c < 3; ++c)
          {
            // The display image has row 0 at the top; display positions count from the bottom.
            mean[std::size_t(c)] +=
                255.0 * r.display.at(at[0] + dx, size[1] - 1 - (at[1] + dy), c) / 49.0;
          }
        }
      }
      return mean;
    };
    const aniso::RenderResult offscreen = aniso::renderOffscreen(settings);
    settings.parts[1].material = settings.parts[0].material;
    const aniso::RenderResult allAluminium = aniso::renderOffscreen(settings);
    const auto leftOffscreen = offscreenAround(offscreen, leftAt);
    const auto rightOffscreen = offscreenAround(offscreen, rightAt);
    const auto leftAlone = offscreenAround(allAluminium, leftAt);
    for (std::size_t c = 0; c < 3; ++c)
    {
      QVERIFY2(std::abs(leftAfter[c] - leftOffscreen[c]) < 1.0,
               qPrintable(QString("left, channel %1: window %2, offscreen %3")
                              .arg(c)
                              .arg(leftAfter[c])
                              .arg(leftOffscreen[c])));
      QVERIFY2(std::abs(rightAfter[c] - rightOffscreen[c]) < 1.0,
               qPrintable(QString("right, channel %1: window %2, offscreen %3")
                              .arg(c)
                              .arg(rightAfter[c])
                              .arg(rightOffscreen[c])));
      QVERIFY2(std::abs(leftOffscreen[c] - leftAlone[c]) < 0.5,
               "the left part's pixels depend on the right part's material");
    }
    // Selecting a part compiles, uploads and bakes nothing; an edit of one part's material
    // uploads only that part's new table (the materials' counters, the LUT cache's bakes).
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    const auto counters = [&](int part) { return view->partMaterial(part)->counters(); };
    const auto left0 = counters(0);
    const auto right0 = counters(1);
    const auto bakes0 = window.lutScheduler()->cache().stats().bakes;
    model->setSelection({0});
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    model->setSelection({1});
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    QCOMPARE(counters(0).shaderInstalls, left0.shaderInstalls);
    QCOMPARE(counters(0).textureUploads, left0.textureUploads);
    QCOMPARE(counters(1).shaderInstalls, right0.shaderInstalls);
    QCOMPARE(counters(1).textureUploads, right0.textureUploads);
    QCOMPARE(window.lutScheduler()->cache().stats().bakes, bakes0);
    window.editor()->edit("f0", aniso::colorValue(1.0, 0.5, 0.2));
    window.editor()->edit("nu", numberValue(37.0));
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    QCOMPARE(counters(0).shaderInstalls, left0.shaderInstalls);
    QCOMPARE(counters(0).textureUploads, left0.textureUploads);
    QCOMPARE(counters(1).shaderInstalls, right0.shaderInstalls); // n_u and F0 are uniforms
    QVERIFY(counters(1).textureUploads > right0.textureUploads); // the new half-vector table
    QCOMPARE(model->materials().at(model->parts()[0].material).value("f0").number[0],
             aniso::builtinMaterials().at(aniso::kStartMaterialName).value("f0").number[0]);

    // An edit of the selection reaches only the right part's material.
    const double leftNu = model->materials().at(model->parts()[0].material).value("nu").number[0];
    window.editor()->edit("nu", numberValue(20.0));
    QCOMPARE(model->materials().at("satin gold").value("nu").number[0], 20.0);
    QCOMPARE(model->materials().at(model->parts()[0].material).value("nu").number[0], leftNu);

    // Hidden, the right part leaves the renderer and the camera frames the left one alone.
    window.view()->resetCamera();
    window.editor()->setPartsVisible({1}, false);
    QVERIFY(!view->partDrawn(1));
    QVERIFY(!view->renderer()->HasViewProp(view->partActor(1)));
    QCOMPARE(view->drawnTriangles(), leftTriangles);
    const aniso::DrawingFrame& frame = view->drawingFrame();
    QVERIFY(std::abs(frame.centre.x + 1.5) < 0.05);
    window.editor()->undoStack()->undo();
    QVERIFY(view->partDrawn(1));

    // A session of the scene opens with the same parts and materials.
    const QString session = dir.filePath("scene.json");
    QVERIFY(window.saveSession(session));
    aniso::MainWindow other;
    other.setErrorDialogs(false);
    QVERIFY(other.openSession(session));
    QCOMPARE(other.model()->parts(), model->parts());
    QVERIFY(other.model()->materials() == model->materials());
    QCOMPARE(other.view()->partCount(), 2);
  }

  // A file's blocks become its parts, grouped under the file: an OBJ's groups (written here) and
  // a VTM's blocks (written by VTK's multiblock writer); undo of the add takes them away.
  void aFilesBlocksBecomeItsParts()
  {
    QTemporaryDir dir;
    const QString obj = dir.filePath("pair.obj");
    {
      QFile f(obj);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\n"
              "g lower\nf 1 2 3\ng upper\nf 4 5 6\n");
    }
    const QString vtm = dir.filePath("blocks.vtm");
    {
      vtkNew<vtkMultiBlockDataSet> blocks;
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(3.0, 0.0, 0.0);
      sphere->Update();
      vtkNew<vtkSphereSource> other;
      other->SetCenter(-3.0, 0.0, 0.0);
      other->SetThetaResolution(12);
      other->Update();
      blocks->SetNumberOfBlocks(2);
      blocks->SetBlock(0, sphere->GetOutput());
      blocks->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "ball");
      blocks->SetBlock(1, other->GetOutput());
      blocks->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "lower");
      vtkNew<vtkXMLMultiBlockDataWriter> writer;
      writer->SetFileName(vtm.toStdString().c_str());
      writer->SetInputData(blocks);
      QVERIFY(writer->Write() == 1);
    }
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    QVERIFY(window.openMesh(obj));
    aniso::SceneModel* model = window.model();
    QCOMPARE(model->parts().size(), std::size_t(2));
    QCOMPARE(model->parts()[0].name, std::string("lower"));
    QCOMPARE(model->parts()[1].block, std::string("upper"));
    QCOMPARE(model->parts()[1].group, std::string("pair.obj"));
    QCOMPARE(window.view()->partTriangles(0), 1LL);
    QVERIFY(window.addMeshes({vtm}));
    QCOMPARE(model->parts().size(), std::size_t(4));
    QCOMPARE(model->parts()[2].name, std::string("ball"));
    QCOMPARE(model->parts()[3].name, std::string("lower 2")); // unique in the scene
    QCOMPARE(model->parts()[3].block, std::string("lower"));
    QCOMPARE(model->parts()[3].group, std::string("blocks.vtm"));
    QVERIFY(window.view()->partTriangles(3) > 0);
    // The dock shows the two files as groups of two parts each.
    QTreeWidget* tree = window.sceneDock()->tree();
    QCOMPARE(tree->topLevelItemCount(), 2);
    QCOMPARE(tree->topLevelItem(1)->text(0), QString("blocks.vtm"));
    QCOMPARE(tree->topLevelItem(1)->childCount(), 2);
    window.editor()->undoStack()->undo();
    QCOMPARE(model->parts().size(), std::size_t(2));
    QCOMPARE(window.view()->partCount(), 2);
  }

  // A file of polylines only (a hand-written VTK legacy file: a circle of radius 1 in the plane
  // y = 0, 64 segments) opens as its line part: listed in the dock, drawn as lines (no faces,
  // its tangents along the line), brighter on the circle than at its empty centre; a wider
  // line-width covers more of a square on the circle.
  void aFileOfLinesIsALinePartInTheView()
  {
    QTemporaryDir dir;
    const QString vtk = dir.filePath("ring.vtk");
    {
      QFile f(vtk);
      QVERIFY(f.open(QIODevice::WriteOnly));
      QByteArray text = "# vtk DataFile Version 3.0\nring\nASCII\nDATASET POLYDATA\n"
                        "POINTS 64 double\n";
      for (int i = 0; i < 64; ++i)
      {
        const double a = 2.0 * M_PI * i / 64.0;
        text += QByteArray::number(std::cos(a), 'g', 17) + " 0 " +
                QByteArray::number(std::sin(a), 'g', 17) + "\n";
      }
      text += "LINES 1 66\n65";
      for (int i = 0; i <= 64; ++i)
      {
        text += " " + QByteArray::number(i % 64);
      }
      text += "\n";
      f.write(text);
    }
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    window.view()->setSettleMs(30);
    window.view()->setFrameBudgetMs(0);
    window.model()->setValues({{"samples", numberValue(4.0)},
                               {"target-samples", numberValue(4.0)},
                               {"background", textValue("color")},
                               {"background-color", aniso::colorValue(0.0, 0.0, 0.0)}});
    window.resize(900, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openMesh(vtk));
    aniso::SceneModel* model = window.model();
    QCOMPARE(model->parts().size(), std::size_t(1));
    QCOMPARE(model->parts()[0].block, std::string("ring lines"));
    QCOMPARE(window.sceneDock()->tree()->topLevelItemCount(), 1);
    aniso::SceneView* view = window.view();
    vtkPolyData* drawn = view->partDrawnSurface(0);
    QVERIFY(drawn);
    QCOMPARE(drawn->GetNumberOfLines(), vtkIdType(1));
    QCOMPARE(drawn->GetNumberOfPolys(), vtkIdType(0));
    QVERIFY(drawn->GetPointData()->GetArray("Tangents"));

    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    const auto onLine = displayOf(view, {1.0, 0.0, 0.0});
    const auto centre = displayOf(view, {0.0, 0.0, 0.0});
    const auto lit = meanAround(view, onLine);
    const auto empty = meanAround(view, centre);
    QVERIFY2(lit[0] + lit[1] + lit[2] > empty[0] + empty[1] + empty[2] + 3.0,
             "the line is not drawn");
    window.editor()->edit("line-width", numberValue(6.0));
    QTRY_VERIFY_WITH_TIMEOUT(settled(window), 60000);
    const auto wide = meanAround(view, onLine);
    QVERIFY2(std::abs(wide[0] + wide[1] + wide[2] - (lit[0] + lit[1] + lit[2])) > 3.0,
             "the line's width did not change what it covers");
  }

  // A placed part is drawn where its placement puts it, and its tangent model's axis turns with
  // it: the same sphere file twice, the second shifted by 4 along x and turned 90 degrees about z,
  // with tangents along the part's x axis (so along the scene's y).
  void placedPartsAreDrawnWhereTheyArePut()
  {
    QTemporaryDir dir;
    const QString ball = dir.filePath("ball.ply");
    const long long triangles = writeSphere(ball, 0.0);
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    QVERIFY(window.openMesh(ball));
    QVERIFY(window.addMeshes({ball}));
    aniso::SceneModel* model = window.model();
    std::vector<ScenePart> parts = model->parts();
    QCOMPARE(parts.size(), std::size_t(2));
    QCOMPARE(parts[1].name, std::string("ball 2"));
    parts[1].placement = {0, -1, 0, 4, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    aniso::MaterialLibrary library = model->materials();
    aniso::Material axis = aniso::defaultMaterial("along x");
    axis.values["tangents"] = textValue("axis:1,0,0");
    library.put(axis);
    parts[0].material = "along x";
    parts[1].material = "along x";
    window.editor()->editParts(parts, library, "Place");
    aniso::SceneView* view = window.view();
    QCOMPARE(view->drawnTriangles(), 2 * triangles);
    // The two spheres' joint bounding sphere: centred between them.
    QVERIFY(std::abs(view->drawingFrame().centre.x - 2.0) < 0.05);
    vtkPolyData* placed =
        vtkPolyData::SafeDownCast(view->partActor(1)->GetMapper()->GetInputDataObject(0, 0));
    QVERIFY(placed);
    vtkDataArray* tangents = placed->GetPointData()->GetTangents();
    vtkDataArray* normals = placed->GetPointData()->GetNormals();
    QVERIFY(tangents && normals);
    // Away from the poles of the turned axis (the scene's y), each tangent is the scene's y made
    // orthogonal to the normal, y - n (n . y), up to its sign.
    int along = 0;
    int checked = 0;
    for (vtkIdType i = 0; i < tangents->GetNumberOfTuples(); ++i)
    {
      double t[3];
      double n[3];
      tangents->GetTuple(i, t);
      normals->GetTuple(i, n);
      if (std::abs(n[1]) > 0.5)
      {
        continue;
      }
      ++checked;
      double e[3] = {-n[0] * n[1], 1.0 - n[1] * n[1], -n[2] * n[1]};
      const double length = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
      const double cosine = (t[0] * e[0] + t[1] * e[1] + t[2] * e[2]) / length;
      along += std::abs(cosine) > 0.999 ? 1 : 0;
    }
    QVERIFY(checked > 0);
    QVERIFY2(along == checked, qPrintable(QString("%1 of %2").arg(along).arg(checked)));
  }

  // File > Export Scene as glTF (MainWindow::exportGltf): the scene's parts read back through
  // loadMeshBlocks (the glTF reader, an independent path) with their names, triangles, surfaces
  // in their own frames (the bounds of the spheres written), placements and library materials
  // (n_u, n_v, F0, albedo to rounding); a hidden part is left out; a file that cannot be written
  // is reported naming it and gives false.
  void sceneExportsAsGltf()
  {
    QTemporaryDir dir;
    const auto [left, right, leftTriangles, rightTriangles] = writeTwoSpheres(dir);
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    QVERIFY(window.openMesh(left));
    QVERIFY(window.addMeshes({right}));
    aniso::SceneModel* model = window.model();
    std::vector<ScenePart> parts = model->parts();
    QCOMPARE(parts.size(), std::size_t(2));
    parts[1].material = "satin gold";
    // A quarter turn about Z and a move.
    parts[1].placement = {0, -1, 0, 0.5, 1, 0, 0, 2, 0, 0, 1, -1, 0, 0, 0, 1};
    model->setParts(parts, model->materials());
    const QString file = dir.filePath("scene.glb");
    QVERIFY(window.exportGltf(file));
    const aniso::LoadedBlocks back = aniso::loadMeshBlocks(file.toStdString());
    QCOMPARE(back.blocks.size(), std::size_t(2));
    const long long triangles[2] = {leftTriangles, rightTriangles};
    const double centres[2] = {-1.5, 1.5};
    for (std::size_t i = 0; i < 2; ++i)
    {
      const aniso::MeshBlock& block = back.blocks[i];
      QCOMPARE(block.name, parts[i].name);
      QCOMPARE(static_cast<long long>(block.mesh.polyData->GetNumberOfPolys()), triangles[i]);
      double bounds[6];
      block.mesh.polyData->GetBounds(bounds);
      // vtkSphereSource's 16 rings from pole to pole are 12 degrees apart: the widest are at
      // 84 and 96 degrees, of radius sin 84.
      const double radius = std::sin(84.0 * 3.14159265358979323846 / 180.0);
      QVERIFY2(std::abs(bounds[0] - (centres[i] - radius)) < 1e-4 &&
                   std::abs(bounds[1] - (centres[i] + radius)) < 1e-4,
               qPrintable(QString("x from %1 to %2").arg(bounds[0]).arg(bounds[1])));
      for (std::size_t k = 0; k < 16; ++k)
      {
        QVERIFY(std::abs(block.placement[k] - parts[i].placement[k]) < 1e-9);
      }
      QVERIFY(block.material.has_value());
      const aniso::Material& drawn = model->partMaterial(int(i));
      QCOMPARE(block.material->name, drawn.name);
      for (const char* key : {"nu", "nv"})
      {
        const double n = drawn.value(key).number[0];
        QVERIFY2(std::abs(block.material->value(key).number[0] - n) < 1e-4 * (1.0 + n), key);
      }
      for (const char* key : {"f0", "albedo"})
      {
        for (std::size_t c = 0; c < 3; ++c)
        {
          QVERIFY2(std::abs(block.material->value(key).number[c] - drawn.value(key).number[c]) <
                       1e-5,
                   key);
        }
      }
    }
    QCOMPARE(back.blocks[1].material->name, std::string("satin gold"));

    parts[0].visible = false;
    model->setParts(parts, model->materials());
    const QString one = dir.filePath("one.gltf");
    QVERIFY(window.exportGltf(one));
    const aniso::LoadedBlocks visible = aniso::loadMeshBlocks(one.toStdString());
    QCOMPARE(visible.blocks.size(), std::size_t(1));

    QSignalSpy errors(&window, &aniso::MainWindow::errorReported);
    const QString nowhere = dir.filePath("absent/scene.glb");
    QVERIFY(!window.exportGltf(nowhere));
    QCOMPARE(errors.count(), 1);
    QVERIFY(errors.at(0).at(0).toString().contains(nowhere));
  }

  // A part whose file is gone is skipped with a warning naming the part and the file; the other
  // part is drawn.
  void aMissingPartIsSkipped()
  {
    QTemporaryDir dir;
    const TwoSpheres spheres = writeTwoSpheres(dir);
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    QVERIFY(window.openMesh(spheres.left));
    QVERIFY(window.addMeshes({spheres.right}));
    const QString session = dir.filePath("scene.json");
    QVERIFY(window.saveSession(session));
    QVERIFY(QFile::remove(spheres.right));

    aniso::MainWindow other;
    other.setErrorDialogs(false);
    QSignalSpy errors(&other, &aniso::MainWindow::errorReported);
    QVERIFY(other.openSession(session));
    QCOMPARE(other.model()->parts().size(), std::size_t(2));
    QVERIFY(other.view()->partDrawn(0));
    QVERIFY(!other.view()->partDrawn(1));
    bool named = false;
    for (const auto& e : errors)
    {
      const QString text = e.at(0).toString();
      named = named || (text.contains("right") && text.contains("right.ply"));
    }
    QVERIFY(named);

    // A file that fails as a whole adds nothing.
    const auto before = other.model()->parts();
    QVERIFY(!other.addMeshes({dir.filePath("absent.obj")}));
    QCOMPARE(other.model()->parts(), before);
  }
};

QTEST_MAIN(TestScenePartsWindow)
#include "test_scene_parts_window.moc"
