// Render tests of the microstructure material (vtkpasses/render/MicrostructureMaterial.h) on the
// built-in plate seen by a parallel camera: every pixel's footprint in structure space, view and
// position follow analytically from the camera, and the core's CPU evaluation
// (shadeMicroPixel, core/microstructure/microstructure.h) of the same structure, options, lights
// and jitter seeds gives the expected pixel. Compared per configuration (masking, shadowing,
// BRDF, full or jittered grid) by the relative L1 error over the image, within a stated bound.
// The purpose of the K x K sampling: with several tiles of structure under each pixel, the GL
// images with K = 1, 2, 4, 8 approach the pixel average (the CPU evaluation with K = 24), the
// error falling with K.
// No output may hold NaN or Inf.
#include "core/env/environment.h"
#include "core/frame.h"
#include "core/sampling/hammersley.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/MicrostructureMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <vtkPolyData.h>

namespace aniso::test
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 28;

CameraPlacement plateCamera(double elevationDegrees)
{
  const double e = elevationDegrees * kPi / 180.0;
  CameraPlacement c;
  c.position = glm::dvec3(0.0, -4.0 * std::cos(e), 4.0 * std::sin(e));
  c.viewUp = glm::dvec3(0.0, 0.0, 1.0);
  c.parallel = true;
  c.parallelScale = 0.8 * std::sin(e);
  return c;
}

// The plate's plane (z = 0) under the centre of pixel (x, y) of the test's image.
PlaneHit plateHit(const CameraPlacement& camera, double x, double y)
{
  return planeHit(camera, kSize, x, y);
}

struct Case
{
  std::string name;
  MicroPattern pattern;
  MicroShadingOptions options;
  double bound; // relative L1
};

double relativeL1(const Image& rendered, const Image& expected)
{
  double difference = 0.0;
  double total = 0.0;
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x)
      for (int c = 0; c < 3; ++c)
      {
        difference += std::abs(double(rendered.at(x, y, c)) - expected.at(x, y, c));
        total += std::abs(double(expected.at(x, y, c)));
      }
  return difference / total;
}

TEST(RenderMicrostructure, MatchesTheCpuModel)
{
  ANISO_REQUIRE_DISPLAY();
  std::vector<Case> cases;
  {
    Case c{"pyramids, POM, self-shadowing, GGX", MicroPattern::Pyramids, {}, 0.01};
    c.options.samplesPerAxis = 3;
    c.options.masking = MicroMasking::ParallaxOcclusion;
    c.options.selfShadowing = true;
    c.options.roughness = 0.3;
    c.options.f0 = glm::dvec3(0.6);
    cases.push_back(c);
  }
  {
    Case c{"pits, parallax, Blinn-Phong, jittered", MicroPattern::InvertedPyramids, {}, 0.01};
    c.options.samplesPerAxis = 2;
    c.options.jittered = true;
    c.options.masking = MicroMasking::Parallax;
    c.options.brdf = MicroBrdf::BlinnPhong;
    c.options.blinnExponent = 60.0;
    c.options.f0 = glm::dvec3(0.5);
    cases.push_back(c);
  }
  {
    Case c{"silk, normal masking, GGX", MicroPattern::Silk, {}, 0.01};
    c.options.samplesPerAxis = 4;
    c.options.masking = MicroMasking::Normal;
    c.options.roughness = 0.4;
    cases.push_back(c);
  }
  {
    Case c{"grooves, parallax, self-shadowing, sharp GGX", MicroPattern::Grooves, {}, 0.01};
    c.options.samplesPerAxis = 3;
    c.options.masking = MicroMasking::Parallax;
    c.options.selfShadowing = true;
    c.options.marchSteps = 8;
    c.options.roughness = 0.05;
    c.options.f0 = glm::dvec3(0.95, 0.9, 0.8);
    cases.push_back(c);
  }
  {
    // The extremes of the options' ranges: one sample, one march step, the narrowest GGX.
    Case c{"pyramids, POM with one step, K = 1, alpha = 0.001", MicroPattern::Pyramids, {}, 0.01};
    c.options.samplesPerAxis = 1;
    c.options.marchSteps = 1;
    c.options.selfShadowing = true;
    c.options.roughness = 1e-3;
    c.options.f0 = glm::dvec3(1.0);
    cases.push_back(c);
  }
  const CameraPlacement camera = plateCamera(60.0);
  Light sun;
  sun.vector = glm::normalize(glm::dvec3(0.4, 0.3, 0.7));
  sun.intensity = glm::dvec3(2.0);
  Light lamp;
  lamp.type = LightType::Point;
  lamp.vector = glm::dvec3(-0.6, -0.8, 1.0);
  lamp.intensity = glm::dvec3(0.8, 1.0, 1.2);
  const std::vector<Light> lights = {sun, lamp};
  const std::uint32_t frameSeed = microFrameSeed(frameShift(0));
  const Frame frame;

  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    MicrostructureSettings settings;
    settings.structure = std::make_shared<Microstructure>(makeMicrostructure(c.pattern, 32, 0.2));
    settings.options = c.options;
    settings.tiles = 40.0; // about 1.4 tiles across a pixel
    settings.lights = lights;
    RenderSettings s;
    s.surface = makePlate(1);
    s.environment = std::make_shared<UniformEnvironment>(glm::dvec3(0.0));
    s.cubeSize = 8;
    s.display.background = BackgroundMode::Transparent;
    s.camera = camera;
    s.width = s.height = kSize;
    s.jitter = false;
    s.installMaterial = MicrostructureShadingMaterial::installer(settings);
    const RenderResult result = renderOffscreen(s);
    ASSERT_EQ(result.coveredPixels, kSize * kSize);
    EXPECT_EQ(nonFiniteValues(result.linear), 0);

    Image expected(kSize, kSize, 4);
    for (int y = 0; y < kSize; ++y)
    {
      for (int x = 0; x < kSize; ++x)
      {
        const PlaneHit g = plateHit(camera, x, y);
        PixelFootprint footprint;
        footprint.centre = g.uv * settings.tiles;
        footprint.axisU = (plateHit(camera, x + 1, y).uv - g.uv) * settings.tiles;
        footprint.axisV = (plateHit(camera, x, y - 1).uv - g.uv) * settings.tiles;
        MicroShadingOptions options = c.options;
        options.seed = microPixelSeed(x, kSize - 1 - y, frameSeed);
        const glm::dvec3 radiance = shadeMicroPixel(*settings.structure, options, footprint, frame,
                                                    g.position, g.view, lights);
        for (int ch = 0; ch < 3; ++ch)
        {
          expected.at(x, y, ch) = float(radiance[ch]);
        }
        expected.at(x, y, 3) = 1.0f;
      }
    }
    const double error = relativeL1(result.linear, expected);
    std::printf("microstructure GL vs CPU, %s: relative L1 error %.2e\n", c.name.c_str(), error);
    // Float arithmetic and the hardware's bilinear weights against double precision (llvmpipe
    // measures about 1e-6).
    EXPECT_LT(error, c.bound);
    if (HasFailure())
    {
      keepImages("micro_" + std::to_string(&c - cases.data()), result.linear, expected);
    }
  }
}
TEST(RenderMicrostructure, ConvergesToThePixelAverageWithTheGrid)
{
  ANISO_REQUIRE_DISPLAY();
  const CameraPlacement camera = plateCamera(50.0);
  Light sun;
  sun.vector = glm::normalize(glm::dvec3(-0.3, 0.5, 0.6));
  sun.intensity = glm::dvec3(2.0);
  MicrostructureSettings settings;
  settings.structure =
      std::make_shared<Microstructure>(makeMicrostructure(MicroPattern::InvertedPyramids, 32, 0.2));
  settings.options.masking = MicroMasking::ParallaxOcclusion;
  settings.options.selfShadowing = true;
  settings.options.roughness = 0.2;
  settings.options.f0 = glm::dvec3(0.5);
  settings.tiles = 150.0; // 4 to 5 tiles across each pixel
  settings.lights = {sun};
  const Frame frame;

  Image average(kSize, kSize, 4);
  MicroShadingOptions fine = settings.options;
  fine.samplesPerAxis = 24;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      const PlaneHit g = plateHit(camera, x, y);
      PixelFootprint footprint;
      footprint.centre = g.uv * settings.tiles;
      footprint.axisU = (plateHit(camera, x + 1, y).uv - g.uv) * settings.tiles;
      footprint.axisV = (plateHit(camera, x, y - 1).uv - g.uv) * settings.tiles;
      const glm::dvec3 radiance = shadeMicroPixel(*settings.structure, fine, footprint, frame,
                                                  g.position, g.view, settings.lights);
      for (int c = 0; c < 3; ++c)
      {
        average.at(x, y, c) = float(radiance[c]);
      }
      average.at(x, y, 3) = 1.0f;
    }
  }
  std::vector<double> errors;
  for (int k : {1, 2, 4, 8})
  {
    settings.options.samplesPerAxis = k;
    RenderSettings s;
    s.surface = makePlate(1);
    s.environment = std::make_shared<UniformEnvironment>(glm::dvec3(0.0));
    s.cubeSize = 8;
    s.display.background = BackgroundMode::Transparent;
    s.camera = camera;
    s.width = s.height = kSize;
    s.jitter = false;
    s.installMaterial = MicrostructureShadingMaterial::installer(settings);
    const RenderResult result = renderOffscreen(s);
    EXPECT_EQ(nonFiniteValues(result.linear), 0);
    errors.push_back(relativeL1(result.linear, average));
    std::printf("microstructure K = %d against the pixel average: relative L1 error %.4f\n", k,
                errors.back());
  }
  for (std::size_t i = 1; i < errors.size(); ++i)
  {
    EXPECT_LT(errors[i], errors[i - 1]);
  }
  // Measured on llvmpipe: 0.64, 0.43, 0.33, 0.16 for K = 1, 2, 4, 8.
  EXPECT_LT(errors.back() * 3.0, errors.front());
}
} // namespace
} // namespace aniso::test
