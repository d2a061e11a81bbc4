// Tangent-plane rotation maps: every texel is a unit tangent, and each pattern has the geometry
// its name promises, checked against the texel-centre coordinates recomputed here: linear at the
// requested angle, circular orthogonal to the radius vector, radial along it, spiral at the pitch
// angle to the circle, wave (cos pi v, sin pi v); angle images round-trip through atan2; every
// malformed pattern text gives an aniso::Error naming it.
#include "core/error.h"
#include "core/image/image.h"
#include "core/maps/tpr_map.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace
{
using aniso::Image;
using aniso::TprParams;
using aniso::TprPattern;
using glm::dvec2;

constexpr double kPi = 3.14159265358979323846;
constexpr double kFloatTolerance = 1e-6; // maps store float

dvec2 texelAt(const Image& map, int col, int row)
{
  return {map.at(col, row, 0), map.at(col, row, 1)};
}

// Texel centre in (u, v), v = 0 at the bottom row (the documented sampling).
dvec2 uvAt(const Image& map, int col, int row)
{
  return {(col + 0.5) / map.width, 1.0 - (row + 0.5) / map.height};
}

double cross(const dvec2& a, const dvec2& b)
{
  return a.x * b.y - a.y * b.x;
}

TprParams withCentre(TprPattern pattern, dvec2 centre, double pitch = 15.0)
{
  TprParams p;
  p.pattern = pattern;
  p.centre = centre;
  p.pitchDegrees = pitch;
  return p;
}

// Odd sizes put a texel centre exactly on the centre (0.5, 0.5), where r = 0.
TEST(TprMap, EveryTexelIsUnitLength)
{
  std::vector<TprParams> all;
  TprParams linear;
  linear.angleDegrees = 37.0;
  all.push_back(linear);
  for (TprPattern pattern : {TprPattern::Circular, TprPattern::Radial, TprPattern::Spiral})
  {
    all.push_back(withCentre(pattern, {0.5, 0.5}));
    all.push_back(withCentre(pattern, {-0.3, 1.7}));
  }
  TprParams wave;
  wave.pattern = TprPattern::Wave;
  all.push_back(wave);
  for (const TprParams& params : all)
  {
    for (const auto& size : std::vector<std::pair<int, int>>{{33, 33}, {64, 17}, {1, 1}})
    {
      const Image map = aniso::bakeTprMap(params, size.first, size.second);
      ASSERT_EQ(map.width, size.first);
      ASSERT_EQ(map.height, size.second);
      ASSERT_EQ(map.channels, 2);
      for (int row = 0; row < map.height; ++row)
      {
        for (int col = 0; col < map.width; ++col)
        {
          ASSERT_NEAR(glm::length(texelAt(map, col, row)), 1.0, kFloatTolerance);
        }
      }
    }
  }
}

TEST(TprMap, LinearIsAtTheRequestedAngle)
{
  for (double degrees : {0.0, 30.0, -45.0, 90.0, 400.0})
  {
    TprParams params;
    params.angleDegrees = degrees;
    const Image map = aniso::bakeTprMap(params, 8, 5);
    const double angle = degrees * kPi / 180.0;
    for (int row = 0; row < map.height; ++row)
    {
      for (int col = 0; col < map.width; ++col)
      {
        const dvec2 t = texelAt(map, col, row);
        ASSERT_NEAR(t.x, std::cos(angle), kFloatTolerance);
        ASSERT_NEAR(t.y, std::sin(angle), kFloatTolerance);
      }
    }
  }
}

// Circular: t . r = 0 and r x t > 0 (counter-clockwise); radial: t x r = 0 and t . r > 0.
TEST(TprMap, CircularIsTangentAndRadialIsAlongTheRadius)
{
  const dvec2 centre{0.3, 0.7};
  const Image circular = aniso::bakeTprMap(withCentre(TprPattern::Circular, centre), 40, 30);
  const Image radial = aniso::bakeTprMap(withCentre(TprPattern::Radial, centre), 40, 30);
  for (int row = 0; row < 30; ++row)
  {
    for (int col = 0; col < 40; ++col)
    {
      const dvec2 r = glm::normalize(uvAt(circular, col, row) - centre);
      const dvec2 tc = texelAt(circular, col, row);
      ASSERT_NEAR(glm::dot(tc, r), 0.0, kFloatTolerance);
      ASSERT_NEAR(cross(r, tc), 1.0, kFloatTolerance);
      const dvec2 tr = texelAt(radial, col, row);
      ASSERT_NEAR(cross(tr, r), 0.0, kFloatTolerance);
      ASSERT_NEAR(glm::dot(tr, r), 1.0, kFloatTolerance);
    }
  }
}

// The spiral makes the pitch angle with the circle direction (-r.y, r.x), opening outwards for
// a positive pitch; 0 and 90 degrees are the circular and radial patterns.
TEST(TprMap, SpiralMakesThePitchAngleWithTheCircle)
{
  const dvec2 centre{0.45, 0.55};
  for (double pitch : {15.0, -30.0, 0.0, 60.0, 90.0})
  {
    const Image map = aniso::bakeTprMap(withCentre(TprPattern::Spiral, centre, pitch), 24, 24);
    for (int row = 0; row < map.height; ++row)
    {
      for (int col = 0; col < map.width; ++col)
      {
        const dvec2 r = glm::normalize(uvAt(map, col, row) - centre);
        const dvec2 circle{-r.y, r.x};
        const dvec2 t = texelAt(map, col, row);
        const double angle = std::atan2(glm::dot(t, r), glm::dot(t, circle)) * 180.0 / kPi;
        ASSERT_NEAR(angle, pitch, 1e-4) << col << "," << row;
      }
    }
  }
}

TEST(TprMap, WaveIsCosSinOfPiV)
{
  TprParams params;
  params.pattern = TprPattern::Wave;
  const Image map = aniso::bakeTprMap(params, 7, 50);
  for (int row = 0; row < map.height; ++row)
  {
    const double v = 1.0 - (row + 0.5) / map.height;
    for (int col = 0; col < map.width; ++col)
    {
      ASSERT_NEAR(map.at(col, row, 0), std::cos(kPi * v), kFloatTolerance);
      ASSERT_NEAR(map.at(col, row, 1), std::sin(kPi * v), kFloatTolerance);
    }
  }
}

// At r = 0 the direction is undefined; the documented choice is +u.
TEST(TprMap, CentreHasTheDefinedTangent)
{
  for (TprPattern pattern : {TprPattern::Circular, TprPattern::Radial, TprPattern::Spiral})
  {
    const TprParams params = withCentre(pattern, {0.25, 0.75});
    EXPECT_EQ(aniso::tprTangentAt(params, {0.25, 0.75}), dvec2(1.0, 0.0));
    // The texel whose centre is the pattern centre: 5x5, column 2, row 2 is (0.5, 0.5).
    const Image map = aniso::bakeTprMap(withCentre(pattern, {0.5, 0.5}), 5, 5);
    EXPECT_EQ(texelAt(map, 2, 2), dvec2(1.0, 0.0));
  }
}

// Angle a -> (cos pi a, sin pi a), recovered by atan2(y, x) / pi for a in [0, 1].
TEST(TprMap, AngleImageRoundTrips)
{
  Image angles(101, 3, 3);
  for (int row = 0; row < angles.height; ++row)
  {
    for (int col = 0; col < angles.width; ++col)
    {
      angles.at(col, row, 0) = float(col) / 100.0f;
      angles.at(col, row, 1) = 123.0f; // other channels are ignored
    }
  }
  const Image map = aniso::tprFromAngleImage(angles);
  ASSERT_EQ(map.width, angles.width);
  ASSERT_EQ(map.height, angles.height);
  ASSERT_EQ(map.channels, 2);
  for (int row = 0; row < map.height; ++row)
  {
    for (int col = 0; col < map.width; ++col)
    {
      const dvec2 t = texelAt(map, col, row);
      ASSERT_NEAR(glm::length(t), 1.0, kFloatTolerance);
      ASSERT_NEAR(std::atan2(t.y, t.x) / kPi, angles.at(col, row, 0), kFloatTolerance);
    }
  }
}

TEST(TprMap, AngleImageRejectsBadInput)
{
  Image angles(2, 2, 1);
  angles.at(1, 1, 0) = std::nanf("");
  EXPECT_THROW(aniso::tprFromAngleImage(angles), aniso::Error);
  EXPECT_THROW(aniso::tprFromAngleImage(Image()), aniso::Error);
}

TEST(TprMap, BakeRejectsBadSizes)
{
  for (const auto& size : std::vector<std::pair<int, int>>{{0, 4}, {4, -1}, {40000, 1}})
  {
    EXPECT_THROW(aniso::bakeTprMap(TprParams(), size.first, size.second), aniso::Error);
  }
}

TEST(TprMap, ParsesEveryForm)
{
  TprParams p = aniso::parseTprPattern("linear");
  EXPECT_EQ(p.pattern, TprPattern::Linear);
  EXPECT_EQ(p.angleDegrees, 0.0);
  p = aniso::parseTprPattern("Linear:-22.5");
  EXPECT_EQ(p.pattern, TprPattern::Linear);
  EXPECT_EQ(p.angleDegrees, -22.5);
  p = aniso::parseTprPattern("circular");
  EXPECT_EQ(p.pattern, TprPattern::Circular);
  EXPECT_EQ(p.centre, dvec2(0.5, 0.5));
  p = aniso::parseTprPattern("circular:0.25,0.75");
  EXPECT_EQ(p.centre, dvec2(0.25, 0.75));
  p = aniso::parseTprPattern("radial:1,-2e-1");
  EXPECT_EQ(p.pattern, TprPattern::Radial);
  EXPECT_EQ(p.centre, dvec2(1.0, -0.2));
  p = aniso::parseTprPattern("spiral");
  EXPECT_EQ(p.pattern, TprPattern::Spiral);
  EXPECT_EQ(p.pitchDegrees, 15.0);
  p = aniso::parseTprPattern("spiral:0.1,0.2:-30");
  EXPECT_EQ(p.centre, dvec2(0.1, 0.2));
  EXPECT_EQ(p.pitchDegrees, -30.0);
  p = aniso::parseTprPattern("WAVE");
  EXPECT_EQ(p.pattern, TprPattern::Wave);
}

TEST(TprMap, ParseErrorsNameTheText)
{
  for (const std::string text :
       {"", "brushed", "linear:", "linear:abc", "linear:1:2", "linear:nan", "linear:inf",
        "linear:1e999", "linear: 5", "circular:0.5", "circular:0.5,", "circular:a,b",
        "circular:1,2,3", "radial:1,2:3", "spiral:0.5,0.5:100", "spiral:0.5,0.5:1:2", "wave:1"})
  {
    try
    {
      aniso::parseTprPattern(text);
      ADD_FAILURE() << "'" << text << "' was accepted";
    }
    catch (const aniso::Error& e)
    {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("TPR pattern '" + text + "': ", 0), 0u) << message;
    }
  }
}
} // namespace
