// Error against sample count for the specular sampling strategies on the CPU: lobe-only
// (the published method's `exact` estimator), environment-only, and their MIS combinations,
// measured against the converged reference integrator, for a rough and a sharp lobe under the
// studio and under a sun of 1e5 over a sky of 1. Prints Markdown tables (docs/BENCHMARKS.md).
//
// The shading points are those of a unit sphere seen from -Y: normals on a Fibonacci spiral over
// the visible hemisphere, tangents along the parallels (Z up), the view towards the camera. Each
// point gets `rotations` independent Cranley-Patterson rotations of its N-point set. Errors are
// relative to the reference: "L2" = sqrt(sum (estimate - reference)^2 / sum reference^2) over
// points and rotations (as the renderer's relative L2 over covered pixels), "median" = the median
// over points and rotations of |estimate - reference| / reference (what a typical pixel shows).
//
// With --split it compares instead the choices of the lobe share c of one-sample MIS (the
// shader's strategy): the share from the lobe's width alone (the rule used before), and the
// share misLobeFraction derives from the lobe and the environment's densities, next to lobe
// sampling alone, for four lobes at equal sample counts.
//
// Usage: bench_variance [--rotations K] [--points P] [--split]
#include "bench/mis_width_rule.h"
#include "core/brdf/ashikhmin_shirley.h"
#include "core/env/env_sampling.h"
#include "core/env/environment.h"
#include "core/env/sun_sky.h"
#include "core/frame.h"
#include "core/reference/mc_estimator.h"
#include "core/reference/reference_integrator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;

double luminance(const glm::dvec3& c)
{
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

struct Point
{
  aniso::Frame frame;
  glm::dvec3 view; // world, towards the camera
};

// Normals on the hemisphere facing the camera at -Y (Fibonacci spiral, even in solid angle),
// kept away from the silhouette (n.v >= 0.1) where every strategy is dominated by the horizon.
std::vector<Point> spherePoints(int count)
{
  const glm::dvec3 toCamera(0.0, -1.0, 0.0);
  std::vector<Point> points;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i)
  {
    const double c = 1.0 - (i + 0.5) / count * 0.9; // n.v in [0.1, 1]
    const double s = std::sqrt(1.0 - c * c);
    const double a = golden * i;
    // Around the view axis: n = c (-Y) + s (cos a X + sin a Z).
    const glm::dvec3 n =
        c * toCamera + s * (std::cos(a) * glm::dvec3(1, 0, 0) + std::sin(a) * glm::dvec3(0, 0, 1));
    // Tangent along the parallel (longitude direction of the built-in sphere).
    glm::dvec3 t = glm::cross(glm::dvec3(0, 0, 1), n);
    if (glm::length(t) < 1e-9)
      t = glm::dvec3(1, 0, 0);
    points.push_back({aniso::Frame::fromNormalTangent(n, t), toCamera});
  }
  return points;
}

struct Scene
{
  std::string name;
  std::shared_ptr<aniso::Environment> env;
  std::shared_ptr<aniso::SunSkyEnvironment> sunSky;
  std::shared_ptr<const aniso::EnvironmentDistribution> distribution;
  double bakeSeconds = 0.0;
};

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Scene makeScene(const std::string& name)
{
  Scene s;
  s.name = name;
  aniso::EnvSamplingOptions options;
  if (name == "studio")
  {
    s.env = std::make_shared<aniso::StudioEnvironment>();
    options.width = 512;
    options.supersample = 2;
  }
  else
  {
    // The sun high in front of the sphere, so it reflects in part of the visible points.
    s.sunSky = std::make_shared<aniso::SunSkyEnvironment>(
        glm::dvec3(0.3, -0.6, 0.74), aniso::SunSkyEnvironment::kSunAngularRadius, glm::dvec3(1e5),
        glm::dvec3(1.0));
    s.env = s.sunSky;
    options.width = 1024;
    options.supersample = 4;
  }
  const auto start = std::chrono::steady_clock::now();
  s.distribution = aniso::sharedDistribution(*s.env, options);
  s.bakeSeconds = secondsSince(start);
  return s;
}

struct Method
{
  aniso::SamplingStrategy strategy;
  double lobeFraction;
  const char* name;
};

struct Row
{
  std::string scene;
  std::string lobe;
  const char* method;
  uint32_t samples;
  double l2;
  double median;
  double nsPerSample;
};
// Converged references (luminance) at each point, to 1e-5 relative (below the smallest error
// reported); *worst receives the largest relative error estimate.
std::vector<double> references(const Scene& scene, const aniso::AsLobe& lobe, const glm::dvec3& f0,
                               const std::vector<Point>& points, double* worst)
{
  std::vector<double> reference;
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-5;
  for (const Point& p : points)
  {
    const aniso::ReferenceResult r =
        scene.sunSky
            ? aniso::integrateSpecularSunSky(lobe, f0, p.frame, p.view, *scene.sunSky, options)
            : aniso::integrateSpecular(lobe, f0, p.frame, p.view, *scene.env, options);
    reference.push_back(luminance(r.value));
    *worst = std::max(*worst, r.errorEstimate / std::max(luminance(r.value), 1e-300));
  }
  return reference;
}

struct Errors
{
  double l2 = 0.0;
  double median = 0.0;
};

// Relative L2 and median relative error of one strategy at N samples over the points, each with
// `rotations` random Cranley-Patterson shifts (the same shifts for every strategy).
Errors measure(const Scene& scene, const aniso::AsLobe& lobe, const glm::dvec3& f0,
               const std::vector<Point>& points, const std::vector<double>& reference,
               aniso::SamplingStrategy strategy, double lobeFraction, uint32_t n, int rotations)
{
  std::mt19937_64 random(1234);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  aniso::EstimatorOptions options;
  options.strategy = strategy;
  options.lobeFraction = lobeFraction;
  options.samples = n;
  double squaredError = 0.0;
  double squaredReference = 0.0;
  std::vector<double> relative;
  for (std::size_t k = 0; k < points.size(); ++k)
    for (int r = 0; r < rotations; ++r)
    {
      options.shift = {uniform(random), uniform(random)};
      const double value =
          luminance(aniso::estimateSpecular(lobe, f0, points[k].frame, points[k].view, *scene.env,
                                            scene.distribution.get(), options));
      squaredError += (value - reference[k]) * (value - reference[k]);
      squaredReference += reference[k] * reference[k];
      relative.push_back(std::abs(value - reference[k]) / reference[k]);
    }
  std::nth_element(relative.begin(), relative.begin() + relative.size() / 2, relative.end());
  return {std::sqrt(squaredError / squaredReference), relative[relative.size() / 2]};
}

// The --split table: lobe only, one-sample MIS with the width rule's share and with
// misLobeFraction's, at equal N.
void compareSplits(const std::vector<Point>& points, int rotations, const glm::dvec3& f0)
{
  const aniso::AsLobe lobes[] = {{10, 10}, {100, 10}, {1000, 100}, {20000, 70}};
  const uint32_t counts[] = {16, 64, 256};
  std::printf("\n| Environment | Lobe | c width rule | c new | Strategy |");
  for (uint32_t n : counts)
    std::printf(" N=%u |", n);
  std::printf("\n| --- | --- | --- | --- | --- |");
  for (std::size_t i = 0; i < std::size(counts); ++i)
    std::printf(" --- |");
  std::printf("\n");
  for (const char* sceneName : {"studio", "sun+sky"})
  {
    const Scene scene = makeScene(sceneName);
    for (const aniso::AsLobe& lobe : lobes)
    {
      double worst = 0.0;
      const std::vector<double> reference = references(scene, lobe, f0, points, &worst);
      const double before = aniso::bench::widthRuleFraction(lobe);
      const double after = aniso::misLobeFraction(lobe, *scene.distribution);
      struct Choice
      {
        const char* name;
        aniso::SamplingStrategy strategy;
        double c;
      };
      const Choice choices[] = {{"lobe only", aniso::SamplingStrategy::Brdf, 1.0},
                                {"MIS, width rule", aniso::SamplingStrategy::MisOneSample, before},
                                {"MIS, new split", aniso::SamplingStrategy::MisOneSample, after}};
      for (const Choice& choice : choices)
      {
        std::printf("| %s | (%g, %g) | %.3f | %.3f | %s |", sceneName, lobe.nu, lobe.nv, before,
                    after, choice.name);
        for (uint32_t n : counts)
        {
          const Errors e =
              measure(scene, lobe, f0, points, reference, choice.strategy, choice.c, n, rotations);
          std::printf(" %.3g / %.3g |", e.l2, e.median);
        }
        std::printf("\n");
        std::fflush(stdout);
      }
      std::fprintf(stderr, "%s (%g, %g): reference error estimate at most %.1e\n", sceneName,
                   lobe.nu, lobe.nv, worst);
    }
  }
}
} // namespace

int main(int argc, char** argv)
{
  int rotations = 64;
  int pointCount = 16;
  bool split = false;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--split") == 0)
    {
      split = true;
      continue;
    }
    if (std::strcmp(argv[i], "--rotations") == 0 && i + 1 < argc)
      rotations = std::max(2, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--points") == 0 && i + 1 < argc)
      pointCount = std::max(1, std::atoi(argv[++i]));
    else
    {
      std::fprintf(stderr, "usage: %s [--rotations K] [--points P] [--split]\n", argv[0]);
      return 2;
    }
  }
  const std::vector<Point> points = spherePoints(pointCount);
  if (split)
  {
    std::printf("Points: %d on the sphere, %d rotations each; F0 = (0.95, 0.64, 0.54). "
                "Relative L2 / median relative error.\n",
                pointCount, rotations);
    compareSplits(points, rotations, glm::dvec3(0.95, 0.64, 0.54));
    return 0;
  }
  const aniso::AsLobe lobes[] = {{10, 10}, {20000, 70}};
  // The MIS rows share the samples equally between the techniques, but for the last one, which
  // gives the lobe 7/8 of them (what a sharp lobe wants).
  const Method methods[] = {{aniso::SamplingStrategy::Brdf, 0.5, "brdf"},
                            {aniso::SamplingStrategy::Environment, 0.5, "env"},
                            {aniso::SamplingStrategy::MisBalance, 0.5, "mis-balance"},
                            {aniso::SamplingStrategy::MisPower, 0.5, "mis-power"},
                            {aniso::SamplingStrategy::MisOneSample, 0.5, "mis-one-sample"},
                            {aniso::SamplingStrategy::MisPower, 0.875, "mis-power, lobe 7/8"}};
  const uint32_t counts[] = {1, 4, 16, 64, 256, 1024};
  const glm::dvec3 f0(0.95, 0.64, 0.54);

  std::vector<Row> rows;
  std::printf("Points: %d on the sphere, %d rotations each; F0 = (0.95, 0.64, 0.54).\n\n",
              pointCount, rotations);
  for (const char* sceneName : {"studio", "sun+sky"})
  {
    const Scene scene = makeScene(sceneName);
    std::printf("%s: environment distribution %dx%d baked in %.2f s\n", sceneName,
                scene.distribution->width(), scene.distribution->height(), scene.bakeSeconds);
    for (const aniso::AsLobe& lobe : lobes)
    {
      char lobeName[32];
      std::snprintf(lobeName, sizeof lobeName, "(%g, %g)", lobe.nu, lobe.nv);
      double worstReferenceError = 0.0;
      const std::vector<double> reference =
          references(scene, lobe, f0, points, &worstReferenceError);
      std::printf("%s %s: reference error estimate at most %.1e (relative)\n", sceneName, lobeName,
                  worstReferenceError);
      for (const Method& method : methods)
        for (uint32_t n : counts)
        {
          const auto start = std::chrono::steady_clock::now();
          const Errors e = measure(scene, lobe, f0, points, reference, method.strategy,
                                   method.lobeFraction, n, rotations);
          const double seconds = secondsSince(start);
          rows.push_back({sceneName, lobeName, method.name, n, e.l2, e.median,
                          seconds * 1e9 / (double(n) * double(points.size()) * rotations)});
        }
    }
  }

  std::printf("\n| Environment | Lobe | Strategy |");
  for (uint32_t n : counts)
    std::printf(" N=%u |", n);
  std::printf(" CPU ns/sample |\n| --- | --- | --- |");
  for (std::size_t i = 0; i < std::size(counts); ++i)
    std::printf(" --- |");
  std::printf(" --- |\n");
  const std::size_t perStrategy = std::size(counts);
  for (std::size_t i = 0; i < rows.size(); i += perStrategy)
  {
    std::printf("| %s | %s | %s |", rows[i].scene.c_str(), rows[i].lobe.c_str(), rows[i].method);
    for (std::size_t j = 0; j < perStrategy; ++j)
      std::printf(" %.3g / %.3g |", rows[i + j].l2, rows[i + j].median);
    std::printf(" %.0f |\n", rows[i + perStrategy - 1].nsPerSample);
  }

  // Samples for 1% relative L2 from N = 1024, assuming error ~ 1 / sqrt(N) from there on.
  std::printf("\nSamples per point for 1%% relative L2, extrapolated from N = 1024 as 1 / sqrt(N) "
              "(lobe-only next to the sun has not reached that regime: see the text):\n\n"
              "| Environment | Lobe |");
  for (const Method& method : methods)
    std::printf(" %s |", method.name);
  std::printf("\n| --- | --- |");
  for (std::size_t i = 0; i < std::size(methods); ++i)
    std::printf(" --- |");
  std::printf("\n");
  const std::size_t perLobe = perStrategy * std::size(methods);
  for (std::size_t i = 0; i < rows.size(); i += perLobe)
  {
    std::printf("| %s | %s |", rows[i].scene.c_str(), rows[i].lobe.c_str());
    for (std::size_t s = 0; s < std::size(methods); ++s)
    {
      const Row& last = rows[i + s * perStrategy + perStrategy - 1];
      std::printf(" %.3g |", last.samples * (last.l2 / 0.01) * (last.l2 / 0.01));
    }
    std::printf("\n");
  }
  return 0;
}
