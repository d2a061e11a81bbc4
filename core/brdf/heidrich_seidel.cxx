#include "core/brdf/heidrich_seidel.h"

#include "core/brdf/sv_common.h"

namespace aniso
{
void validateHeidrichSeidel(const HeidrichSeidelMaterial& material)
{
  sv::checkColour("diffuse", material.diffuse, 1.0);
  sv::checkColour("specular", material.specular, kFibreMaxSpecular);
  sv::checkRange("exponent", material.exponent, 0.0, kFibreMaxExponent);
}

glm::dvec3 heidrichSeidelTerm(const HeidrichSeidelMaterial& material, const glm::dvec3& v,
                              const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return glm::dvec3(0.0);
  const double cosR = fibreSpecularCosine(v, l);
  // Only V.R' > 0 lights: 0^e = 0 for every e > 0, and the limit keeps it so at e = 0.
  const double specular = cosR > 0.0 ? std::pow(cosR, material.exponent) : 0.0;
  return material.diffuse * (l.z / sv::kPi) + material.specular * specular;
}

glm::dvec3 evalHeidrichSeidel(const HeidrichSeidelMaterial& material, const glm::dvec3& v,
                              const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return glm::dvec3(0.0);
  // The floor keeps k_s / (n.l) finite at grazing light (k_s <= 1e3).
  return heidrichSeidelTerm(material, v, l) / std::max(l.z, 1e-300);
}

glm::dvec3 shadeHeidrichSeidel(const HeidrichSeidelMaterial& material, const Frame& frame,
                               const glm::dvec3& position, const glm::dvec3& viewWorld,
                               const std::vector<Light>& lights)
{
  return sumOverLights(lights, frame, position, viewWorld,
                       [&](const glm::dvec3& v, const glm::dvec3& l)
                       { return heidrichSeidelTerm(material, v, l); });
}
} // namespace aniso
