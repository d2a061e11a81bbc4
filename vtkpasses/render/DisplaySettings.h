#pragma once
// How accumulated linear radiance is shown: exposure, tone mapping and sRGB encoding for the
// screen and PNG files, and what lies behind the surfaces. EXR output bypasses all but the
// background.
#include <glm/vec3.hpp>

namespace aniso
{
class ParameterSet;

enum class ToneMapping
{
  Aces,     // Narkowicz's fit of the ACES filmic curve: x(2.51x+0.03) / (x(2.43x+0.59)+0.14)
  Reinhard, // x / (1 + x)
  Clamp,    // min(x, 1): no compression, exact up to 1
};

enum class BackgroundMode
{
  Environment, // the environment seen along each view ray (a skybox)
  Color,       // a uniform linear radiance (backgroundColor)
  Transparent, // nothing: PNG alpha is the coverage of the surfaces
};

struct DisplaySettings
{
  double exposureEV = 0.0; // radiance is multiplied by 2^EV before tone mapping
  ToneMapping toneMapping = ToneMapping::Aces;
  BackgroundMode background = BackgroundMode::Environment;
  glm::dvec3 backgroundColor{0.18, 0.18, 0.18}; // linear radiance, seen through the transform

  bool operator==(const DisplaySettings& o) const
  {
    return exposureEV == o.exposureEV && toneMapping == o.toneMapping &&
           background == o.background && backgroundColor == o.backgroundColor;
  }
  bool operator!=(const DisplaySettings& o) const { return !(*this == o); }
};
// From the declared parameters (core/parameters/parameters.h): exposure, tone-mapping,
// background, background-color.
DisplaySettings displayFromParameters(const ParameterSet& parameters);
} // namespace aniso
