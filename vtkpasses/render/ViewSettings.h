#pragma once
// Where the camera looks from: the world is Z-up; the camera looks at the centre of the object's
// bounding sphere from a direction, far enough for the sphere to fit the view.
#include <glm/vec3.hpp>
#include <string>
#include <vector>

class vtkPolyData;
class vtkRenderer;

namespace aniso
{
struct ViewSettings
{
  glm::dvec3 direction{0.0, -1.0, 0.0}; // from the centre towards the camera (front view)
  bool parallel = false;                // orthographic projection
  double viewAngleDegrees = 30.0;       // vertical field of view (perspective)
  double margin = 1.1;                  // bounding radius times this fits the view's half height
};

// "+x", "-x", "+y", "-y", "+z", "-z": the camera on that side of the object.
// Throws aniso::Error "SUBJECT: reason".
glm::dvec3 viewDirectionFromName(const std::string& name, const std::string& subject);
// Azimuth 0 is the -Y side (the front view), growing counter-clockwise seen from above (90 is
// +X); elevation is the angle above the XY plane, in [-90, 90].
glm::dvec3 viewDirectionFromAngles(double azimuthDegrees, double elevationDegrees);

struct CameraPlacement
{
  glm::dvec3 position{0.0};
  glm::dvec3 focalPoint{0.0};
  glm::dvec3 viewUp{0.0, 0.0, 1.0}; // +Z, or +Y when looking along Z
  double viewAngleDegrees = 30.0;   // perspective
  double parallelScale = 1.0;       // parallel: half the view height in world units
  bool parallel = false;
};

// A sphere around every point of SURFACE: the bounding box's centre and the distance to the
// farthest point.
void boundingSphere(vtkPolyData* surface, glm::dvec3& centre, double& radius);
// The sphere around several surfaces together (a scene of parts; null ones are skipped): the
// centre of their joint bounding box and the distance to the farthest point of any. For one
// surface, the same sphere as above.
void boundingSphere(const std::vector<vtkPolyData*>& surfaces, glm::dvec3& centre, double& radius);

// The camera for an object with bounding sphere (centre, radius > 0).
CameraPlacement placeCamera(const ViewSettings& view, const glm::dvec3& centre, double radius);

// Gives RENDERER's active camera PLACEMENT and fits its clipping range to what the renderer
// draws.
void applyCamera(vtkRenderer* renderer, const CameraPlacement& placement);
} // namespace aniso
