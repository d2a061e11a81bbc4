// Unstructured grids whose cells VTK 9.1's surface filter would read past (VtkReaders.cxx,
// checkGridCells): grids written by VTK's own legacy and XML writers load when their cells are
// sound (a hexahedron, a wedge, a polygon, a polyhedron with its face stream) and are refused
// with the file's name and the first cell at fault (the message starting so) when a cell has fewer points than its type,
// a point id past the points, a type VTK does not know, or a polyhedron's face names a point
// that is not there. The data model lets each be built and VTK's writers write it as it is.
#include "core/error.h"
#include "tests/vtkpasses/mesh/mesh_test_files.h"
#include "vtkpasses/mesh/MeshLoader.h"

#include <functional>
#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <vtkCellType.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace aniso
{
namespace
{
class GridCellsTest : public test::MeshFilesTest
{
protected:
  // A unit cube's eight corners and whatever cells ADD puts in, written by VTK's legacy writer
  // (.vtk) and by its XML writer (.vtu); returns both paths.
  std::vector<std::string> writeGrid(const std::string& stem,
                                     const std::function<void(vtkUnstructuredGrid*)>& add) const
  {
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 8; ++i)
    {
      points->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    }
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);
    add(grid);
    vtkNew<vtkUnstructuredGridWriter> legacy;
    legacy->SetInputData(grid);
    legacy->SetFileName(this->path(stem + ".vtk").c_str());
    EXPECT_EQ(legacy->Write(), 1);
    vtkNew<vtkXMLUnstructuredGridWriter> xml;
    xml->SetInputData(grid);
    xml->SetFileName(this->path(stem + ".vtu").c_str());
    EXPECT_EQ(xml->Write(), 1);
    return {this->path(stem + ".vtk"), this->path(stem + ".vtu")};
  }
};

void insert(vtkUnstructuredGrid* grid, int type, const std::vector<vtkIdType>& ids)
{
  grid->InsertNextCell(type, static_cast<vtkIdType>(ids.size()), ids.data());
}

const std::vector<vtkIdType> kHex = {0, 1, 3, 2, 4, 5, 7, 6};

// The cube as a polyhedron: six quads, each its number of corners and their ids.
std::vector<vtkIdType> cubeFaces(vtkIdType lastCorner)
{
  return {4, 0, 2, 3, 1, 4, 4, 5, 7, 6, 4, 0, 1, 5, 4, 4, 2, 6, 7, 3, 4, 0, 4, 6, 2,
          4, 1, 3, 7, lastCorner};
}

TEST_F(GridCellsTest, SoundCellsLoad)
{
  for (const std::string& path : this->writeGrid("sound", [](vtkUnstructuredGrid* grid) {
         insert(grid, VTK_HEXAHEDRON, kHex);
         insert(grid, VTK_WEDGE, {0, 1, 2, 4, 5, 6});
         insert(grid, VTK_POLYGON, {0, 1, 3, 2});
         std::vector<vtkIdType> faces = cubeFaces(5);
         grid->InsertNextCell(VTK_POLYHEDRON, 8, kHex.data(), 6, faces.data());
       }))
  {
    SCOPED_TRACE(path);
    const LoadedMesh mesh = loadMesh(path);
    EXPECT_GT(mesh.polyData->GetNumberOfCells(), 0);
  }
}

struct Fault
{
  const char* stem;
  std::function<void(vtkUnstructuredGrid*)> add;
  const char* reason;
};

TEST_F(GridCellsTest, CellsVtkWouldReadPastAreRefusedNamingTheCell)
{
  const std::vector<Fault> faults = {
      {"short-hexahedron",
       [](vtkUnstructuredGrid* g) {
         insert(g, VTK_HEXAHEDRON, kHex);
         insert(g, VTK_HEXAHEDRON, {0, 1, 3, 2});
       },
       "cell 1: cell type 12 with 4 points"},
      {"point-past-points",
       [](vtkUnstructuredGrid* g) { insert(g, VTK_TETRA, {0, 1, 2, 8}); },
       "cell 0: point id 8 of 8 points"},
      {"unknown-type",
       [](vtkUnstructuredGrid* g) { insert(g, 19, {0, 1, 2}); },
       "cell 0: cell type 19 is not one VTK knows"},
      {"polyhedron-face-past-points",
       [](vtkUnstructuredGrid* g) {
         std::vector<vtkIdType> faces = cubeFaces(9);
         g->InsertNextCell(VTK_POLYHEDRON, 8, kHex.data(), 6, faces.data());
       },
       // the legacy file lists a polyhedron's points by its faces, the XML file by the cell
       "cell 0: point id 9 of 8 points"},
  };
  for (const Fault& fault : faults)
  {
    for (const std::string& path : this->writeGrid(fault.stem, fault.add))
    {
      SCOPED_TRACE(path);
      try
      {
        loadMesh(path);
        ADD_FAILURE() << "read, though " << fault.reason;
      }
      catch (const Error& e)
      {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path + ": " + fault.reason, 0), 0u) << what;
      }
    }
  }
}
} // namespace
} // namespace aniso
