#pragma once
// Anisotropic Blinn-Phong (docs/METHOD.md, source 2) in tangent space: t = +X, b = +Y, n = +Z, all
// vectors unit length. The exponent is read from the material textures t / alpha_x and
// b / alpha_y (the "exponent form"):
//   e(h) = ((h . t/alpha_x)^2 + (h . b/alpha_y)^2) / (1 - (n.h)^2)
//        = e_x cos^2(phi_h) + e_y sin^2(phi_h),   e_x = 1 / alpha_x^2, e_y = 1 / alpha_y^2,
// so alpha_x = alpha_y = alpha is isotropic Blinn-Phong with exponent 1 / alpha^2.
// The lobe is normalised as a microfacet distribution,
//   D(h) = sqrt((e_x + 2)(e_y + 2)) / (2 pi) (n.h)^e(h),  with  integral D (n.h) dw_h = 1
// exactly (the azimuthal integral of 1 / (e(phi) + 2) is 2 pi / sqrt((e_x+2)(e_y+2))), and the
// BRDF uses the implicit geometry term (n.l)(n.v) of normalised Blinn-Phong:
//   f(v, l) = rho_d / pi + k_s D(h) / 4.
// Reciprocal (it depends on h only); not a Fresnel model (k_s is the specular reflectance).
#include "core/brdf/shading_frame.h"
#include "core/frame.h"
#include "core/lights/light.h"

#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
// Roughness range of the shift-variant models (Blinn-Phong, Ward): alpha = 1e-3 is an exponent
// of 1e6, alpha = 10 a nearly uniform lobe.
constexpr double kSvMinAlpha = 1e-3;
constexpr double kSvMaxAlpha = 10.0;

struct BlinnPhongAnisoMaterial
{
  double alphaX = 0.2;       // roughness along t (exponent 1 / alpha_x^2)
  double alphaY = 0.2;       // roughness along b
  glm::dvec3 diffuse{0.0};   // rho_d, in [0, 1]
  glm::dvec3 specular{0.04}; // k_s, in [0, 1]
};

// Throws aniso::Error ("alpha_x: ...", "alpha_y: ...", "diffuse: ...", "specular: ...") unless
// the roughnesses are in [kSvMinAlpha, kSvMaxAlpha] and the reflectances in [0, 1].
void validateBlinnPhongAniso(const BlinnPhongAnisoMaterial& material);

// e(h) from the tangent-plane components of h; at h = n (where it is 0/0) the mean of e_x, e_y.
double blinnPhongExponent(const BlinnPhongAnisoMaterial& material, const glm::dvec3& h);

// The same exponent as source 2 computes it per pixel, from world-space vectors: the material
// textures' t / alpha_x and b / alpha_y, the normal and a unit half vector.
double blinnPhongExponent(const ScaledTangents& scaled, const glm::dvec3& n, const glm::dvec3& h);

// D(h) above; 0 for h.z <= 0.
double blinnPhongDistribution(const BlinnPhongAnisoMaterial& material, const glm::dvec3& h);

// f(v, l); zero below either horizon.
glm::dvec3 evalBlinnPhongAniso(const BlinnPhongAnisoMaterial& material, const glm::dvec3& v,
                               const glm::dvec3& l);

// Sum over lights of f E (n.l)+ at a world-space point with shading frame `frame`.
glm::dvec3 shadeBlinnPhongAniso(const BlinnPhongAnisoMaterial& material, const Frame& frame,
                                const glm::dvec3& position, const glm::dvec3& viewWorld,
                                const std::vector<Light>& lights);
} // namespace aniso
