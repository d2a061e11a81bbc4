#include "app/gui/StandardViews.h"

#include "core/error.h"
#include "vtkpasses/render/ViewSettings.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
glm::dvec3 vec(const std::array<double, 3>& a)
{
  return {a[0], a[1], a[2]};
}

std::array<double, 3> array(const glm::dvec3& v)
{
  return {v.x, v.y, v.z};
}

CameraState stateOf(const CameraPlacement& p)
{
  CameraState c;
  c.set = true;
  c.position = array(p.position);
  c.focalPoint = array(p.focalPoint);
  c.viewUp = array(p.viewUp);
  c.viewAngle = p.viewAngleDegrees;
  c.parallel = p.parallel;
  c.parallelScale = p.parallelScale;
  return c;
}

double degrees(double radians)
{
  return radians * 180.0 / M_PI;
}
} // namespace

CameraState framedCamera(const glm::dvec3& direction, const DrawingFrame& drawing,
                         const CameraState& current, int width, int height)
{
  ViewSettings view;
  view.direction = direction;
  view.parallel = current.parallel;
  view.viewAngleDegrees =
      current.viewAngle > 0.0 && current.viewAngle < 180.0 ? current.viewAngle : 30.0;
  return stateOf(placeCamera(fittedToFrame(view, width, height), drawing.centre, drawing.radius));
}

CameraState frameAll(const CameraState& current, const DrawingFrame& drawing, int width, int height)
{
  glm::dvec3 direction = vec(current.position) - vec(current.focalPoint);
  if (!(glm::length(direction) > 0.0) || !std::isfinite(glm::length(direction)))
  {
    direction = glm::dvec3(0.0, -1.0, 0.0); // the front view
  }
  CameraState framed = framedCamera(direction, drawing, current, width, height);
  // The user's roll stays, unless it lies along the view direction.
  const glm::dvec3 up = vec(current.viewUp);
  const glm::dvec3 d = glm::normalize(direction);
  if (glm::length(glm::cross(up, d)) > 1e-6 * glm::length(up))
  {
    framed.viewUp = current.viewUp;
  }
  return framed;
}

void azimuthElevationOf(const CameraState& current, const DrawingFrame& drawing,
                        double& azimuthDegrees, double& elevationDegrees)
{
  const glm::dvec3 d = vec(current.position) - drawing.centre;
  const double horizontal = std::hypot(d.x, d.y);
  // viewDirectionFromAngles: (sin a cos e, -cos a cos e, sin e).
  azimuthDegrees = horizontal > 0.0 ? degrees(std::atan2(d.x, -d.y)) : 0.0;
  elevationDegrees = degrees(std::atan2(d.z, horizontal));
}

CameraState orbitCamera(const CameraState& current, const DrawingFrame& drawing,
                        double azimuthDegrees, double elevationDegrees)
{
  // Straight above or below, +Z cannot be up: the poles are kept just off.
  const double elevation = std::clamp(elevationDegrees, -89.9, 89.9);
  double distance = glm::length(vec(current.position) - vec(current.focalPoint));
  if (!(distance > 0.0) || !std::isfinite(distance))
  {
    distance = 3.0 * drawing.radius;
  }
  CameraState c = current;
  c.set = true;
  c.focalPoint = array(drawing.centre);
  c.position =
      array(drawing.centre + distance * viewDirectionFromAngles(azimuthDegrees, elevation));
  c.viewUp = {0.0, 0.0, 1.0};
  return c;
}
} // namespace aniso
