#pragma once
// Converged reference radiance of a render, per pixel, from the CPU reference integrator
// (core/reference): on a regular subset of the pixels the render covers, with the frames the
// shader shades there (pixel_geometry.h). References are expensive (milliseconds to a tenth of
// a second per pixel), so they are cached on disk, keyed by everything they depend on.
// GL-free.
#include "core/reference/pixel_geometry.h"
#include "core/brdf/ashikhmin_shirley.h"
#include "core/brdf/ggx.h"
#include "core/env/environment.h"
#include "core/image/image.h"
#include "core/reference/reference_integrator.h"

#include <atomic>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace aniso
{
// The model a reference integrates: Ashikhmin-Shirley (the project's renders) or GGX (VTK's
// own physically based shading, its lobe from ggxLobeFromVtk). GGX's anisotropy direction is
// the pixel tangent turned about the normal by tangentRotation radians (towards b).
struct ReferenceModel
{
  bool ggx = false;
  AsLobe asLobe;
  GgxLobe ggxLobe;
  double tangentRotation = 0.0;
  glm::dvec3 f0{1.0};
};

struct ReferencePixel
{
  int x = 0;
  int y = 0;
  glm::dvec3 value{0.0};
  double errorEstimate = 0.0; // the integrator's estimate, on luminance
  bool converged = false;     // the integrator's own verdict (ReferenceResult::converged)
};

struct ReferenceImage
{
  int width = 0;
  int height = 0;
  std::vector<ReferencePixel> pixels;
  // Relative L2 of the integrator's own error estimates over the pixels (each pixel's relative
  // estimate applied to its RGB value): how far the reference itself may be from the truth.
  double relativeErrorBound = 0.0;
  uint64_t evaluations = 0;
  int64_t unconverged = 0; // pixels whose integration ran out of evaluations
  double seconds = 0.0;    // computing it (0 when read from the cache)
  bool fromCache = false;
};

// Pixels to compare: hit pixels whose 3x3 neighbourhood is hit too (the rasteriser and the ray
// caster may disagree right at a silhouette) and that face the viewer (n.v > 0), on a grid of
// stride s chosen so that about `count` pixels remain. Row-major indices into GEOMETRY.
std::vector<int> selectPixels(const std::vector<PixelSample>& geometry, int width, int height,
                              int count);
// The same pixels on a grid of the given STRIDE (>= 1): columns and rows stride / 2,
// stride / 2 + stride, ... (a quarter of the eligible pixels at stride 2).
std::vector<int> selectPixelGrid(const std::vector<PixelSample>& geometry, int width, int height,
                                 int stride);

// The reference at the selected pixels, from DIRECTORY's cache when present (an empty
// directory disables the cache). Each pixel is integrated in the frame
// Frame::fromNormalTangent(normal, tangent) towards its view; a SunSkyEnvironment goes through
// integrateSpecularSunSky / integrateSpecularGgxSunSky (the sun's disc over its own cone), any
// other environment through integrateSpecular / integrateSpecularGgx. Runs on all hardware
// threads.
ReferenceImage computeReference(const std::vector<PixelSample>& geometry, int width, int height,
                                const std::vector<int>& selected, const ReferenceModel& model,
                                const Environment& environment, const ReferenceOptions& options,
                                const std::string& directory);

struct ImageError
{
  // sqrt(sum |render - ref|^2 / sum |ref|^2) over the compared pixels and RGB.
  double relativeL2 = 0.0;
  // 99th percentile of |render - ref| / rms(ref), per pixel (RGB length), where rms(ref) is the
  // root mean square of |ref| over the compared pixels: a pixel error relative to the image's
  // brightness, so dark pixels do not dominate it.
  double percentile99 = 0.0;
  int64_t uncovered = 0; // compared pixels the render did not cover (coverage < 1)
  int64_t nonFinite = 0; // compared pixels with NaN or Inf
};

ImageError compareToReference(const Image& render, const ReferenceImage& reference);

// A scene's reference: what the anisotropic environment material converges to at each pixel, per
// part's material (PixelSample::material indexes MATERIALS): the Ashikhmin-Shirley specular
// (integrateSpecular, the sun-sky's sun over its own cone) plus the Lambert diffuse the shader
// adds, (1 - F(n.v)) albedo / pi times the irradiance E(n) (integrateIrradiance), F Schlick's
// at the view. The environment is turned as the renderer turns it: WORLD_TO_ENVIRONMENT maps the
// frame and the view into the environment's coordinates. The error estimate adds the two
// integrals' (the diffuse one times its factor). Not cached: a view's pixels are its own.
struct ReferenceMaterial
{
  AsLobe lobe;
  glm::dvec3 f0{1.0};
  glm::dvec3 albedo{0.0};
};
ReferencePixel referencePixel(const PixelSample& sample, int x, int y,
                              const ReferenceMaterial& material, const Environment& environment,
                              const glm::dmat3& worldToEnvironment,
                              const ReferenceOptions& options, uint64_t* evaluations = nullptr);

// The scene's reference at the SELECTED pixels (row-major indices into GEOMETRY), on all
// hardware threads. CANCEL (may be null) is read between pixels: once true, the pixels not yet
// begun are left out (ReferenceImage::pixels holds those done, in no particular order, and
// cancelled is set).
struct SceneReference : ReferenceImage
{
  bool cancelled = false;
};
SceneReference computeSceneReference(const std::vector<PixelSample>& geometry, int width,
                                     int height, const std::vector<int>& selected,
                                     const std::vector<ReferenceMaterial>& materials,
                                     const Environment& environment,
                                     const glm::dmat3& worldToEnvironment,
                                     const ReferenceOptions& options,
                                     const std::atomic<bool>* cancel = nullptr);

// Per compared pixel of REFERENCE, |render - ref| / rms(ref) (RGB lengths; rms over the
// compared pixels, as ImageError::percentile99): an image of WIDTH x HEIGHT with one channel,
// NaN where nothing was compared.
Image errorMap(const Image& render, const ReferenceImage& reference);
} // namespace aniso
