#pragma once
// A test environment for variance measurements: a small, very bright disc (a sun of radiance
// ~1e5) over a uniform sky (1, or black), analytic so the reference integrator can integrate it
// exactly. Real HDRIs hold such sources; sampling only the BRDF lobe leaves rough materials
// noisy next to them.
#include "core/env/environment.h"

#include <glm/vec3.hpp>
#include <string>

namespace aniso
{
// Radiance `radiance` inside the cone of half-angle angularRadius around direction (unit),
// zero outside; the edge is hard, as a real sun's.
struct DiscSource
{
  glm::dvec3 direction{0.0, 0.0, 1.0};
  double angularRadius = 0.0;
  glm::dvec3 radiance{0.0};
};

class SunSkyEnvironment : public Environment
{
public:
  // The sun's apparent radius, about 0.27 degrees.
  static constexpr double kSunAngularRadius = 0.00465;

  // Throws aniso::Error: "sun direction: ..." unless finite and non-zero (it is normalised),
  // "sun radius: ..." unless in (0, pi / 2], "sun radiance: ..." / "sky radiance: ..." unless
  // finite and >= 0 per channel.
  SunSkyEnvironment(const glm::dvec3& sunDirection, double sunAngularRadius,
                    const glm::dvec3& sunRadiance, const glm::dvec3& skyRadiance);

  // sky + sun inside the disc (the sky continues behind the sun).
  glm::dvec3 radiance(const glm::dvec3& d) const override;
  // "builtin:sunsky:" followed by every parameter at full precision.
  std::string key() const override { return key_; }

  const DiscSource& sun() const { return sun_; }
  const glm::dvec3& sky() const { return sky_; }
  // Solid angle of the disc: 2 pi (1 - cos r).
  double sunSolidAngle() const;

private:
  DiscSource sun_;
  glm::dvec3 sky_;
  double cosRadius_ = 1.0;
  std::string key_;
};
} // namespace aniso
