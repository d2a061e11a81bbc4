#pragma once
// A light in words, as the lights dock lists it: its type, where it comes from as azimuth and
// elevation in degrees (the convention of `aniso render`'s --azimuth and --elevation and of the
// environment's sources: core/env/env_source_text.h), and its intensity. The stored text
// (formatLight, "dir:X,Y,Z:I") stays what sessions and --light read.
#include "core/lights/light.h"

#include <string>

namespace aniso
{
// "directional from azimuth 213.7, elevation 48.0, intensity 3"
// "point at azimuth 45.0, elevation 35.3, distance 1.73, intensity 10"
// A colour intensity reads "intensity 1, 0.5, 0.25". Angles to 0.1 degree, the distance and
// intensity to 3 significant digits.
std::string lightText(const Light& light);
} // namespace aniso
