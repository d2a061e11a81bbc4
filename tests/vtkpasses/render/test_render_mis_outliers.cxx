// Environment MIS next to a small bright source (the 1e5 sun of `builtin:sunsky`), on the
// default cube map of 256^2 per face, whose texels are wider than the 1024 x 512 grid of the
// environment distribution (docs/BENCHMARKS.md, "MIS outliers next to the sun"):
// - unfiltered, the cube's bilinear reach of the sun lies partly on grid texels of sky density;
//   lobe samples landing there carried up to L_sun / c: single-pixel spikes. Checked: no pixel
//   above 8 times the median of its 3 x 3 neighbourhood (the old density gave 16 over three
//   lobes at 256 x 256, 4 frames of 16 samples);
// - filtered, the level of a lobe sample next to the sun (low mixture density, a coarse level)
//   blurred the sun into sky directions, which MIS weighs as sky: the sun counted once more
//   (the image 1.7 to 1.9 times too bright). Checked: relative L2 against the CPU reference
//   integrator.
// The built-in sphere, F0 = 1, albedo 0, fixed camera, no jitter; references as in
// test_render_sampling (the analytic sphere, frame n = p, t along the parallels).
#include "core/env/environment.h"
#include "core/env/sun_sky.h"
#include "core/frame.h"
#include "core/reference/reference_integrator.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <gtest/gtest.h>
#include <memory>
#include <vector>
#include <vtkPolyData.h>

namespace aniso::test
{
namespace
{
RenderSettings misSettings(const AsLobe& lobe, int size, bool filtered, int frames)
{
  RenderSettings s = sphereScene(sunSkyEnvironment(), lobe, size);
  s.cubeSize = 256; // the default, 1.3 grid texels per cube texel at a face's centre
  s.material.filtered = filtered;
  s.material.halfVectors = HalfVectorSource::Shader;
  s.material.samples = 16;
  s.material.environmentSampling = EnvironmentSampling::Mis;
  s.frames = frames;
  return s;
}

double luminance(const Image& image, int x, int y)
{
  return 0.2126 * image.at(x, y, 0) + 0.7152 * image.at(x, y, 1) + 0.0722 * image.at(x, y, 2);
}

// Covered pixels whose 3 x 3 neighbourhood is covered and whose luminance exceeds `factor` times
// the neighbourhood's median.
int outliers(const Image& image, double factor)
{
  int count = 0;
  for (int y = 1; y + 1 < image.height; ++y)
  {
    for (int x = 1; x + 1 < image.width; ++x)
    {
      std::array<double, 9> around{};
      bool covered = true;
      for (int k = 0; k < 9; ++k)
      {
        covered = covered && image.at(x + k % 3 - 1, y + k / 3 - 1, 3) == 1.0f;
        around[std::size_t(k)] = luminance(image, x + k % 3 - 1, y + k / 3 - 1);
      }
      if (!covered)
      {
        continue;
      }
      std::nth_element(around.begin(), around.begin() + 4, around.end());
      if (luminance(image, x, y) > factor * around[4])
      {
        ++count;
      }
    }
  }
  return count;
}

TEST(RenderMisOutliers, NoSinglePixelSpikesNextToTheSun)
{
  ANISO_REQUIRE_DISPLAY();
  int total = 0;
  for (const AsLobe lobe : {AsLobe{10.0, 10.0}, AsLobe{100.0, 10.0}, AsLobe{1000.0, 100.0}})
  {
    const RenderResult result = renderOffscreen(misSettings(lobe, 256, false, 4));
    EXPECT_EQ(nonFiniteValues(result.linear), 0);
    const int count = outliers(result.linear, 8.0);
    std::printf("  (%g, %g), unfiltered, 256 x 256, 16 x 4 samples: %d pixels above 8x their "
                "3 x 3 median\n",
                lobe.nu, lobe.nv, count);
    total += count;
    if (count > 0)
    {
      keepImages("mis_outliers", result.linear, result.linear);
    }
  }
  EXPECT_EQ(total, 0);
}

// Filtered lookups (the default) with MIS converge to the reference, as unfiltered ones do.
TEST(RenderMisOutliers, FilteredMisMatchesTheReference)
{
  ANISO_REQUIRE_DISPLAY();
  const auto env = sunSkyEnvironment();
  ASSERT_TRUE(env);
  for (const AsLobe lobe : {AsLobe{10.0, 10.0}, AsLobe{1000.0, 100.0}})
  {
    const RenderSettings filtered = misSettings(lobe, 48, true, 16);
    ReferenceOptions options;
    options.relativeTolerance = 2e-3;
    const std::vector<Compared> pixels = referencePixels(
        filtered, [&](const Frame& frame, const glm::dvec3& v)
        { return integrateSpecularSunSky(lobe, glm::dvec3(1.0), frame, v, *env, options); });
    ASSERT_GT(pixels.size(), 200u);
    double sums[3] = {0.0, 0.0, 0.0}; // reference, filtered, unfiltered
    double errors[2] = {0.0, 0.0};
    int index = 0;
    for (bool f : {true, false})
    {
      const RenderResult result = renderOffscreen(misSettings(lobe, 48, f, 16));
      EXPECT_EQ(nonFiniteValues(result.linear), 0);
      errors[index] = relativeL2(result.linear, pixels);
      for (const Compared& p : pixels)
      {
        sums[index + 1] += luminance(result.linear, p.x, p.y);
        sums[0] += index == 0 ? 0.2126 * p.reference.x + 0.7152 * p.reference.y +
                                    0.0722 * p.reference.z
                              : 0.0;
      }
      ++index;
    }
    std::printf("  (%g, %g), 48 x 48, 16 x 16 samples, %zu pixels: relative L2 filtered %.4f, "
                "unfiltered %.4f; mean over reference: filtered %.3f, unfiltered %.3f\n",
                lobe.nu, lobe.nv, pixels.size(), errors[0], errors[1], sums[1] / sums[0],
                sums[2] / sums[0]);
    EXPECT_LT(errors[0], 0.1) << lobe.nu;
    EXPECT_LT(errors[0], 1.5 * errors[1] + 0.01) << lobe.nu;
    EXPECT_NEAR(sums[1] / sums[0], 1.0, 0.05) << lobe.nu;
  }
}
} // namespace
} // namespace aniso::test
