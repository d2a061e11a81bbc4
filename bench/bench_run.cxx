#include "bench/bench_run.h"

#include "bench/bench_models.h"
#include "bench/bench_scenes.h"
#include "bench/render_session.h"
#include "core/cache_directory.h"
#include "core/env/env_sources.h"
#include "core/error.h"
#include "core/parameters/parameters.h"
#include "core/quality/error_estimate.h"
#include "core/reference/reference_image.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <thread>

namespace aniso::bench
{
namespace
{
namespace fs = std::filesystem;

constexpr int kPublishedSamples = 256; // the published method's sample count (goal 1)
constexpr int kGoalSize = 512;

// The defaults of a material the user has not touched (MaterialSettings, parameters.h):
// aluminium F0, no diffuse (the reference integrates the specular term).
const glm::dvec3 kF0{0.913, 0.922, 0.924};
// The application's default material and scene (./run): n_u = 1000, n_v = 50 on the torus.
const AsLobe kDefaultLobe{1000.0, 50.0};
constexpr int kDefaultWidth = 800;
constexpr int kDefaultHeight = 600;
constexpr int kCubeSize = 256; // the cube-size parameter's default
// The environments the hdri family draws the default scene under: the studio (auto: off), a
// sun (city), lamps (interior) and a weak sun (sunset).
constexpr uint64_t kHdriEvaluations = 1ull << 22; // per reference pixel under the HDRIs
const std::string kHdriDefaultScenes[] = {"builtin:studio", "city", "interior", "sunset"};

struct Config
{
  SpecularMethod method = SpecularMethod::Exact;
  bool filtered = true;
  HalfVectorSource halfVectors = HalfVectorSource::Lut;
  EnvironmentSampling sampling = EnvironmentSampling::Off;
  int samples = 16;
  // With sources: each pixel's own source samples instead of the points the frame's pixels
  // share (MaterialSettings::sharedSourcePoints off).
  bool pixelSources = false;
};

struct ReferenceSpec
{
  int pixels = 1024;
  double tolerance = 1e-3;
  uint64_t maxEvaluations = ReferenceOptions{}.maxEvaluations; // per pixel
};

struct ScenePlan
{
  std::string mesh;
  std::string environment;
  std::vector<AsLobe> lobes;
  std::vector<Config> configs;
  std::vector<Config> progressive; // each accumulated up to the last of progressiveFrames
  std::vector<int> progressiveFrames;
  bool vtk = true;
  ReferenceSpec reference;
  ReferenceSpec ggxReference;
  std::string kind = "sweep";
  bool counters = false; // run the counter check after this scene
  // Progressive runs stop at the first checkpoint whose error is below this (0: never).
  double stopBelow = 0.0;
  // Progressive runs refine as the window's still view under this error target (its pixels
  // stop one by one; the runs still draw their frames): 0, plain accumulation.
  double stillTarget = 0.0;
  // When not empty: the checkpoints of the progressive configurations other than auto's.
  std::vector<int> forcedFrames;
  // The still view as the window draws it by default (quality-mode error): auto's
  // configuration run anew until the error estimated from its own frames is at error-target's
  // default, at most target-samples' default; rows of kind KIND-still. Off when false.
  bool still = false;
};

std::vector<Config> sweep(SpecularMethod method, bool filtered, HalfVectorSource halfVectors,
                          std::vector<int> samples,
                          EnvironmentSampling sampling = EnvironmentSampling::Off)
{
  std::vector<Config> configs;
  for (int n : samples)
  {
    configs.push_back({method, filtered, halfVectors, sampling, n});
  }
  return configs;
}

void append(std::vector<Config>& to, const std::vector<Config>& more)
{
  to.insert(to.end(), more.begin(), more.end());
}

std::vector<ScenePlan> planQuick()
{
  using M = SpecularMethod;
  using H = HalfVectorSource;
  ScenePlan sphere;
  sphere.mesh = "sphere";
  sphere.environment = "builtin:studio";
  sphere.lobes = benchLobes();
  append(sphere.configs, sweep(M::Exact, false, H::Lut, {1, 4, 16, 64, 256}));
  append(sphere.configs, sweep(M::Exact, true, H::Lut, {1, 4, 16, 64}));
  append(sphere.configs, sweep(M::SplitSum, false, H::Lut, {16, 256}));
  append(sphere.configs, sweep(M::SplitSum, true, H::Lut, {16}));
  append(sphere.configs, sweep(M::Exact, false, H::Shader, {16}));
  append(sphere.configs, sweep(M::Exact, false, H::Lut, {16}, EnvironmentSampling::Mis));
  sphere.progressive = sweep(M::Exact, true, H::Lut, {16});
  sphere.progressiveFrames = {1, 2, 4, 8};
  sphere.reference = {192, 2e-3};
  sphere.ggxReference = {48, 1e-3};
  sphere.counters = true;
  return {sphere};
}

std::vector<ScenePlan> planFull(const std::string& hdriDirectory)
{
  using M = SpecularMethod;
  using H = HalfVectorSource;
  std::vector<ScenePlan> plans;
  ScenePlan sphere;
  sphere.mesh = "sphere";
  sphere.environment = "builtin:studio";
  sphere.lobes = benchLobes();
  for (bool filtered : {true, false})
  {
    append(sphere.configs, sweep(M::Exact, filtered, H::Lut, {1, 4, 16, 64, 256}));
    append(sphere.configs, sweep(M::SplitSum, filtered, H::Lut, {1, 4, 16, 64, 256}));
  }
  append(sphere.configs, sweep(M::Exact, false, H::Shader, {1, 4, 16, 64, 256}));
  append(sphere.configs, sweep(M::Exact, false, H::Lut, {1024}));
  append(sphere.configs, sweep(M::Exact, false, H::Lut, {4, 16, 64}, EnvironmentSampling::Mis));
  sphere.progressive = {{M::Exact, true, H::Lut, EnvironmentSampling::Off, 16},
                        {M::Exact, false, H::Lut, EnvironmentSampling::Off, 16}};
  sphere.progressiveFrames = {1, 2, 4, 8, 16, 32};
  sphere.reference = {1024, 1e-3};
  sphere.ggxReference = {192, 2e-3};
  sphere.counters = true;
  plans.push_back(sphere);

  for (const char* mesh : {"torus", "flange"})
  {
    ScenePlan scene;
    scene.mesh = mesh;
    scene.environment = "builtin:studio";
    scene.lobes = benchLobes();
    append(scene.configs, sweep(M::Exact, true, H::Lut, {1, 4, 16, 64, 256}));
    append(scene.configs, sweep(M::Exact, false, H::Lut, {4, 16, 64}));
    append(scene.configs, sweep(M::SplitSum, false, H::Lut, {1, 4, 16, 64, 256}));
    scene.reference = {512, 1e-3};
    scene.ggxReference = {128, 2e-3};
    plans.push_back(scene);
  }

  // Real HDRIs hold small bright sources; their references cost far more per pixel, so one
  // material, fewer pixels and the key configurations are compared.
  const std::vector<std::string> environments = benchEnvironments(hdriDirectory);
  for (std::size_t i = 1; i < environments.size(); ++i)
  {
    ScenePlan scene;
    scene.mesh = "sphere";
    scene.environment = environments[i];
    scene.lobes = {{1000.0, 100.0}};
    append(scene.configs, sweep(M::Exact, true, H::Lut, {16}));
    append(scene.configs, sweep(M::Exact, false, H::Lut, {16, 256}));
    append(scene.configs, sweep(M::Exact, false, H::Lut, {16}, EnvironmentSampling::Mis));
    append(scene.configs, sweep(M::SplitSum, false, H::Lut, {256}));
    scene.reference = {kHdriReferencePixels, kHdriReferenceTolerance, kHdriReferenceMaxEvaluations};
    scene.ggxReference = {64, 1e-2};
    plans.push_back(scene);
  }
  return plans;
}

// Goal 1 is stated at 512x512: the published method at 256 samples against the modes that
// could reach its error sooner, on the sphere under the studio.
ScenePlan planGoal()
{
  using M = SpecularMethod;
  using H = HalfVectorSource;
  ScenePlan plan;
  plan.kind = "goal";
  plan.mesh = "sphere";
  plan.environment = "builtin:studio";
  plan.lobes = {{10.0, 10.0}, {1000.0, 100.0}, {20000.0, 70.0}};
  plan.configs = sweep(M::SplitSum, false, H::Lut, {kPublishedSamples});
  append(plan.configs, sweep(M::Exact, true, H::Lut, {4, 8, 12, 16, 24, 32}));
  append(plan.configs, sweep(M::Exact, false, H::Lut, {4, 8, 12, 16, 24, 32}));
  plan.vtk = false;
  plan.reference = {1024, 1e-3};
  return plan;
}

// Issue 14: real HDRIs with the default settings. Per environment and lobe the published method
// (one frame) and progressive runs of the default (env-sampling auto, up to 64 frames) beside
// lobe sampling only, MIS and sources forced (up to 16 frames). References on 96 pixels to
// 3e-3 with at most 2^22 evaluations a pixel: a wide lobe under a sun runs to the integrator's
// 2^26 and takes many minutes per reference on two shared cores, so the full set would take
// hours; the rows carry each reference's own bound. The quick set: the studio and the sun-sky,
// two lobes, 16 frames. Both run the window's still view as well (ScenePlan::still).
std::vector<ScenePlan> planHdri(bool quick, const std::string& hdriDirectory)
{
  using M = SpecularMethod;
  using H = HalfVectorSource;
  using S = EnvironmentSampling;
  std::vector<std::string> environments =
      quick ? std::vector<std::string>{"builtin:studio", "builtin:sunsky"}
            : benchEnvironments(hdriDirectory);
  std::vector<ScenePlan> plans;
  for (const std::string& environment : environments)
  {
    ScenePlan plan;
    plan.kind = "hdri";
    plan.mesh = "sphere";
    plan.environment = environment;
    plan.lobes = quick ? std::vector<AsLobe>{{10.0, 10.0}, {1000.0, 100.0}} : benchLobes();
    plan.configs = sweep(M::SplitSum, false, H::Lut, {kPublishedSamples});
    for (S sampling : {S::Auto, S::Off, S::Mis, S::Sources})
    {
      plan.progressive.push_back({M::Exact, true, H::Lut, sampling, 16});
    }
    // The two designs of the sources' technique side by side: per-pixel source samples.
    plan.progressive.push_back({M::Exact, true, H::Lut, S::Sources, 16, true});
    plan.progressiveFrames =
        quick ? std::vector<int>{1, 4, 16} : std::vector<int>{1, 2, 4, 8, 16, 32, 64};
    if (!quick)
    {
      plan.forcedFrames = {1, 2, 4, 8, 16};
    }
    plan.still = true;
    plan.vtk = false;
    plan.reference = quick ? ReferenceSpec{96, 2e-3} : ReferenceSpec{96, 3e-3, kHdriEvaluations};
    plans.push_back(plan);
  }
  return plans;
}

std::string methodName(SpecularMethod m)
{
  return m == SpecularMethod::Exact ? "exact" : "split-sum";
}

// Auto as the lighting resolved it: "auto(sources)", "auto(off)".
std::string autoText(EnvironmentSampling resolved)
{
  return "auto(" + std::string(spelling(resolved)) + ")";
}

std::string describe(const Config& c, EnvironmentSampling resolved = EnvironmentSampling::Off)
{
  std::ostringstream s;
  s << methodName(c.method) << (c.filtered ? " filtered" : " unfiltered")
    << (c.halfVectors == HalfVectorSource::Lut ? " LUT" : " shader")
    << (c.sampling == EnvironmentSampling::Mis ? std::string(" MIS")
        : c.sampling == EnvironmentSampling::Sources
            ? std::string(c.pixelSources ? " sources(pixel)" : " sources")
        : c.sampling == EnvironmentSampling::Auto ? " " + autoText(resolved)
                                                  : std::string())
    << " N=" << c.samples;
  return s.str();
}

std::string lobeText(const AsLobe& lobe)
{
  char text[64];
  std::snprintf(text, sizeof text, "(%g, %g)", lobe.nu, lobe.nv);
  return text;
}

double loadAverage()
{
  std::ifstream in("/proc/loadavg");
  double load = 0.0;
  in >> load;
  return load;
}

std::string machineDescription()
{
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  std::string model = "unknown CPU";
  while (std::getline(in, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " threads";
}

// The references' cache: "bench" in the project's cache directory (none without one).
std::string benchCacheDirectory()
{
  const std::string base = defaultCacheDirectory();
  return base.empty() ? std::string() : (fs::path(base) / "bench").string();
}

MaterialSettings materialFor(const AsLobe& lobe, const Config& c)
{
  MaterialSettings m;
  m.lobe = lobe;
  m.f0 = kF0;
  m.albedo = glm::dvec3(0.0);
  m.method = c.method;
  m.filtered = c.filtered;
  m.halfVectors = c.halfVectors;
  m.environmentSampling = c.sampling;
  m.samples = c.samples;
  m.sharedSourcePoints = !c.pixelSources;
  return m;
}

// Timed frames after the first: enough for a median, fewer for the slowest configurations.
int timedRuns(int samples, bool quick)
{
  if (quick)
  {
    return 2;
  }
  return samples >= 64 ? 2 : 3;
}

class Runner
{
public:
  Runner(const BenchOptions& options, std::ostream& log, BenchResult& result)
      : options_(options), log_(log), result_(result),
        cache_(options.cacheDirectory.empty() ? benchCacheDirectory() : options.cacheDirectory)
  {
  }

  void runScene(const ScenePlan& plan, RenderSession& session)
  {
    const BenchMesh& mesh = meshNamed(plan.mesh);
    session.setSurface(mesh.surface, mesh.view);
    const std::shared_ptr<const Environment> environment = environmentNamed(plan.environment);
    session.setEnvironment(environment, kCubeSize);
    const std::vector<PixelSample> geometry =
        castPixels(mesh.triangles, session.clipToWorld(), session.width(), session.height());
    const std::vector<int> pixels =
        selectPixels(geometry, session.width(), session.height(), plan.reference.pixels);
    const std::vector<int> ggxPixels =
        selectPixels(geometry, session.width(), session.height(), plan.ggxReference.pixels);
    const std::string envName = environmentName(plan.environment);
    autoResolved_ = EnvironmentSampling::Off;
    if (std::any_of(plan.progressive.begin(), plan.progressive.end(),
                    [](const Config& c) { return c.sampling == EnvironmentSampling::Auto; }) ||
        std::any_of(plan.configs.begin(), plan.configs.end(),
                    [](const Config& c) { return c.sampling == EnvironmentSampling::Auto; }))
    {
      autoResolved_ = session.lighting().resolveSampling(EnvironmentSampling::Auto);
    }
    // Under the HDRIs the row says whether the analysis lists a sun (the goal of an interactive
    // frame under a sun reads it).
    std::string variant;
    if (plan.kind.rfind("hdri", 0) == 0)
    {
      const EnvAnalysis& analysis = session.lighting().analysis();
      const bool sun = std::any_of(analysis.sources.begin(), analysis.sources.end(),
                                   [](const EnvSource& x) { return x.kind == EnvSourceKind::Sun; });
      variant = sun ? "sun" : "no sun";
      log_ << "  analysis: " << analysis.sources.size() << " source(s), " << variant
           << ", concentrated " << (analysis.concentrated() ? "yes" : "no") << ": auto is "
           << spelling(autoResolved_) << std::endl;
    }

    for (const AsLobe& lobe : plan.lobes)
    {
      BenchRow base;
      base.kind = plan.kind;
      base.variant = variant;
      base.mesh = plan.mesh;
      base.environment = envName;
      base.lobe = lobe;
      base.width = session.width();
      base.height = session.height();

      ReferenceModel model;
      model.asLobe = lobe;
      model.f0 = kF0;
      const ReferenceImage reference =
          referenceFor(geometry, session, pixels, model, *environment, plan.reference, base);

      for (const Config& config : plan.configs)
      {
        measureConfig(session, materialFor(lobe, config), config, reference, base);
      }
      // A forced sampling that auto resolved to draws the same shader with the same uniforms
      // (no jitter: the same images): its rows are auto's, not rendered twice.
      std::vector<std::pair<Config, std::size_t>> autoRows; // auto's config, its first row
      for (const Config& config : plan.progressive)
      {
        const auto same = std::find_if(
            autoRows.begin(), autoRows.end(),
            [&](const std::pair<Config, std::size_t>& a)
            {
              return config.sampling == autoResolved_ && !config.pixelSources &&
                     a.first.method == config.method && a.first.filtered == config.filtered &&
                     a.first.halfVectors == config.halfVectors && a.first.samples == config.samples;
            });
        if (same != autoRows.end())
        {
          const std::size_t first = same->second;
          const std::size_t last = result_.rows.size();
          for (std::size_t i = first; i < last && result_.rows[i].method.find("+auto") !=
                                                      std::string::npos;
               ++i)
          {
            if (result_.rows[i].kind == base.kind + "-still")
            {
              continue; // the still view is the default's alone
            }
            BenchRow row = result_.rows[i];
            describeConfig(row, config);
            result_.rows.push_back(row);
          }
          log_ << "  " << plan.mesh << " " << envName << " " << lobeText(lobe) << " progressive "
               << describe(config) << ": the rows of " << autoText(autoResolved_) << std::endl;
          continue;
        }
        const std::size_t first = result_.rows.size();
        const bool forced = config.sampling != EnvironmentSampling::Auto;
        session.setStillRefinement(plan.stillTarget);
        measureProgressive(session, materialFor(lobe, config), config, reference, base,
                           forced && !plan.forcedFrames.empty() ? plan.forcedFrames
                                                                : plan.progressiveFrames,
                           plan.stopBelow);
        session.setStillRefinement(0.0);
        if (config.sampling == EnvironmentSampling::Auto)
        {
          autoRows.push_back({config, first});
          if (plan.still)
          {
            measureStill(session, materialFor(lobe, config), config, reference, base);
          }
        }
      }
      if (plan.vtk)
      {
        measureVtk(session, geometry, ggxPixels, lobe, *environment, plan.ggxReference, base);
      }
      if (plan.counters && &lobe == &plan.lobes.back())
      {
        checkCounters(session, lobe, plan.configs.front());
      }
    }
  }

  const std::string& cacheDirectory() const { return cache_; }

  void runGoalScene()
  {
    RenderSession session(kGoalSize, kGoalSize);
    runScene(planGoal(), session);
  }

  // The application's default scene and settings at 800 x 600: the frame of the interactive
  // setting against VTK's, and the time a still view takes to converge.
  void runDefaultScene()
  {
    RenderSession session(kDefaultWidth, kDefaultHeight);
    ScenePlan plan;
    plan.kind = "default";
    plan.mesh = "torus";
    plan.environment = "builtin:studio";
    plan.lobes = {kDefaultLobe};
    const Config interactive; // MaterialSettings' defaults: exact, filtered, LUT, 16 samples
    plan.configs = {interactive};
    // Fewer samples, for what a frame within twice VTK's cost would show.
    append(plan.configs, sweep(SpecularMethod::Exact, true, HalfVectorSource::Lut, {4, 8}));
    Config unfiltered = interactive;
    unfiltered.filtered = false;
    plan.progressive = {interactive, unfiltered};
    plan.progressiveFrames = {1, 2, 4, 8, 12, 16, 24, 32};
    plan.reference = {1024, 1e-3};
    plan.ggxReference = {192, 2e-3};
    runScene(plan, session);
  }

  // Issue 14: the sphere under the studio and the HDRIs (planHdri) at SIZE, then, but for the
  // quick set, the default scene: torus, (1000, 50), 800x600, the default settings accumulated
  // frame by frame up to 32 or until under 1%, under a subset (kHdriDefaultScenes: a frame
  // there costs several times the sphere's).
  void runHdri(bool quick, const std::string& hdriDirectory, int size)
  {
    const std::vector<ScenePlan> plans = planHdri(quick, hdriDirectory);
    {
      RenderSession session(size, size);
      log_ << "hdri: " << plans.size() << " environment(s), sphere at " << size << "x" << size
           << std::endl;
      for (const ScenePlan& plan : plans)
      {
        log_ << "scene " << plan.mesh << " " << environmentName(plan.environment) << std::endl;
        runScene(plan, session);
      }
      if (result_.renderer.empty())
      {
        result_.renderer = session.rendererName();
      }
    }
    if (quick)
    {
      return;
    }
    RenderSession session(kDefaultWidth, kDefaultHeight);
    for (const ScenePlan& sphere : plans)
    {
      const std::string name = environmentName(sphere.environment);
      if (std::find(std::begin(kHdriDefaultScenes), std::end(kHdriDefaultScenes), name) ==
          std::end(kHdriDefaultScenes))
      {
        continue;
      }
      ScenePlan plan;
      plan.kind = "hdri-default";
      plan.mesh = "torus";
      plan.environment = sphere.environment;
      plan.lobes = {kDefaultLobe};
      plan.progressive = {Config{SpecularMethod::Exact, true, HalfVectorSource::Lut,
                                 EnvironmentSampling::Auto, 16}};
      for (int f = 1; f <= 32; ++f)
      {
        plan.progressiveFrames.push_back(f);
      }
      plan.stopBelow = 0.01;
      // As the window refines its still view: its error target's pixels that stop.
      plan.stillTarget = parameterSpec("error-target").defaultValue[0];
      plan.vtk = false;
      plan.reference = {96, 3e-3, kHdriEvaluations};
      log_ << "scene: the default scene at " << kDefaultWidth << "x" << kDefaultHeight << " under "
           << environmentName(plan.environment) << std::endl;
      runScene(plan, session);
    }
  }

private:
  const BenchMesh& meshNamed(const std::string& name)
  {
    auto found = meshes_.find(name);
    if (found == meshes_.end())
    {
      found = meshes_.emplace(name, makeBenchMesh(name)).first;
    }
    return found->second;
  }

  std::shared_ptr<const Environment> environmentNamed(const std::string& spec)
  {
    auto found = environments_.find(spec);
    if (found == environments_.end())
    {
      found = environments_.emplace(spec, openEnvironment(spec)).first;
    }
    return found->second;
  }

  ReferenceImage referenceFor(const std::vector<PixelSample>& geometry,
                              const RenderSession& session, const std::vector<int>& pixels,
                              const ReferenceModel& model, const Environment& environment,
                              const ReferenceSpec& spec, const BenchRow& base)
  {
    ReferenceOptions options;
    options.relativeTolerance = spec.tolerance;
    options.maxEvaluations = spec.maxEvaluations;
    ReferenceImage reference = computeReference(geometry, session.width(), session.height(), pixels,
                                                model, environment, options, cache_);
    log_ << "  reference " << base.mesh << " " << base.environment << " "
         << (model.ggx ? "GGX" : lobeText(base.lobe)) << ": " << reference.pixels.size()
         << " pixels, bound " << reference.relativeErrorBound
         << (reference.fromCache ? " (cached)" : ", " + std::to_string(reference.seconds) + " s")
         << std::endl;
    return reference;
  }

  BenchRow measured(const BenchRow& base, const Image& image, const ReferenceImage& reference)
  {
    BenchRow row = base;
    const ImageError error = compareToReference(image, reference);
    row.relativeL2 = error.relativeL2;
    row.percentile99 = error.percentile99;
    row.referenceBound = reference.relativeErrorBound;
    row.comparedPixels = static_cast<int>(reference.pixels.size());
    row.coveredPixels = coveredPixels(image);
    if (error.uncovered > 0)
    {
      log_ << "  warning: " << error.uncovered << " compared pixels not covered by the render"
           << std::endl;
    }
    return row;
  }

  void measureConfig(RenderSession& session, const MaterialSettings& material, const Config& config,
                     const ReferenceImage& reference, const BenchRow& base)
  {
    session.useMaterial(material);
    const std::vector<FrameTime> first = session.render(1);
    const Image image = session.read();
    BenchRow row = measured(base, image, reference);
    row.runs = timedRuns(config.samples, options_.quick);
    const std::vector<FrameTime> timed = session.renderMore(row.runs);
    describeConfig(row, config);
    row.firstFrameSeconds = first.front().wall;
    const FrameTime median = medianFrameTime(timed);
    row.medianFrameSeconds = median.wall;
    row.totalSeconds = row.medianFrameSeconds;
    row.medianFrameCpuSeconds = median.cpu;
    row.totalCpuSeconds = row.medianFrameCpuSeconds;
    row.samplesPerSecond = double(row.coveredPixels) * config.samples / row.medianFrameSeconds;
    log_ << "  " << row.mesh << " " << row.environment << " " << lobeText(row.lobe) << " "
         << describe(config, autoResolved_) << ": " << row.medianFrameSeconds * 1e3 << " ms, L2 "
         << row.relativeL2
         << std::endl;
    result_.rows.push_back(row);
  }

  // ROW's frames and times as an accumulation of FRAMES frames of SAMPLES samples whose frame
  // times are TIMES (the first of them the accumulation's first frame).
  static void setAccumulationTimes(BenchRow& row, const std::vector<FrameTime>& times, int frames,
                                   int samples)
  {
    row.frames = frames;
    row.runs = frames;
    row.firstFrameSeconds = times.front().wall;
    const FrameTime median = medianFrameTime(times);
    row.medianFrameSeconds = median.wall;
    row.medianFrameCpuSeconds = median.cpu;
    for (const FrameTime& t : times)
    {
      row.totalSeconds += t.wall;
      row.totalCpuSeconds += t.cpu;
    }
    row.samplesPerSecond = double(row.coveredPixels) * samples * frames / row.totalSeconds;
  }

  void measureProgressive(RenderSession& session, const MaterialSettings& material,
                          const Config& config, const ReferenceImage& reference,
                          const BenchRow& base, const std::vector<int>& checkpoints,
                          double stopBelow = 0.0)
  {
    if (checkpoints.empty())
    {
      return;
    }
    session.useMaterial(material);
    // A warm-up accumulation, so compiles and uploads are not counted as convergence time.
    session.render(1);
    std::vector<FrameTime> times = session.render(1);
    for (int checkpoint : checkpoints)
    {
      const int more = checkpoint - session.accumulatedFrames();
      if (more > 0)
      {
        const std::vector<FrameTime> extra = session.renderMore(more);
        times.insert(times.end(), extra.begin(), extra.end());
      }
      BenchRow row = measured(base, session.read(), reference);
      row.kind = base.kind == "sweep" ? "progressive" : base.kind + "-progressive";
      describeConfig(row, config);
      setAccumulationTimes(row, times, checkpoint, config.samples);
      result_.rows.push_back(row);
      if (stopBelow > 0.0 && row.relativeL2 <= stopBelow)
      {
        break;
      }
    }
    const BenchRow& last = result_.rows.back();
    log_ << "  " << last.mesh << " " << last.environment << " " << lobeText(last.lobe)
         << " progressive " << describe(config, autoResolved_) << " x " << last.frames << ": " << last.totalSeconds
         << " s, L2 " << last.relativeL2 << std::endl;
  }

  // The window's default still view: frames until the error they estimate themselves is at
  // error-target's default (from 256 samples a pixel on), at most target-samples' default (in
  // frames of the config's samples).
  void measureStill(RenderSession& session, const MaterialSettings& material, const Config& config,
                    const ReferenceImage& reference, const BenchRow& base)
  {
    const double target = parameterSpec("error-target").defaultValue[0];
    const int most = std::max(1, static_cast<int>(parameterSpec("target-samples").defaultValue[0]) /
                                     config.samples);
    session.useMaterial(material);
    session.render(1); // warm-up, as the progressive runs
    const std::vector<FrameTime> times =
        session.renderToError(target, minimumErrorStopFrames(config.samples), most);
    BenchRow row = measured(base, session.read(), reference);
    row.kind = base.kind + "-still";
    describeConfig(row, config);
    setAccumulationTimes(row, times, session.accumulatedFrames(), config.samples);
    row.estimatedError = session.estimatedError();
    result_.rows.push_back(row);
    log_ << "  " << row.mesh << " " << row.environment << " " << lobeText(row.lobe)
         << " still view " << describe(config, autoResolved_) << ": stopped after " << row.frames
         << " of at most " << most << " frames, estimate " << row.estimatedError << ", L2 "
         << row.relativeL2 << ", " << row.totalSeconds << " s" << std::endl;
  }

  void measureVtk(RenderSession& session, const std::vector<PixelSample>& geometry,
                  const std::vector<int>& pixels, const AsLobe& lobe,
                  const Environment& environment, const ReferenceSpec& spec, const BenchRow& base)
  {
    const VtkPbrMaterial material = vtkPbrFor(lobe, kF0);
    ReferenceModel model;
    model.ggx = true;
    model.ggxLobe = vtkGgxLobe(material);
    model.tangentRotation = vtkTangentRotation(material);
    model.f0 = kF0;
    const ReferenceImage reference =
        referenceFor(geometry, session, pixels, model, environment, spec, base);
    session.useVtkPbr(material);
    const std::vector<FrameTime> first = session.render(1);
    BenchRow row = measured(base, session.read(), reference);
    row.kind = base.kind == "sweep" ? "vtk" : base.kind + "-vtk";
    row.method = "vtk-pbr";
    row.filtered = "-";
    row.halfVectors = "-";
    row.samples = 1;
    row.runs = 5;
    const std::vector<FrameTime> timed = session.renderMore(row.runs);
    row.firstFrameSeconds = first.front().wall;
    const FrameTime median = medianFrameTime(timed);
    row.medianFrameSeconds = median.wall;
    row.totalSeconds = row.medianFrameSeconds;
    row.medianFrameCpuSeconds = median.cpu;
    row.totalCpuSeconds = row.medianFrameCpuSeconds;
    row.samplesPerSecond = double(row.coveredPixels) / row.medianFrameSeconds;
    log_ << "  " << row.mesh << " " << row.environment << " " << lobeText(lobe)
         << " VTK PBR (roughness " << material.roughness << ", anisotropy " << material.anisotropy
         << "): " << row.medianFrameSeconds * 1e3 << " ms (first " << row.firstFrameSeconds
         << " s), L2 " << row.relativeL2 << std::endl;
    result_.rows.push_back(row);
  }

  // Method names: "exact", "exact+mis", "exact+sources", "exact+auto(sources)" (auto as the
  // session's lighting resolved it), "split-sum".
  void describeConfig(BenchRow& row, const Config& config) const
  {
    row.method = methodName(config.method);
    if (config.sampling == EnvironmentSampling::Mis)
    {
      row.method += "+mis";
    }
    else if (config.sampling == EnvironmentSampling::Sources)
    {
      row.method += config.pixelSources ? "+sources(pixel)" : "+sources";
    }
    else if (config.sampling == EnvironmentSampling::Auto)
    {
      row.method += "+" + autoText(autoResolved_);
    }
    row.filtered = config.filtered ? "on" : "off";
    row.halfVectors = config.halfVectors == HalfVectorSource::Lut ? "lut" : "shader";
    row.samples = config.samples;
  }

  // Each step changes one input (or none) and counts what the session did meanwhile.
  void checkCounters(RenderSession& session, const AsLobe& lobe, const Config& config)
  {
    MaterialSettings material = materialFor(lobe, config);
    session.useMaterial(material);
    session.render(1);
    auto step = [&](const std::string& change, const std::string& expected,
                    const std::function<void()>& apply, uint64_t programs, uint64_t uploads,
                    uint64_t maxBakes)
    {
      const SessionCounters before = session.counters();
      apply();
      session.render(1);
      const SessionCounters after = session.counters();
      CounterStep s;
      s.change = change;
      s.expected = expected;
      s.shaderPrograms = after.shaderPrograms - before.shaderPrograms;
      s.textureUploads = after.textureUploads - before.textureUploads;
      s.lutBakes = after.lutBakes - before.lutBakes;
      s.environmentBakes = after.environmentBakes - before.environmentBakes;
      s.asExpected = s.shaderPrograms == programs && s.textureUploads == uploads &&
                     s.lutBakes <= maxBakes && s.environmentBakes == 0;
      result_.counters.push_back(s);
    };
    step(
        "nothing (the view drawn again)", "nothing", [] {}, 0, 0, 0);
    step(
        "samples 16 -> 32 and F0 (uniforms)", "nothing",
        [&]
        {
          material.samples = 32;
          material.f0 = glm::dvec3(0.95, 0.64, 0.54);
          session.useMaterial(material);
        },
        0, 0, 0);
    const AsLobe other{lobe.nu * 0.5, lobe.nv * 2.0};
    step(
        "n_u, n_v to " + lobeText(other) + " (half vectors from the LUT)",
        "1 upload (the new LUT), at most 1 bake, no compile",
        [&]
        {
          material.lobe = other;
          session.useMaterial(material);
        },
        0, 1, 1);
    step(
        "n_u, n_v back to " + lobeText(lobe), "1 upload, no bake (LUT cache hit), no compile",
        [&]
        {
          material.lobe = lobe;
          session.useMaterial(material);
        },
        0, 1, 0);
    step(
        "filtering toggled (a variant compiled before)", "nothing",
        [&]
        {
          material.filtered = !material.filtered;
          session.useMaterial(material);
        },
        0, 0, 0);
  }

  const BenchOptions& options_;
  std::ostream& log_;
  BenchResult& result_;
  std::string cache_;
  std::map<std::string, BenchMesh> meshes_;
  std::map<std::string, std::shared_ptr<const Environment>> environments_;
  EnvironmentSampling autoResolved_ = EnvironmentSampling::Off; // of the scene being run
};
} // namespace

const std::vector<std::string>& benchFamilies()
{
  static const std::vector<std::string> families{"as-env", "lit", "leadr", "micro", "hdri"};
  return families;
}

const std::vector<std::string>& defaultBenchFamilies()
{
  static const std::vector<std::string> families{"as-env", "lit", "leadr", "micro"};
  return families;
}

std::vector<std::string> parseBenchFamilies(const std::string& list)
{
  std::vector<std::string> families;
  std::istringstream in(list);
  for (std::string name; std::getline(in, name, ',');)
  {
    const auto& known = benchFamilies();
    if (std::find(known.begin(), known.end(), name) == known.end())
    {
      throw errorAbout("--models", "'" + name + "' is not one of as-env, lit, leadr, micro, hdri");
    }
    if (std::find(families.begin(), families.end(), name) != families.end())
    {
      throw errorAbout("--models", "'" + name + "' is given twice");
    }
    families.push_back(name);
  }
  if (families.empty())
  {
    throw errorAbout("--models", "no family given (as-env, lit, leadr, micro, hdri)");
  }
  return families;
}

BenchResult runBench(const BenchOptions& options, std::ostream& log)
{
  const auto start = std::chrono::steady_clock::now();
  BenchResult result;
  result.quick = options.quick;
  result.size =
      options.size > 0 ? options.size : (options.quick ? kQuickImageSize : kFullImageSize);
  result.commandLine = options.commandLine;
  result.machine = machineDescription();
  result.loadBefore = loadAverage();
  const std::vector<std::string>& families =
      options.families.empty() ? defaultBenchFamilies() : options.families;
  const auto runs = [&](const char* family)
  { return std::find(families.begin(), families.end(), family) != families.end(); };
  Runner runner(options, log, result);
  if (runs("as-env"))
  {
    const std::vector<ScenePlan> plans =
        options.quick ? planQuick()
                      : planFull(options.hdriDirectory.empty() ? kBlenderHdriDirectory
                                                               : options.hdriDirectory);
    RenderSession session(result.size, result.size);
    log << "bench: " << plans.size() << " scene(s) at " << result.size << "x" << result.size
        << std::endl;
    for (const ScenePlan& plan : plans)
    {
      log << "scene " << plan.mesh << " " << environmentName(plan.environment) << std::endl;
      runner.runScene(plan, session);
    }
    result.renderer = session.rendererName();
    if (!options.quick)
    {
      log << "scene: the published method's goal at " << kGoalSize << "x" << kGoalSize << std::endl;
      runner.runGoalScene();
      log << "scene: the default scene at " << kDefaultWidth << "x" << kDefaultHeight << std::endl;
      runner.runDefaultScene();
    }
  }
  ModelBenchOptions models;
  models.quick = options.quick;
  models.size = result.size;
  models.lit = runs("lit");
  models.leadr = runs("leadr");
  models.microstructure = runs("micro");
  models.cacheDirectory = runner.cacheDirectory();
  if (models.lit || models.leadr || models.microstructure)
  {
    const std::string renderer = runModelBenches(models, log, result.rows);
    if (result.renderer.empty())
    {
      result.renderer = renderer;
    }
  }
  if (runs("hdri"))
  {
    runner.runHdri(options.quick,
                   options.hdriDirectory.empty() ? kBlenderHdriDirectory : options.hdriDirectory,
                   result.size);
  }
  if (runs("as-env"))
  {
    result.goals = evaluateGoals(result);
    result.qualityFits = fitQuality(result.rows);
  }
  if (runs("hdri"))
  {
    result.hdriGoals = evaluateHdriGoals(result);
  }
  result.loadAfter = loadAverage();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}
} // namespace aniso::bench
