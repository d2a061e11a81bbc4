// The colour maps of core/fields/color_map.h against VTK, which ParaView draws them with:
//  - each map matches a vtkColorTransferFunction holding the preset's points, rescaled to
//    [0, 1] as ParaView rescales a preset to a range, in the colour space ParaView 5.11's
//    ColorMaps.json names (written out here, so that a preset given the wrong space fails), at
//    1001 values of t and at every control point: to 1e-6 between the points, to 2e-4 at them
//    (where the map gives the point's colour and VTK its round trip through L*a*b*);
//  - the NaN colours are the JSON's (and, for Cividis, which has none, the default of
//    vtkColorTransferFunction), and a NaN t gives them;
//  - the middle of Cool to Warm is its grey control point, (0.865, 0.865, 0.865);
//  - t outside [0, 1] gives the end colours;
//  - the linear table is srgbToLinear of the map's colours at i / (count - 1);
//  - srgbToLinear and linearToSrgb are each other's inverse, with the standard's values.
#include "core/error.h"
#include "core/fields/color_map.h"
#include "core/fields/color_map_data.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>
#include <vector>
#include <vtkColorTransferFunction.h>
#include <vtkNew.h>

namespace aniso
{
namespace
{
struct Expected
{
  ColorMap map;
  const char* name;
  ColorMapSpace space; // ColorMaps.json's "ColorSpace"
  glm::dvec3 nanColor; // ColorMaps.json's "NanColor"; Cividis: vtkColorTransferFunction's default
};

const Expected kExpected[] = {
    {ColorMap::Viridis, "Viridis (matplotlib)", ColorMapSpace::Diverging, {1.0, 0.0, 0.0}},
    {ColorMap::Cividis, "Cividis", ColorMapSpace::Lab, {0.5, 0.0, 0.0}},
    {ColorMap::CoolToWarm, "Cool to Warm", ColorMapSpace::Diverging, {1.0, 1.0, 0.0}},
    {ColorMap::Grayscale, "Grayscale", ColorMapSpace::Rgb, {1.0, 0.0, 0.0}},
};

// The preset as ParaView applies it to the range [0, 1]: its points' x rescaled.
void fillTransferFunction(const Expected& expected, vtkColorTransferFunction* ctf)
{
  const ColorMapPreset& preset = colorMapPreset(expected.map);
  const double* p = preset.rgbPoints;
  const double first = p[0];
  const double last = p[4 * (preset.pointCount - 1)];
  for (int i = 0; i < preset.pointCount; ++i)
  {
    const double* q = p + 4 * i;
    ctf->AddRGBPoint((q[0] - first) / (last - first), q[1], q[2], q[3]);
  }
  switch (expected.space)
  {
  case ColorMapSpace::Rgb:
    ctf->SetColorSpaceToRGB();
    break;
  case ColorMapSpace::Lab:
    ctf->SetColorSpaceToLab();
    break;
  case ColorMapSpace::Diverging:
    ctf->SetColorSpaceToDiverging();
    break;
  }
}

double largestDifference(const glm::dvec3& a, const double b[3])
{
  return std::max({std::abs(a.x - b[0]), std::abs(a.y - b[1]), std::abs(a.z - b[2])});
}

TEST(ColorMap, MatchesVtkColorTransferFunction)
{
  // At a control point other than the first, VTK interpolates to the end of the segment before
  // it, through L*a*b* for Lab and Diverging: its 4-digit RGB-to-XYZ matrix and the inverse one
  // are not exact inverses, so it lands up to about 1.3e-4 from the point's colour, which the map
  // gives as it is. Between the points the two agree to rounding error.
  constexpr double kBetweenPoints = 1e-6;
  constexpr double kAtPoints = 2e-4;
  for (const Expected& expected : kExpected)
  {
    SCOPED_TRACE(expected.name);
    vtkNew<vtkColorTransferFunction> ctf;
    fillTransferFunction(expected, ctf);
    ASSERT_EQ(ctf->GetSize(), colorMapPreset(expected.map).pointCount);

    std::vector<double> points;
    for (int i = 0; i < ctf->GetSize(); ++i)
    {
      double node[6];
      ctf->GetNodeValue(i, node);
      points.push_back(node[0]);
    }
    std::vector<double> ts = points;
    for (int i = 0; i <= 1000; ++i)
    {
      ts.push_back(i / 1000.0);
    }

    double maxBetween = 0.0;
    double maxAt = 0.0;
    for (const double t : ts)
    {
      double vtk[3];
      ctf->GetColor(t, vtk);
      const glm::dvec3 ours = colorMapColor(expected.map, t);
      const double difference = largestDifference(ours, vtk);
      const bool atPoint = std::find(points.begin(), points.end(), t) != points.end();
      EXPECT_LE(difference, atPoint ? kAtPoints : kBetweenPoints)
          << "t = " << t << ": (" << ours.x << ", " << ours.y << ", " << ours.z
          << ") against VTK's (" << vtk[0] << ", " << vtk[1] << ", " << vtk[2] << ")";
      double& largest = atPoint ? maxAt : maxBetween;
      largest = std::max(largest, difference);
    }
    std::cout << expected.name << ": largest difference from vtkColorTransferFunction "
              << maxBetween << " between the control points, " << maxAt << " at them\n";
  }
}

TEST(ColorMap, PresetNamesAndNanColors)
{
  vtkNew<vtkColorTransferFunction> fresh;
  double vtkDefaultNan[3];
  fresh->GetNanColor(vtkDefaultNan);
  for (const Expected& expected : kExpected)
  {
    SCOPED_TRACE(expected.name);
    EXPECT_EQ(colorMapPresetName(expected.map), expected.name);
    EXPECT_EQ(colorMapNanColor(expected.map), expected.nanColor);
    EXPECT_EQ(colorMapColor(expected.map, std::numeric_limits<double>::quiet_NaN()),
              expected.nanColor);
  }
  // Cividis' NaN colour is VTK's default, as ParaView leaves it.
  EXPECT_EQ(colorMapNanColor(ColorMap::Cividis),
            glm::dvec3(vtkDefaultNan[0], vtkDefaultNan[1], vtkDefaultNan[2]));
}

TEST(ColorMap, CoolToWarmMiddleIsItsGrey)
{
  const glm::dvec3 middle = colorMapColor(ColorMap::CoolToWarm, 0.5);
  EXPECT_NEAR(middle.x, 0.865, 1e-12);
  EXPECT_NEAR(middle.y, 0.865, 1e-12);
  EXPECT_NEAR(middle.z, 0.865, 1e-12);
}

TEST(ColorMap, ClampsOutsideUnitInterval)
{
  for (const Expected& expected : kExpected)
  {
    SCOPED_TRACE(expected.name);
    const ColorMapPreset& preset = colorMapPreset(expected.map);
    const double* firstPoint = preset.rgbPoints;
    const double* lastPoint = preset.rgbPoints + 4 * (preset.pointCount - 1);
    const glm::dvec3 first{firstPoint[1], firstPoint[2], firstPoint[3]};
    const glm::dvec3 last{lastPoint[1], lastPoint[2], lastPoint[3]};
    EXPECT_EQ(colorMapColor(expected.map, 0.0), first);
    EXPECT_EQ(colorMapColor(expected.map, -0.25), first);
    EXPECT_EQ(colorMapColor(expected.map, -std::numeric_limits<double>::infinity()), first);
    EXPECT_EQ(colorMapColor(expected.map, 1.0), last);
    EXPECT_EQ(colorMapColor(expected.map, 1.75), last);
    EXPECT_EQ(colorMapColor(expected.map, std::numeric_limits<double>::infinity()), last);
  }
}

TEST(ColorMap, LinearTableDecodesTheColors)
{
  constexpr int kCount = 256;
  for (const Expected& expected : kExpected)
  {
    SCOPED_TRACE(expected.name);
    const std::vector<float> table = colorMapTableLinear(expected.map, kCount);
    ASSERT_EQ(table.size(), std::size_t{3 * kCount});
    for (int i = 0; i < kCount; ++i)
    {
      const glm::dvec3 c = colorMapColor(expected.map, i / 255.0);
      EXPECT_EQ(table[3 * i + 0], static_cast<float>(srgbToLinear(c.x))) << "entry " << i;
      EXPECT_EQ(table[3 * i + 1], static_cast<float>(srgbToLinear(c.y))) << "entry " << i;
      EXPECT_EQ(table[3 * i + 2], static_cast<float>(srgbToLinear(c.z))) << "entry " << i;
    }
  }
  EXPECT_THROW(colorMapTableLinear(ColorMap::Viridis, 1), Error);
}

TEST(ColorMap, SrgbTransferFunctions)
{
  // IEC 61966-2-1's values: the ends, the linear segment, and mid-grey.
  EXPECT_EQ(srgbToLinear(0.0), 0.0);
  EXPECT_NEAR(srgbToLinear(1.0), 1.0, 1e-15);
  EXPECT_NEAR(srgbToLinear(0.02), 0.02 / 12.92, 1e-17);
  EXPECT_NEAR(srgbToLinear(0.5), 0.21404114048223255, 1e-15);
  EXPECT_NEAR(linearToSrgb(0.001), 0.01292, 1e-17);
  EXPECT_NEAR(linearToSrgb(0.21404114048223255), 0.5, 1e-15);
  // Round trips over [0, 1], across both segments' joins.
  for (int i = 0; i <= 1000; ++i)
  {
    const double c = i / 1000.0;
    EXPECT_NEAR(linearToSrgb(srgbToLinear(c)), c, 1e-12) << c;
    EXPECT_NEAR(srgbToLinear(linearToSrgb(c)), c, 1e-12) << c;
  }
}
} // namespace
} // namespace aniso
