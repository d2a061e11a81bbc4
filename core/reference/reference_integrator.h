#pragma once
// Ground truth: the reflected radiance integral of f_s L_i (n.l) over the hemisphere, without the
// split-sum approximation and without any LUT. Independent of the sampling code it checks:
// it does not call sampleHalfVector, the BRDF evaluation or the LUT bakers; it integrates
// deterministically over the half-vector hemisphere with a change of variables adapted to the
// lobe width, and doubles the resolution until three successive resolutions agree to the
// requested precision.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/brdf/ggx.h"
#include "core/env/environment.h"
#include "core/env/sun_sky.h"
#include "core/frame.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

namespace aniso
{
struct ReferenceOptions
{
  double relativeTolerance = 1e-3; // on the luminance of the result
  double absoluteTolerance = 1e-6;
  uint64_t maxEvaluations = 1ull << 26; // at least kReferenceMinEvaluations
};

// The three coarsest resolutions: the fewest with which an integration can converge.
constexpr uint64_t kReferenceMinEvaluations = 21504;

struct ReferenceResult
{
  glm::dvec3 value{0.0};
  // The larger of the last two |differences| between successive resolutions (luminance): both
  // within tolerance when converged.
  double errorEstimate = 0.0;
  uint64_t evaluations = 0; // quadrature nodes visited (radiance lookups at most)
  // The last two differences between successive resolutions were within tolerance before
  // maxEvaluations ran out.
  bool converged = false;
};

// Outgoing specular radiance towards world direction viewWorld from a surface with shading frame
// `frame` (world space, orthonormal) lit by env. A view below the surface gives 0.
// Throws aniso::Error for exponents outside [0, kMaxExponent] (validateLobe), F0 outside [0, 1],
// a non-finite or zero view, negative tolerances or maxEvaluations below
// kReferenceMinEvaluations.
ReferenceResult integrateSpecular(const AsLobe& lobe, const glm::dvec3& f0, const Frame& frame,
                                  const glm::dvec3& viewWorld, const Environment& env,
                                  const ReferenceOptions& options = {});

// The same integral for the anisotropic GGX model (brdf/ggx.h: D, height-correlated Smith G2,
// Schlick F), without calling its evaluation or sampling code. Over half vectors in slope space:
// D(h)(n.h) dw_h is the uniform measure dq dpsi / (2 pi) in the stretched polar coordinates
// (r, psi) of the slope, q = r^2 / (1 + r^2); the rule runs over s = ln r (where that measure is
// sech^2(s) / 2 ds), so environment features far out in GGX's heavy tail stay resolved in angle.
// Azimuths crowd towards the meridians perpendicular to the view, as for Ashikhmin-Shirley, and
// towards the axis of the smaller alpha, where masking changes fastest with the azimuth.
// Throws as integrateSpecular, with validateGgxLobe for the lobe.
ReferenceResult integrateSpecularGgx(const GgxLobe& lobe, const glm::dvec3& f0, const Frame& frame,
                                     const glm::dvec3& viewWorld, const Environment& env,
                                     const ReferenceOptions& options = {});

// Both models under a SunSkyEnvironment. The sun's hard edge would need a grid fine enough to
// resolve the disc everywhere, so the sky (uniform) goes through the rules above and the sun is
// integrated over its own cone (Gauss-Legendre in the angle from its centre, equally spaced
// around it), each part refined to the tolerance; errorEstimate and evaluations are the sums,
// converged needs both. maxEvaluations applies to each part.
ReferenceResult integrateSpecularSunSky(const AsLobe& lobe, const glm::dvec3& f0,
                                        const Frame& frame, const glm::dvec3& viewWorld,
                                        const SunSkyEnvironment& env,
                                        const ReferenceOptions& options = {});
ReferenceResult integrateSpecularGgxSunSky(const GgxLobe& lobe, const glm::dvec3& f0,
                                           const Frame& frame, const glm::dvec3& viewWorld,
                                           const SunSkyEnvironment& env,
                                           const ReferenceOptions& options = {});

// An equirectangular environment's bright sources, for integrating them on their own: the
// analysis' excess (core/env/env_sources.h) of the sources whose peak reaches
// EnvAnalysis::kConcentratedPeak x T (suns, lamps, bright panels; a broad dim region above T, a
// bright sky, stays with the rules, which resolve it) as an environment, the bilinear
// interpolation of that image (EquirectEnvironment's), and the texels the interpolation reaches
// (each of those texels and its eight neighbours). env(d) - excess(d) is what the rules
// integrate, so the two parts add up to env exactly.
struct SourceQuadrature
{
  std::shared_ptr<const Environment> excess;
  int width = 0; // the excess image's grid
  int height = 0;
  std::vector<std::uint32_t> support; // texel indices y W + x
};

// Per process and environment key (thread-safe): the sources of ENV when it is an
// EquirectEnvironment whose analysis (sharedEnvironmentAnalysis) finds concentrated ones
// (EnvAnalysis::concentrated: suns and lamps, where the rules above converge slowly because the
// sources are smaller than their coarse grids), else null.
std::shared_ptr<const SourceQuadrature> sharedSourceQuadrature(const Environment& env);

// integrateSpecular under env = residual + excess: the residual (env less the excess) through
// integrateSpecular's rule, the excess over its support, each texel cut into k x k cells of equal
// solid angle (midpoints in phi and cos theta), k = 1, 2, 4, ... refined as the rules are; the
// parts summed as integrateSpecularSunSky sums its two (errorEstimate and evaluations added,
// converged needs both, maxEvaluations applies to each part). Throws as integrateSpecular.
ReferenceResult integrateSpecularSources(const AsLobe& lobe, const glm::dvec3& f0,
                                         const Frame& frame, const glm::dvec3& viewWorld,
                                         const Environment& env, const SourceQuadrature& sources,
                                         const ReferenceOptions& options = {});

// Irradiance E(n) = integral of L (n.l)+ dw by brute-force quadrature (checks the SH9 path).
ReferenceResult integrateIrradiance(const glm::dvec3& normalWorld, const Environment& env,
                                    const ReferenceOptions& options = {});
} // namespace aniso
