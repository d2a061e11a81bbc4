// lightText: the lights dock's words for a light.
//  - A directional light built from an azimuth and elevation by the formula --azimuth and
//    --elevation use (0 towards -Y, 90 towards +X, elevation above the XY plane) reads those
//    angles back, over a grid of angles on every side.
//  - The default scene's key light "dir:-1,-1.5,2:3" (the text the dock showed before) reads
//    azimuth 326.3 (= 360 - atan(1/1.5)), elevation 48.0 (= asin(2/sqrt(7.25))), intensity 3.
//  - A point light names its distance; a colour intensity lists its channels.
#include "core/lights/light.h"
#include "core/lights/light_text.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>

namespace
{
constexpr double kPi = 3.14159265358979323846;

std::string oneDecimal(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

TEST(LightText, DirectionalReadsBackTheAnglesItWasBuiltFrom)
{
  for (double azimuth = 0.0; azimuth < 360.0; azimuth += 22.5)
  {
    for (double elevation : {-60.0, -10.0, 0.0, 15.0, 47.5, 80.0})
    {
      const double a = azimuth * kPi / 180.0;
      const double e = elevation * kPi / 180.0;
      aniso::Light light;
      light.vector = {std::sin(a) * std::cos(e), -std::cos(a) * std::cos(e), std::sin(e)};
      light.intensity = glm::dvec3(2.5);
      EXPECT_EQ(aniso::lightText(light), "directional from azimuth " + oneDecimal(azimuth) +
                                             ", elevation " + oneDecimal(elevation) +
                                             ", intensity 2.5");
    }
  }
}

TEST(LightText, DefaultKeyLight)
{
  const aniso::Light light = aniso::parseLight("dir:-1,-1.5,2:3");
  const double azimuth = 360.0 - std::atan(1.0 / 1.5) * 180.0 / kPi;
  const double elevation = std::asin(2.0 / std::sqrt(7.25)) * 180.0 / kPi;
  EXPECT_EQ(oneDecimal(azimuth), "326.3");
  EXPECT_EQ(oneDecimal(elevation), "48.0");
  EXPECT_EQ(aniso::lightText(light), "directional from azimuth 326.3, elevation 48.0, intensity 3");
}

TEST(LightText, PointAndColour)
{
  // (1, 1, 1): azimuth atan2(x, -y) = 135, elevation asin(1/sqrt(3)) = 35.26, distance 1.732.
  EXPECT_EQ(aniso::lightText(aniso::parseLight("point:1,1,1:10")),
            "point at azimuth 135.0, elevation 35.3, distance 1.73, intensity 10");
  EXPECT_EQ(aniso::lightText(aniso::parseLight("dir:0,0,1:1,0.5,0.25")),
            "directional from azimuth 0.0, elevation 90.0, intensity 1, 0.5, 0.25");
}
} // namespace
