#include "vtkpasses/render/DisplaySettings.h"

#include "core/parameters/parameters.h"

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
} // namespace aniso
