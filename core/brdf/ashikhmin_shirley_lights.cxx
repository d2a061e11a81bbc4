#include "core/brdf/ashikhmin_shirley_lights.h"

#include "core/brdf/sv_common.h"

namespace aniso
{
namespace
{
// 1 - (1 - c/2)^5, the Fresnel-like factor of the AS diffuse term.
double diffuseFactor(double c)
{
  const double m = 1.0 - 0.5 * c;
  const double m2 = m * m;
  return 1.0 - m2 * m2 * m;
}
} // namespace

void validateAsMaterial(const AsMaterial& material)
{
  validateLobe(material.lobe);
  sv::checkColour("F0", material.f0, 1.0);
  sv::checkColour("diffuse", material.diffuse, 1.0);
}

glm::dvec3 evalAsDiffuse(const AsMaterial& material, const glm::dvec3& v, const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return glm::dvec3(0.0);
  const double scale = 28.0 / (23.0 * sv::kPi) * diffuseFactor(l.z) * diffuseFactor(v.z);
  return material.diffuse * (glm::dvec3(1.0) - material.f0) * scale;
}

glm::dvec3 evalAshikhminShirley(const AsMaterial& material, const glm::dvec3& v,
                                const glm::dvec3& l)
{
  return evalSpecular(material.lobe, material.f0, v, l) + evalAsDiffuse(material, v, l);
}

glm::dvec3 shadeAshikhminShirley(const AsMaterial& material, const Frame& frame,
                                 const glm::dvec3& position, const glm::dvec3& viewWorld,
                                 const std::vector<Light>& lights)
{
  return shadeBrdfWithLights(lights, frame, position, viewWorld,
                             [&](const glm::dvec3& v, const glm::dvec3& l)
                             { return evalAshikhminShirley(material, v, l); });
}
} // namespace aniso
