#include "core/reference/mc_estimator.h"

#include "core/error.h"
#include "core/sampling/hammersley.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

namespace aniso
{
namespace
{
// One lobe sample: the light direction (tangent space), f (n.l) / pdf as the shader weighs it,
// and f (n.l) for the MIS combinations. A direction below the horizon carries nothing.
struct LobeSample
{
  glm::dvec3 l{0.0, 0.0, 1.0};
  glm::dvec3 weight{0.0};
  bool valid = false;
};

// The model-specific part: Ashikhmin-Shirley.
struct AsModel
{
  const AsLobe& lobe;
  const glm::dvec3& f0;
  const glm::dvec3& v;

  LobeSample sample(const glm::dvec2& xi) const
  {
    LobeSample s;
    const glm::dvec3 h = sampleHalfVector(lobe, xi);
    const double vDotH = glm::dot(v, h);
    s.l = reflectAbout(v, h);
    if (!(vDotH > 0.0) || !(s.l.z > 0.0))
      return s;
    s.valid = true;
    s.weight = schlickFresnel(f0, vDotH) * (s.l.z / std::max(s.l.z, v.z));
    return s;
  }
  double pdf(const glm::dvec3& l) const { return pdfLight(lobe, v, l); }
  glm::dvec3 brdfCos(const glm::dvec3& l) const { return evalSpecular(lobe, f0, v, l) * l.z; }
};

// The model-specific part: GGX with visible-normal sampling.
struct GgxModel
{
  const GgxLobe& lobe;
  const glm::dvec3& f0;
  const glm::dvec3& v;

  LobeSample sample(const glm::dvec2& xi) const
  {
    LobeSample s;
    const glm::dvec3 h = sampleVisibleNormal(lobe, v, xi);
    const double vDotH = glm::dot(v, h);
    s.l = reflectAbout(v, h);
    if (!(vDotH > 0.0) || !(s.l.z > 0.0))
      return s;
    s.valid = true;
    // f (n.l) / pdf = F G2 / G1(v): D and the Jacobian cancel.
    s.weight =
        schlickFresnel(f0, vDotH) * (ggxMaskingShadowing(lobe, v, s.l) / ggxMasking(lobe, v));
    return s;
  }
  double pdf(const glm::dvec3& l) const { return pdfLight(lobe, v, l); }
  glm::dvec3 brdfCos(const glm::dvec3& l) const { return evalSpecular(lobe, f0, v, l) * l.z; }
};

// Second point set of two-sample MIS: the first one shifted by a fixed R2 step, so the two
// techniques do not reuse the same points.
glm::dvec2 secondShift(const glm::dvec2& shift)
{
  return cranleyPatterson(shift, frameShift(1));
}

// Lobe samples of two-sample MIS: the nearest count to N times the fraction, at least one when
// the fraction is positive (so N = 1 with the default 1/2 is one lobe sample).
uint32_t twoSampleLobeCount(uint32_t n, double fraction)
{
  if (fraction <= 0.0)
    return 0;
  const long nearest = std::lround(double(n) * fraction);
  return uint32_t(std::clamp<long>(nearest, 1, long(n)));
}

double heuristic(SamplingStrategy strategy, double mine, double other)
{
  if (strategy == SamplingStrategy::MisPower)
  {
    mine *= mine;
    other *= other;
  }
  const double sum = mine + other;
  return sum > 0.0 ? mine / sum : 0.0;
}

template <class Model>
glm::dvec3 estimate(const Model& model, const Frame& frame, const Environment& env,
                    const EnvironmentDistribution* distribution, const EstimatorOptions& options)
{
  const uint32_t n = options.samples;
  const SamplingStrategy strategy = options.strategy;
  glm::dvec3 sum(0.0);
  auto radiance = [&](const glm::dvec3& local) { return env.radiance(frame.toWorld(local)); };

  // Lobe samples: alone, or MIS-weighted against the environment density.
  auto lobeSamples = [&](uint32_t count, double lobeCount, double envCount)
  {
    for (uint32_t i = 0; i < count; ++i)
    {
      const LobeSample s = model.sample(cranleyPatterson(hammersley(i, count), options.shift));
      if (!s.valid)
        continue;
      if (envCount == 0.0)
      {
        sum += s.weight * radiance(s.l);
        continue;
      }
      const double pLobe = model.pdf(s.l);
      const double pEnv = distribution->pdf(frame.toWorld(s.l));
      const double w = heuristic(strategy, lobeCount * pLobe, envCount * pEnv);
      // w f (n.l) / pLobe, with f (n.l) / pLobe taken from the sample (no division by a pdf).
      sum += w * s.weight * radiance(s.l);
    }
  };
  // Environment samples, weighted likewise.
  auto envSamples = [&](uint32_t count, double lobeCount, double envCount, const glm::dvec2& shift)
  {
    for (uint32_t i = 0; i < count; ++i)
    {
      const EnvSample e = distribution->sample(cranleyPatterson(hammersley(i, count), shift));
      const glm::dvec3 l = frame.toLocal(e.direction);
      if (!(l.z > 0.0) || !(e.pdf > 0.0))
        continue;
      const glm::dvec3 value = model.brdfCos(l) * env.radiance(e.direction);
      if (lobeCount == 0.0)
      {
        sum += value / e.pdf;
        continue;
      }
      const double w = heuristic(strategy, envCount * e.pdf, lobeCount * model.pdf(l));
      sum += (w / e.pdf) * value;
    }
  };

  switch (strategy)
  {
  case SamplingStrategy::Brdf:
    lobeSamples(n, double(n), 0.0);
    return sum / double(n);
  case SamplingStrategy::Environment:
    envSamples(n, 0.0, double(n), options.shift);
    return sum / double(n);
  case SamplingStrategy::MisBalance:
  case SamplingStrategy::MisPower:
  {
    // Each technique's sum is divided by its own count: (1/n_i) sum w_i f L (n.l) / p_i.
    const uint32_t lobeCount = twoSampleLobeCount(n, options.lobeFraction);
    const uint32_t envCount = n - lobeCount;
    glm::dvec3 lobePart(0.0);
    if (lobeCount > 0)
    {
      lobeSamples(lobeCount, double(lobeCount), double(envCount));
      lobePart = sum / double(lobeCount);
    }
    sum = glm::dvec3(0.0);
    if (envCount > 0)
      envSamples(envCount, double(lobeCount), double(envCount), secondShift(options.shift));
    return lobePart + (envCount > 0 ? sum / double(envCount) : glm::dvec3(0.0));
  }
  case SamplingStrategy::MisOneSample:
  {
    const double c = options.lobeFraction;
    for (uint32_t i = 0; i < n; ++i)
    {
      const glm::dvec2 p = cranleyPatterson(hammersley(i, n), options.shift);
      glm::dvec3 l(0.0);
      if (p.x < c)
      {
        const LobeSample s = model.sample({p.x / c, p.y});
        if (!s.valid)
          continue;
        l = s.l;
      }
      else
      {
        l = frame.toLocal(distribution->sample({(p.x - c) / (1.0 - c), p.y}).direction);
        if (!(l.z > 0.0))
          continue;
      }
      const double mixture = c * model.pdf(l) + (1.0 - c) * distribution->pdf(frame.toWorld(l));
      if (mixture > 0.0)
        sum += model.brdfCos(l) * radiance(l) / mixture;
    }
    return sum / double(n);
  }
  }
  return sum;
}

void validateEstimate(const glm::dvec3& f0, const glm::dvec3& viewWorld,
                      const EnvironmentDistribution* distribution, const EstimatorOptions& options)
{
  for (int c = 0; c < 3; ++c)
    if (!(f0[c] >= 0.0 && f0[c] <= 1.0))
      throw errorAbout("F0", "must be in [0, 1] per channel");
  const double length = glm::length(viewWorld);
  if (!std::isfinite(length) || !(length > 0.0))
    throw errorAbout("view", "must be a finite non-zero vector");
  if (options.samples == 0)
    throw errorAbout("samples", "must be at least 1");
  if (!(options.lobeFraction >= 0.0 && options.lobeFraction <= 1.0))
    throw errorAbout("lobeFraction", "must be in [0, 1]");
  if (options.strategy != SamplingStrategy::Brdf && distribution == nullptr)
    throw errorAbout("environment distribution",
                     std::string("required by strategy ") + strategyName(options.strategy));
}
// Validates the inputs common to both models, then estimates for a view above the surface
// (below it nothing is reflected).
template <class Model, class Lobe>
glm::dvec3 estimateAbove(const Lobe& lobe, const glm::dvec3& f0, const Frame& frame,
                         const glm::dvec3& viewWorld, const Environment& env,
                         const EnvironmentDistribution* distribution,
                         const EstimatorOptions& options)
{
  validateEstimate(f0, viewWorld, distribution, options);
  const glm::dvec3 v = glm::normalize(frame.toLocal(glm::normalize(viewWorld)));
  if (!(v.z > 0.0))
    return glm::dvec3(0.0);
  return estimate(Model{lobe, f0, v}, frame, env, distribution, options);
}
} // namespace

const char* strategyName(SamplingStrategy strategy)
{
  switch (strategy)
  {
  case SamplingStrategy::Brdf:
    return "brdf";
  case SamplingStrategy::Environment:
    return "env";
  case SamplingStrategy::MisBalance:
    return "mis-balance";
  case SamplingStrategy::MisPower:
    return "mis-power";
  case SamplingStrategy::MisOneSample:
    return "mis-one-sample";
  }
  return "unknown";
}

glm::dvec3 estimateSpecular(const AsLobe& lobe, const glm::dvec3& f0, const Frame& frame,
                            const glm::dvec3& viewWorld, const Environment& env,
                            const EnvironmentDistribution* distribution,
                            const EstimatorOptions& options)
{
  validateLobe(lobe);
  return estimateAbove<AsModel>(lobe, f0, frame, viewWorld, env, distribution, options);
}

glm::dvec3 estimateSpecularGgx(const GgxLobe& lobe, const glm::dvec3& f0, const Frame& frame,
                               const glm::dvec3& viewWorld, const Environment& env,
                               const EnvironmentDistribution* distribution,
                               const EstimatorOptions& options)
{
  validateGgxLobe(lobe);
  return estimateAbove<GgxModel>(lobe, f0, frame, viewWorld, env, distribution, options);
}
} // namespace aniso
