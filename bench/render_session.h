#pragma once
// One off-screen window kept for a whole benchmark run. renderOffscreen (OffscreenRenderer.h)
// opens a window, bakes the environment and compiles the shaders on every call; a run of
// hundreds of renders reuses them here instead: one X connection, one GL context, one cubemap
// per environment, one compile per shader variant. The same window draws the actor with the
// anisotropic material or with VTK's own physically based shading (image-based lighting and
// anisotropy), both through the accumulation pass, so both read back as linear float radiance.
#include "core/env/environment.h"
#include "core/image/image.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "vtkpasses/render/ViewSettings.h"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso::bench
{
// VTK's physically based material (vtkProperty with PBR interpolation): metallic, base colour
// = F0, roughness and anisotropy in [0, 1], the anisotropy direction turned about the normal by
// rotation x 2 pi from the mesh tangent.
struct VtkPbrMaterial
{
  double roughness = 0.5;
  double anisotropy = 0.0;
  double rotation = 0.0;
  glm::dvec3 baseColor{1.0};
};

// One frame's cost: wall time, and the CPU time of the whole process meanwhile (the GL driver's
// threads included: llvmpipe renders on the CPU), which a loaded machine changes less.
struct FrameTime
{
  double wall = 0.0;
  double cpu = 0.0;
};

// The median wall time and the median CPU time of FRAMES (each median taken alone).
FrameTime medianFrameTime(const std::vector<FrameTime>& frames);
// Pixels of a read image with coverage > 0.
int64_t coveredPixels(const Image& image);

// Where one frame went, stage by stage (seconds; the accumulation pass's stages, each waited
// for), and the frame's whole time while they were timed: the rest is VTK's own work around
// the pass (its render steps before the props, the window's buffers).
struct FrameStages
{
  double prepare = 0.0;
  double clear = 0.0;
  double scene = 0.0;
  double accumulate = 0.0;
  double present = 0.0;
  double frame = 0.0;
};

// What the session did, for showing that nothing is redone when nothing changed.
struct SessionCounters
{
  uint64_t shaderPrograms = 0;   // distinct shader programs the actor was drawn with (compiles)
  uint64_t textureUploads = 0;   // textures the project uploaded (TextureUpload.h)
  uint64_t lutBakes = 0;         // lookup tables baked by the shared LutCache
  uint64_t environmentBakes = 0; // cubemaps and SH9 projections (one per setEnvironment)
};

class RenderSession
{
public:
  // Throws aniso::Error "render: reason" without an X display.
  RenderSession(int width, int height);
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }

  // The surface (prepared: "Normals", "Tangents") and the camera placed as ViewSettings says.
  void setSurface(vtkSmartPointer<vtkPolyData> surface, const ViewSettings& view);
  // The surface seen from CAMERA as it is (a close-up that need not show the whole surface).
  void setSurface(vtkSmartPointer<vtkPolyData> surface, const CameraPlacement& camera);
  // Clip to world of the camera the mappers draw with (for CPU rays through the pixels).
  glm::dmat4 clipToWorld() const;

  // Bakes the cubemap (cubeSize) and the irradiance of ENVIRONMENT; VTK's own environment
  // texture is made when VTK's shading first needs it.
  void setEnvironment(std::shared_ptr<const Environment> environment, int cubeSize);
  // The lighting of the last setEnvironment (its analysis, what `auto` sampling resolves to).
  // Throws aniso::Error "environment: reason" before any.
  EnvironmentLighting& lighting();

  void useMaterial(const MaterialSettings& settings);
  void useVtkPbr(const VtkPbrMaterial& material);
  // Another shading model (the lit models, LEADR, microstructure): INSTALLER gives the actor a
  // new material of that model, replacing whatever drew it before.
  void useInstalled(const MaterialInstaller& installer);

  // Starts a new accumulation and draws FRAMES progressive frames (each with its sample-set
  // shift, no jitter: every frame samples the pixel centres); returns the time of each, GPU
  // work included.
  std::vector<FrameTime> render(int frames);
  // Draws FRAMES more frames into the same accumulation.
  std::vector<FrameTime> renderMore(int frames);
  int accumulatedFrames() const;
  // The window's still view by error (quality-mode error): a new accumulation drawn frame by
  // frame until the error estimated from its own frames (vtkAnisoAccumulationPass::
  // SetErrorTarget) is at most ERROR_TARGET from FROM_FRAMES frames on, or MOST frames; returns
  // their times. The estimate stays readable (estimatedError()) until the next render.
  std::vector<FrameTime> renderToError(double errorTarget, int fromFrames, int most);
  // Later accumulations (render, renderMore) refine as the window's still view does under
  // ERROR_TARGET (vtkAnisoAccumulationPass::SetErrorTarget: estimates at the checkpoints, pixels
  // that stop, core/quality/error_estimate.h freezeConvergedPixels) but draw the frames asked
  // for (the view is never stopped); 0: no target (the default).
  void setStillRefinement(double errorTarget);
  double estimatedError() const;
  // The accumulated mean: RGBA float, linear radiance, alpha = coverage, row 0 at the top.
  Image read();

  // Draws through VTK's own render passes instead of the accumulation pass (VTK's frame as VTK
  // draws it: no float targets, no display transform); render() then returns frame times and
  // read() is not available. Off by default.
  void setVtkPasses(bool vtkPasses);
  // Times each stage of the accumulation pass (FrameStages) while on; stages() holds those of
  // every frame drawn since it was switched on.
  void setStageTiming(bool timing);
  const std::vector<FrameStages>& stages() const;

  SessionCounters counters() const;
  std::string rendererName();

private:
  class Impl;
  std::unique_ptr<Impl> impl_;
  int width_;
  int height_;
  double estimatedError_ = -1.0;
};
} // namespace aniso::bench
