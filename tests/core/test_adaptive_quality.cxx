// The adaptive quality control (quality/adaptive_quality.h):
//   - the sample count it chooses is the fewest whose predicted error meets the target (the
//     model's own prediction at N and N - 1), sharper lobes never need more samples, and bad
//     targets are refused;
//   - the model, fitted to GPU renders by `aniso bench`, against an independent measurement:
//     the CPU `exact` estimator (core/reference/mc_estimator, the same unrotated Hammersley set
//     a single frame uses) at the chosen N, on points of the unit sphere seen from -Y under the
//     built-in studio, has a relative L2 error against the reference integrator within a factor
//     2.5 of the target (measured: 0.5 to 2 times).
#include "core/env/environment.h"
#include "core/error.h"
#include "core/frame.h"
#include "core/quality/adaptive_quality.h"
#include "core/reference/mc_estimator.h"
#include "core/reference/reference_integrator.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <vector>

namespace aniso
{
namespace
{
const AsLobe kLobes[] = {{10.0, 10.0},    {30.0, 30.0},    {100.0, 10.0}, {300.0, 300.0},
                         {1000.0, 100.0}, {20000.0, 70.0}, {1e5, 1e5}};

TEST(AdaptiveQuality, ChoosesTheFewestSamplesMeetingTheTarget)
{
  for (const AsLobe& lobe : kLobes)
  {
    for (bool filtered : {false, true})
    {
      for (double target : {0.2, 0.05, 0.01, 0.003})
      {
        const QualityChoice q = chooseSamples(target, lobe, filtered);
        ASSERT_GE(q.samples, 1);
        ASSERT_LE(q.samples, kMaxQualitySamples);
        EXPECT_DOUBLE_EQ(q.predictedError, predictedError(lobe, filtered, q.samples));
        if (q.reachable)
        {
          EXPECT_LE(q.predictedError, target);
          if (q.samples > 1)
          {
            EXPECT_GT(predictedError(lobe, filtered, q.samples - 1), target);
          }
        }
        else
        {
          EXPECT_EQ(q.samples, kMaxQualitySamples);
          EXPECT_GT(q.predictedError, target);
        }
      }
    }
  }
}

TEST(AdaptiveQuality, SharperLobesNeedNoMoreSamples)
{
  // kLobes is ordered by sqrt((n_u + 1)(n_v + 1)), the width the model interpolates in.
  for (bool filtered : {false, true})
  {
    int previous = kMaxQualitySamples;
    for (const AsLobe& lobe : kLobes)
    {
      const int samples = chooseSamples(0.01, lobe, filtered).samples;
      EXPECT_LE(samples, previous) << lobe.nu << ", " << lobe.nv;
      previous = samples;
    }
  }
}

TEST(AdaptiveQuality, RefusesBadTargetsAndLobes)
{
  for (double target : {0.0, -0.01, 1.5, std::nan(""), double(INFINITY)})
  {
    EXPECT_THROW(chooseSamples(target, {100.0, 100.0}, true), Error) << target;
  }
  EXPECT_THROW(chooseSamples(0.01, {-1.0, 100.0}, true), Error);
}

TEST(AdaptiveQuality, AgreesWithTheCpuEstimator)
{
  const StudioEnvironment env;
  const glm::dvec3 f0(0.913, 0.922, 0.924);
  for (const AsLobe lobe : {AsLobe{100.0, 10.0}, AsLobe{20000.0, 70.0}})
  {
    struct Point
    {
      Frame frame;
      glm::dvec3 reference;
    };
    // A 10 x 10 grid over the sphere's disc seen from -Y (away from the silhouette and the
    // poles), tangents along the parallels as on the built-in sphere.
    const glm::dvec3 view(0.0, -1.0, 0.0);
    std::vector<Point> points;
    for (int i = 0; i < 10; ++i)
    {
      for (int j = 0; j < 10; ++j)
      {
        const double x = -0.9 + 1.8 * (i + 0.5) / 10.0;
        const double z = -0.9 + 1.8 * (j + 0.5) / 10.0;
        if (x * x + z * z > 0.9)
        {
          continue;
        }
        const glm::dvec3 n(x, -std::sqrt(1.0 - x * x - z * z), z);
        ReferenceOptions options;
        options.relativeTolerance = 3e-3;
        const Frame frame = Frame::fromNormalTangent(n, {-n.y, n.x, 0.0});
        points.push_back({frame, integrateSpecular(lobe, f0, frame, view, env, options).value});
      }
    }
    for (double target : {0.1, 0.03})
    {
      const QualityChoice q = chooseSamples(target, lobe, false);
      double error = 0.0;
      double norm = 0.0;
      for (const Point& p : points)
      {
        EstimatorOptions options;
        options.samples = static_cast<uint32_t>(q.samples);
        const glm::dvec3 d =
            estimateSpecular(lobe, f0, p.frame, view, env, nullptr, options) - p.reference;
        error += glm::dot(d, d);
        norm += glm::dot(p.reference, p.reference);
      }
      const double measured = std::sqrt(error / norm);
      EXPECT_GT(measured, target / 2.5) << lobe.nu << ", " << lobe.nv << " N=" << q.samples;
      EXPECT_LT(measured, target * 2.5) << lobe.nu << ", " << lobe.nv << " N=" << q.samples;
    }
  }
}
} // namespace
} // namespace aniso
