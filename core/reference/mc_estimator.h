#pragma once
// Monte-Carlo estimates of the specular integral that the reference integrator computes (the
// `exact` method of the renderer: no split sum, no LUT), with the sampling strategies a shader
// can use, on the CPU, so that their variance can be measured against the converged reference.
// Points are an N-point Hammersley set under a Cranley-Patterson rotation: with a uniformly
// random shift every point is uniform, so each estimate is unbiased, and the spread over shifts
// is the estimator's error at that N.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/brdf/ggx.h"
#include "core/env/env_sampling.h"
#include "core/env/environment.h"
#include "core/frame.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace aniso
{
enum class SamplingStrategy
{
  // N lobe samples (Ashikhmin-Shirley half vectors, GGX visible normals), each weighted by
  // f (n.l) / pdf: for Ashikhmin-Shirley F(v.h)(n.l) / max(n.l, n.v), the shader's weight.
  Brdf,
  // N samples of the environment distribution, each weighted by f (n.l) / pdf.
  Environment,
  // Two-sample multiple importance sampling: n_lobe = N x lobeFraction (rounded, at least 1)
  // lobe samples and the rest environment samples, each technique on its own rotated Hammersley
  // set, combined by the balance heuristic (n_i p_i / sum_j n_j p_j) ...
  MisBalance,
  // ... or by the power heuristic with exponent 2.
  MisPower,
  // One-sample MIS: each of the N points takes the lobe technique with probability c =
  // lobeFraction (by its first coordinate: x < c, so a Hammersley set splits in proportion) or
  // the environment otherwise, and is weighted by the mixture density c p_lobe + (1 - c) p_env:
  // one loop, as a shader would run it.
  MisOneSample,
};

// "brdf", "env", "mis-balance", "mis-power", "mis-one-sample".
const char* strategyName(SamplingStrategy strategy);

struct EstimatorOptions
{
  SamplingStrategy strategy = SamplingStrategy::Brdf;
  uint32_t samples = 64; // radiance lookups per estimate, >= 1
  glm::dvec2 shift{0.0}; // Cranley-Patterson rotation of the point sets, in [0, 1)^2
  // Share of the lobe technique in the MIS strategies, in [0, 1]: sharp lobes gain from more
  // lobe samples, rough ones next to bright sources from more environment samples.
  double lobeFraction = 0.5;
};

// Estimate of integrateSpecular(lobe, f0, frame, viewWorld, env) with N = options.samples.
// distribution is required (non-null) by every strategy but Brdf; it must describe the same
// environment for the estimate to be efficient (any distribution keeps it unbiased as long as
// its density is positive wherever env is, e.g. with a uniform fraction > 0). A view below the
// surface gives 0. Throws aniso::Error for an invalid lobe or F0, a non-finite or zero view,
// samples = 0, lobeFraction outside [0, 1] or a missing distribution.
glm::dvec3 estimateSpecular(const AsLobe& lobe, const glm::dvec3& f0, const Frame& frame,
                            const glm::dvec3& viewWorld, const Environment& env,
                            const EnvironmentDistribution* distribution,
                            const EstimatorOptions& options);

// The same for the GGX model (estimates integrateSpecularGgx); its lobe weight is
// F(v.h) G2(v, l) / G1(v).
glm::dvec3 estimateSpecularGgx(const GgxLobe& lobe, const glm::dvec3& f0, const Frame& frame,
                               const glm::dvec3& viewWorld, const Environment& env,
                               const EnvironmentDistribution* distribution,
                               const EstimatorOptions& options);
} // namespace aniso
