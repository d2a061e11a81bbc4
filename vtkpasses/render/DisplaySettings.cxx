#include "vtkpasses/render/DisplaySettings.h"

#include "aniso_shaders.h"
#include "core/parameters/parameters.h"

#include <cmath>
#include <sstream>

namespace aniso
{
DisplaySettings displayFromParameters(const ParameterSet& parameters)
{
  DisplaySettings d;
  d.exposureEV = parameters.real("exposure");
  d.toneMapping = parseToneMapping(parameters.text("tone-mapping"));
  d.background = parseBackgroundMode(parameters.text("background"));
  d.backgroundColor = parameters.color("background-color");
  d.legend = parseOnOff("legend", parameters.text("legend")) == OnOff::On;
  return d;
}

std::string toneMappingDefines(const DisplaySettings& display)
{
  switch (display.toneMapping)
  {
  case ToneMapping::Aces:
    return "#define ANISO_TONE_MAP_ACES\n";
  case ToneMapping::Reinhard:
    return "#define ANISO_TONE_MAP_REINHARD\n";
  case ToneMapping::Clamp:
    break;
  }
  return {};
}

std::vector<std::pair<std::string, std::string>>
displayInFragmentCode(const DisplaySettings& display)
{
  std::ostringstream impl;
  impl.precision(9);
  impl << "gl_FragData[0].rgb = encodeSrgb(toneMap(max(gl_FragData[0].rgb, vec3(0.0)) * "
       << std::exp2(display.exposureEV) << "));\n";
  return {{"//VTK::Output::Dec", toneMappingDefines(display) + shaders::kDisplayTransform},
          {"//VTK::TCoord::Impl", impl.str()}};
}
} // namespace aniso
