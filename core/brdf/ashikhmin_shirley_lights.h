#pragma once
// The Ashikhmin-Shirley model under point and directional lights (docs/METHOD.md, sources 1 and 2):
// the specular term of brdf/ashikhmin_shirley.h plus the AS diffuse term that couples to it,
//   f_d(v, l) = 28 rho_d / (23 pi) (1 - R_s) (1 - (1 - n.l/2)^5) (1 - (1 - n.v/2)^5),
// R_s the specular reflectance at normal incidence (F0, per channel). Its directional albedo is
// rho_d (1 - R_s) (1 - (1 - n.v/2)^5) <= rho_d (1 - R_s): the diffuse only takes what the
// specular leaves. Reciprocal. Tangent space: t = +X (n_u), b = +Y (n_v), n = +Z.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/frame.h"
#include "core/lights/light.h"

#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
struct AsMaterial
{
  AsLobe lobe;
  glm::dvec3 f0{0.04};     // R_s, in [0, 1]
  glm::dvec3 diffuse{0.0}; // rho_d, in [0, 1]
};

// Throws aniso::Error ("n_u: ...", "n_v: ...", "F0: ...", "diffuse: ...").
void validateAsMaterial(const AsMaterial& material);

// f_d above; zero below either horizon.
glm::dvec3 evalAsDiffuse(const AsMaterial& material, const glm::dvec3& v, const glm::dvec3& l);

// f = evalSpecular + evalAsDiffuse.
glm::dvec3 evalAshikhminShirley(const AsMaterial& material, const glm::dvec3& v,
                                const glm::dvec3& l);

// Sum over lights of f E (n.l)+ at a world-space point with shading frame `frame`.
glm::dvec3 shadeAshikhminShirley(const AsMaterial& material, const Frame& frame,
                                 const glm::dvec3& position, const glm::dvec3& viewWorld,
                                 const std::vector<Light>& lights);
} // namespace aniso
