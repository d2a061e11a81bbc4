#include "vtkpasses/render/DisplaySettings.h"

#include "core/parameters/parameters.h"

namespace aniso
{
DisplaySettings displayFromParameters(const ParameterSet& parameters)
{
  DisplaySettings d;
  d.exposureEV = parameters.real("exposure");
  const std::string& tone = parameters.text("tone-mapping");
  d.toneMapping = tone == "reinhard" ? ToneMapping::Reinhard
                  : tone == "clamp"  ? ToneMapping::Clamp
                                     : ToneMapping::Aces;
  const std::string& background = parameters.text("background");
  d.background = background == "none"    ? BackgroundMode::Transparent
                 : background == "color" ? BackgroundMode::Color
                                         : BackgroundMode::Environment;
  d.backgroundColor = parameters.color("background-color");
  return d;
}
} // namespace aniso
