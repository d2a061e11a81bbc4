#pragma once
// Headless rendering of a scene of parts, each with its own anisotropic material (one object with
// one material being the scene of one part): a plain off-screen vtkRenderWindow (an X display is
// needed, e.g. under xvfb-run), progressive accumulation for the requested number of frames over
// the whole scene, and the results read back: the linear float image (EXR) and the
// display-transformed 8-bit one (PNG).
//
// Each visible part is an actor of its own with its own AnisoMaterial; every part shares the one
// EnvironmentLighting (the environment's textures are uploaded once per render) and, through
// LutCache::shared(), the lookup tables of equal inputs (parts of one lobe use one table in
// memory; each material uploads its own copy as a texture). Hidden parts are not added to the
// renderer: they cost nothing and play no part in where the camera goes. The scene is drawn in
// the frame of the visible parts' joint bounding sphere (DrawingFrame.h), so the camera placed by
// `view` fits them together.
#include "core/env/environment.h"
#include "core/image/image.h"
#include "vtkpasses/render/DisplaySettings.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/LineStyle.h"
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/MaterialShaderSource.h"
#include "vtkpasses/render/ViewSettings.h"

#include <cstdint>
#include <functional>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace aniso
{
class EnvironmentLighting;

// Installs a material of another shading model on the actor (drawn by the renderer, lit by the
// scene's lighting) in place of the anisotropic one; what it returns is kept alive while the
// frames are rendered. Throws aniso::Error for settings it cannot render.
using MaterialInstaller = std::function<std::shared_ptr<void>(
    vtkActor*, vtkRenderer*, const std::shared_ptr<EnvironmentLighting>&)>;

// One part of a scene: a surface with its own material.
struct RenderPart
{
  std::string name; // for messages and RenderResult::parts
  // A prepared surface (SurfacePreparation.h): triangles with "Normals", and "Tangents",
  // "TCoords" when available; or a line set (vtkpasses/mesh/LineSet.h: polylines with
  // "Tangents"), drawn as illuminated lines of `lineStyle` by the same materials.
  vtkSmartPointer<vtkPolyData> surface;
  LineStyle lineStyle; // for a line set
  MaterialSettings material;
  bool visible = true; // a hidden part is not drawn at all (and may have no surface)
  // When set, this part is shaded by it instead of `material` and of
  // RenderSettings::installMaterial (another shading model with this part's own material).
  MaterialInstaller installMaterial;
};

struct RenderSettings
{
  // The scene of one part: a prepared surface (as RenderPart::surface) drawn with `material`.
  // Used when `parts` is empty.
  vtkSmartPointer<vtkPolyData> surface;
  std::shared_ptr<const Environment> environment;
  int cubeSize = 256; // level-0 face of the environment cubemap
  double environmentRotationDegrees = 0.0;
  MaterialSettings material;
  // A scene of several parts, drawn together instead of `surface` with `material` (`surface`
  // must then be unset; `material` is not drawn, though installers may read it).
  std::vector<RenderPart> parts;
  DisplaySettings display;
  ViewSettings view;
  // When set, this camera is used as it is instead of one placed by `view` (the application's
  // screenshots keep the camera of its window).
  std::optional<CameraPlacement> camera;
  int width = 512;
  int height = 512;
  int frames = 1;     // progressive frames accumulated (each with its own sample shift)
  bool jitter = true; // sub-pixel camera jitter between frames (anti-aliasing)
  // When positive, frames stop early once the mean's error estimated from its own frames
  // (vtkAnisoAccumulationPass::SetErrorTarget) is at or below it, from errorStopFrames frames
  // on; `frames` is then the most.
  double errorTarget = 0.0;
  int errorStopFrames = 4;
  // When set, the object is shaded by this instead of `material` (which is then unused). In a
  // scene of parts it is installed on every visible part without an installer of its own
  // (called once for each part's actor), in place of the parts' own materials.
  MaterialInstaller installMaterial;
};

// The parts SETTINGS draws: `parts`, or the one part made of `surface` and `material`.
std::vector<RenderPart> sceneParts(const RenderSettings& settings);

// What was drawn of a part.
struct RenderedPart
{
  std::string name;
  bool visible = true;
  MaterialVariant variant; // the anisotropic material's compiled variant (visible parts)
  bool mapsDropped = false;
};

struct RenderResult
{
  Image linear;  // RGBA float, linear radiance, alpha = coverage; row 0 at the top
  Image display; // RGBA in [0, 1] holding the 8-bit values / 255 of the displayed frame
  std::vector<double> frameSeconds; // wall time of each frame, GPU work included (one a frame)
  // With an error target: the estimate at the last checkpoint (negative before one) and the
  // frames it was taken after.
  double estimatedError = -1.0;
  int estimatedErrorFrames = 0;
  int frozenPixels = 0; // with an error target: the pixels that stopped before the view did
  int64_t coveredPixels = 0;        // pixels with coverage > 0
  MaterialVariant variant;          // the shader variant of the first visible part
  bool mapsDropped = false;         // maps given but a visible mesh has no texture coordinates
  std::string renderer;             // the OpenGL renderer string (e.g. "llvmpipe ...")
  std::vector<RenderedPart> parts;  // every part of sceneParts(), in order
  // Where the pixels' rays go, for the CPU reference (core/reference/pixel_geometry.h): the
  // scene was drawn in DRAWING's frame, its clip coordinates back to that frame by CLIP_TO_WORLD,
  // and the environment turned by WORLD_TO_ENVIRONMENT.
  DrawingFrame drawing;
  glm::dmat4 clipToWorld{1.0};
  glm::dmat3 worldToEnvironment{1.0};
};

// Throws aniso::Error "SUBJECT: reason" for invalid settings (a visible part's invalid material
// names the part: "part NAME: SUBJECT: reason"), a scene with nothing visible, a missing display
// or a failed OpenGL context.
RenderResult renderOffscreen(const RenderSettings& settings);

// Opens this process's connection to the X display named by DISPLAY, once, and keeps it open
// for the life of the process (an X server that loses its last client resets and refuses
// connections for a moment, so windows made one after another would fail at random); retries
// for two seconds while a server resets. Throws aniso::Error "render: reason" otherwise.
void requireXDisplay();

// Median of the frame times (0 for none).
double medianSeconds(std::vector<double> seconds);
} // namespace aniso
