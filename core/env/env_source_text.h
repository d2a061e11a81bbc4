#pragma once
// The environment analysis (env_sources.h) in words and angles, as the environment dock's table
// and `aniso render`'s log show it: one spelling for both.
#include "core/env/env_sources.h"

#include <glm/vec3.hpp>
#include <string>

namespace aniso
{
// A direction's azimuth and elevation in degrees, in the convention of `aniso render`'s
// --azimuth and --elevation (viewDirectionFromAngles): azimuth 0 towards -Y, growing
// counter-clockwise seen from above (90 towards +X), in [0, 360); elevation above the XY plane,
// in [-90, 90]. d need not be unit length; the zero vector gives (0, 0). d is in the
// environment's coordinates; ROTATION_DEGREES is the environment's rotation about the world's Z
// axis (the env-rotation parameter, counter-clockwise seen from above), so the angles are the
// world's: the azimuth grows by it.
struct SkyAngles
{
  double azimuthDegrees = 0.0;
  double elevationDegrees = 0.0;
};
SkyAngles skyAnglesOf(const glm::dvec3& d, double rotationDegrees = 0.0);

// The apex angle (degrees) of the cone of this solid angle (steradians): 2 acos(1 - omega / 2 pi),
// omega clamped to [0, 4 pi]. A sun of radius 0.00465 rad gives 0.533 degrees.
double equivalentDiameterDegrees(double solidAngle);

// A share in [0, 1] as a percentage: "86%" from 10% up, "4.2%" below, "<0.1%" for less than
// 0.05%.
std::string percentText(double share);

// "sun at azimuth 26.6, elevation 47.8 (6.8e-05 sr, 99%)", the angles the world's under an
// environment rotated by ROTATION_DEGREES (skyAnglesOf).
std::string sourceText(const EnvSource& source, double rotationDegrees = 0.0);

// "3 sources carry 92% of the power; concentration 0.87", "1 source carries ...", or
// "no concentrated sources; concentration 0.01" when none is listed.
std::string analysisSummary(const EnvAnalysis& analysis);
} // namespace aniso
