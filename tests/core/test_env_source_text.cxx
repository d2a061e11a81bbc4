// The environment analysis in words: azimuth and elevation of directions built here from their
// angles (the convention of `aniso render --azimuth/--elevation`: 0 towards -Y, 90 towards +X),
// the cone of a solid angle against the sun's own radius, and the lines the dock and the
// command show for analyses made up here (no analysis run: the text only).
#include "core/env/env_source_text.h"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace
{
constexpr double kPi = 3.14159265358979323846;

glm::dvec3 fromAngles(double azimuthDegrees, double elevationDegrees)
{
  const double a = azimuthDegrees * kPi / 180.0;
  const double e = elevationDegrees * kPi / 180.0;
  return {std::sin(a) * std::cos(e), -std::cos(a) * std::cos(e), std::sin(e)};
}

TEST(EnvSourceText, AnglesInvertTheirDirections)
{
  for (double azimuth : {0.0, 26.5, 90.0, 179.0, 181.0, 270.0, 359.5})
  {
    for (double elevation : {-89.0, -30.0, 0.0, 12.5, 47.8, 89.0})
    {
      // Length 3: the direction need not be unit.
      const aniso::SkyAngles angles = aniso::skyAnglesOf(3.0 * fromAngles(azimuth, elevation));
      EXPECT_NEAR(angles.azimuthDegrees, azimuth, 1e-9) << azimuth << " " << elevation;
      EXPECT_NEAR(angles.elevationDegrees, elevation, 1e-9) << azimuth << " " << elevation;
    }
  }
  EXPECT_NEAR(aniso::skyAnglesOf({1.0, 0.0, 0.0}).azimuthDegrees, 90.0, 1e-12);
  EXPECT_NEAR(aniso::skyAnglesOf({0.0, 1.0, 0.0}).azimuthDegrees, 180.0, 1e-12);
  // Straight up, straight down and nothing: azimuth 0, never 180 from a -0.
  EXPECT_EQ(aniso::skyAnglesOf({0.0, 0.0, 1.0}).azimuthDegrees, 0.0);
  EXPECT_EQ(aniso::skyAnglesOf({0.0, 0.0, 1.0}).elevationDegrees, 90.0);
  EXPECT_EQ(aniso::skyAnglesOf({0.0, -0.0, -2.0}).azimuthDegrees, 0.0);
  EXPECT_EQ(aniso::skyAnglesOf({0.0, 0.0, -2.0}).elevationDegrees, -90.0);
  EXPECT_EQ(aniso::skyAnglesOf({0.0, 0.0, 0.0}).azimuthDegrees, 0.0);
  EXPECT_EQ(aniso::skyAnglesOf({0.0, 0.0, 0.0}).elevationDegrees, 0.0);
}

// A rotation about Z by a (counter-clockwise seen from above) takes (x, y) to
// (x cos a - y sin a, x sin a + y cos a): the angles of the rotated direction.
TEST(EnvSourceText, RotationTurnsTheAzimuth)
{
  const glm::dvec3 d = fromAngles(26.5, 47.8);
  for (double rotation : {-180.0, -90.0, -30.0, 0.0, 45.0, 170.0, 180.0, 720.0})
  {
    const double a = rotation * kPi / 180.0;
    const glm::dvec3 rotated(d.x * std::cos(a) - d.y * std::sin(a),
                             d.x * std::sin(a) + d.y * std::cos(a), d.z);
    const aniso::SkyAngles expected = aniso::skyAnglesOf(rotated);
    const aniso::SkyAngles angles = aniso::skyAnglesOf(d, rotation);
    EXPECT_NEAR(angles.azimuthDegrees, expected.azimuthDegrees, 1e-9) << rotation;
    EXPECT_GE(angles.azimuthDegrees, 0.0);
    EXPECT_LT(angles.azimuthDegrees, 360.0);
    EXPECT_NEAR(angles.elevationDegrees, 47.8, 1e-9) << rotation;
  }
}

// A cone of half-angle r has solid angle 2 pi (1 - cos r); the sphere is a 360-degree cone.
TEST(EnvSourceText, DiameterOfASolidAngle)
{
  const double r = 0.00465;
  EXPECT_NEAR(aniso::equivalentDiameterDegrees(2.0 * kPi * (1.0 - std::cos(r))),
              2.0 * r * 180.0 / kPi, 1e-9);
  EXPECT_NEAR(aniso::equivalentDiameterDegrees(2.0 * kPi), 180.0, 1e-9);
  EXPECT_NEAR(aniso::equivalentDiameterDegrees(4.0 * kPi), 360.0, 1e-9);
  EXPECT_NEAR(aniso::equivalentDiameterDegrees(9.0 * kPi), 360.0, 1e-9);
  EXPECT_EQ(aniso::equivalentDiameterDegrees(-1.0), 0.0);
}

TEST(EnvSourceText, PercentagesKeepTwoFigures)
{
  EXPECT_EQ(aniso::percentText(0.862), "86%");
  EXPECT_EQ(aniso::percentText(1.0), "100%");
  EXPECT_EQ(aniso::percentText(0.0423), "4.2%");
  EXPECT_EQ(aniso::percentText(0.0996), "10%");
  EXPECT_EQ(aniso::percentText(0.0004), "<0.1%");
  EXPECT_EQ(aniso::percentText(0.0), "<0.1%");
}

TEST(EnvSourceText, SourcesAndSummaries)
{
  aniso::EnvSource sun;
  sun.kind = aniso::EnvSourceKind::Sun;
  sun.direction = fromAngles(123.4, 35.2);
  sun.solidAngle = 6.8e-5;
  sun.powerShare = 0.86;
  EXPECT_EQ(aniso::sourceText(sun), "sun at azimuth 123.4, elevation 35.2 (6.8e-05 sr, 86%)");
  EXPECT_EQ(aniso::sourceText(sun, -150.0),
            "sun at azimuth 333.4, elevation 35.2 (6.8e-05 sr, 86%)");

  aniso::EnvAnalysis analysis;
  analysis.concentration = 0.0123;
  EXPECT_EQ(aniso::analysisSummary(analysis), "no concentrated sources; concentration 0.01");
  analysis.concentration = 0.87;
  analysis.sources = {sun};
  EXPECT_EQ(aniso::analysisSummary(analysis),
            "1 source carries 86% of the power; concentration 0.87");
  aniso::EnvSource lamp;
  lamp.kind = aniso::EnvSourceKind::Lamp;
  lamp.powerShare = 0.04;
  analysis.sources = {sun, lamp, lamp};
  EXPECT_EQ(aniso::analysisSummary(analysis),
            "3 sources carry 94% of the power; concentration 0.87");
}
} // namespace
