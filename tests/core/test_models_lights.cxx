// Lights: parsing of the --light syntax (values and errors), the inverse-square falloff of point
// lights, and the light sum against sums written out by hand.
#include "core/error.h"
#include "core/lights/light.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <string>

namespace
{
using aniso::Light;
using aniso::LightType;

std::string errorOf(const std::string& text)
{
  try
  {
    aniso::parseLight(text);
  }
  catch (const aniso::Error& e)
  {
    return e.what();
  }
  return "";
}

// A directional light with a scalar intensity: normalised direction, grey intensity.
TEST(Lights, ParsesDirectionalWithScalarIntensity)
{
  const Light light = aniso::parseLight("dir:0,0,2:3.5");
  EXPECT_EQ(light.type, LightType::Directional);
  EXPECT_DOUBLE_EQ(light.vector.z, 1.0);
  EXPECT_DOUBLE_EQ(light.vector.x, 0.0);
  EXPECT_EQ(light.intensity, glm::dvec3(3.5));
}

// A point light with an RGB intensity, mixed case and blanks: the position is kept as given.
TEST(Lights, ParsesPointWithRgbIntensity)
{
  const Light light = aniso::parseLight("Point: 1, -2.5 ,3e1 :0.5,1,2");
  EXPECT_EQ(light.type, LightType::Point);
  EXPECT_EQ(light.vector, glm::dvec3(1.0, -2.5, 30.0));
  EXPECT_EQ(light.intensity, glm::dvec3(0.5, 1.0, 2.0));
}

// formatLight writes text that parses back to the same light (to the last bit for positions
// and intensities, and within one rounding for directions, which are normalised again).
TEST(Lights, FormatRoundTrips)
{
  for (const char* text : {"dir:0.3,-0.7,0.2:1.25", "point:0.1,1e-7,-3:0.2,0.3,0.4"})
  {
    const Light a = aniso::parseLight(text);
    const Light b = aniso::parseLight(aniso::formatLight(a));
    EXPECT_EQ(a.type, b.type);
    EXPECT_NEAR(glm::length(a.vector - b.vector), 0.0, 4e-16 * glm::length(a.vector)) << text;
    EXPECT_EQ(a.intensity, b.intensity) << text;
  }
}

// Malformed texts are refused with "light "TEXT": reason", the reason naming the problem.
TEST(Lights, RejectsMalformedText)
{
  const struct
  {
    const char* text;
    const char* reason;
  } cases[] = {
      {"", "expected dir:X,Y,Z:INTENSITY"},
      {"dir:0,0,1", "expected dir:X,Y,Z:INTENSITY"},
      {"dir:0,0,1:1:2", "expected dir:X,Y,Z:INTENSITY"},
      {"spot:0,0,1:1", "unknown type \"spot\""},
      {"dir:0,1:1", "direction needs 3 numbers"},
      {"point:0,1,2,3:1", "position needs 3 numbers"},
      {"dir:0,0,0:1", "must not be zero"},
      {"dir:0,x,1:1", "\"x\" is not a number"},
      {"dir:0,,1:1", "empty number"},
      {"dir:0,0,1:nan", "not a finite number"},
      {"point:inf,0,1:1", "not a finite number"},
      {"point:1e999,0,1:1", "not a finite number"},
      {"dir:0,0,1:-1", "must be >= 0"},
      {"dir:0,0,1:1,2", "intensity needs 1 number or 3"},
      {"dir:0,0,1:1,-2,3", "must be >= 0"},
  };
  for (const auto& c : cases)
  {
    const std::string message = errorOf(c.text);
    EXPECT_EQ(message.rfind(std::string("light \"") + c.text + "\": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.reason), std::string::npos) << c.text << " -> " << message;
  }
}

// Lights built in code are validated with the same rules.
TEST(Lights, ValidatesLightsBuiltInCode)
{
  Light zero;
  zero.vector = glm::dvec3(0.0);
  EXPECT_THROW(aniso::validateLight(zero), aniso::Error);
  Light negative;
  negative.intensity = glm::dvec3(1.0, -1e-9, 1.0);
  EXPECT_THROW(aniso::validateLight(negative), aniso::Error);
  Light farPoint;
  farPoint.type = LightType::Point;
  farPoint.vector = glm::dvec3(std::numeric_limits<double>::infinity(), 0.0, 0.0);
  EXPECT_THROW(aniso::validateLight(farPoint), aniso::Error);
  EXPECT_NO_THROW(aniso::validateLight(aniso::parseLight("point:0,0,5:2")));
}

// A point light of intensity I at distance d gives irradiance I / d^2 along the unit vector
// towards it; a directional light gives its intensity everywhere. At the light's own position
// nothing arrives (rather than an infinite value).
TEST(Lights, PointLightFallsOffAsInverseSquare)
{
  const Light point = aniso::parseLight("point:1,2,3:8,4,2");
  const glm::dvec3 p(1.0, 2.0 - 3.0, 3.0 - 4.0); // 5 units away along (0, 3, 4) / 5
  const aniso::LightArrival a = aniso::arriveAt(point, p);
  EXPECT_NEAR(a.distance, 5.0, 1e-15);
  EXPECT_NEAR(glm::length(a.direction - glm::dvec3(0.0, 0.6, 0.8)), 0.0, 1e-15);
  EXPECT_NEAR(a.irradiance.x, 8.0 / 25.0, 1e-15);
  EXPECT_NEAR(a.irradiance.z, 2.0 / 25.0, 1e-15);

  const aniso::LightArrival twice = aniso::arriveAt(point, glm::dvec3(1.0, 2.0 - 6.0, 3.0 - 8.0));
  EXPECT_NEAR(twice.irradiance.x * 4.0, a.irradiance.x, 1e-15);

  const aniso::LightArrival at = aniso::arriveAt(point, point.vector);
  EXPECT_EQ(at.irradiance, glm::dvec3(0.0));

  const Light sun = aniso::parseLight("dir:3,0,4:2");
  const aniso::LightArrival s = aniso::arriveAt(sun, glm::dvec3(100.0, -7.0, 0.0));
  EXPECT_NEAR(glm::length(s.direction - glm::dvec3(0.6, 0.0, 0.8)), 0.0, 1e-15);
  EXPECT_EQ(s.irradiance, glm::dvec3(2.0));
  EXPECT_TRUE(std::isinf(s.distance));
}

// A Lambertian surface (f = rho / pi) lit by a directional and a point light, in a tilted frame:
// the sum equals rho / pi * (E1 cos1 + E2 cos2) computed by hand in world space; a light below
// the horizon and a view below it contribute nothing.
TEST(Lights, SumsLambertianOverLights)
{
  const aniso::Frame frame =
      aniso::Frame::fromNormalTangent(glm::dvec3(0.0, 0.6, 0.8), glm::dvec3(1.0, 0.0, 0.0));
  const glm::dvec3 position(0.5, 0.0, 0.0);
  const std::vector<Light> lights = {
      aniso::parseLight("dir:0,0,1:2"),
      aniso::parseLight("point:0.5,3,4:5,10,15"), // 5 units away along (0, 0.6, 0.8)
      aniso::parseLight("dir:0,-1,-1:100"),       // below the tilted horizon
  };
  const double rho = 0.5;
  const auto lambert = [&](const glm::dvec3&, const glm::dvec3&) { return glm::dvec3(rho / M_PI); };
  const glm::dvec3 view = glm::normalize(glm::dvec3(0.2, 0.3, 1.0));
  const glm::dvec3 sum = aniso::shadeBrdfWithLights(lights, frame, position, view, lambert);
  const double cos1 = 0.8;                                  // (0, 0, 1) . n
  const glm::dvec3 e2 = glm::dvec3(5.0, 10.0, 15.0) / 25.0; // cos2 = 1
  const glm::dvec3 expected = rho / M_PI * (2.0 * cos1 + e2);
  EXPECT_NEAR(glm::length(sum - expected), 0.0, 1e-14);

  const glm::dvec3 below = aniso::shadeBrdfWithLights(lights, frame, position, -view, lambert);
  EXPECT_EQ(below, glm::dvec3(0.0));
}
} // namespace
