#pragma once
// The composite tree behind the .vtm seeds (fuzz_make_seeds) and the pieces fuzz_vtm keeps
// beside its inputs: VTK's vtkXMLMultiBlockDataWriter writes the tree as STEM.vtm and its
// leaves as STEM/STEM_I.vt?, so a .vtm seed written under the stem kVtmFixtureStem names pieces
// that the harness has written with the same writer, and the fuzzed XML reaches real leaves.
// The tree: a named polydata leaf, a named level holding an unstructured grid (a hexahedron,
// read back through its outer surface) and an empty leaf, and a leaf without a name.
#include "vtkpasses/mesh/BuiltinMeshes.h"

#include <string>
#include <vtkCellType.h>
#include <vtkCompositeDataSet.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataWriter.h>

namespace aniso::fuzz
{
inline constexpr const char* kVtmFixtureStem = "pieces";

inline vtkSmartPointer<vtkMultiBlockDataSet> makeVtmFixture()
{
  auto root = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  root->SetBlock(0, aniso::makeSphere(8, 4));
  root->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "sphere");

  vtkNew<vtkPoints> points;
  for (int i = 0; i < 8; ++i)
  {
    points->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType hex[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  vtkNew<vtkMultiBlockDataSet> inner;
  inner->SetBlock(0, grid);
  inner->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "cube");
  inner->SetBlock(1, nullptr);
  root->SetBlock(1, inner);
  root->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "assembly");

  root->SetBlock(2, aniso::makePlate(2));
  return root;
}

// Writes the tree as DIR/pieces.vtm with its pieces under DIR/pieces/; false when it failed.
inline bool writeVtmFixture(const std::string& dir, bool binary)
{
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  writer->SetInputData(makeVtmFixture());
  writer->SetFileName((dir + "/" + kVtmFixtureStem + ".vtm").c_str());
  binary ? writer->SetDataModeToBinary() : writer->SetDataModeToAscii();
  return writer->Write() == 1;
}
} // namespace aniso::fuzz
