#pragma once
// Banks's fibre model (Banks 1994; docs/METHOD.md, source 2) in tangent space: the fibres run along
// t = +X, b = +Y, n = +Z, all vectors unit length. A fibre has every normal of its normal plane;
// for the diffuse part the one closest to l (its projection N') lights it, and l mirrors into a
// cone of directions around t (all with r.t = -l.t), whose direction R' closest to v gives the
// highlight:
//   N'.L = sqrt(1 - (l.t)^2),
//   V.R' = sqrt(1 - (l.t)^2) sqrt(1 - (v.t)^2) - (l.t)(v.t)      (the largest v.r on the cone),
// and the surface the fibres lie on shadows them with its own normal (the (n.l)+ factor):
//   radiance = E (n.l)+ [ rho_d / pi (N'.L) + k_s max(V.R', 0)^e ].
// As a BRDF (radiance = f E (n.l)+): f = rho_d / pi (N'.L) + k_s max(V.R', 0)^e.
// The specular part is reciprocal (V.R' is symmetric in v and l); the diffuse part is not (it
// depends on l only). Diffuse albedo is rho_d 8 / (3 pi) for every view (the fibre cosine never
// exceeds Lambert's); the specular part is not normalised (k_s is the peak value of f, sr^-1).
#include "core/frame.h"
#include "core/lights/light.h"

#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
// Exponent range of the fibre models (Banks, Heidrich-Seidel).
constexpr double kFibreMaxExponent = 1e6;

struct BanksMaterial
{
  glm::dvec3 diffuse{0.5};  // rho_d in [0, 1]
  glm::dvec3 specular{0.5}; // k_s >= 0 (sr^-1), at most kFibreMaxSpecular
  double exponent = 50.0;   // e in [0, kFibreMaxExponent]
};

constexpr double kFibreMaxSpecular = 1e3;

// Throws aniso::Error ("diffuse: ...", "specular: ...", "exponent: ...").
void validateBanks(const BanksMaterial& material);

// N'.L and V.R' for a fibre along +X (closed forms above); N'.L in [0, 1], V.R' in [-1, 1].
double fibreDiffuseCosine(const glm::dvec3& l);
double fibreSpecularCosine(const glm::dvec3& v, const glm::dvec3& l);

// f(v, l) as above; zero below either horizon.
glm::dvec3 evalBanks(const BanksMaterial& material, const glm::dvec3& v, const glm::dvec3& l);

// Sum over lights of E (n.l)+ [rho_d / pi N'.L + k_s (V.R')^e], the customary form.
glm::dvec3 shadeBanks(const BanksMaterial& material, const Frame& frame, const glm::dvec3& position,
                      const glm::dvec3& viewWorld, const std::vector<Light>& lights);
} // namespace aniso
