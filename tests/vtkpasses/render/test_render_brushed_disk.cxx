// Render test of the brushed disk: the microstructure material (vtkpasses/render/MicrostructureMaterial.h)
// with V-grooves turned by a circular TPR map on the built-in disk, seen by a parallel camera
// from above at 60 degrees elevation under a directional and a point light. Every pixel's
// position, view and footprint follow analytically from the camera; the expected pixel is the
// core's CPU evaluation (turnMicroPixel with sampleTprDirection, then shadeMicroPixel) of the
// same structure, map, options and lights. Compared by the relative L1 error over the pixels
// well inside the disk, within a stated bound; the same comparison against the unturned
// structure must fail, so the test sees the turn. No output may hold NaN or Inf.
#include "core/env/environment.h"
#include "core/frame.h"
#include "core/maps/tpr_map.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/MicrostructureMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <vector>
#include <vtkPolyData.h>

namespace aniso::test
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 40;

// The disk's plane (z = 0) under the centre of pixel (x, y) of the test's image.
PlaneHit diskHit(const CameraPlacement& camera, double x, double y)
{
  return planeHit(camera, kSize, x, y);
}

TEST(RenderBrushedDisk, MatchesTheCpuModel)
{
  ANISO_REQUIRE_DISPLAY();
  const double e = 60.0 * kPi / 180.0;
  CameraPlacement camera;
  camera.position = glm::dvec3(0.0, -4.0 * std::cos(e), 4.0 * std::sin(e));
  camera.viewUp = glm::dvec3(0.0, 0.0, 1.0);
  camera.parallel = true;
  camera.parallelScale = 1.05;

  TprParams circular;
  circular.pattern = TprPattern::Circular;
  const auto map = std::make_shared<const Image>(bakeTprMap(circular, 256, 256));
  Light sun;
  sun.vector = glm::normalize(glm::dvec3(0.4, 0.3, 0.7));
  sun.intensity = glm::dvec3(2.0);
  Light lamp;
  lamp.type = LightType::Point;
  lamp.vector = glm::dvec3(-0.6, 0.8, 1.0);
  lamp.intensity = glm::dvec3(0.8, 1.0, 1.2);

  MicrostructureSettings settings;
  settings.structure =
      std::make_shared<Microstructure>(makeMicrostructure(MicroPattern::Grooves, 32, 0.3));
  settings.options.samplesPerAxis = 3;
  settings.options.masking = MicroMasking::ParallaxOcclusion;
  settings.options.selfShadowing = true;
  settings.options.marchSteps = 8;
  settings.options.roughness = 0.1;
  settings.options.f0 = glm::dvec3(0.95, 0.9, 0.8);
  settings.tiles = 40.0; // about a tile across a pixel
  settings.lights = {sun, lamp};
  settings.tprMap = map;

  RenderSettings s;
  s.surface = makeDisk(256, 16);
  s.environment = std::make_shared<UniformEnvironment>(glm::dvec3(0.0));
  s.cubeSize = 8;
  s.display.background = BackgroundMode::Transparent;
  s.camera = camera;
  s.width = s.height = kSize;
  s.jitter = false;
  s.installMaterial = MicrostructureShadingMaterial::installer(settings);
  const RenderResult result = renderOffscreen(s);
  EXPECT_EQ(nonFiniteValues(result.linear), 0);

  // Pixels whose centre lies inside radius 0.95 (the polygon's edge and partial coverage stay
  // out) and outside 0.05 (where the circles' direction turns within a texel of the map).
  Image turned(kSize, kSize, 4);
  Image straight(kSize, kSize, 4);
  double differenceTurned = 0.0;
  double differenceStraight = 0.0;
  double total = 0.0;
  int compared = 0;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      const PlaneHit g = diskHit(camera, x, y);
      const double radius = std::hypot(g.position.x, g.position.y);
      if (radius > 0.95 || radius < 0.05)
      {
        continue;
      }
      PixelFootprint footprint;
      footprint.centre = g.uv * settings.tiles;
      footprint.axisU = (diskHit(camera, x + 1, y).uv - g.uv) * settings.tiles;
      footprint.axisV = (diskHit(camera, x, y - 1).uv - g.uv) * settings.tiles;
      const TurnedPixel pixel = turnMicroPixel(Frame{}, footprint, sampleTprDirection(*map, g.uv));
      const glm::dvec3 expected =
          shadeMicroPixel(*settings.structure, settings.options, pixel.footprint, pixel.frame,
                          g.position, g.view, settings.lights);
      const glm::dvec3 unturned = shadeMicroPixel(*settings.structure, settings.options, footprint,
                                                  Frame{}, g.position, g.view, settings.lights);
      ASSERT_GT(result.linear.at(x, y, 3), 0.5f) << "pixel " << x << ", " << y;
      for (int c = 0; c < 3; ++c)
      {
        const double rendered = result.linear.at(x, y, c);
        differenceTurned += std::abs(rendered - expected[c]);
        differenceStraight += std::abs(rendered - unturned[c]);
        total += std::abs(expected[c]);
        turned.at(x, y, c) = float(expected[c]);
        straight.at(x, y, c) = float(unturned[c]);
      }
      turned.at(x, y, 3) = straight.at(x, y, 3) = 1.0f;
      ++compared;
    }
  }
  ASSERT_GT(compared, kSize * kSize / 2);
  ASSERT_GT(total, 0.0);
  const double errorTurned = differenceTurned / total;
  const double errorStraight = differenceStraight / total;
  std::printf("brushed disk GL vs CPU over %d pixels: relative L1 error %.2e (against straight "
              "grooves: %.2e)\n",
              compared, errorTurned, errorStraight);
  // Float arithmetic and the hardware's bilinear weights (structure and map) against double
  // precision: llvmpipe measures 8e-5.
  EXPECT_LT(errorTurned, 1e-3);
  EXPECT_GT(errorStraight, 0.1);
  if (HasFailure())
  {
    keepImages("brushed_disk", result.linear, turned);
  }
}
} // namespace
} // namespace aniso::test
