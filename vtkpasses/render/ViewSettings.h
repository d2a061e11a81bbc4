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

// Azimuth 0 is the -Y side (the front view), growing counter-clockwise seen from above (90 is
// +X); elevation is the angle above the XY plane, in [-90, 90].
glm::dvec3 viewDirectionFromAngles(double azimuthDegrees, double elevationDegrees);

// The named views: `aniso render --view NAME` and the window's View menu list the same ones,
// in this order. The first, "three-quarter", is the default view of both (and so of the
// window's screenshots): from the front left and above (azimuth -35, elevation 35), so a part
// lying flat in the XY plane is seen from above rather than edge-on and a round one shows its
// side and top. The others look from one side of the object: "+x", "-x", "+y", "-y" (the front),
// "+z" (the top), "-z".
struct ViewPreset
{
  std::string name;     // "three-quarter", "+x", ...
  std::string label;    // "Three-quarter", "Right (+x)", ... for menus
  glm::dvec3 direction; // from the centre towards the camera
};
const std::vector<ViewPreset>& viewPresets();
inline constexpr double kDefaultViewAzimuth = -35.0;
inline constexpr double kDefaultViewElevation = 35.0;
// The name of the default view (viewPresets().front().name).
std::string defaultViewName();
// "three-quarter | +x | ... | -z", for help texts.
std::string viewPresetNames(const std::string& separator);

// The direction of the view NAME (viewPresets). Throws aniso::Error "SUBJECT: reason".
glm::dvec3 viewDirectionFromName(const std::string& name, const std::string& subject);

// The view every frame starts from unless told otherwise (`aniso render` without --view or
// --azimuth, the window's first and reset camera): the three-quarter view.
ViewSettings defaultViewSettings();

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
// VIEW for a frame of WIDTH x HEIGHT pixels: placeCamera fits the sphere to the view's height,
// so a frame narrower than high gets its margin grown by height / width to fit the width too.
ViewSettings fittedToFrame(ViewSettings view, int width, int height);

// Gives RENDERER's active camera PLACEMENT and fits its clipping range to what the renderer
// draws.
void applyCamera(vtkRenderer* renderer, const CameraPlacement& placement);
} // namespace aniso
