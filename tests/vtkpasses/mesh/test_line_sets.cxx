// Line sets: a file's polylines as parts of their own (loadMeshBlocks), sanitised by
// sanitizeLines (LineSet.h). References: files written here by VTK's own writers
// (vtkXMLPolyDataWriter, vtkPolyDataWriter) and a hand-written OBJ, whose definitions are the
// reference; the tangents against the analytic tangent of the circle the points lie on (a
// central difference of a circle's points, p(a + h) - p(a - h), is exactly along the tangent at
// p(a), so the bound is float rounding only).
#include "core/error.h"
#include "tests/vtkpasses/mesh/mesh_test_files.h"
#include "vtkpasses/mesh/LineSet.h"
#include "vtkpasses/mesh/MeshLoader.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <vector>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

namespace aniso
{
namespace
{
constexpr int kCirclePoints = 24;
constexpr double kRadius = 2.5;

glm::dvec3 circlePoint(int i)
{
  const double a = 2.0 * M_PI * i / kCirclePoints;
  return {kRadius * std::cos(a), kRadius * std::sin(a), 0.5};
}

// An open polyline along most of a circle (points 0 .. kCirclePoints - 4), and, with FACES, one
// triangle beside it.
vtkSmartPointer<vtkPolyData> arcWithTriangle(bool faces)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(kCirclePoints - 3);
  for (int i = 0; i < kCirclePoints - 3; ++i)
  {
    const glm::dvec3 p = circlePoint(i);
    lines->InsertCellPoint(points->InsertNextPoint(p.x, p.y, p.z));
  }
  poly->SetPoints(points);
  poly->SetLines(lines);
  if (faces)
  {
    const vtkIdType a = points->InsertNextPoint(0, 0, 0);
    const vtkIdType b = points->InsertNextPoint(1, 0, 0);
    const vtkIdType c = points->InsertNextPoint(0, 1, 0);
    vtkNew<vtkCellArray> polys;
    const vtkIdType ids[3] = {a, b, c};
    polys->InsertNextCell(3, ids);
    poly->SetPolys(polys);
  }
  return poly;
}

// Every point of LINES lies on the circle and its tangent is the circle's there (up to sign:
// along the polyline's order, which runs counter-clockwise).
void expectCircleTangents(vtkPolyData* lines, int points)
{
  ASSERT_EQ(lines->GetNumberOfPoints(), points);
  vtkDataArray* tangents = lines->GetPointData()->GetArray("Tangents");
  ASSERT_NE(tangents, nullptr);
  ASSERT_EQ(tangents->GetNumberOfComponents(), 3);
  EXPECT_EQ(lines->GetPointData()->GetTangents(), tangents);
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    lines->GetPoint(i, p);
    const double a = std::atan2(p[1], p[0]);
    const glm::dvec3 exact(-std::sin(a), std::cos(a), 0.0);
    const glm::dvec3 t(tangents->GetComponent(i, 0), tangents->GetComponent(i, 1),
                       tangents->GetComponent(i, 2));
    EXPECT_NEAR(glm::length(t), 1.0, 1e-6) << i;
    if (i == 0 || i == points - 1)
    {
      // The ends: the one segment's direction, half a step (pi / 24) off the tangent.
      EXPECT_NEAR(glm::dot(t, exact), std::cos(M_PI / kCirclePoints), 1e-6) << i;
    }
    else
    {
      EXPECT_NEAR(glm::dot(t, exact), 1.0, 1e-6) << i;
    }
  }
}

class LineSetsTest : public test::MeshFilesTest
{
};

TEST_F(LineSetsTest, VtpPolylinesAreAPartOfTheirOwnBesideTheFaces)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(arcWithTriangle(true));
  writer->SetFileName(path("fibres.vtp").c_str());
  ASSERT_EQ(writer->Write(), 1);

  const LoadedBlocks loaded = loadMeshBlocks(path("fibres.vtp"));
  ASSERT_EQ(loaded.blocks.size(), 2u);
  EXPECT_TRUE(loaded.warnings.empty());
  const MeshBlock& surface = loaded.blocks[0];
  EXPECT_EQ(surface.name, "fibres");
  EXPECT_FALSE(surface.lines);
  EXPECT_EQ(surface.mesh.report.triangles, 1);
  // The lines went to their own part: not counted as dropped from the surface.
  EXPECT_EQ(surface.mesh.report.nonSurfaceCellsDropped, 0);
  const MeshBlock& lines = loaded.blocks[1];
  EXPECT_EQ(lines.name, "fibres lines");
  EXPECT_TRUE(lines.lines);
  EXPECT_TRUE(isLineSet(lines.mesh.polyData));
  EXPECT_EQ(lines.mesh.polyData->GetNumberOfLines(), 1);
  EXPECT_EQ(lines.mesh.report.lineSegments, kCirclePoints - 4);
  EXPECT_EQ(lines.mesh.report.triangles, 0);
  EXPECT_TRUE(lines.mesh.report.hasTangents);
  expectCircleTangents(lines.mesh.polyData, kCirclePoints - 3);

  // loadMesh (one surface) keeps the faces only, as before.
  const LoadedMesh merged = loadMesh(path("fibres.vtp"));
  EXPECT_EQ(merged.report.triangles, 1);
  EXPECT_EQ(merged.report.nonSurfaceCellsDropped, 1);
}

TEST_F(LineSetsTest, VtkLegacyFileOfLinesOnlyIsOneLinePart)
{
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetInputData(arcWithTriangle(false));
  writer->SetFileName(path("tract.vtk").c_str());
  ASSERT_EQ(writer->Write(), 1);

  const LoadedBlocks loaded = loadMeshBlocks(path("tract.vtk"));
  ASSERT_EQ(loaded.blocks.size(), 1u);
  EXPECT_TRUE(loaded.warnings.empty());
  EXPECT_EQ(loaded.blocks[0].name, "tract lines");
  EXPECT_TRUE(loaded.blocks[0].lines);
  expectCircleTangents(loaded.blocks[0].mesh.polyData, kCirclePoints - 3);
  // As one surface it has nothing to draw, and says why.
  EXPECT_THROW(loadMesh(path("tract.vtk")), Error);
}

TEST_F(LineSetsTest, ObjLineStatementsFollowTheirGroup)
{
  // A group with a face and a line, and a group of two lines (one of them a single segment):
  // the first makes a surface part and a line part, the second a line part alone.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nv 2 0 1\n"
                          "g plate\nf 1 2 3\nl 1 4 5\n"
                          "g hair\nl 4 5 6\nl 2 6\n";
  const LoadedBlocks loaded = loadMeshBlocks(write("strands.obj", obj));
  ASSERT_EQ(loaded.blocks.size(), 3u);
  EXPECT_EQ(loaded.blocks[0].name, "plate");
  EXPECT_FALSE(loaded.blocks[0].lines);
  EXPECT_EQ(loaded.blocks[0].mesh.report.triangles, 1);
  EXPECT_EQ(loaded.blocks[1].name, "plate lines");
  EXPECT_TRUE(loaded.blocks[1].lines);
  EXPECT_EQ(loaded.blocks[1].mesh.report.lineSegments, 2);
  EXPECT_EQ(loaded.blocks[2].name, "hair lines");
  EXPECT_TRUE(loaded.blocks[2].lines);
  vtkPolyData* hair = loaded.blocks[2].mesh.polyData;
  EXPECT_EQ(hair->GetNumberOfLines(), 2);
  EXPECT_EQ(loaded.blocks[2].mesh.report.lineSegments, 3);
  // Each polyline has its own points: 3 + 2.
  ASSERT_EQ(hair->GetNumberOfPoints(), 5);
  vtkDataArray* tangents = hair->GetPointData()->GetArray("Tangents");
  ASSERT_NE(tangents, nullptr);
  // The middle point of "l 4 5 6": (p6 - p4) / |p6 - p4| = (2, 0, 0) / 2.
  EXPECT_NEAR(tangents->GetComponent(1, 0), 1.0, 1e-6);
  EXPECT_NEAR(tangents->GetComponent(1, 1), 0.0, 1e-6);
  EXPECT_NEAR(tangents->GetComponent(1, 2), 0.0, 1e-6);
  // The single segment "l 2 6": (1, 0, 1) / sqrt 2 at both ends.
  for (vtkIdType i : {vtkIdType(3), vtkIdType(4)})
  {
    EXPECT_NEAR(tangents->GetComponent(i, 0), std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(tangents->GetComponent(i, 1), 0.0, 1e-6);
    EXPECT_NEAR(tangents->GetComponent(i, 2), std::sqrt(0.5), 1e-6);
  }
}

// An OBJ whose one group's lines are all unusable (a segment of one point twice) has no part:
// the error names the file and the line part's reason, once.
TEST_F(LineSetsTest, AnObjOfUnusableLinesOnlyFailsWithTheLinesReason)
{
  const std::string file = write("broken.obj", "v 1 1 1\nv 1 1 1\ng hair\nl 1 2\n");
  try
  {
    loadMeshBlocks(file);
    FAIL() << "no error";
  }
  catch (const Error& e)
  {
    EXPECT_EQ(std::string(e.what()),
              file + ": part hair lines: no line segments left (every line has fewer than two "
                     "distinct valid points)");
  }
}

// The sanitising steps of LineSet.h on a line of 8 points: a NaN point splits it, a repeated
// point is a zero-length segment, an out-of-range id drops its cell, a piece of one point goes.
TEST(SanitizeLines, SplitsAtNanDropsZeroLengthSegmentsAndBrokenCells)
{
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double xs[8] = {0, 1, 1, 2, nan, 3, nan, 4};
  for (double x : xs)
  {
    points->InsertNextPoint(x, 0.0, 0.0);
  }
  poly->SetPoints(points);
  vtkNew<vtkCellArray> lines;
  // 0 1 1 2 | nan | 3 | nan | 4: pieces (0, 1, 2) after the repeat, (3) dropped, (4) dropped.
  const vtkIdType all[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  lines->InsertNextCell(8, all);
  const vtkIdType broken[2] = {0, 99};
  lines->InsertNextCell(2, broken);
  poly->SetLines(lines);

  MeshReport report;
  vtkSmartPointer<vtkPolyData> clean = sanitizeLines(poly, "test", report);
  EXPECT_EQ(report.cellsRead, 2);
  EXPECT_EQ(report.nonFiniteVertices, 2);
  EXPECT_EQ(report.zeroLengthSegmentsDropped, 1);
  EXPECT_EQ(report.invalidCellsDropped, 3); // the broken cell, the pieces (3) and (4)
  EXPECT_EQ(clean->GetNumberOfLines(), 1);
  EXPECT_EQ(clean->GetNumberOfPoints(), 3);
  EXPECT_EQ(report.lineSegments, 2);
  for (vtkIdType i = 0; i < 3; ++i)
  {
    double p[3];
    clean->GetPoint(i, p);
    EXPECT_EQ(p[0], double(i));
  }
  bool splitNote = false;
  for (const std::string& note : report.notes())
  {
    splitNote = splitNote || note.find("split") != std::string::npos;
  }
  EXPECT_TRUE(splitNote);

  // Nothing usable left: an error naming the subject.
  vtkNew<vtkPolyData> degenerate;
  vtkNew<vtkPoints> same;
  same->InsertNextPoint(1, 1, 1);
  same->InsertNextPoint(1, 1, 1);
  degenerate->SetPoints(same);
  vtkNew<vtkCellArray> one;
  const vtkIdType pair[2] = {0, 1};
  one->InsertNextCell(2, pair);
  degenerate->SetLines(one);
  MeshReport failed;
  try
  {
    sanitizeLines(degenerate, "file.vtp", failed);
    FAIL() << "no error";
  }
  catch (const Error& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("file.vtp: no line segments left", 0), 0u) << e.what();
  }
}
} // namespace
} // namespace aniso
