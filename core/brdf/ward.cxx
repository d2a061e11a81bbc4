#include "core/brdf/ward.h"

#include "core/brdf/sv_common.h"

#include <glm/geometric.hpp>
#include <limits>

namespace aniso
{
namespace
{
// S(p) grows without bound at grazing angles; flooring p keeps every value finite (p underflows
// to 0 only when both cosines are below 1e-150, where E is already 0 or the product stays finite).
constexpr double kMinCosineProduct = 1e-300;

double specularScale(const WardMaterial& material)
{
  return 1.0 / (4.0 * sv::kPi * material.alphaX * material.alphaY);
}
} // namespace

void validateWard(const WardMaterial& material)
{
  sv::checkRange("alpha_x", material.alphaX, kSvMinAlpha, kSvMaxAlpha);
  sv::checkRange("alpha_y", material.alphaY, kSvMinAlpha, kSvMaxAlpha);
  sv::checkColour("diffuse", material.diffuse, 1.0);
  sv::checkColour("specular", material.specular, 1.0);
}

double wardS(double p)
{
  return p > 0.0 ? 1.0 / std::sqrt(p) : std::numeric_limits<double>::infinity();
}

double wardE(double m, double d)
{
  return std::exp(-2.0 * m / (1.0 + d));
}

glm::dvec3 evalWard(const WardMaterial& material, const glm::dvec3& v, const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return glm::dvec3(0.0);
  const glm::dvec3 h = sv::normalizeScaled(v + l);
  const double thetaH = std::atan2(std::hypot(h.x, h.y), h.z);
  const double phiH = std::atan2(h.y, h.x);
  const double c = std::cos(phiH);
  const double s = std::sin(phiH);
  const double anisotropy =
      c * c / (material.alphaX * material.alphaX) + s * s / (material.alphaY * material.alphaY);
  double exponent = 0.0;
  if (material.form == WardForm::Gaussian)
  {
    const double tanTheta = std::tan(thetaH);
    exponent = tanTheta * tanTheta * anisotropy;
  }
  else
  {
    exponent = 2.0 * (1.0 - std::cos(thetaH)) * anisotropy;
  }
  const double lobe =
      specularScale(material) * std::exp(-exponent) * wardS(std::max(v.z * l.z, kMinCosineProduct));
  return material.diffuse / sv::kPi + material.specular * lobe;
}

glm::dvec3 evalWardFactored(const WardMaterial& material, const ScaledTangents& scaled,
                            const glm::dvec3& n, const glm::dvec3& viewWorld,
                            const glm::dvec3& lightWorld)
{
  const double nv = glm::dot(n, viewWorld);
  const double nl = glm::dot(n, lightWorld);
  if (!(nv > 0.0) || !(nl > 0.0))
    return glm::dvec3(0.0);
  const glm::dvec3 h = sv::normalizeScaled(viewWorld + lightWorld);
  const double ht = glm::dot(h, scaled.tScaled);
  const double hb = glm::dot(h, scaled.bScaled);
  const double m = ht * ht + hb * hb;
  const double d = glm::dot(h, n);
  const double gaussian =
      material.form == WardForm::Gaussian ? std::exp(-m / (d * d)) : wardE(m, d);
  const double lobe =
      specularScale(material) * wardS(std::max(nl * nv, kMinCosineProduct)) * gaussian;
  return material.diffuse / sv::kPi + material.specular * lobe;
}

glm::dvec3 shadeWard(const WardMaterial& material, const Frame& frame, const glm::dvec3& position,
                     const glm::dvec3& viewWorld, const std::vector<Light>& lights)
{
  return shadeBrdfWithLights(lights, frame, position, viewWorld,
                             [&](const glm::dvec3& v, const glm::dvec3& l)
                             { return evalWard(material, v, l); });
}
} // namespace aniso
