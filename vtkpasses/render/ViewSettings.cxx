#include "vtkpasses/render/ViewSettings.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vtkCamera.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

namespace aniso
{
glm::dvec3 viewDirectionFromAngles(double azimuthDegrees, double elevationDegrees)
{
  const double a = azimuthDegrees * M_PI / 180.0;
  const double e = elevationDegrees * M_PI / 180.0;
  return {std::sin(a) * std::cos(e), -std::cos(a) * std::cos(e), std::sin(e)};
}

const std::vector<ViewPreset>& viewPresets()
{
  static const std::vector<ViewPreset> presets = {
      {"three-quarter", "Three-quarter",
       viewDirectionFromAngles(kDefaultViewAzimuth, kDefaultViewElevation)},
      {"-y", "Front (-y)", {0.0, -1.0, 0.0}},
      {"+y", "Back (+y)", {0.0, 1.0, 0.0}},
      {"-x", "Left (-x)", {-1.0, 0.0, 0.0}},
      {"+x", "Right (+x)", {1.0, 0.0, 0.0}},
      {"+z", "Top (+z)", {0.0, 0.0, 1.0}},
      {"-z", "Bottom (-z)", {0.0, 0.0, -1.0}},
  };
  return presets;
}

std::string defaultViewName()
{
  return viewPresets().front().name;
}

std::string viewPresetNames(const std::string& separator)
{
  std::string names;
  for (const ViewPreset& preset : viewPresets())
  {
    names += (names.empty() ? "" : separator) + preset.name;
  }
  return names;
}

glm::dvec3 viewDirectionFromName(const std::string& name, const std::string& subject)
{
  for (const ViewPreset& preset : viewPresets())
  {
    if (preset.name == name)
    {
      return preset.direction;
    }
  }
  throw errorAbout(subject, "'" + name + "' is not one of " + viewPresetNames(", "));
}

ViewSettings defaultViewSettings()
{
  ViewSettings view;
  view.direction = viewPresets().front().direction;
  return view;
}

ViewSettings fittedToFrame(ViewSettings view, int width, int height)
{
  if (width > 0 && height > 0 && width < height)
  {
    view.margin *= static_cast<double>(height) / width;
  }
  return view;
}

void boundingSphere(vtkPolyData* surface, glm::dvec3& centre, double& radius)
{
  boundingSphere(std::vector<vtkPolyData*>{surface}, centre, radius);
}

void boundingSphere(const std::vector<vtkPolyData*>& surfaces, glm::dvec3& centre, double& radius)
{
  double bounds[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  bool first = true;
  for (vtkPolyData* surface : surfaces)
  {
    if (!surface || surface->GetNumberOfPoints() == 0)
    {
      continue;
    }
    double b[6];
    surface->GetBounds(b);
    for (int axis = 0; axis < 3; ++axis)
    {
      bounds[2 * axis] = first ? b[2 * axis] : std::min(bounds[2 * axis], b[2 * axis]);
      bounds[2 * axis + 1] =
          first ? b[2 * axis + 1] : std::max(bounds[2 * axis + 1], b[2 * axis + 1]);
    }
    first = false;
  }
  centre = {0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
            0.5 * (bounds[4] + bounds[5])};
  double r2 = 0.0;
  for (vtkPolyData* surface : surfaces)
  {
    vtkPoints* points = surface ? surface->GetPoints() : nullptr;
    for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      const glm::dvec3 d = glm::dvec3(p[0], p[1], p[2]) - centre;
      r2 = std::max(r2, glm::dot(d, d));
    }
  }
  radius = std::sqrt(r2);
}

CameraPlacement placeCamera(const ViewSettings& view, const glm::dvec3& centre, double radius)
{
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    throw errorAbout("view", "the object has no extent");
  }
  const double length = glm::length(view.direction);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    throw errorAbout("view", "no view direction");
  }
  const glm::dvec3 d = view.direction / length;
  CameraPlacement c;
  c.focalPoint = centre;
  c.parallel = view.parallel;
  c.viewAngleDegrees = view.viewAngleDegrees;
  const double halfHeight = radius * view.margin;
  c.parallelScale = halfHeight;
  // Perspective: the sphere's silhouette subtends asin(r / distance); keep it inside the view.
  const double halfAngle = 0.5 * view.viewAngleDegrees * M_PI / 180.0;
  const double distance = halfHeight / std::sin(halfAngle);
  c.position = centre + d * distance;
  c.viewUp = std::abs(d.z) > 0.999 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
  return c;
}

void applyCamera(vtkRenderer* renderer, const CameraPlacement& placement)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(placement.focalPoint.x, placement.focalPoint.y, placement.focalPoint.z);
  camera->SetPosition(placement.position.x, placement.position.y, placement.position.z);
  camera->SetViewUp(placement.viewUp.x, placement.viewUp.y, placement.viewUp.z);
  camera->SetViewAngle(placement.viewAngleDegrees);
  camera->SetParallelScale(placement.parallelScale);
  camera->SetParallelProjection(placement.parallel);
  renderer->ResetCameraClippingRange();
}
} // namespace aniso
