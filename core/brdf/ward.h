#pragma once
// Ward's anisotropic Gaussian model (Ward 1992; docs/METHOD.md, source 2) in tangent space: t = +X,
// b = +Y, n = +Z, all vectors unit length.
//   f(v, l) = rho_d / pi + rho_s / (4 pi alpha_x alpha_y) * S(p) * E
// with S(p) = 1 / sqrt(p), p = (n.l)(n.v), and the Gaussian factor E in one of Ward's two forms:
//   Gaussian   (Ward's eq. 5a): exp(-tan^2(theta_h) (cos^2(phi_h)/alpha_x^2 +
//   sin^2(phi_h)/alpha_y^2)) HalfVector (Ward's eq. 5b, the form source 2 factors into lookups):
//              E(m, d) = exp(-2 m / (1 + d)),  m = (h . t/alpha_x)^2 + (h . b/alpha_y)^2, d = n.h,
//              h the unit half vector.
// For a unit h, 2 m / (1 + d) = 2 (1 - cos(theta_h)) (cos^2(phi_h)/alpha_x^2 + ...), which equals
// the eq. 5a exponent to second order in theta_h only: eq. 5b is Ward's approximation, the same at
// the peak and slightly wider away from it (never smaller than eq. 5a). alpha_x = alpha_y gives
// the isotropic model. Reciprocal in both forms. The directional albedo is about cos(theta_v) for
// narrow lobes; towards grazing views the 1/sqrt(p) factor makes it grow without bound, so rough
// lobes exceed 1 there (alpha = 1 at 89.9 degrees; see the tests).
#include "core/brdf/blinn_phong_aniso.h"
#include "core/brdf/shading_frame.h"
#include "core/frame.h"
#include "core/lights/light.h"

#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
enum class WardForm
{
  HalfVector, // eq. 5b, exp(-2 m / (1 + d)): source 2's factored form (default)
  Gaussian    // eq. 5a, exp(-tan^2(theta_h) ...)
};

struct WardMaterial
{
  double alphaX = 0.2;       // roughness along t, in [kSvMinAlpha, kSvMaxAlpha]
  double alphaY = 0.2;       // roughness along b
  glm::dvec3 diffuse{0.0};   // rho_d in [0, 1]
  glm::dvec3 specular{0.04}; // rho_s in [0, 1]
  WardForm form = WardForm::HalfVector;
};

// Throws aniso::Error ("alpha_x: ...", "alpha_y: ...", "diffuse: ...", "specular: ...").
void validateWard(const WardMaterial& material);

// The two lookups of source 2: S(p) = 1 / sqrt(p) for p > 0 (+infinity at p = 0), and
// E(m, d) = exp(-2 m / (1 + d)) for m >= 0, d in (-1, 1].
double wardS(double p);
double wardE(double m, double d);

// Direct evaluation from the half vector's angles (theta_h, phi_h), in the material's form.
// Zero below either horizon.
glm::dvec3 evalWard(const WardMaterial& material, const glm::dvec3& v, const glm::dvec3& l);

// Factored evaluation as source 2 does it per pixel, from world-space vectors: the textures'
// t / alpha_x and b / alpha_y, the normal, and view and light directions; S and E as above (for
// WardForm::Gaussian the Gaussian factor is exp(-m / d^2) with the same m and d). The
// roughnesses inside `material` are used only for the 1 / (4 pi alpha_x alpha_y) scale.
glm::dvec3 evalWardFactored(const WardMaterial& material, const ScaledTangents& scaled,
                            const glm::dvec3& n, const glm::dvec3& viewWorld,
                            const glm::dvec3& lightWorld);

// Sum over lights of f E (n.l)+ at a world-space point with shading frame `frame`.
glm::dvec3 shadeWard(const WardMaterial& material, const Frame& frame, const glm::dvec3& position,
                     const glm::dvec3& viewWorld, const std::vector<Light>& lights);
} // namespace aniso
