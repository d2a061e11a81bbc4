#include "app/gui/ViewCamera.h"

#include <vtkCamera.h>

namespace aniso
{
void setCameraState(vtkCamera* camera, const CameraState& c, const DrawingFrame& drawing)
{
  const glm::dvec3 position = drawing.pointToDrawing({c.position[0], c.position[1], c.position[2]});
  const glm::dvec3 focalPoint =
      drawing.pointToDrawing({c.focalPoint[0], c.focalPoint[1], c.focalPoint[2]});
  camera->SetPosition(position.x, position.y, position.z);
  camera->SetFocalPoint(focalPoint.x, focalPoint.y, focalPoint.z);
  camera->SetViewUp(c.viewUp.data());
  camera->SetViewAngle(c.viewAngle);
  camera->SetParallelProjection(c.parallel);
  camera->SetParallelScale(c.parallelScale / drawing.radius);
}

CameraState cameraStateOf(vtkCamera* camera, const DrawingFrame& drawing)
{
  CameraState c;
  c.set = true;
  camera->GetPosition(c.position.data());
  camera->GetFocalPoint(c.focalPoint.data());
  camera->GetViewUp(c.viewUp.data());
  c.viewAngle = camera->GetViewAngle();
  c.parallel = camera->GetParallelProjection() != 0;
  // From the drawing frame back to the mesh's coordinates.
  for (std::size_t i = 0; i < 3; ++i)
  {
    c.position[i] = c.position[i] * drawing.radius + drawing.centre[int(i)];
    c.focalPoint[i] = c.focalPoint[i] * drawing.radius + drawing.centre[int(i)];
  }
  c.parallelScale = camera->GetParallelScale() * drawing.radius;
  return c;
}

CameraPlacement placementOf(const CameraState& c)
{
  CameraPlacement p;
  p.position = {c.position[0], c.position[1], c.position[2]};
  p.focalPoint = {c.focalPoint[0], c.focalPoint[1], c.focalPoint[2]};
  p.viewUp = {c.viewUp[0], c.viewUp[1], c.viewUp[2]};
  p.viewAngleDegrees = c.viewAngle;
  p.parallel = c.parallel;
  p.parallelScale = c.parallelScale;
  return p;
}

CameraPlacement defaultPlacement(int width, int height)
{
  return viewPlacement(defaultViewSettings(), width, height);
}

CameraPlacement viewPlacement(const ViewSettings& view, int width, int height)
{
  return placeCamera(fittedToFrame(view, width, height), glm::dvec3(0.0), 1.0);
}

} // namespace aniso
