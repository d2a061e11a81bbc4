// The still view that stops by its own error (vtkAnisoAccumulationPass::SetErrorTarget,
// core/quality/error_estimate.h: the mean against the mean of its first half), against the CPU
// reference integrator: the sphere of the sampling tests (render_test_helpers.h: F0 = 1, no
// jitter), the reference at the centre rays of every other pixel. What is checked:
//   - with an error target the frames stop before the most allowed, at a checkpoint whose
//     estimate is at or below 3/4 of the target (kErrorStopShare), and the error against the
//     reference is then at or below the target;
//   - the estimate tracks the error against the reference (within 0.6x to 2x of it), and a
//     tighter target takes more frames to a smaller error;
//   - without a target nothing is estimated and the frame count alone stops the view;
//   - under Blender's city HDRI (a sun; the defaults: filtered, LUT half vectors, auto sampling)
//     the sharpest benchmark lobe, stopped from 256 samples a pixel on as the window stops, is
//     within 1% of the reference. (Stopped after 8 frames it was not: the estimate there was
//     half the error, core/quality/error_estimate.h.)
#include "core/env/environment.h"
#include "core/frame.h"
#include "core/quality/error_estimate.h"
#include "core/reference/reference_integrator.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <memory>
#include <vector>

namespace aniso::test
{
namespace
{
constexpr int kSize = 48;
const char* const kCity = "/usr/share/blender/datafiles/studiolights/world/city.exr";

struct Stopped
{
  int frames = 0;
  double estimate = -1.0;
  int estimateFrames = 0;
  double error = 0.0; // against the reference
};

Stopped runToTarget(RenderSettings s, double target, int mostFrames,
                    const std::vector<Compared>& pixels, int fromFrames = 4)
{
  s.errorTarget = target;
  s.errorStopFrames = fromFrames;
  s.frames = mostFrames;
  const RenderResult result = renderOffscreen(s);
  Stopped stopped;
  stopped.frames = static_cast<int>(result.frameSeconds.size());
  stopped.estimate = result.estimatedError;
  stopped.estimateFrames = result.estimatedErrorFrames;
  stopped.error = relativeL2(result.linear, pixels);
  std::printf("  target %.3f: stopped after %d of at most %d frames, estimate %.4f (after %d), "
              "against the reference %.4f\n",
              target, stopped.frames, mostFrames, stopped.estimate, stopped.estimateFrames,
              stopped.error);
  return stopped;
}

std::vector<Compared> sphereReference(const RenderSettings& s, const Environment& env,
                                     double tolerance)
{
  ReferenceOptions options;
  options.relativeTolerance = tolerance;
  const AsLobe lobe = s.material.lobe;
  return referencePixels(s,
                         [&](const Frame& frame, const glm::dvec3& v) {
                           return integrateSpecular(lobe, glm::dvec3(1.0), frame, v, env, options);
                         });
}

TEST(ConvergeByError, StopsAtTheTargetWithTheEstimateTrackingTheError)
{
  ANISO_REQUIRE_DISPLAY();
  const std::shared_ptr<Environment> env = openEnvironment("builtin:studio");
  RenderSettings s = sphereScene(env, AsLobe{1000.0, 100.0}, kSize);
  s.cubeSize = 256;
  s.material.samples = 16;
  const std::vector<Compared> pixels = sphereReference(s, *env, 1e-3);
  ASSERT_GT(pixels.size(), 200u);
  std::printf("builtin:studio, (1000, 100), %zu pixels, frames of 16 samples:\n", pixels.size());

  const Stopped loose = runToTarget(s, 0.02, 64, pixels);
  EXPECT_LT(loose.frames, 64);
  EXPECT_EQ(loose.estimateFrames, loose.frames);
  EXPECT_GE(loose.estimate, 0.0);
  EXPECT_LE(loose.estimate, kErrorStopShare * 0.02);
  EXPECT_LE(loose.error, 0.02);
  EXPECT_GE(loose.estimate, 0.6 * loose.error);
  EXPECT_LE(loose.estimate, 2.0 * loose.error);

  const Stopped tight = runToTarget(s, 0.005, 64, pixels);
  EXPECT_LT(tight.frames, 64);
  EXPECT_GT(tight.frames, loose.frames);
  EXPECT_LE(tight.estimate, kErrorStopShare * 0.005);
  EXPECT_LT(tight.error, loose.error);
  EXPECT_LE(tight.error, 0.005);
  EXPECT_GE(tight.estimate, 0.6 * tight.error);
  EXPECT_LE(tight.estimate, 2.0 * tight.error);

  // No target: no estimate, and every frame asked for.
  const Stopped counted = runToTarget(s, 0.0, 6, pixels);
  EXPECT_EQ(counted.frames, 6);
  EXPECT_LT(counted.estimate, 0.0);
  EXPECT_EQ(counted.estimateFrames, 0);
}

TEST(ConvergeByError, CityStopsAtOnePercentWithTheDefaults)
{
  ANISO_REQUIRE_DISPLAY();
  if (!std::filesystem::exists(kCity))
  {
    GTEST_SKIP() << kCity << " is not installed (package blender-data)";
  }
  const std::shared_ptr<Environment> env = openEnvironment(kCity);
  RenderSettings s = sphereScene(env, AsLobe{20000.0, 70.0}, kSize);
  s.cubeSize = 256;
  s.material.samples = 16;
  s.material.environmentSampling = EnvironmentSampling::Auto;
  // Each pixel to 2e-3 (its share of the sun is what costs): far below the 1% judged.
  const std::vector<Compared> pixels = sphereReference(s, *env, 2e-3);
  ASSERT_GT(pixels.size(), 200u);
  std::printf("city, (20000, 70), %zu pixels, frames of 16 samples:\n", pixels.size());
  // From 256 samples a pixel on, as the window and `aniso render --converge` stop.
  const Stopped stopped = runToTarget(s, 0.01, 256, pixels, minimumErrorStopFrames(16));
  EXPECT_EQ(minimumErrorStopFrames(16), 16);
  EXPECT_GE(stopped.frames, 16);
  EXPECT_LT(stopped.frames, 256);
  EXPECT_LE(stopped.estimate, kErrorStopShare * 0.01);
  EXPECT_LE(stopped.error, 0.01);
}
} // namespace
} // namespace aniso::test
