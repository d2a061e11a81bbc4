#pragma once
// The frame a surface is drawn in. OpenGL computes in single precision: vertex positions, the
// view and projection matrices, the clipping range and the shaders' view vectors (camera minus
// surface point) lose everything for a mesh of size 1e30 (squares overflow), 1e-30 (they
// underflow) or far from the origin (positions rounded). So the renderer draws the surface
// mapped, in double precision, to a frame where its bounding sphere is the unit sphere at the
// origin, and maps whatever else lives in the mesh's coordinates (the camera, point lights) the
// same way. What the user sees is unchanged: the view and the lighting are invariant under the
// map. The user's camera and lights stay in the mesh's own coordinates.
#include "core/lights/light.h"
#include "vtkpasses/render/ViewSettings.h"

#include <glm/vec3.hpp>
#include <vector>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;

namespace aniso
{
struct DrawingFrame
{
  glm::dvec3 centre{0.0}; // in mesh coordinates: drawn at the origin
  double radius = 1.0;    // a mesh length of RADIUS is drawn as 1

  glm::dvec3 pointToDrawing(const glm::dvec3& p) const { return (p - centre) / radius; }
  // Point lights move with the mesh; their intensity is divided by radius^2 so that the
  // irradiance intensity / distance^2 at every surface point stays the same. Directional
  // lights are unchanged.
  Light lightToDrawing(const Light& light) const;
  CameraPlacement cameraToDrawing(const CameraPlacement& camera) const;
};

// The frame of SURFACE's bounding sphere (boundingSphere in ViewSettings.h). Throws
// aniso::Error "view: the object has no extent" for a surface without a positive finite radius.
DrawingFrame drawingFrameOf(vtkPolyData* surface);
// The frame of several surfaces' joint bounding sphere (the visible parts of a scene, drawn
// together in one frame); the same error when they have no extent together.
DrawingFrame drawingFrameOf(const std::vector<vtkPolyData*>& surfaces);

// A shallow copy of SURFACE (cells and point attributes shared: directions do not change under
// the map) with its points mapped to FRAME, as floats.
vtkSmartPointer<vtkPolyData> inDrawingFrame(vtkPolyData* surface, const DrawingFrame& frame);

// The frame ACTOR's surface was drawn in, kept on the actor (its property keys) so that the
// materials installed on it map their point lights; an actor without one is drawn in the mesh's
// own coordinates (the identity frame).
void setDrawingFrame(vtkActor* actor, const DrawingFrame& frame);
DrawingFrame drawingFrame(vtkActor* actor);
} // namespace aniso
