#include "vtkpasses/mesh/LineSet.h"

#include "core/error.h"
#include "vtkpasses/mesh/GeometryAccess.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vector>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
bool finite(const glm::dvec3& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

glm::dvec3 pointAt(vtkPoints* points, vtkIdType id)
{
  double p[3];
  points->GetPoint(id, p);
  return {p[0], p[1], p[2]};
}

// The shortest segment kept: 1e-9 of the finite points' bounding-box diagonal.
double minimumSegmentLength(vtkPoints* points)
{
  glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
  bool any = false;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = pointAt(points, i);
    if (finite(p))
    {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
      any = true;
    }
  }
  return any ? 1e-9 * glm::length(hi - lo) : 0.0;
}
} // namespace

bool hasLineCells(vtkPolyData* poly)
{
  return poly && poly->GetNumberOfLines() > 0;
}

bool hasFaceCells(vtkPolyData* poly)
{
  return poly && (poly->GetNumberOfPolys() > 0 || poly->GetNumberOfStrips() > 0);
}

bool isLineSet(vtkPolyData* poly)
{
  return hasLineCells(poly) && !hasFaceCells(poly);
}

vtkSmartPointer<vtkPolyData> sanitizeLines(vtkPolyData* input, const std::string& subject,
                                           MeshReport& report)
{
  if (!input)
  {
    throw errorAbout(subject, "the reader produced no data");
  }
  vtkPoints* points = input->GetPoints();
  const vtkIdType pointCount = points ? points->GetNumberOfPoints() : 0;
  report.pointsRead = pointCount;
  report.cellsRead = input->GetNumberOfLines();
  const double minimum = points ? minimumSegmentLength(points) : 0.0;

  std::vector<char> nonFinite(static_cast<size_t>(pointCount), 0);
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    if (!finite(pointAt(points, i)))
    {
      nonFinite[static_cast<size_t>(i)] = 1;
      ++report.nonFiniteVertices;
    }
  }

  // The polylines as runs of positions, split at non-finite points.
  std::vector<std::vector<glm::dvec3>> runs;
  auto close = [&](std::vector<glm::dvec3>& run)
  {
    if (run.size() >= 2)
    {
      runs.push_back(std::move(run));
    }
    else if (!run.empty())
    {
      ++report.invalidCellsDropped;
    }
    run.clear();
  };
  vtkCellArray* lines = input->GetLines();
  if (lines && pointCount > 0)
  {
    // forEachCell: a malformed cell array's cells outside its connectivity come empty.
    geometry::forEachCell(lines, [&](vtkIdType n, const vtkIdType* ids)
    {
      bool inRange = n >= 2;
      for (vtkIdType k = 0; k < n && inRange; ++k)
      {
        inRange = ids[k] >= 0 && ids[k] < pointCount;
      }
      if (!inRange)
      {
        ++report.invalidCellsDropped;
        return;
      }
      std::vector<glm::dvec3> run;
      for (vtkIdType k = 0; k < n; ++k)
      {
        if (nonFinite[static_cast<size_t>(ids[k])])
        {
          close(run);
          continue;
        }
        const glm::dvec3 p = pointAt(points, ids[k]);
        if (!run.empty() && glm::length(p - run.back()) <= minimum)
        {
          ++report.zeroLengthSegmentsDropped;
          continue;
        }
        run.push_back(p);
      }
      close(run);
    });
  }
  else if (lines)
  {
    report.invalidCellsDropped += lines->GetNumberOfCells();
  }

  if (runs.empty())
  {
    std::string reason = "no line segments";
    if (report.cellsRead == 0)
    {
      reason = "no line cells";
    }
    else if (report.nonFiniteVertices > 0)
    {
      reason += " left (NaN/Inf coordinates in " + std::to_string(report.nonFiniteVertices) +
                " vertices)";
    }
    else
    {
      reason += " left (every line has fewer than two distinct valid points)";
    }
    throw errorAbout(subject, reason);
  }

  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataType(points->GetDataType() == VTK_DOUBLE ? VTK_DOUBLE : VTK_FLOAT);
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> outLines;
  int64_t segments = 0;
  for (const std::vector<glm::dvec3>& run : runs)
  {
    const size_t n = run.size();
    outLines->InsertNextCell(static_cast<int>(n));
    for (size_t i = 0; i < n; ++i)
    {
      glm::dvec3 d = run[std::min(i + 1, n - 1)] - run[i == 0 ? 0 : i - 1];
      if (glm::length(d) <= minimum)
      {
        d = run[i] - run[i - 1]; // a turn back: the incoming segment (never at an end)
      }
      d = glm::normalize(d);
      const vtkIdType id = outPoints->InsertNextPoint(run[i].x, run[i].y, run[i].z);
      tangents->InsertNextTuple3(d.x, d.y, d.z);
      outLines->InsertCellPoint(id);
    }
    segments += static_cast<int64_t>(n) - 1;
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(outPoints);
  result->SetLines(outLines);
  result->GetPointData()->SetTangents(tangents);
  report.points = outPoints->GetNumberOfPoints();
  report.lineSegments = segments;
  report.triangles = 0;
  report.hasNormals = false;
  report.hasTCoords = false;
  report.hasTangents = true;
  return result;
}
} // namespace aniso
