#pragma once
// Shift-variant materials as source 2 stores them (docs/METHOD.md, source 2): per-texel tangent
// direction, roughnesses along and across it, diffuse albedo, specular coefficient k_s (kept in
// the alpha channel, as the source does) and a bump normal; and how one texel becomes the
// parameters of each lit model, so that every model renders the same material.
#include "core/brdf/ashikhmin_shirley_lights.h"
#include "core/brdf/banks.h"
#include "core/brdf/blinn_phong_aniso.h"
#include "core/brdf/heidrich_seidel.h"
#include "core/brdf/ward.h"
#include "core/frame.h"
#include "core/image/image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace aniso
{
struct SvTexel
{
  glm::dvec3 normal{0.0, 0.0, 1.0}; // tangent-space bump normal, unit
  glm::dvec2 tangent{1.0, 0.0};     // direction of t in the tangent plane (+u = (1, 0)), unit
  double alphaX = 0.2;              // roughness along t, in [kSvMinAlpha, kSvMaxAlpha]
  double alphaY = 0.2;              // roughness along b
  glm::dvec3 diffuse{0.5};          // rho_d in [0, 1]
  double specular = 0.04;           // k_s / rho_s / F0 in [0, 1]
};

// The maps of a material, all tiling [0, 1)^2 of texture space (row 0 at v = 1):
//   tangentAlpha   RGBA: tangent x, y, alpha_x, alpha_y
//   albedoSpecular RGBA: diffuse albedo RGB, k_s in alpha
//   normal         RGB : tangent-space normal (float, signed)
//   height         R   : height in texture units (already scaled; empty when the material has no
//                        relief). The normal map is derived from it when present.
struct SvMaps
{
  Image tangentAlpha;
  Image albedoSpecular;
  Image normal;
  Image height;
};

// Bilinear lookup with wrapping at (u, v); the tangent and normal are renormalised after
// filtering (a zero filtered tangent falls back to +u, a zero normal to +Z) and the roughnesses
// clamped to [kSvMinAlpha, kSvMaxAlpha]. Maps of different sizes are each sampled at (u, v).
// Throws aniso::Error "material maps: reason" if a map is empty or has too few channels.
SvTexel sampleSvMaps(const SvMaps& maps, const glm::dvec2& uv);

// 1x1 maps holding one texel (uniform materials such as the brushed spheres).
SvMaps uniformSvMaps(const SvTexel& texel);

// World-space shading frame at a pixel: perturbedFrame with the texel's normal and tangent.
Frame svShadingFrame(const glm::dvec3& interpolatedNormal, const glm::dvec3& interpolatedTangent,
                     const SvTexel& texel);

// One texel as each model's parameters:
//   Blinn-Phong, Ward: alpha_x, alpha_y as they are, k_s as the specular reflectance;
//   Ashikhmin-Shirley: n = 2 / alpha^2 - 2 (Beckmann-equivalent Phong exponent, clamped to
//     [0, kMaxExponent]), F0 = k_s;
//   Banks, Heidrich-Seidel: fibres along t, e = 1 / (2 alpha_x^2) (a cone of half-width
//     about 2 alpha_x, the spread of mirror directions of normals of roughness alpha_x), and
//     k_s scaled by sqrt(e / (2 pi)) / pi so that the specular albedo of a view across the
//     fibres is about k_s (Laplace approximation of the cone integral).
BlinnPhongAnisoMaterial toBlinnPhong(const SvTexel& texel);
WardMaterial toWard(const SvTexel& texel, WardForm form = WardForm::HalfVector);
AsMaterial toAshikhminShirley(const SvTexel& texel);
BanksMaterial toBanks(const SvTexel& texel);
HeidrichSeidelMaterial toHeidrichSeidel(const SvTexel& texel);
} // namespace aniso
