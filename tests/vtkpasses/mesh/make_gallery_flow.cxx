// Writes the flow field of the README's field-brushing gallery image (docs/gallery-flow.png): a
// sphere of radius 1 (vtkSphereSource, 256 x 128) as an unstructured grid of its triangles
// (vtkXMLUnstructuredGridWriter), with the point array "velocity": four vortices on the sphere,
// each the rotation about its own axis a_k, faded with the distance from it,
//   v(p) = sum_k s_k exp(-|p - a_k|^2 / 0.35) (a_k x p),
// s_k = +1 or -1 (their sense), and a cell array "pressure" (the speed at the face's first
// vertex). Where the vortices meet, the field turns through saddles; it vanishes at each vortex
// centre (between the sphere's vertices here: a vertex there would take the fallback tangent,
// and the render's report would count it).
//   cmake --build build --target make_gallery_flow
//   build/tests/vtkpasses/mesh/make_gallery_flow flow.vtu
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: make_gallery_flow OUTPUT.vtu\n");
    return 2;
  }
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(256);
  source->SetPhiResolution(128);
  source->SetRadius(1.0);
  source->Update();
  vtkPolyData* sphere = source->GetOutput();

  const glm::dvec3 axes[4] = {glm::normalize(glm::dvec3(0.3, -0.9, 0.4)),
                              glm::normalize(glm::dvec3(-0.8, -0.5, -0.2)),
                              glm::normalize(glm::dvec3(0.7, -0.2, -0.6)),
                              glm::normalize(glm::dvec3(-0.2, 0.4, 0.9))};
  const double senses[4] = {1.0, -1.0, 1.0, -1.0};
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(sphere->GetNumberOfPoints());
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    double q[3];
    sphere->GetPoint(i, q);
    const glm::dvec3 p(q[0], q[1], q[2]);
    glm::dvec3 v(0.0);
    for (int k = 0; k < 4; ++k)
    {
      const glm::dvec3 d = p - axes[k];
      v += senses[k] * std::exp(-glm::dot(d, d) / 0.35) * glm::cross(axes[k], p);
    }
    velocity->SetTuple3(i, v.x, v.y, v.z);
  }

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(sphere->GetPoints());
  grid->GetPointData()->AddArray(velocity);
  grid->SetCells(VTK_TRIANGLE, sphere->GetPolys());
  vtkNew<vtkFloatArray> pressure;
  pressure->SetName("pressure");
  pressure->SetNumberOfTuples(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    double v[3];
    velocity->GetTuple(grid->GetCell(c)->GetPointId(0), v);
    pressure->SetValue(c, float(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])));
  }
  grid->GetCellData()->AddArray(pressure);

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(argv[1]);
  if (writer->Write() != 1)
  {
    std::fprintf(stderr, "make_gallery_flow: %s could not be written\n", argv[1]);
    return 1;
  }
  return 0;
}
