#pragma once
// Heidrich-Seidel line lighting applied to surfaces (Heidrich and Seidel 1998; docs/METHOD.md,
// source 2) in tangent space: fibres along t = +X, b = +Y, n = +Z, all vectors unit length.
// The specular highlight is that of an infinitely thin fibre, a function of (l.t, v.t) only
// (which is why it fits a 2D table indexed by the two dot products):
//   V.R' = sqrt(1 - (l.t)^2) sqrt(1 - (v.t)^2) - (l.t)(v.t)    (the reflection cone of Banks's
//                                                               model, at its point closest to v),
// added to a Lambertian term on the surface normal. Unlike Banks's form, the fibre highlight is
// not attenuated by the surface's (n.l); the surface only hides what lies below its horizon:
//   radiance = E [ rho_d / pi (n.l)+ + k_s max(V.R', 0)^e ]   for n.l > 0 and n.v > 0.
// As a BRDF (radiance = f E (n.l)+): f = rho_d / pi + k_s max(V.R', 0)^e / (n.l), which is not
// reciprocal (the 1 / (n.l) of line lighting). The specular directional albedo is bounded by
// k_s 2 pi sqrt(pi) Gamma((e+1)/2) / Gamma(e/2 + 1) (the integral over the whole reflection cone).
#include "core/brdf/banks.h"
#include "core/frame.h"
#include "core/lights/light.h"

#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
struct HeidrichSeidelMaterial
{
  glm::dvec3 diffuse{0.5};  // rho_d in [0, 1]
  glm::dvec3 specular{0.5}; // k_s in [0, kFibreMaxSpecular] (peak radiance per irradiance)
  double exponent = 50.0;   // e in [0, kFibreMaxExponent]
};

// Throws aniso::Error ("diffuse: ...", "specular: ...", "exponent: ...").
void validateHeidrichSeidel(const HeidrichSeidelMaterial& material);

// Radiance per unit irradiance, the customary form above (cosine included); zero below either
// horizon.
glm::dvec3 heidrichSeidelTerm(const HeidrichSeidelMaterial& material, const glm::dvec3& v,
                              const glm::dvec3& l);

// f(v, l) = heidrichSeidelTerm / (n.l); zero below either horizon.
glm::dvec3 evalHeidrichSeidel(const HeidrichSeidelMaterial& material, const glm::dvec3& v,
                              const glm::dvec3& l);

// Sum over lights of heidrichSeidelTerm E.
glm::dvec3 shadeHeidrichSeidel(const HeidrichSeidelMaterial& material, const Frame& frame,
                               const glm::dvec3& position, const glm::dvec3& viewWorld,
                               const std::vector<Light>& lights);
} // namespace aniso
