// Render tests of environment sampling `sources` (the environment's bright sources split off by
// its analysis, core/env/env_sources.h: the residual integrated by lobe samples, the sources by
// their own samples and the lobe's, combined by MIS) and of `auto`, against the CPU reference
// integrator. The built-in sphere seen from the front, F0 = 1, albedo 0, no jitter; the
// reference is the radiance of the analytic sphere hit by each compared pixel's centre ray
// (render_test_helpers.h). Metric: relative L2 over the compared pixels, over RGB.
#include "core/env/env_sources.h"
#include "core/env/environment.h"
#include "core/env/sun_sky.h"
#include "core/frame.h"
#include "core/reference/reference_integrator.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/MaterialShaderSource.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>
#include <vtkPolyData.h>

namespace aniso::test
{
namespace
{
constexpr int kSize = 48;
const char* const kCity = "/usr/share/blender/datafiles/studiolights/world/city.exr";

std::shared_ptr<SunSkyEnvironment> sunSky()
{
  return sunSkyEnvironment();
}

RenderSettings sphereSettings(std::shared_ptr<const Environment> env, const AsLobe& lobe,
                              int samples, int frames)
{
  RenderSettings s = sphereScene(std::move(env), lobe, kSize);
  s.cubeSize = 256;
  s.material.samples = samples;
  s.frames = frames;
  return s;
}

double measure(const char* label, const RenderSettings& settings,
               const std::vector<Compared>& pixels)
{
  const RenderResult result = renderOffscreen(settings);
  EXPECT_EQ(nonFiniteValues(result.linear), 0) << label;
  const double error = relativeL2(result.linear, pixels);
  std::printf("  %-44s relative L2 %.4f\n", label, error);
  return error;
}

RenderSettings withSampling(RenderSettings s, EnvironmentSampling sampling)
{
  s.material.environmentSampling = sampling;
  return s;
}

// GL-free: `sources` is a variant of the exact method only, compiled only when on.
TEST(SourcesVariant, IsAnExactVariantCompiledOnlyWhenOn)
{
  MaterialSettings s;
  s.environmentSampling = EnvironmentSampling::Sources;
  MaterialVariant v = materialVariant(s, true, true, true);
  EXPECT_TRUE(v.environmentSources);
  EXPECT_FALSE(v.environmentMis);
  EXPECT_NE(
      composeMaterialShaders(v).fragmentDeclarations.find("#define ANISO_ENVIRONMENT_SOURCES"),
      std::string::npos);
  s.method = SpecularMethod::SplitSum;
  EXPECT_FALSE(materialVariant(s, true, true, true).environmentSources);
  s.method = SpecularMethod::Exact;
  s.environmentSampling = EnvironmentSampling::Off;
  v = materialVariant(s, true, true, true);
  EXPECT_EQ(
      composeMaterialShaders(v).fragmentDeclarations.find("#define ANISO_ENVIRONMENT_SOURCES"),
      std::string::npos);
}

// GL-free: auto resolves by the environment's analysis (EnvAnalysis::concentrated): sources
// under the sun and sky and Blender's sunset, lobe samples alone under a uniform environment
// (nothing found) and the built-in studio (soft boxes only a few times the threshold).
TEST(SourcesVariant, AutoFollowsTheAnalysis)
{
  EnvironmentLighting sun(sunSky(), 16);
  EXPECT_TRUE(sun.analysis().concentrated());
  EXPECT_EQ(sun.resolveSampling(EnvironmentSampling::Auto), EnvironmentSampling::Sources);
  EXPECT_EQ(sun.resolveSampling(EnvironmentSampling::Mis), EnvironmentSampling::Mis);
  EnvironmentLighting white(openEnvironment("builtin:white"), 16);
  EXPECT_EQ(white.resolveSampling(EnvironmentSampling::Auto), EnvironmentSampling::Off);
  EXPECT_EQ(white.resolveSampling(EnvironmentSampling::Sources), EnvironmentSampling::Sources);
  // The built-in studio's soft boxes reach about 3 T: lobe sampling integrates them well.
  EnvironmentLighting studio(openEnvironment("builtin:studio"), 16);
  EXPECT_EQ(studio.resolveSampling(EnvironmentSampling::Auto), EnvironmentSampling::Off);
  // Sunset: a sun of 2.3% of the power at 449 T, which lobe samples miss.
  const std::string sunset = "/usr/share/blender/datafiles/studiolights/world/sunset.exr";
  if (std::filesystem::exists(sunset))
  {
    EnvironmentLighting lighting(openEnvironment(sunset), 16);
    EXPECT_EQ(lighting.resolveSampling(EnvironmentSampling::Auto), EnvironmentSampling::Sources);
  }
}

// GL-free: the split the renderer draws adds up to the environment: the residual cube's texels
// plus the excess, integrated over the sphere, give the environment's power within the cube's
// and grid's resolution (the excess by its texels' solid angles, the cube by its own).
TEST(SourcesVariant, TheSplitAddsUpToTheEnvironment)
{
  EnvironmentLighting lighting(sunSky(), 64);
  const EnvironmentLighting::SourceSplit& split = lighting.sourceSplit();
  auto cubePower = [](const Cubemap& cube)
  {
    double power = 0.0;
    for (int f = 0; f < 6; ++f)
    {
      for (int y = 0; y < cube.size; ++y)
      {
        for (int x = 0; x < cube.size; ++x)
        {
          const Image& face = cube.mips[0][std::size_t(f)];
          const double l = 0.2126 * face.at(x, y, 0) + 0.7152 * face.at(x, y, 1) +
                           0.0722 * face.at(x, y, 2);
          power += l * cubeTexelSolidAngle(x, y, cube.size);
        }
      }
    }
    return power;
  };
  const Image& excess = split.analysis->excess;
  double excessPower = 0.0;
  for (int y = 0; y < excess.height; ++y)
  {
    const double band = 2.0 * M_PI / excess.width *
                        (std::cos(M_PI * y / excess.height) - std::cos(M_PI * (y + 1) / excess.height));
    for (int x = 0; x < excess.width; ++x)
    {
      excessPower += band * (0.2126 * excess.at(x, y, 0) + 0.7152 * excess.at(x, y, 1) +
                             0.0722 * excess.at(x, y, 2));
    }
  }
  const auto env = sunSky();
  const double sun = env->sunSolidAngle() * 0.2126 * env->sun().radiance.x +
                     env->sunSolidAngle() * 0.7152 * env->sun().radiance.y +
                     env->sunSolidAngle() * 0.0722 * env->sun().radiance.z;
  const double sky = 4.0 * M_PI * (0.2126 * env->sky().x + 0.7152 * env->sky().y +
                                   0.0722 * env->sky().z);
  const double whole = cubePower(lighting.cubemap());
  const double parts = cubePower(split.residualCube) + excessPower;
  std::printf("power: analytic %.6g, cube %.6g, residual cube + excess %.6g (excess %.6g)\n",
              sun + sky, whole, parts, excessPower);
  EXPECT_NEAR(parts / (sun + sky), 1.0, 0.01);
  EXPECT_GT(excessPower, 0.9 * sun);
}

// A rough and a medium lobe next to a sun of 1e5 (the case lobe samples miss): at the same N
// (16 x 16) the split must beat lobe-only sampling severalfold (with the points the frame's
// pixels share, the default, and with each pixel's own source samples) and do at least as well
// as one-sample MIS of the whole environment; auto picks it, and converges below 1% (16 x 64).
class SourcesUnderTheSun : public ::testing::TestWithParam<AsLobe>
{
};

TEST_P(SourcesUnderTheSun, ConvergeBelowOnePercent)
{
  ANISO_REQUIRE_DISPLAY();
  const auto env = sunSky();
  const AsLobe lobe = GetParam();
  const RenderSettings base = sphereSettings(env, lobe, 16, 16);
  ReferenceOptions options;
  options.relativeTolerance = 1e-3;
  const std::vector<Compared> pixels = referencePixels(
      base, [&](const Frame& frame, const glm::dvec3& v)
      { return integrateSpecularSunSky(lobe, glm::dvec3(1.0), frame, v, *env, options); });
  ASSERT_GT(pixels.size(), 200u);
  std::printf("sun and sky, (%g, %g), %zu pixels, 16 x 16 samples, filtered:\n", lobe.nu,
              lobe.nv, pixels.size());
  const double off = measure("lobe only", withSampling(base, EnvironmentSampling::Off), pixels);
  const double mis = measure("MIS", withSampling(base, EnvironmentSampling::Mis), pixels);
  const double sources =
      measure("sources", withSampling(base, EnvironmentSampling::Sources), pixels);
  const double automatic = measure("auto", withSampling(base, EnvironmentSampling::Auto), pixels);
  // The other design of the sources' technique: each pixel's own source samples.
  RenderSettings perPixel = withSampling(base, EnvironmentSampling::Sources);
  perPixel.material.sharedSourcePoints = false;
  const double own = measure("sources, each pixel's own samples", perPixel, pixels);
  EXPECT_LT(own, off / 4.0);
  EXPECT_LT(sources, off / 4.0);
  EXPECT_LE(sources, 1.05 * mis);
  EXPECT_EQ(automatic, sources); // the same variant, the same image
  RenderSettings converged = withSampling(base, EnvironmentSampling::Auto);
  converged.frames = 64;
  EXPECT_LT(measure("auto, 16 x 64 samples", converged, pixels), 0.01);
}

INSTANTIATE_TEST_SUITE_P(Lobes, SourcesUnderTheSun,
                         ::testing::Values(AsLobe{10.0, 10.0}, AsLobe{1000.0, 100.0}));

// Blender's city HDRI (a sun of about 3.4e4 in a 1024 x 512 image), the default settings
// (filtered, LUT half vectors, auto): converged, the render agrees with the reference
// integrating the image itself: lobe samples alone stay far off at 16 x 16 samples, auto
// (sources) gets below a quarter of their error and converges below 1% (16 x 64). Most of the
// sphere's pixels here (82%, counted with a build that writes the choice out) see too little
// of the sources to take source samples and take them by their lobe samples alone
// (lobeSamplesSuffice): that path is what converges to the reference there.
TEST(SourcesUnderAnHdri, CityConvergesWithTheDefaults)
{
  ANISO_REQUIRE_DISPLAY();
  if (!std::filesystem::exists(kCity))
  {
    GTEST_SKIP() << kCity << " is not installed (package blender-data)";
  }
  const std::shared_ptr<Environment> env = openEnvironment(kCity);
  const AsLobe lobe{1000.0, 100.0};
  RenderSettings base = sphereSettings(env, lobe, 16, 16);
  base.material.environmentSampling = EnvironmentSampling::Auto;
  ReferenceOptions options;
  options.relativeTolerance = 1e-3;
  const std::vector<Compared> pixels = referencePixels(
      base, [&](const Frame& frame, const glm::dvec3& v)
      { return integrateSpecular(lobe, glm::dvec3(1.0), frame, v, *env, options); });
  ASSERT_GT(pixels.size(), 200u);
  std::printf("city, (1000, 100), %zu pixels, 16 x 16 samples, filtered:\n", pixels.size());
  const double off = measure("lobe only", withSampling(base, EnvironmentSampling::Off), pixels);
  const double automatic = measure("auto (sources)", base, pixels);
  EXPECT_LT(automatic, off / 4.0);
  RenderSettings converged = base;
  converged.frames = 64;
  EXPECT_LT(measure("auto (sources), 16 x 64 samples", converged, pixels), 0.01);
}
} // namespace
} // namespace aniso::test
