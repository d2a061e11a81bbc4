#pragma once
// The presets behind core/fields/color_map.h as ParaView 5.11's ColorMaps.json writes them
// (color_map_data.cxx): internal to core/fields, and read by the tests that rebuild each preset
// in vtkColorTransferFunction.
#include "core/fields/color_map.h"

#include <glm/vec3.hpp>
#include <string_view>

namespace aniso
{
// The space vtkColorTransferFunction interpolates a preset's colours in (its "ColorSpace").
enum class ColorMapSpace
{
  Rgb,
  Lab,
  Diverging,
};

struct ColorMapPreset
{
  std::string_view name; // ParaView's "Name"
  ColorMapSpace space;
  glm::dvec3 nanColor;
  // "RGBPoints": x, r, g, b per point, x strictly ascending, r, g, b sRGB values in [0, 1].
  // x spans the file's range (0 .. 255 for Cividis, 0 .. 1 for the others): a map's t in
  // [0, 1] covers the first point's x to the last's, as ParaView rescales a preset to a range.
  const double* rgbPoints;
  int pointCount;
};

const ColorMapPreset& colorMapPreset(ColorMap map);
} // namespace aniso
