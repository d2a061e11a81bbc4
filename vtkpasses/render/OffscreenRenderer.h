#pragma once
// Headless rendering of one object with an anisotropic material: a plain off-screen
// vtkRenderWindow (an X display is needed, e.g. under xvfb-run), progressive accumulation for
// the requested number of frames, and the results read back: the linear float image (EXR) and
// the display-transformed 8-bit one (PNG).
#include "core/env/environment.h"
#include "core/image/image.h"
#include "vtkpasses/render/DisplaySettings.h"
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/MaterialShaderSource.h"
#include "vtkpasses/render/ViewSettings.h"

#include <cstdint>
#include <functional>
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

struct RenderSettings
{
  // A prepared surface (SurfacePreparation.h): triangles with "Normals", and "Tangents",
  // "TCoords" when available.
  vtkSmartPointer<vtkPolyData> surface;
  std::shared_ptr<const Environment> environment;
  int cubeSize = 256; // level-0 face of the environment cubemap
  double environmentRotationDegrees = 0.0;
  MaterialSettings material;
  DisplaySettings display;
  ViewSettings view;
  // When set, this camera is used as it is instead of one placed by `view` (the application's
  // screenshots keep the camera of its window).
  std::optional<CameraPlacement> camera;
  int width = 512;
  int height = 512;
  int frames = 1;     // progressive frames accumulated (each with its own sample shift)
  bool jitter = true; // sub-pixel camera jitter between frames (anti-aliasing)
  // When set, the object is shaded by this instead of `material` (which is then unused).
  MaterialInstaller installMaterial;
};

struct RenderResult
{
  Image linear;  // RGBA float, linear radiance, alpha = coverage; row 0 at the top
  Image display; // RGBA in [0, 1] holding the 8-bit values / 255 of the displayed frame
  std::vector<double> frameSeconds; // wall time of each frame, GPU work included
  int64_t coveredPixels = 0;        // pixels with coverage > 0
  MaterialVariant variant;          // the shader variant that was compiled
  bool mapsDropped = false;         // maps given but the mesh has no texture coordinates
  std::string renderer;             // the OpenGL renderer string (e.g. "llvmpipe ...")
};

// Throws aniso::Error "SUBJECT: reason" for invalid settings, a missing display or a failed
// OpenGL context.
RenderResult renderOffscreen(const RenderSettings& settings);

// Opens this process's connection to the X display named by DISPLAY, once, and keeps it open
// for the life of the process (an X server that loses its last client resets and refuses
// connections for a moment, so windows made one after another would fail at random); retries
// for two seconds while a server resets. Throws aniso::Error "render: reason" otherwise.
void requireXDisplay();

// Median of the frame times (0 for none).
double medianSeconds(std::vector<double> seconds);
} // namespace aniso
