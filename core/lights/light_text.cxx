#include "core/lights/light_text.h"

#include "core/env/env_source_text.h"

#include <cstdio>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
std::string printed(const char* format, double value)
{
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string intensityText(const glm::dvec3& i)
{
  if (i.x == i.y && i.y == i.z)
  {
    return printed("%.3g", i.x);
  }
  return printed("%.3g", i.x) + ", " + printed("%.3g", i.y) + ", " + printed("%.3g", i.z);
}
} // namespace

std::string lightText(const Light& light)
{
  const SkyAngles angles = skyAnglesOf(light.vector);
  const std::string where = "azimuth " + printed("%.1f", angles.azimuthDegrees) + ", elevation " +
                            printed("%.1f", angles.elevationDegrees);
  if (light.type == LightType::Directional)
  {
    return "directional from " + where + ", intensity " + intensityText(light.intensity);
  }
  return "point at " + where + ", distance " + printed("%.3g", glm::length(light.vector)) +
         ", intensity " + intensityText(light.intensity);
}
} // namespace aniso
