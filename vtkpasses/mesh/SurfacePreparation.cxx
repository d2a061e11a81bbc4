#include "vtkpasses/mesh/SurfacePreparation.h"

#include "core/error.h"
#include "vtkpasses/mesh/CadReader.h"
#include "vtkpasses/mesh/GeometryAccess.h"
#include "vtkpasses/mesh/MeshValidation.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>

namespace aniso
{
namespace
{
// A tangent whose part orthogonal to n is shorter than this fraction of it lies within about
// 0.06 degrees of the normal: it gives no usable direction in the tangent plane.
constexpr double kParallelTangent = 1e-3;

using geometry::tupleAt;

glm::dvec3 pointAt(vtkPolyData* surface, vtkIdType id)
{
  return geometry::pointAt(surface->GetPoints(), id);
}

bool isUnitFinite(const glm::dvec3& v)
{
  const double length = glm::length(v);
  return std::isfinite(length) && length > 0.0;
}

// vtkPolyDataNormals leaves a zero normal where the faces around a vertex cancel (two faces of
// a folded, non-manifold sheet); such a vertex takes the normal of its first face instead.
int64_t repairZeroNormals(vtkPolyData* surface)
{
  vtkDataArray* shared = surface->GetPointData()->GetNormals();
  std::vector<char> bad(static_cast<size_t>(surface->GetNumberOfPoints()), 0);
  int64_t badCount = 0;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    if (!isUnitFinite(tupleAt(shared, i)))
    {
      bad[static_cast<size_t>(i)] = 1;
      ++badCount;
    }
  }
  if (badCount == 0)
  {
    return 0;
  }
  // A copy, so that the caller's mesh, whose arrays this surface may share, stays untouched.
  vtkNew<vtkFloatArray> normals;
  normals->DeepCopy(shared);
  normals->SetName("Normals");
  surface->GetPointData()->SetNormals(normals);
  geometry::forEachCell(surface->GetPolys(),
                        [&](vtkIdType count, const vtkIdType* ids)
                        {
                          if (count != 3)
                          {
                            return;
                          }
                          const glm::dvec3 p0 = pointAt(surface, ids[0]);
                          const glm::dvec3 face = glm::cross(pointAt(surface, ids[1]) - p0,
                                                             pointAt(surface, ids[2]) - p0);
                          if (!isUnitFinite(face))
                          {
                            return;
                          }
                          const glm::dvec3 n = glm::normalize(face);
                          for (int k = 0; k < 3; ++k)
                          {
                            if (bad[static_cast<size_t>(ids[k])])
                            {
                              normals->SetTuple3(ids[k], n.x, n.y, n.z);
                              bad[static_cast<size_t>(ids[k])] = 0;
                            }
                          }
                        });
  return badCount;
}

// Mesh tangents that are not finite or lie along the normal.
int64_t countInvalidTangents(vtkDataArray* tangents, vtkDataArray* normals)
{
  int64_t invalid = 0;
  for (vtkIdType i = 0; i < tangents->GetNumberOfTuples(); ++i)
  {
    const glm::dvec3 t = tupleAt(tangents, i);
    const glm::dvec3 n = glm::normalize(tupleAt(normals, i));
    const double length = glm::length(t);
    if (!std::isfinite(length) ||
        !(glm::length(t - glm::dot(t, n) * n) > kParallelTangent * length))
    {
      ++invalid;
    }
  }
  return invalid;
}

// Gram-Schmidt of valid mesh tangents against the (possibly recomputed) normals, as floats.
void orthonormaliseTangents(vtkPolyData* surface)
{
  vtkPointData* pd = surface->GetPointData();
  vtkDataArray* tangents = pd->GetTangents();
  vtkDataArray* normals = pd->GetNormals();
  vtkNew<vtkFloatArray> result;
  result->SetName("Tangents");
  result->SetNumberOfComponents(3);
  result->SetNumberOfTuples(tangents->GetNumberOfTuples());
  for (vtkIdType i = 0; i < tangents->GetNumberOfTuples(); ++i)
  {
    const glm::dvec3 n = glm::normalize(tupleAt(normals, i));
    const glm::dvec3 t = tupleAt(tangents, i);
    const glm::dvec3 u = glm::normalize(t - glm::dot(t, n) * n);
    result->SetTuple3(i, u.x, u.y, u.z);
  }
  pd->RemoveArray(tangents->GetName());
  pd->SetTangents(result);
}

std::string formatAngle(double degrees)
{
  std::ostringstream out;
  out << degrees;
  return out.str();
}
} // namespace

std::vector<std::string> SurfaceReport::notes() const
{
  std::vector<std::string> out;
  if (normalsComputed)
  {
    out.push_back("normals computed, split at edges sharper than " +
                  formatAngle(featureAngleDegrees) + " degrees (" +
                  std::to_string(pointsAddedBySplitting) + " vertices added)" +
                  (normalsAutoOriented ? ", oriented outwards" : ""));
  }
  if (repairedNormals > 0)
  {
    out.push_back(std::to_string(repairedNormals) +
                  " vertices whose faces cancel out took the normal of one of their faces");
  }
  if (invalidMeshTangents > 0)
  {
    out.push_back(std::to_string(invalidMeshTangents) +
                  " mesh tangents were NaN, zero or along the normal; all tangents regenerated");
  }
  out.push_back("tangents: " + tangentSource);
  if (nonFiniteFieldTangents > 0)
  {
    out.push_back(std::to_string(nonFiniteFieldTangents) +
                  " vertices where the tangent field is NaN or Inf got a fixed fallback tangent");
  }
  if (fallbackTangents - nonFiniteFieldTangents > 0)
  {
    out.push_back(
        std::to_string(fallbackTangents - nonFiniteFieldTangents) +
        " vertices where the brushing direction is along the normal, zero (or on the axis) got a "
        "fixed fallback tangent");
  }
  return out;
}

vtkSmartPointer<vtkPolyData> computeFeatureNormals(vtkPolyData* triangles,
                                                   double featureAngleDegrees, bool autoOrient)
{
  if (!(featureAngleDegrees > 0.0 && featureAngleDegrees <= 180.0))
  {
    throw errorAbout("feature angle",
                     "must be in (0, 180] degrees, got " + formatAngle(featureAngleDegrees));
  }
  vtkNew<vtkPolyData> input;
  input->ShallowCopy(triangles); // own point data object: the caller's arrays stay untouched
  vtkPointData* pd = input->GetPointData();
  if (vtkDataArray* old = pd->GetNormals())
  {
    pd->SetNormals(nullptr);
    if (old->GetName())
    {
      pd->RemoveArray(old->GetName());
    }
  }
  pd->RemoveArray("Normals");

  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(input);
  normals->SetFeatureAngle(featureAngleDegrees);
  normals->SplittingOn();
  normals->ConsistencyOn();
  normals->SetAutoOrientNormals(autoOrient);
  normals->NonManifoldTraversalOn();
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  normals->Update();
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(normals->GetOutput());
  return result;
}

PreparedSurface prepareSurface(vtkPolyData* mesh, const SurfaceOptions& options,
                               const std::string& subject)
{
  if (!mesh || mesh->GetNumberOfPolys() == 0)
  {
    throw errorAbout(subject, "no faces to prepare");
  }
  PreparedSurface prepared;
  SurfaceReport& report = prepared.report;
  report.featureAngleDegrees = options.featureAngleDegrees;

  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->ShallowCopy(mesh);
  vtkDataArray* meshNormals = surface->GetPointData()->GetNormals();
  if (!meshNormals || meshNormals->GetNumberOfComponents() != 3 || options.recomputeNormals)
  {
    const EdgeCounts edges = countEdges(surface);
    report.normalsAutoOriented = edges.boundary == 0 && edges.nonManifold == 0;
    const vtkIdType before = surface->GetNumberOfPoints();
    surface =
        computeFeatureNormals(surface, options.featureAngleDegrees, report.normalsAutoOriented);
    report.normalsComputed = true;
    report.pointsAddedBySplitting = surface->GetNumberOfPoints() - before;
  }
  report.repairedNormals = repairZeroNormals(surface);

  vtkPointData* pd = surface->GetPointData();
  vtkDataArray* meshTangents = pd->GetTangents();
  const bool wantsUvDirection = !options.brushing || options.brushing->kind == BrushingKind::Uv;
  bool keepMeshTangents = false;
  if (wantsUvDirection && meshTangents && meshTangents->GetNumberOfComponents() >= 3)
  {
    report.invalidMeshTangents = countInvalidTangents(meshTangents, pd->GetNormals());
    keepMeshTangents = report.invalidMeshTangents == 0;
  }

  if (keepMeshTangents)
  {
    orthonormaliseTangents(surface);
    report.tangentSource = "mesh";
  }
  else
  {
    BrushingModel model;
    if (options.brushing)
    {
      model = *options.brushing;
    }
    else if (!pd->GetTCoords() && pd->GetArray(kBRepTangentUArray))
    {
      model.kind = BrushingKind::FaceU;
    }
    else if (!pd->GetTCoords())
    {
      model.kind = BrushingKind::Axis;
      model.vector = glm::dvec3(1.0, 0.0, 0.0);
    }
    if (meshTangents && meshTangents->GetName())
    {
      pd->RemoveArray(meshTangents->GetName());
    }
    pd->SetTangents(nullptr);
    const TangentStats stats = computeBrushingTangents(surface, model, subject);
    report.fallbackTangents = stats.fallbackPoints;
    report.nonFiniteFieldTangents = stats.nonFinitePoints;
    report.tangentSource = toString(model);
  }
  prepared.polyData = surface;
  return prepared;
}
} // namespace aniso
