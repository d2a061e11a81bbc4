#include "core/brdf/blinn_phong_aniso.h"

#include "core/brdf/sv_common.h"

#include <glm/geometric.hpp>

namespace aniso
{
void validateBlinnPhongAniso(const BlinnPhongAnisoMaterial& material)
{
  sv::checkRange("alpha_x", material.alphaX, kSvMinAlpha, kSvMaxAlpha);
  sv::checkRange("alpha_y", material.alphaY, kSvMinAlpha, kSvMaxAlpha);
  sv::checkColour("diffuse", material.diffuse, 1.0);
  sv::checkColour("specular", material.specular, 1.0);
}

double blinnPhongExponent(const BlinnPhongAnisoMaterial& material, const glm::dvec3& h)
{
  const double ex = 1.0 / (material.alphaX * material.alphaX);
  const double ey = 1.0 / (material.alphaY * material.alphaY);
  return sv::azimuthalBlend(ex, ey, h.x, h.y);
}

double blinnPhongExponent(const ScaledTangents& scaled, const glm::dvec3& n, const glm::dvec3& h)
{
  const double a = glm::dot(h, scaled.tScaled);
  const double b = glm::dot(h, scaled.bScaled);
  const double c = glm::dot(h, n);
  const double sin2 = std::max(1.0 - c * c, 0.0);
  if (!(sin2 > 0.0))
    return 0.5 *
           (glm::dot(scaled.tScaled, scaled.tScaled) + glm::dot(scaled.bScaled, scaled.bScaled));
  return (a * a + b * b) / sin2;
}

double blinnPhongDistribution(const BlinnPhongAnisoMaterial& material, const glm::dvec3& h)
{
  if (!(h.z > 0.0))
    return 0.0;
  const double ex = 1.0 / (material.alphaX * material.alphaX);
  const double ey = 1.0 / (material.alphaY * material.alphaY);
  const double norm = std::sqrt((ex + 2.0) * (ey + 2.0)) / (2.0 * sv::kPi);
  // (n.h)^e as exp(e ln(n.h)): exact at the pole for any exponent, no pow(0, 0).
  return norm * std::exp(blinnPhongExponent(material, h) * sv::logCosTheta(h));
}

glm::dvec3 evalBlinnPhongAniso(const BlinnPhongAnisoMaterial& material, const glm::dvec3& v,
                               const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return glm::dvec3(0.0);
  const glm::dvec3 h = sv::normalizeScaled(v + l);
  return material.diffuse / sv::kPi +
         material.specular * (0.25 * blinnPhongDistribution(material, h));
}

glm::dvec3 shadeBlinnPhongAniso(const BlinnPhongAnisoMaterial& material, const Frame& frame,
                                const glm::dvec3& position, const glm::dvec3& viewWorld,
                                const std::vector<Light>& lights)
{
  return shadeBrdfWithLights(lights, frame, position, viewWorld,
                             [&](const glm::dvec3& v, const glm::dvec3& l)
                             { return evalBlinnPhongAniso(material, v, l); });
}
} // namespace aniso
