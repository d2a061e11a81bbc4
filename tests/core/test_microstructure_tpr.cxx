// The microstructure turned by a tangent-plane rotation map (turnMicroPixel and
// sampleTprDirection, core/microstructure/microstructure.h) on a disk with the circular TPR
// pattern: a brushed disk. Checked against the geometry of concentric circles, computed here
// from the point's position and not from the map:
//  - the grooves' direction at a point of the disk is the circle's tangent there, at the angle
//    atan2(y, x) + pi / 2 around the centre;
//  - the grooves' micro normals (in world space) have no component along that tangent, so they
//    tilt only towards and away from the centre;
//  - rotational symmetry: a point at angle phi lit and seen from directions turned by phi about
//    the disk's normal (its footprint turned likewise) shades like the point at angle 0, while
//    the unturned structure (straight grooves) breaks that symmetry.
#include "core/maps/tpr_map.h"
#include "core/microstructure/microstructure.h"

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kTiles = 200.0; // structure tiles per unit of texture coordinate

// The disk of radius 1 in the XY plane with the built-in disk's UVs: u = (x + 1) / 2.
glm::dvec2 uvOf(double radius, double phi)
{
  return {0.5 + 0.5 * radius * std::cos(phi), 0.5 + 0.5 * radius * std::sin(phi)};
}

aniso::Image circularMap()
{
  aniso::TprParams params;
  params.pattern = aniso::TprPattern::Circular;
  params.centre = glm::dvec2(0.5, 0.5);
  return aniso::bakeTprMap(params, 256, 256);
}

glm::dvec3 rotatedAboutZ(const glm::dvec3& d, double angle)
{
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * d.x - s * d.y, s * d.x + c * d.y, d.z};
}

// Angle difference of two directions of lines (a groove has no sign), in [0, pi / 2].
double lineAngleBetween(double a, double b)
{
  const double d = std::remainder(a - b, kPi);
  return std::abs(d);
}

TEST(MicrostructureTpr, GroovesFollowTheCircles)
{
  const aniso::Image map = circularMap();
  const aniso::Microstructure grooves =
      aniso::makeMicrostructure(aniso::MicroPattern::Grooves, 64, 0.3);
  double worstAngle = 0.0;
  double worstAlong = 0.0;
  double meanAcross = 0.0;
  int samples = 0;
  for (double radius : {0.15, 0.4, 0.7, 0.95})
  {
    for (int k = 0; k < 24; ++k)
    {
      const double phi = 2.0 * kPi * (k + 0.3) / 24.0;
      const glm::dvec2 uv = uvOf(radius, phi);
      const glm::dvec3 position(2.0 * uv.x - 1.0, 2.0 * uv.y - 1.0, 0.0);
      // The independent reference: the circle through the point, counter-clockwise.
      const double circleAngle = std::atan2(position.y, position.x) + 0.5 * kPi;
      const glm::dvec3 circleTangent(std::cos(circleAngle), std::sin(circleAngle), 0.0);

      aniso::PixelFootprint footprint;
      footprint.centre = uv * kTiles;
      const aniso::TurnedPixel turned =
          aniso::turnMicroPixel(aniso::Frame{}, footprint, aniso::sampleTprDirection(map, uv));
      // The grooves run along the structure's y axis: the turned frame's b.
      const glm::dvec3 along = turned.frame.b;
      worstAngle =
          std::max(worstAngle, lineAngleBetween(std::atan2(along.y, along.x), circleAngle));
      EXPECT_NEAR(glm::length(glm::cross(turned.frame.t, turned.frame.b) - turned.frame.n), 0.0,
                  1e-12);
      // Micro normals across one tile of the turned structure, in world space.
      for (int i = 0; i < 8; ++i)
      {
        const glm::dvec2 p = turned.footprint.centre + glm::dvec2((i + 0.5) / 8.0, 0.37);
        const glm::dvec3 m = turned.frame.toWorld(aniso::sampleMicrostructure(grooves, p).normal);
        worstAlong = std::max(worstAlong, std::abs(glm::dot(m, circleTangent)));
        meanAcross += std::abs(glm::dot(m, glm::normalize(glm::dvec3(position.x, position.y, 0))));
        ++samples;
      }
    }
  }
  meanAcross /= samples;
  std::printf("brushed disk: worst groove angle error %.2e rad, worst normal component along the "
              "circle %.2e, mean radial component %.3f\n",
              worstAngle, worstAlong, meanAcross);
  // A 256^2 map interpolated bilinearly and renormalised: the angle error is second order in
  // the texel's angular size (about 1e-3 rad measured at radius 0.15, 19 texels from the centre).
  EXPECT_LT(worstAngle, 5e-3);
  EXPECT_LT(worstAlong, 5e-3);
  // The walls of V-grooves of depth 0.3 tilt by atan(0.6), sin = 0.51, away from and towards
  // the centre (less where the bilinear normal crosses a ridge or the valley).
  EXPECT_GT(meanAcross, 0.4);
}

TEST(MicrostructureTpr, BrushedDiskIsRotationallySymmetric)
{
  const aniso::Image map = circularMap();
  const aniso::Microstructure grooves =
      aniso::makeMicrostructure(aniso::MicroPattern::Grooves, 64, 0.3);
  aniso::MicroShadingOptions options;
  options.samplesPerAxis = 24;
  options.masking = aniso::MicroMasking::Normal;
  options.roughness = 0.15;
  options.f0 = glm::dvec3(0.9);
  // Light and view at angle 0 (the point on +X): light across the grooves, low, view above.
  const glm::dvec3 light0 = glm::normalize(glm::dvec3(0.9, 0.2, 0.5));
  const glm::dvec3 view0 = glm::normalize(glm::dvec3(-0.5, 0.1, 0.8));
  const double radius = 0.6;

  auto shade = [&](double phi, bool turnedByMap)
  {
    const glm::dvec2 uv = uvOf(radius, phi);
    aniso::PixelFootprint footprint;
    footprint.centre = uv * kTiles;
    // Three tiles across the pixel, turned with the point as a camera turned with the light and
    // view would see it.
    footprint.axisU = 3.0 * glm::dvec2(std::cos(phi), std::sin(phi));
    footprint.axisV = 3.0 * glm::dvec2(-std::sin(phi), std::cos(phi));
    aniso::TurnedPixel pixel{aniso::Frame{}, footprint};
    if (turnedByMap)
    {
      pixel = aniso::turnMicroPixel(pixel.frame, footprint, aniso::sampleTprDirection(map, uv));
    }
    aniso::Light sun;
    sun.vector = rotatedAboutZ(light0, phi);
    sun.intensity = glm::dvec3(1.0);
    const glm::dvec3 position(2.0 * uv.x - 1.0, 2.0 * uv.y - 1.0, 0.0);
    return aniso::shadeMicroPixel(grooves, options, pixel.footprint, pixel.frame, position,
                                  rotatedAboutZ(view0, phi), {sun})
        .x;
  };

  const double atZero = shade(0.0, true);
  ASSERT_GT(atZero, 0.0);
  double worstTurned = 0.0;
  double worstStraight = 0.0;
  const double straightAtZero = shade(0.0, false);
  for (int k = 1; k < 12; ++k)
  {
    const double phi = 2.0 * kPi * k / 12.0;
    worstTurned = std::max(worstTurned, std::abs(shade(phi, true) / atZero - 1.0));
    worstStraight = std::max(worstStraight, std::abs(shade(phi, false) / straightAtZero - 1.0));
  }
  std::printf("brushed disk: radiance around the disk differs from angle 0 by at most %.2e "
              "(turned) and %.2e (straight grooves)\n",
              worstTurned, worstStraight);
  // The structure-space footprint is the same at every angle; what remains is the map's
  // interpolated direction (1e-4 rad off) and the tile phase under the grid (measured 8e-6).
  EXPECT_LT(worstTurned, 1e-3);
  // Straight grooves seen from turned directions are another material: the test can tell.
  EXPECT_GT(worstStraight, 0.2);
}
} // namespace
