#include "core/env/sun_sky.h"

#include "core/error.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

void checkRadiance(const char* name, const glm::dvec3& value)
{
  for (int c = 0; c < 3; ++c)
    if (!(value[c] >= 0.0) || !std::isfinite(value[c]))
      throw errorAbout(name, "must be finite and >= 0 per channel");
}
} // namespace

SunSkyEnvironment::SunSkyEnvironment(const glm::dvec3& sunDirection, double sunAngularRadius,
                                     const glm::dvec3& sunRadiance, const glm::dvec3& skyRadiance)
{
  const double length = glm::length(sunDirection);
  if (!std::isfinite(length) || !(length > 0.0))
    throw errorAbout("sun direction", "must be a finite non-zero vector");
  if (!(sunAngularRadius > 0.0 && sunAngularRadius <= 0.5 * kPi))
    throw errorAbout("sun radius", "must be in (0, pi/2] radians");
  checkRadiance("sun radiance", sunRadiance);
  checkRadiance("sky radiance", skyRadiance);
  sun_.direction = sunDirection / length;
  sun_.angularRadius = sunAngularRadius;
  sun_.radiance = sunRadiance;
  sky_ = skyRadiance;
  cosRadius_ = std::cos(sunAngularRadius);
  std::ostringstream key;
  key.precision(17);
  key << "builtin:sunsky:" << sun_.direction.x << ',' << sun_.direction.y << ',' << sun_.direction.z
      << ':' << sunAngularRadius << ':' << sunRadiance.x << ',' << sunRadiance.y << ','
      << sunRadiance.z << ':' << sky_.x << ',' << sky_.y << ',' << sky_.z;
  key_ = key.str();
}

glm::dvec3 SunSkyEnvironment::radiance(const glm::dvec3& d) const
{
  // d need not be exactly unit: compare the cosine of the angle, not d.sun alone.
  const double length = glm::length(d);
  if (length > 0.0 && glm::dot(d, sun_.direction) >= cosRadius_ * length)
    return sky_ + sun_.radiance;
  return sky_;
}

double SunSkyEnvironment::sunSolidAngle() const
{
  // 1 - cos r = 2 sin^2(r / 2), exact for tiny discs.
  const double s = std::sin(0.5 * sun_.angularRadius);
  return 4.0 * kPi * s * s;
}
} // namespace aniso
