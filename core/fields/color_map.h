#pragma once
// Colour maps of a data field, as ParaView 5.11 defines its presets of the same names
// (Remoting/Views/ColorMaps.json): control points in sRGB display values, interpolated as
// vtkColorTransferFunction does in the preset's colour space (RGB, CIE L*a*b* or Moreland's
// diverging Msh space), and the preset's colour for NaN. GL-free and VTK-free; tests compare
// with vtkColorTransferFunction.
#include <glm/vec3.hpp>
#include <string_view>
#include <vector>

namespace aniso
{
// "field-colormap"
enum class ColorMap
{
  Viridis,    // "Viridis (matplotlib)": 256 points, diverging interpolation, NaN red
  Cividis,    // "Cividis": 256 points, L*a*b* interpolation, NaN vtkColorTransferFunction's
              // default (0.5, 0, 0)
  CoolToWarm, // "Cool to Warm": 3 points, diverging interpolation (Moreland 2009), NaN yellow
  Grayscale,  // "Grayscale": black to white in RGB, NaN red
};

// ParaView's name of MAP's preset ("Viridis (matplotlib)").
std::string_view colorMapPresetName(ColorMap map);

// The colour of MAP at t (clamped to [0, 1]): sRGB display values in [0, 1]. A NaN t gives the
// preset's NaN colour.
glm::dvec3 colorMapColor(ColorMap map, double t);
glm::dvec3 colorMapNanColor(ColorMap map);

// MAP sampled at t = i / (count - 1), i = 0 .. count - 1, count >= 2, as linear RGB (the sRGB
// colours decoded): count * 3 floats, for a texture that interpolates them linearly.
std::vector<float> colorMapTableLinear(ColorMap map, int count);

// The sRGB transfer function and its inverse, per component (IEC 61966-2-1).
double srgbToLinear(double c);
double linearToSrgb(double c);
} // namespace aniso
