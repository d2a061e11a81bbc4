// Render tests of the environment's sources as lights (core/lights/env_lights.h, env-lights):
//  1. A Ward sphere under the built-in sun-sky turned by 30 degrees, drawn by the lit models'
//     installer with env-lights (litModelInstaller(settings, true): the renderer's lighting
//     analysed, its sources as directional lights) and no light of its own, against the core's
//     evaluation (shadeLitModel) under the sun's light as environmentSourceLights gives it (the
//     metric and the pixels of test_render_lit_models: relative L2 over the sphere away from the
//     silhouette and poles, bound 3e-3). Its brightest pixel lies where the sun's mirror direction
//     says: its normal within 3 degrees (two pixels' normals at the highlight) of the half vector
//     of the sun and the view. Without env-lights (no light at all) the sphere is black.
//  2. LEADR counts a source once: on an equirectangular sky of 1 holding a small sun, LEADR with
//     env-lights (the sun as a light, the residual cube and its SH9) draws what LEADR without it
//     draws (the sun in the cube and the SH9), the mean over the sphere within 5% of the sun's
//     part of the picture (the mean without env-lights less the mean on the residual alone;
//     measured 1.5%, the SH9's approximation of the sun's clamped cosine); counting the sun
//     twice would put it at 100%.
#include "core/env/env_sources.h"
#include "core/env/environment.h"
#include "core/error.h"
#include "core/leadr/leadr.h"
#include "core/lights/env_lights.h"
#include "core/models/height_field.h"
#include "core/models/models.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/LeadrMaterial.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <vector>
#include <vtkPolyData.h>

namespace aniso::test
{
namespace
{
constexpr int kSize = 96;
constexpr double kDegree = M_PI / 180.0;
constexpr double kRotation = 30.0;

RenderSettings sphereSettings(std::shared_ptr<const Environment> env, int size)
{
  RenderSettings s;
  s.surface = makeSphere(256, 128);
  s.environment = std::move(env);
  s.environmentRotationDegrees = kRotation;
  s.cubeSize = 64;
  s.display.background = BackgroundMode::Transparent;
  s.width = size;
  s.height = size;
  s.frames = 1;
  s.jitter = false;
  return s;
}

glm::dvec3 rotateZ(const glm::dvec3& d, double degrees)
{
  const double a = degrees * kDegree;
  return {std::cos(a) * d.x - std::sin(a) * d.y, std::sin(a) * d.x + std::cos(a) * d.y, d.z};
}

TEST(RenderEnvLights, WardSphereLitByTheSunSkysSun)
{
  ANISO_REQUIRE_DISPLAY();
  const std::shared_ptr<const Environment> env = openEnvironment("builtin:sunsky");
  SvTexel texel;
  texel.alphaX = 0.2;
  texel.alphaY = 0.35;
  texel.diffuse = glm::dvec3(0.1, 0.15, 0.2);
  texel.specular = 0.7;
  LitModelSettings lit;
  lit.model = LitModel::Ward;
  lit.maps = std::make_shared<const SvMaps>(uniformSvMaps(texel));
  RenderSettings s = sphereSettings(env, kSize);
  s.installMaterial = litModelInstaller(lit, true);
  const RenderResult on = renderOffscreen(s);
  s.installMaterial = litModelInstaller(lit, false);
  const RenderResult off = renderOffscreen(s);
  EXPECT_EQ(nonFiniteValues(on.linear), 0);

  // The core's evaluation under the lights the installer made.
  const std::shared_ptr<const EnvAnalysis> analysis = sharedEnvironmentAnalysis(*env);
  const std::vector<Light> lights = withEnvironmentLights({}, analysis.get(), kRotation);
  ASSERT_FALSE(lights.empty());
  const glm::dvec3 sun =
      rotateZ(glm::dvec3(0.3, -0.6, 0.74) / glm::length(glm::dvec3(0.3, -0.6, 0.74)), kRotation);
  EXPECT_LT(std::acos(std::min(1.0, glm::dot(lights.front().vector, sun))) / kDegree, 0.2);

  const CameraPlacement camera = placeCamera(ViewSettings{}, glm::dvec3(0.0), 1.0);
  double diff = 0.0;
  double norm = 0.0;
  double offSum = 0.0;
  int pixels = 0;
  float brightest = -1.0f;
  glm::dvec3 brightestNormal(0.0);
  glm::dvec3 brightestView(0.0);
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      const Ray ray = pixelRay(camera, x, y, kSize, kSize);
      const auto hit = hitUnitSphere(ray);
      if (!hit)
        continue;
      const glm::dvec3 n = *hit;
      const glm::dvec3 view = -ray.direction;
      if (glm::dot(n, view) < 0.2 || std::abs(n.z) > 0.95)
        continue;
      const glm::dvec3 t = glm::normalize(glm::dvec3(-n.y, n.x, 0.0));
      const Frame frame = svShadingFrame(n, t, texel);
      const glm::dvec3 expected = shadeLitModel(lit.model, texel, frame, n, view, lights);
      for (int k = 0; k < 3; ++k)
      {
        const double d = on.linear.at(x, y, k) - expected[k];
        diff += d * d;
        norm += expected[k] * expected[k];
        offSum += std::abs(off.linear.at(x, y, k));
      }
      if (on.linear.at(x, y, 0) > brightest)
      {
        brightest = on.linear.at(x, y, 0);
        brightestNormal = n;
        brightestView = view;
      }
      ++pixels;
    }
  }
  ASSERT_GT(pixels, kSize * kSize / 4);
  const double error = std::sqrt(diff / norm);
  const glm::dvec3 half = glm::normalize(brightestView + lights.front().vector);
  const double highlight = std::acos(std::min(1.0, glm::dot(half, brightestNormal))) / kDegree;
  std::printf("Ward under the sun-sky's sun as a light: relative L2 %.2e over %d pixels; "
              "brightest pixel's normal %.2f deg from the half vector; without env-lights the "
              "sphere sums to %g\n",
              error, pixels, highlight, offSum);
  EXPECT_LT(error, 3e-3);
  EXPECT_LT(highlight, 3.0);
  EXPECT_EQ(offSum, 0.0);
}

// Mean linear radiance over the covered pixels.
double coveredMean(const Image& image)
{
  double sum = 0.0;
  int covered = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y, 3) > 0.0f)
      {
        sum += image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2);
        ++covered;
      }
  return covered ? sum / (3.0 * covered) : 0.0;
}

TEST(RenderEnvLights, LeadrCountsTheSunOnce)
{
  ANISO_REQUIRE_DISPLAY();
  // A sky of 1 with a sun of 3000 over a disc of 2.5 degrees radius (its power about 6, twice
  // the sky's irradiance on an upward surface), on a 512 x 256 image.
  const int w = 512;
  const int h = 256;
  const glm::dvec3 sunDir = glm::normalize(glm::dvec3(0.2, -0.7, 0.6));
  Image image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      const glm::dvec3 d = equirectToDirection({(x + 0.5) / w, 1.0 - (y + 0.5) / h});
      const float value = glm::dot(d, sunDir) >= std::cos(2.5 * kDegree) ? 3000.0f : 1.0f;
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = value;
    }
  const auto env = std::make_shared<const EquirectEnvironment>(image, "test:sun-disc");
  const std::shared_ptr<const EnvAnalysis> analysis = sharedEnvironmentAnalysis(*env);
  ASSERT_FALSE(analysis->sources.empty());
  const auto residual =
      std::make_shared<const EquirectEnvironment>(analysis->residual, "test:sun-disc:residual");

  LeadrSettings leadr;
  leadr.moments =
      std::make_shared<const LeadrMips>(bakeLeadrFromHeight(randomWaveHeight(64, 0.3), 1.0));
  leadr.surface.diffuse = glm::dvec3(0.4);
  leadr.surface.f0 = glm::dvec3(0.5);
  leadr.surface.baseAlphaX = leadr.surface.baseAlphaY = 0.3;
  leadr.environment = true;
  // The finest slope grid: its environment quadrature has converged (at n = 4 it overestimates
  // the sun's specular by 20%, at 8 by 7%, at 16 by 0.2%: measured with diffuse 0).
  leadr.gridN = 16;
  auto render = [&](std::shared_ptr<const Environment> e, bool environmentLights)
  {
    LeadrSettings settings = leadr;
    settings.environmentLights = environmentLights;
    const MaterialInstaller install = LeadrShadingMaterial::installer(settings);
    RenderSettings s = sphereSettings(std::move(e), 64);
    const LeadrShadingMaterial* made = nullptr;
    s.installMaterial = [&](vtkActor* actor, vtkRenderer* renderer,
                            const std::shared_ptr<EnvironmentLighting>& lighting)
    {
      lighting->prepare(EnvironmentSampling::Sources); // as the window's worker and the CLI
      std::shared_ptr<void> material = install(actor, renderer, lighting);
      made = static_cast<const LeadrShadingMaterial*>(material.get());
      EXPECT_EQ(made->readsResidual(), environmentLights);
      EXPECT_EQ(made->environmentLights().empty(), !environmentLights);
      return material;
    };
    const RenderResult result = renderOffscreen(s);
    EXPECT_EQ(nonFiniteValues(result.linear), 0);
    return coveredMean(result.linear);
  };
  const double withLights = render(env, true);
  const double whole = render(env, false);
  const double rest = render(residual, false);
  const double sunPart = whole - rest;
  std::printf("LEADR under a sky with a sun: mean %.4f with the sun as a light over the residual, "
              "%.4f with the whole environment, %.4f on the residual alone: the sun's part %.4f, "
              "the difference %.1f%% of it\n",
              withLights, whole, rest, sunPart, 100.0 * (withLights - whole) / sunPart);
  EXPECT_GT(sunPart, 0.3 * whole);
  EXPECT_LT(std::abs(withLights - whole), 0.05 * sunPart);
}
} // namespace
} // namespace aniso::test
