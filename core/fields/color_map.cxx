#include "core/fields/color_map.h"

#include "core/error.h"
#include "core/fields/color_map_data.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

// The constants below are vtkMath's (VTK 9.1: RGBToXYZ, XYZToLab, LabToXYZ, XYZToRGB), rounded
// as VTK rounds them, so that the maps agree with vtkColorTransferFunction to rounding error
// rather than to the fourth digit.

// D65 white (2 degree observer).
constexpr glm::dvec3 kWhite{0.9505, 1.0, 1.089};
// Where CIE L*a*b*'s cube root gives way to its linear segment, and that segment's slope.
constexpr double kLabEpsilon = 0.008856;
constexpr double kLabSlope = 7.787;
constexpr double kLabOffset = 16.0 / 116.0;

glm::dvec3 linearRgbToXyz(const glm::dvec3& c)
{
  return {c.x * 0.4124 + c.y * 0.3576 + c.z * 0.1805, c.x * 0.2126 + c.y * 0.7152 + c.z * 0.0722,
          c.x * 0.0193 + c.y * 0.1192 + c.z * 0.9505};
}

glm::dvec3 xyzToLinearRgb(const glm::dvec3& c)
{
  return {c.x * 3.2406 + c.y * -1.5372 + c.z * -0.4986, c.x * -0.9689 + c.y * 1.8758 + c.z * 0.0415,
          c.x * 0.0557 + c.y * -0.2040 + c.z * 1.0570};
}

double labF(double v)
{
  return v > kLabEpsilon ? std::pow(v, 1.0 / 3.0) : kLabSlope * v + kLabOffset;
}

// The inverse of labF; like VTK, it tests the cube of v against the threshold.
double labFInverse(double v)
{
  const double cube = std::pow(v, 3);
  return cube > kLabEpsilon ? cube : (v - kLabOffset) / kLabSlope;
}

glm::dvec3 srgbToLab(const glm::dvec3& srgb)
{
  const glm::dvec3 xyz =
      linearRgbToXyz({srgbToLinear(srgb.x), srgbToLinear(srgb.y), srgbToLinear(srgb.z)});
  const double fx = labF(xyz.x / kWhite.x);
  const double fy = labF(xyz.y / kWhite.y);
  const double fz = labF(xyz.z / kWhite.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// Out-of-gamut colours are clipped as vtkMath::XYZToRGB clips them: all three scaled down
// together when one exceeds 1 (the hue kept), then negative ones raised to 0.
glm::dvec3 labToSrgb(const glm::dvec3& lab)
{
  const double fy = (lab.x + 16.0) / 116.0;
  const double fx = lab.y / 500.0 + fy;
  const double fz = fy - lab.z / 200.0;
  const glm::dvec3 xyz{kWhite.x * labFInverse(fx), kWhite.y * labFInverse(fy),
                       kWhite.z * labFInverse(fz)};
  const glm::dvec3 linear = xyzToLinearRgb(xyz);
  glm::dvec3 srgb{linearToSrgb(linear.x), linearToSrgb(linear.y), linearToSrgb(linear.z)};
  const double largest = std::max({srgb.x, srgb.y, srgb.z});
  if (largest > 1.0)
  {
    srgb /= largest;
  }
  return {std::max(srgb.x, 0.0), std::max(srgb.y, 0.0), std::max(srgb.z, 0.0)};
}

glm::dvec3 lerp(const glm::dvec3& a, const glm::dvec3& b, double s)
{
  // (1 - s) a + s b, the form vtkColorTransferFunction uses, is exact at s = 0 and s = 1.
  return (1.0 - s) * a + s * b;
}

// Moreland's polar form of L*a*b*: magnitude M, saturation s (angle from the L axis), hue h.
glm::dvec3 labToMsh(const glm::dvec3& lab)
{
  const double m = std::sqrt(lab.x * lab.x + lab.y * lab.y + lab.z * lab.z);
  const double s = m > 0.001 ? std::acos(lab.x / m) : 0.0;
  const double h = s > 0.001 ? std::atan2(lab.z, lab.y) : 0.0;
  return {m, s, h};
}

glm::dvec3 mshToLab(const glm::dvec3& msh)
{
  return {msh.x * std::cos(msh.y), msh.x * std::sin(msh.y) * std::cos(msh.z),
          msh.x * std::sin(msh.y) * std::sin(msh.z)};
}

// The smaller angle between two hues, in [0, pi].
double hueDistance(double h1, double h2)
{
  double d = std::abs(h1 - h2);
  while (d >= 2.0 * kPi)
  {
    d -= 2.0 * kPi;
  }
  return d > kPi ? 2.0 * kPi - d : d;
}

// A hue for an unsaturated end of magnitude unsaturatedM, interpolated towards the saturated
// colour msh: spun away from msh's hue so that the perceived change stays about even along the
// segment (Moreland 2009), away from 0 but for purples.
double spunHue(const glm::dvec3& msh, double unsaturatedM)
{
  if (msh.x >= unsaturatedM - 0.1)
  {
    return msh.z;
  }
  const double spin =
      msh.y * std::sqrt(unsaturatedM * unsaturatedM - msh.x * msh.x) / (msh.x * std::sin(msh.y));
  return msh.z > -0.3 * kPi ? msh.z + spin : msh.z - spin;
}

// vtkColorTransferFunction's diverging interpolation (Moreland 2009) between the sRGB colours
// a and b at s in [0, 1].
glm::dvec3 interpolateDiverging(const glm::dvec3& a, const glm::dvec3& b, double s)
{
  constexpr double kSaturated = 0.05;
  glm::dvec3 msh1 = labToMsh(srgbToLab(a));
  glm::dvec3 msh2 = labToMsh(srgbToLab(b));
  // Two distinct saturated ends pass through an unsaturated white between them: each half
  // interpolates from one end to that white. VTK's test is 0.33 pi, not pi / 3.
  if (msh1.y > kSaturated && msh2.y > kSaturated && hueDistance(msh1.z, msh2.z) > 0.33 * kPi)
  {
    const double whiteM = std::max({msh1.x, msh2.x, 88.0});
    if (s < 0.5)
    {
      msh2 = {whiteM, 0.0, 0.0};
      s = 2.0 * s;
    }
    else
    {
      msh1 = {whiteM, 0.0, 0.0};
      s = 2.0 * s - 1.0;
    }
  }
  // An unsaturated end has no meaningful hue: give it one that suits the saturated end.
  if (msh1.y < kSaturated && msh2.y > kSaturated)
  {
    msh1.z = spunHue(msh2, msh1.x);
  }
  else if (msh2.y < kSaturated && msh1.y > kSaturated)
  {
    msh2.z = spunHue(msh1, msh2.x);
  }
  // The hue is interpolated as it stands, not the short way round, as VTK does: where it crosses
  // +-pi within a segment the colour swings through the opposite hues (Viridis between 0.545098
  // and 0.54902 passes through pink, up to 0.67 from its L*a*b* interpolation), in ParaView too.
  return labToSrgb(mshToLab(lerp(msh1, msh2, s)));
}

glm::dvec3 pointColor(const ColorMapPreset& preset, int i)
{
  const double* p = preset.rgbPoints + 4 * i;
  return {p[1], p[2], p[3]};
}

double pointX(const ColorMapPreset& preset, int i)
{
  return preset.rgbPoints[4 * i];
}
} // namespace

std::string_view colorMapPresetName(ColorMap map)
{
  return colorMapPreset(map).name;
}

glm::dvec3 colorMapNanColor(ColorMap map)
{
  return colorMapPreset(map).nanColor;
}

glm::dvec3 colorMapColor(ColorMap map, double t)
{
  const ColorMapPreset& preset = colorMapPreset(map);
  if (std::isnan(t))
  {
    return preset.nanColor;
  }
  t = std::clamp(t, 0.0, 1.0);
  const double first = pointX(preset, 0);
  const double last = pointX(preset, preset.pointCount - 1);
  // t = 1 lands exactly on the last point (first + (last - first) is exact for 0 .. 1, 0 .. 255).
  const double x = first + t * (last - first);

  // The first point at or after x; vtkColorTransferFunction searches the same way.
  int i = 0;
  while (i < preset.pointCount - 1 && x > pointX(preset, i))
  {
    ++i;
  }
  // At a point its own colour. VTK gives the first point's colour, but at the others the end of
  // the segment before, which for Lab and Diverging is the colour after a round trip through
  // L*a*b* (vtkMath's 4-digit matrices are not exact inverses): up to 1.3e-4 away.
  if (x == pointX(preset, i) || i == 0)
  {
    return pointColor(preset, i);
  }
  const double x1 = pointX(preset, i - 1);
  const double s = (x - x1) / (pointX(preset, i) - x1);
  const glm::dvec3 c1 = pointColor(preset, i - 1);
  const glm::dvec3 c2 = pointColor(preset, i);
  switch (preset.space)
  {
  case ColorMapSpace::Rgb:
    return lerp(c1, c2, s);
  case ColorMapSpace::Lab:
    return labToSrgb(lerp(srgbToLab(c1), srgbToLab(c2), s));
  case ColorMapSpace::Diverging:
    return interpolateDiverging(c1, c2, s);
  }
  return preset.nanColor;
}

std::vector<float> colorMapTableLinear(ColorMap map, int count)
{
  if (count < 2)
  {
    throw errorAbout("colour map table", "needs at least 2 entries, not " + std::to_string(count));
  }
  std::vector<float> table;
  table.reserve(static_cast<std::size_t>(count) * 3);
  for (int i = 0; i < count; ++i)
  {
    const glm::dvec3 c = colorMapColor(map, static_cast<double>(i) / (count - 1));
    table.push_back(static_cast<float>(srgbToLinear(c.x)));
    table.push_back(static_cast<float>(srgbToLinear(c.y)));
    table.push_back(static_cast<float>(srgbToLinear(c.z)));
  }
  return table;
}

double srgbToLinear(double c)
{
  return c > 0.04045 ? std::pow((c + 0.055) / 1.055, 2.4) : c / 12.92;
}

double linearToSrgb(double c)
{
  return c > 0.0031308 ? 1.055 * std::pow(c, 1.0 / 2.4) - 0.055 : 12.92 * c;
}
} // namespace aniso
