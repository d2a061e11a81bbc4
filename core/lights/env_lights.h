#pragma once
// An environment's extracted sources (core/env/env_sources.h) as directional lights
// (core/lights/light.h), so the lit models and LEADR, which integrate lights rather than
// environments, are lit by the environment's sun, lamps and windows too.
//
// A source of excess radiance L over its texels, seen from a surface of normal n, delivers
// E(n) = integral of L(w) (n.w)+ dw. A directional light of intensity E0 from c delivers
// E0 (n.c)+. With c the source's power-weighted mean direction (EnvSource::direction), the two
// agree to first order in the source's extent for every n facing it when E0 is the irradiance
// at normal incidence, E0 = integral of L(w) (c.w) dw = power x the mean cosine of the source's
// texels about c (excess-weighted): what light.h calls a directional light's intensity. The mean
// cosine is 1 - O(r^2) (the sun's: 1 - 5e-6; a window of 0.3 rad radius: about 0.98).
#include "core/env/env_sources.h"
#include "core/lights/light.h"

#include <vector>

namespace aniso
{
struct EnvLightOptions
{
  // At most this many lights, the most powerful sources first. >= 0.
  int maxLights = 8;
  // Only sources carrying at least this share of the environment's power
  // (EnvSource::powerShare). In [0, 1].
  double minPowerShare = 0.0;
};

// The mean cosine about SOURCE's direction of the excess of ANALYSIS over the texels within
// SOURCE's angular radius (weighted by excess luminance x solid angle); 1 when there is none.
double sourceMeanCosine(const EnvAnalysis& analysis, const EnvSource& source);

// ANALYSIS' listed sources as directional lights in world coordinates for an environment turned
// by ROTATIONDEGREES about +Z (EnvironmentLighting's convention: the light arriving from world
// direction d is radiance(R_z(-angle) d), so a source at environment direction s arrives from
// R_z(+angle) s); intensity the source's irradiance at normal incidence (power x
// sourceMeanCosine). Sources of no power are skipped. Throws aniso::Error "env-lights: reason"
// for options out of range or a non-finite rotation.
std::vector<Light> environmentSourceLights(const EnvAnalysis& analysis, double rotationDegrees,
                                           const EnvLightOptions& options = {});
} // namespace aniso
