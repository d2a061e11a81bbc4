#pragma once
// glTF 2.0 metallic-roughness materials with KHR_materials_anisotropy (and KHR_materials_specular
// and KHR_materials_ior, which carry what metallic-roughness cannot) as the Ashikhmin-Shirley
// lobe of a material, and back. Plain values in and out: no glTF parser, no VTK, so the glTF
// reader (vtkpasses/mesh/GltfReader) and writer (vtkpasses/mesh/GltfWriter) share it.
//
// Import (docs/FORMATS.md, "glTF 2.0"):
//   alpha = roughness^2, alpha_t = mix(alpha, 1, strength^2) along the anisotropy direction,
//   alpha_b = alpha across it (KHR_materials_anisotropy); each alpha to an exponent by
//   n = 2 / alpha^2 - 2 (exponentFromRoughness, core/brdf/ashikhmin_shirley.h), clamped to
//   [0, kMaxExponent]. The anisotropy direction is the tangent turned by anisotropyRotation about
//   the normal: a rotation is reduced modulo pi (a tangent line repeats every pi) to
//   phi in (-pi/2, pi/2]; |phi| <= pi/4 keeps n_u = n_t, n_v = n_b and leaves phi to turn the
//   tangent; beyond, the exponents swap (n_u = n_b, n_v = n_t) and phi -/+ pi/2 is left, so a
//   rotation of exactly pi/2 is a swap alone.
//   f0_dielectric = min(((ior - 1) / (ior + 1))^2 specularColor, 1) specularFactor (0.04 by
//   default), F0 = mix(f0_dielectric, baseColor, metallic), albedo = baseColor (1 - metallic).
// Export, the inverse: the rougher axis is the anisotropy direction (alpha_t >= alpha_b):
//   n_u <= n_v: rotation 0, alpha = sqrt(2 / (n_v + 2)), alpha_t = sqrt(2 / (n_u + 2));
//   n_u >  n_v: rotation pi/2, alpha from n_u, alpha_t from n_v;
//   roughness = sqrt(alpha), strength = sqrt((alpha_t - alpha) / (1 - alpha)) (0 when alpha = 1).
//   A metal (albedo 0): metallic 1, baseColor = F0. Otherwise metallic 0, baseColor = albedo, and
//   F0 other than 0.04 in KHR_materials_specular's specularColorFactor = F0 / 0.04 (ior 1.5).
// So gltfToAs(asToGltf(m)) == m to rounding for every n_u, n_v in [0, kMaxExponent], F0 and
// albedo in [0, 1].
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace aniso
{
// What a glTF material says in factors (textures aside), with the specification's defaults.
struct GltfFactors
{
  glm::dvec3 baseColor{1.0}; // linear RGB (the factor's alpha is not used)
  double metallic = 1.0;
  double roughness = 1.0;
  double anisotropyStrength = 0.0; // KHR_materials_anisotropy, in [0, 1]
  double anisotropyRotation = 0.0; // radians, counter-clockwise about the normal from the tangent
  double specularFactor = 1.0;     // KHR_materials_specular
  glm::dvec3 specularColor{1.0};   // KHR_materials_specular's specularColorFactor
  double ior = 1.5;                // KHR_materials_ior
  bool hasSpecular = false;        // the exporter writes KHR_materials_specular
};

// The Ashikhmin-Shirley values of a material.
struct GltfAsValues
{
  double nu = 0.0; // along the part's tangent turned by tangentRotation
  double nv = 0.0;
  glm::dvec3 f0{0.04};
  glm::dvec3 albedo{0.0};
  double tangentRotation = 0.0; // radians in [-pi/4, pi/4], 0 when the rotation was a swap
};

// The roughnesses along and across the anisotropy direction.
struct GltfAlphas
{
  double alphaT = 1.0;
  double alphaB = 1.0;
};
GltfAlphas gltfAlphas(double roughness, double anisotropyStrength);

// F0 of the dielectric part: min(((ior - 1) / (ior + 1))^2 specularColor, 1) specularFactor.
glm::dvec3 gltfDielectricF0(const GltfFactors& factors);

// Import and export as above. Inputs out of range are clamped to it (roughness, metallic and
// strength to [0, 1], colours to [0, 1], ior to [1, inf), a non-finite value takes its default).
GltfAsValues gltfToAs(const GltfFactors& factors);
GltfFactors asToGltf(double nu, double nv, const glm::dvec3& f0, const glm::dvec3& albedo);

// KHR_materials_anisotropy's direction at a texel: the anisotropy texture's RG (in [0, 1],
// decoded to [-1, 1]) turned by ROTATION, unit (a zero vector gives the turned tangent).
glm::dvec2 gltfAnisotropyDirection(const glm::dvec2& textureRg, double rotation);

// KHR_texture_transform on a glTF texture coordinate (origin top left): uv' = offset +
// R (scale * uv), R = [[cos r, sin r], [-sin r, cos r]] (rows): the UVs turned counter-clockwise
// in glTF's u-right, v-down texture space, the image clockwise, as the extension's text says and
// the implementations (Blender's importer and exporter, Babylon.js, three.js) and Khronos'
// TextureTransformTest sample model agree. The extension's GLSL listing, read as GLSL reads
// mat3 (column by column), is the transpose, the opposite turn: KhronosGroup/glTF issue 1563
// records that the listing disagrees with the implementations and the sample model.
struct GltfTextureTransform
{
  glm::dvec2 offset{0.0};
  double rotation = 0.0;
  glm::dvec2 scale{1.0};
  bool operator==(const GltfTextureTransform& o) const
  {
    return offset == o.offset && rotation == o.rotation && scale == o.scale;
  }
  bool isIdentity() const { return *this == GltfTextureTransform{}; }
};
glm::dvec2 applyTextureTransform(const GltfTextureTransform& transform, const glm::dvec2& uv);
} // namespace aniso
