#include "core/models/gltf_material.h"

#include "core/brdf/ashikhmin_shirley.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
// The dielectric F0 of ior 1.5, glTF's default.
constexpr double kDielectricF0 = 0.04;

double finiteOr(double value, double fallback)
{
  return std::isfinite(value) ? value : fallback;
}

double unit(double value, double fallback)
{
  return std::clamp(finiteOr(value, fallback), 0.0, 1.0);
}

glm::dvec3 unitColor(const glm::dvec3& c, double fallback)
{
  return {unit(c.x, fallback), unit(c.y, fallback), unit(c.z, fallback)};
}
} // namespace

GltfAlphas gltfAlphas(double roughness, double anisotropyStrength)
{
  const double r = unit(roughness, 1.0);
  const double s = unit(anisotropyStrength, 0.0);
  const double alpha = r * r;
  return {alpha + (1.0 - alpha) * s * s, alpha};
}

glm::dvec3 gltfDielectricF0(const GltfFactors& factors)
{
  const double ior = std::max(finiteOr(factors.ior, 1.5), 1.0);
  const double fromIor = ((ior - 1.0) / (ior + 1.0)) * ((ior - 1.0) / (ior + 1.0));
  glm::dvec3 color;
  for (int c = 0; c < 3; ++c)
  {
    color[c] = std::max(finiteOr(factors.specularColor[c], 1.0), 0.0);
  }
  return glm::min(fromIor * color, glm::dvec3(1.0)) * unit(factors.specularFactor, 1.0);
}

GltfAsValues gltfToAs(const GltfFactors& factors)
{
  GltfAsValues out;
  const GltfAlphas alphas = gltfAlphas(factors.roughness, factors.anisotropyStrength);
  const double nt = exponentFromRoughness(alphas.alphaT);
  const double nb = exponentFromRoughness(alphas.alphaB);
  const double rotation = finiteOr(factors.anisotropyRotation, 0.0);
  double phi = rotation - kPi * std::round(rotation / kPi); // in [-pi/2, pi/2]
  if (std::abs(phi) <= kPi / 4.0)
  {
    out.nu = nt;
    out.nv = nb;
  }
  else
  {
    out.nu = nb;
    out.nv = nt;
    phi += phi > 0.0 ? -kPi / 2.0 : kPi / 2.0;
  }
  out.tangentRotation = std::abs(phi) < 1e-12 ? 0.0 : phi;
  const glm::dvec3 base = unitColor(factors.baseColor, 1.0);
  const double metallic = unit(factors.metallic, 1.0);
  out.f0 = glm::mix(gltfDielectricF0(factors), base, metallic);
  out.albedo = base * (1.0 - metallic);
  return out;
}

GltfFactors asToGltf(double nu, double nv, const glm::dvec3& f0, const glm::dvec3& albedo)
{
  GltfFactors out;
  nu = std::clamp(finiteOr(nu, 0.0), 0.0, kMaxExponent);
  nv = std::clamp(finiteOr(nv, 0.0), 0.0, kMaxExponent);
  const bool tangentRougher = nu <= nv;
  const double alpha = roughnessFromExponent(tangentRougher ? nv : nu);
  const double alphaT = roughnessFromExponent(tangentRougher ? nu : nv);
  out.roughness = std::sqrt(alpha);
  out.anisotropyStrength =
      alpha < 1.0 ? std::sqrt(std::clamp((alphaT - alpha) / (1.0 - alpha), 0.0, 1.0)) : 0.0;
  out.anisotropyRotation = tangentRougher ? 0.0 : kPi / 2.0;
  const glm::dvec3 a = unitColor(albedo, 0.0);
  const glm::dvec3 f = unitColor(f0, kDielectricF0);
  if (a == glm::dvec3(0.0))
  {
    out.metallic = 1.0;
    out.baseColor = f;
    return out;
  }
  out.metallic = 0.0;
  out.baseColor = a;
  if (f != glm::dvec3(kDielectricF0))
  {
    out.hasSpecular = true;
    out.specularColor = f / kDielectricF0;
  }
  return out;
}

glm::dvec2 gltfAnisotropyDirection(const glm::dvec2& textureRg, double rotation)
{
  glm::dvec2 d = 2.0 * textureRg - glm::dvec2(1.0);
  const double length = glm::length(d);
  d = length > 1e-9 && std::isfinite(length) ? d / length : glm::dvec2(1.0, 0.0);
  const double c = std::cos(rotation);
  const double s = std::sin(rotation);
  return {c * d.x - s * d.y, s * d.x + c * d.y};
}

glm::dvec2 applyTextureTransform(const GltfTextureTransform& transform, const glm::dvec2& uv)
{
  const glm::dvec2 scaled = transform.scale * uv;
  const double c = std::cos(transform.rotation);
  const double s = std::sin(transform.rotation);
  return transform.offset + glm::dvec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y);
}
} // namespace aniso
