#pragma once
// How accumulated linear radiance is shown: exposure, tone mapping and sRGB encoding for the
// screen and PNG files, and what lies behind the surfaces. EXR output bypasses all but the
// background.
#include "core/parameters/choices.h" // ToneMapping, BackgroundMode

#include <glm/vec3.hpp>
#include <string>
#include <utility>
#include <vector>

namespace aniso
{
class ParameterSet;

struct DisplaySettings
{
  double exposureEV = 0.0; // radiance is multiplied by 2^EV before tone mapping
  ToneMapping toneMapping = ToneMapping::Aces;
  BackgroundMode background = BackgroundMode::Environment;
  glm::dvec3 backgroundColor{0.18, 0.18, 0.18}; // linear radiance, seen through the transform
  bool legend = true; // the colour legends of the fields shown (FieldValues.h), over the image

  bool operator==(const DisplaySettings& o) const
  {
    return exposureEV == o.exposureEV && toneMapping == o.toneMapping &&
           background == o.background && backgroundColor == o.backgroundColor && legend == o.legend;
  }
  bool operator!=(const DisplaySettings& o) const { return !(*this == o); }
};
// From the declared parameters (core/parameters/parameters.h): exposure, tone-mapping,
// background, background-color, legend.
DisplaySettings displayFromParameters(const ParameterSet& parameters);

// The GLSL defines that select DISPLAY's tone mapping in the display transform
// (shaders/display_transform.glsl).
std::string toneMappingDefines(const DisplaySettings& display);
// The display transform of DISPLAY (exposure, tone mapping, sRGB encoding) as fragment-shader
// code for a material drawn straight to the screen, where no accumulation pass displays it
// (the ParaView plugin): (tag, code inserted after it) pairs, as ShaderCode::fragment, that turn
// the fragment's linear radiance into the displayed value. The exposure is a constant of the
// code (a new exposure compiles anew). The tags are VTK's own, after the materials' code and
// apart from the ones they use: the functions after "//VTK::Output::Dec", the transform after
// "//VTK::TCoord::Impl".
std::vector<std::pair<std::string, std::string>>
displayInFragmentCode(const DisplaySettings& display);
} // namespace aniso
