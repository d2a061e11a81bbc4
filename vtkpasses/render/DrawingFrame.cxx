#include "vtkpasses/render/DrawingFrame.h"

#include "core/error.h"

#include <cmath>
#include <vtkActor.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
// centre x, y, z and radius; registered with VTK's key manager, which frees it at exit.
vtkInformationDoubleVectorKey* frameKey()
{
  static vtkInformationDoubleVectorKey* key =
      vtkInformationDoubleVectorKey::MakeKey("DRAWING_FRAME", "aniso", 4);
  return key;
}
} // namespace

Light DrawingFrame::lightToDrawing(const Light& light) const
{
  Light out = light;
  if (light.type == LightType::Point)
  {
    out.vector = pointToDrawing(light.vector);
    out.intensity = light.intensity / (radius * radius);
  }
  return out;
}

CameraPlacement DrawingFrame::cameraToDrawing(const CameraPlacement& camera) const
{
  CameraPlacement out = camera;
  out.position = pointToDrawing(camera.position);
  out.focalPoint = pointToDrawing(camera.focalPoint);
  out.parallelScale = camera.parallelScale / radius;
  return out;
}

DrawingFrame drawingFrameOf(vtkPolyData* surface)
{
  return drawingFrameOf(std::vector<vtkPolyData*>{surface});
}

DrawingFrame drawingFrameOf(const std::vector<vtkPolyData*>& surfaces)
{
  DrawingFrame frame;
  boundingSphere(surfaces, frame.centre, frame.radius);
  if (!(frame.radius > 0.0) || !std::isfinite(frame.radius))
  {
    throw errorAbout("view", "the object has no extent");
  }
  return frame;
}

vtkSmartPointer<vtkPolyData> inDrawingFrame(vtkPolyData* surface, const DrawingFrame& frame)
{
  auto drawn = vtkSmartPointer<vtkPolyData>::New();
  drawn->ShallowCopy(surface);
  vtkPoints* in = surface->GetPoints();
  vtkNew<vtkPoints> out;
  out->SetDataTypeToFloat();
  out->SetNumberOfPoints(in->GetNumberOfPoints());
  for (vtkIdType i = 0; i < in->GetNumberOfPoints(); ++i)
  {
    double p[3];
    in->GetPoint(i, p);
    const glm::dvec3 q = frame.pointToDrawing(glm::dvec3(p[0], p[1], p[2]));
    out->SetPoint(i, q.x, q.y, q.z);
  }
  drawn->SetPoints(out);
  return drawn;
}

void setDrawingFrame(vtkActor* actor, const DrawingFrame& frame)
{
  vtkInformation* keys = actor->GetPropertyKeys();
  if (!keys)
  {
    vtkNew<vtkInformation> created;
    actor->SetPropertyKeys(created);
    keys = actor->GetPropertyKeys();
  }
  const double values[4] = {frame.centre.x, frame.centre.y, frame.centre.z, frame.radius};
  keys->Set(frameKey(), values, 4);
}

DrawingFrame drawingFrame(vtkActor* actor)
{
  DrawingFrame frame;
  vtkInformation* keys = actor ? actor->GetPropertyKeys() : nullptr;
  if (keys && keys->Has(frameKey()) && keys->Length(frameKey()) == 4)
  {
    const double* values = keys->Get(frameKey());
    frame.centre = {values[0], values[1], values[2]};
    frame.radius = values[3];
  }
  return frame;
}
} // namespace aniso
