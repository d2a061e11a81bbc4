#include "core/brdf/banks.h"

#include "core/brdf/sv_common.h"

namespace aniso
{
void validateBanks(const BanksMaterial& material)
{
  sv::checkColour("diffuse", material.diffuse, 1.0);
  sv::checkColour("specular", material.specular, kFibreMaxSpecular);
  sv::checkRange("exponent", material.exponent, 0.0, kFibreMaxExponent);
}

double fibreDiffuseCosine(const glm::dvec3& l)
{
  return std::sqrt(std::max(1.0 - l.x * l.x, 0.0));
}

double fibreSpecularCosine(const glm::dvec3& v, const glm::dvec3& l)
{
  const double value = fibreDiffuseCosine(l) * fibreDiffuseCosine(v) - l.x * v.x;
  return std::min(std::max(value, -1.0), 1.0);
}

glm::dvec3 evalBanks(const BanksMaterial& material, const glm::dvec3& v, const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return glm::dvec3(0.0);
  const double cosR = fibreSpecularCosine(v, l);
  // Only V.R' > 0 lights: 0^e = 0 for every e > 0, and the limit keeps it so at e = 0.
  const double specular = cosR > 0.0 ? std::pow(cosR, material.exponent) : 0.0;
  return material.diffuse * (fibreDiffuseCosine(l) / sv::kPi) + material.specular * specular;
}

glm::dvec3 shadeBanks(const BanksMaterial& material, const Frame& frame, const glm::dvec3& position,
                      const glm::dvec3& viewWorld, const std::vector<Light>& lights)
{
  return shadeBrdfWithLights(lights, frame, position, viewWorld,
                             [&](const glm::dvec3& v, const glm::dvec3& l)
                             { return evalBanks(material, v, l); });
}
} // namespace aniso
