#include "core/env/env_sources.h"

#include "core/env/env_sampling.h"
#include "core/env/equirect_cache.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <map>
#include <mutex>
#include <numeric>
#include <sstream>
#include <utility>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kFourPi = 4.0 * kPi;

// Kinds (see docs/METHOD.md, "Environment analysis"). A source is small below
// kSmallSolidAngle: 2e-3 sr is a disc of 1.45 degrees radius, about 4 x 4 texels at the horizon
// of a 1024 x 512 image; the Blender HDRIs' suns and lamps measure 1e-4 to 1e-3 sr, their
// windows and the studio's soft boxes 1e-2 to 0.5 sr. A region that is large but holds a peak
// above kCoreContrast T is a sun (or lamps) in the bright sky (or glow) around it: city's sun
// reaches 7900 T, forest's behind its leaves 575 T, night's street lamps 10000 T, while no
// window or soft box of the HDRIs exceeds 180 T (interior's window 178 T, studio's boxes 165 T).
// It is split into its core, the texels above kCoreFactor T (city's sun keeps its ringing
// texels, which reach down to 20 T, and leaves the sky around it, which stays below 13 T), and
// the rest, each connected part listed on its own. The sun is the most powerful small source
// above the horizon (z > kSunMinZ: a sun setting on a flat horizon still counts), when its peak
// exceeds kSunContrast T and it carries kSunDominance times the power of any other small
// source: an interior's downlights (1.8 times each other) and a night's street lamps (1.1
// times) are lamps. A lone lamp brighter than 100 T above the horizon reads as a sun: one image
// cannot tell them apart.
constexpr double kSmallSolidAngle = 2e-3;
constexpr double kCoreContrast = 400.0;
constexpr double kCoreFactor = 16.0;
constexpr double kSunMinZ = -0.05;
constexpr double kSunContrast = 100.0;
constexpr double kSunDominance = 4.0;
// Share of the sphere's solid angle whose power `concentration` measures.
constexpr double kConcentrationSolidAngle = 0.01;

double luminance(double r, double g, double b)
{
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

double rowSolidAngle(int y, int width, int height)
{
  return kTwoPi / width * (std::cos(kPi * y / height) - std::cos(kPi * (y + 1) / height));
}

glm::dvec3 gridDirection(double x, double y, int width, int height)
{
  return equirectToDirection({x / width, 1.0 - y / height});
}

void validateOptions(const EnvAnalysisOptions& options, const std::string& key)
{
  auto inRange = [&](const char* name, int value, int lo, int hi)
  {
    if (value < lo || value > hi)
      throw errorAbout(key, std::string(name) + " must be in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "], got " + std::to_string(value));
  };
  inRange("width", options.width, 16, 8192);
  inRange("maxWidth", options.maxWidth, 16, 8192);
  if (options.width % 2 != 0)
    throw errorAbout(key, "width must be even, got " + std::to_string(options.width));
  if (options.maxWidth % 2 != 0)
    throw errorAbout(key, "maxWidth must be even, got " + std::to_string(options.maxWidth));
  inRange("maxSources", options.maxSources, 0, 64);
  auto positive = [&](const char* name, double value)
  {
    if (!(value > 0.0) || !std::isfinite(value))
    {
      std::ostringstream reason;
      reason << name << " must be finite and > 0, got " << value;
      throw errorAbout(key, reason.str());
    }
  };
  positive("relativeThreshold", options.relativeThreshold);
  positive("meanThreshold", options.meanThreshold);
}

std::string analysisKey(const std::string& key, const EnvAnalysisOptions& options)
{
  std::ostringstream out;
  out.precision(17);
  out << key << "|envsrc1|w" << options.width << "|mw" << options.maxWidth << "|r"
      << options.relativeThreshold << "|m" << options.meanThreshold << "|n" << options.maxSources;
  return out.str();
}

// The image as checked RGB (grey expanded), refusing what the header says it refuses.
Image checkedRgb(const Image& image, const std::string& key)
{
  if (image.width < 1 || image.height < 1 || image.channels < 1 ||
      image.data.size() !=
          std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
    throw errorAbout(key, "empty or inconsistent image");
  if (image.width != 2 * image.height)
    throw errorAbout(key, "not an equirectangular image: " + std::to_string(image.width) + "x" +
                              std::to_string(image.height) + ", expected width = 2 x height");
  Image rgb(image.width, image.height, 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
      {
        const float value = image.at(x, y, image.channels >= 3 ? c : 0);
        const std::string where = "texel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
        if (!std::isfinite(value))
          throw errorAbout(key, where + " is not finite");
        if (value < 0.0f)
          throw errorAbout(key, where + " is negative");
        rgb.at(x, y, c) = value;
      }
  return rgb;
}

// Halves both sides, each new texel the solid-angle-weighted mean of its four (the power of the
// image is kept exactly). width and height even.
Image halved(const Image& image)
{
  const int w = image.width / 2;
  const int h = image.height / 2;
  Image out(w, h, 3);
  for (int y = 0; y < h; ++y)
  {
    const double top = rowSolidAngle(2 * y, image.width, image.height);
    const double bottom = rowSolidAngle(2 * y + 1, image.width, image.height);
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
      {
        const double sum =
            top * (double(image.at(2 * x, 2 * y, c)) + image.at(2 * x + 1, 2 * y, c)) +
            bottom * (double(image.at(2 * x, 2 * y + 1, c)) + image.at(2 * x + 1, 2 * y + 1, c));
        out.at(x, y, c) = float(sum / (2.0 * (top + bottom)));
      }
  }
  return out;
}

struct Component
{
  double power = 0.0; // excess luminance x solid angle
  glm::dvec3 weightedDirection{0.0};
  glm::dvec3 rgbPower{0.0};
  double solidAngle = 0.0;
  double peak = 0.0;
  int texels = 0;
  double minCos = 1.0; // of the angle from the direction to the farthest texel corner
};

// Labels the 8-connected sets of texels of equal group (wrapping in u; the texels of the first
// and of the last row also touch the ones across the pole). group: -1 for texels outside every
// set. Returns the label of each texel, -1 outside, and the number of labels.
std::vector<int> labelComponents(const std::vector<int>& group, int w, int h, int* count)
{
  std::vector<int> label(group.size(), -1);
  std::vector<int> stack;
  int next = 0;
  for (std::size_t start = 0; start < group.size(); ++start)
  {
    if (group[start] < 0 || label[start] >= 0)
      continue;
    const int wanted = group[start];
    label[start] = next;
    stack.push_back(int(start));
    while (!stack.empty())
    {
      const int index = stack.back();
      stack.pop_back();
      const int x = index % w;
      const int y = index / w;
      auto visit = [&](int nx, int ny)
      {
        nx = ((nx % w) + w) % w;
        const std::size_t n = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
        if (group[n] == wanted && label[n] < 0)
        {
          label[n] = next;
          stack.push_back(int(n));
        }
      };
      for (int dy = -1; dy <= 1; ++dy)
      {
        const int ny = y + dy;
        if (ny < 0 || ny >= h)
        {
          // Across the pole: the texel half a turn away in the same row, and its neighbours.
          for (int dx = -1; dx <= 1; ++dx)
            visit(x + w / 2 + dx, y);
          continue;
        }
        for (int dx = -1; dx <= 1; ++dx)
          if (dx != 0 || dy != 0)
            visit(x + dx, ny);
      }
    }
    ++next;
  }
  *count = next;
  return label;
}
} // namespace

const char* spelling(EnvSourceKind kind)
{
  switch (kind)
  {
  case EnvSourceKind::Sun:
    return "sun";
  case EnvSourceKind::Lamp:
    return "lamp";
  case EnvSourceKind::Window:
    return "window";
  }
  return "lamp";
}

EnvAnalysis analyzeEquirect(const Image& equirect, const std::string& key,
                            const EnvAnalysisOptions& options)
{
  validateOptions(options, key);
  Image image = checkedRgb(equirect, key);
  while (image.width > options.maxWidth && image.height % 2 == 0)
    image = halved(image);
  if (image.width > options.maxWidth)
    throw errorAbout(key, "a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                              " image cannot be halved down to maxWidth " +
                              std::to_string(options.maxWidth));

  const int w = image.width;
  const int h = image.height;
  const std::size_t texels = std::size_t(w) * std::size_t(h);
  EnvAnalysis result;
  result.key = analysisKey(key, options);
  result.width = w;
  result.height = h;

  std::vector<double> omega(static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y)
    omega[std::size_t(y)] = rowSolidAngle(y, w, h);
  std::vector<float> lum(texels);
  double total = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      const double value = luminance(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
      lum[std::size_t(y) * std::size_t(w) + std::size_t(x)] = float(value);
      total += value * omega[std::size_t(y)];
    }
  result.totalPower = total;
  result.meanLuminance = total / kFourPi;

  // Median and concentration from the texels sorted by luminance, brightest first.
  std::vector<std::uint32_t> order(texels);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return lum[a] > lum[b]; });
  {
    double solidAngle = 0.0;
    double power = 0.0;
    bool concentrationDone = false;
    bool medianDone = false;
    const double concentrationLimit = kConcentrationSolidAngle * kFourPi;
    for (const std::uint32_t index : order)
    {
      const double o = omega[index / std::uint32_t(w)];
      const double value = lum[index];
      if (!concentrationDone && solidAngle + o >= concentrationLimit)
      {
        // The texel crossing the limit counts for the part of it inside.
        power += value * (concentrationLimit - solidAngle);
        result.concentration = total > 0.0 ? power / total : 0.0;
        concentrationDone = true;
      }
      else if (!concentrationDone)
        power += value * o;
      solidAngle += o;
      if (!medianDone && solidAngle >= 0.5 * kFourPi)
      {
        result.medianLuminance = value;
        medianDone = true;
      }
      if (medianDone && concentrationDone)
        break;
    }
  }
  const double threshold = std::max(options.relativeThreshold * result.medianLuminance,
                                    options.meanThreshold * result.meanLuminance);
  result.threshold = threshold;

  // The split: excess = L (1 - T / Y) above T, the residual the rest (luminance T there).
  result.excess = Image(w, h, 3);
  result.residual = image;
  std::vector<int> group(texels, -1);
  double excessPower = 0.0;
  for (std::size_t i = 0; i < texels; ++i)
  {
    // In double, as the threshold was found (lum is rounded to float).
    const double y = luminance(image.data[i * 3], image.data[i * 3 + 1], image.data[i * 3 + 2]);
    if (!(y > threshold))
      continue;
    group[i] = 0;
    const double keep = threshold / y;
    for (int c = 0; c < 3; ++c)
    {
      const float value = image.data[i * 3 + std::size_t(c)];
      const float residual = float(value * keep);
      result.residual.data[i * 3 + std::size_t(c)] = residual;
      result.excess.data[i * 3 + std::size_t(c)] = value - residual;
    }
    const double excessLuminance = luminance(
        result.excess.data[i * 3], result.excess.data[i * 3 + 1], result.excess.data[i * 3 + 2]);
    excessPower += excessLuminance * omega[i / std::size_t(w)];
  }
  result.sourcePowerShare = total > 0.0 ? excessPower / total : 0.0;

  // Sources: connected sets of texels above T, a large one with a far brighter core split
  // into the core and the rest (see kCoreContrast).
  int regions = 0;
  const std::vector<int> region = labelComponents(group, w, h, &regions);
  {
    std::vector<double> regionSolidAngle(static_cast<std::size_t>(regions), 0.0);
    std::vector<double> regionPeak(static_cast<std::size_t>(regions), 0.0);
    for (std::size_t i = 0; i < texels; ++i)
      if (region[i] >= 0)
      {
        regionSolidAngle[std::size_t(region[i])] += omega[i / std::size_t(w)];
        regionPeak[std::size_t(region[i])] =
            std::max(regionPeak[std::size_t(region[i])], double(lum[i]));
      }
    for (std::size_t i = 0; i < texels; ++i)
    {
      if (region[i] < 0)
        continue;
      const std::size_t r = std::size_t(region[i]);
      const bool split =
          regionSolidAngle[r] >= kSmallSolidAngle && regionPeak[r] > kCoreContrast * threshold;
      group[i] = 2 * region[i] + (split && lum[i] > kCoreFactor * threshold ? 1 : 0);
    }
  }
  int count = 0;
  const std::vector<int> label = labelComponents(group, w, h, &count);
  std::vector<Component> components(static_cast<std::size_t>(count));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
      if (label[i] < 0)
        continue;
      Component& component = components[std::size_t(label[i])];
      const double o = omega[std::size_t(y)];
      const glm::dvec3 excess(result.excess.data[i * 3], result.excess.data[i * 3 + 1],
                              result.excess.data[i * 3 + 2]);
      const double power = luminance(excess.x, excess.y, excess.z) * o;
      component.power += power;
      component.weightedDirection += power * gridDirection(x + 0.5, y + 0.5, w, h);
      component.rgbPower += excess * o;
      component.solidAngle += o;
      component.peak = std::max(component.peak, double(lum[i]));
      ++component.texels;
    }
  std::vector<glm::dvec3> directions(components.size());
  for (std::size_t k = 0; k < components.size(); ++k)
  {
    const glm::dvec3 sum = components[k].weightedDirection;
    // A ring around a pole sums to its axis; a degenerate sum (no excess) keeps the zenith.
    directions[k] = glm::length(sum) > 0.0 ? glm::normalize(sum) : glm::dvec3(0.0, 0.0, 1.0);
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      const int k = label[std::size_t(y) * std::size_t(w) + std::size_t(x)];
      if (k < 0)
        continue;
      Component& component = components[std::size_t(k)];
      for (int cy = 0; cy <= 1; ++cy)
        for (int cx = 0; cx <= 1; ++cx)
          component.minCos =
              std::min(component.minCos,
                       glm::dot(directions[std::size_t(k)], gridDirection(x + cx, y + cy, w, h)));
    }

  std::vector<int> byPower(components.size());
  std::iota(byPower.begin(), byPower.end(), 0);
  std::sort(byPower.begin(), byPower.end(),
            [&](int a, int b)
            { return components[std::size_t(a)].power > components[std::size_t(b)].power; });
  {
    std::vector<int> rankOf(components.size());
    for (std::size_t rank = 0; rank < byPower.size(); ++rank)
      rankOf[std::size_t(byPower[rank])] = int(rank);
    result.sourceRank.assign(texels, -1);
    for (std::size_t i = 0; i < texels; ++i)
      if (label[i] >= 0)
        result.sourceRank[i] = rankOf[std::size_t(label[i])];
  }
  const std::size_t listed = std::min<std::size_t>(byPower.size(), std::size_t(options.maxSources));
  for (std::size_t rank = 0; rank < listed; ++rank)
  {
    const std::size_t k = std::size_t(byPower[rank]);
    const Component& component = components[k];
    EnvSource source;
    source.direction = directions[k];
    source.solidAngle = component.solidAngle;
    source.angularRadius = std::acos(std::clamp(component.minCos, -1.0, 1.0));
    source.power = component.rgbPower;
    source.radiance = component.rgbPower / component.solidAngle;
    source.powerShare = total > 0.0 ? component.power / total : 0.0;
    source.peakLuminance = component.peak;
    source.texels = component.texels;
    source.kind =
        component.solidAngle < kSmallSolidAngle ? EnvSourceKind::Lamp : EnvSourceKind::Window;
    result.sources.push_back(source);
  }
  // The sun: the most powerful small source above the horizon, far brighter than T and alone.
  int sun = -1;
  double otherSmall = 0.0; // the most powerful other small source's power (listed or not)
  for (const int k : byPower)
  {
    const Component& component = components[std::size_t(k)];
    if (component.solidAngle >= kSmallSolidAngle)
      continue;
    if (sun < 0 && directions[std::size_t(k)].z > kSunMinZ)
      sun = k;
    else
    {
      otherSmall = component.power;
      if (sun >= 0)
        break;
    }
  }
  if (sun >= 0)
  {
    const Component& component = components[std::size_t(sun)];
    if (component.peak > kSunContrast * threshold && component.power >= kSunDominance * otherSmall)
      for (std::size_t rank = 0; rank < listed; ++rank)
        if (byPower[rank] == sun)
          result.sources[rank].kind = EnvSourceKind::Sun;
  }
  return result;
}

EnvAnalysis analyzeEnvironment(const Environment& env, const EnvAnalysisOptions& options)
{
  const std::string key = env.key();
  validateOptions(options, key);
  if (const auto* equirect = dynamic_cast<const EquirectEnvironment*>(&env))
  {
    const Image& image = equirect->image();
    // An image that is not exactly 2:1 (loadEquirect accepts an odd extra column) or cannot be
    // halved to maxWidth is sampled through its interpolation like any other environment.
    int width = image.width;
    int height = image.height;
    while (width > options.maxWidth && height % 2 == 0)
    {
      width /= 2;
      height /= 2;
    }
    if (image.width == 2 * image.height && width <= options.maxWidth)
      return analyzeEquirect(image, key, options);
  }
  // The supersamples find a sun's disc, the refinement its edge (see renderEquirectRefined).
  constexpr int kSupersample = 4;
  // Kept on disk for the built-in environments (equirect_cache.h): seconds per process.
  Image image = cachedEquirectRefined(env, options.width, options.width / 2, kSupersample);
  return analyzeEquirect(image, key, options);
}

std::shared_ptr<const EnvAnalysis> sharedEnvironmentAnalysis(const Environment& env,
                                                             const EnvAnalysisOptions& options)
{
  const std::string envKey = env.key();
  validateOptions(options, envKey);
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const EnvAnalysis>> cache;
  const std::string key = analysisKey(envKey, options);
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto found = cache.find(key);
    if (found != cache.end())
    {
      if (auto existing = found->second.lock())
        return existing;
    }
  }
  // Analysed outside the lock so other keys are not held up; two simultaneous first requests
  // for one key both analyse, and the first stored result wins.
  auto analysed = std::make_shared<const EnvAnalysis>(analyzeEnvironment(env, options));
  std::lock_guard<std::mutex> lock(mutex);
  // Forget entries nobody holds any more, so the map does not grow with every key ever asked.
  for (auto it = cache.begin(); it != cache.end();)
    it = it->second.expired() ? cache.erase(it) : std::next(it);
  if (auto existing = cache[key].lock())
    return existing;
  cache[key] = analysed;
  return analysed;
}

namespace
{
class ResidualEnvironment : public Environment
{
public:
  ResidualEnvironment(std::shared_ptr<const Environment> env,
                      std::shared_ptr<const EnvAnalysis> analysis)
      : env_(std::move(env)), analysis_(std::move(analysis)),
        excess_(analysis_->excess, analysis_->key + ":excess"),
        key_(env_->key() + ":residual:" + analysis_->key)
  {
  }
  glm::dvec3 radiance(const glm::dvec3& d) const override
  {
    return env_->radiance(d) - excess_.radiance(d);
  }
  std::string key() const override { return key_; }

private:
  std::shared_ptr<const Environment> env_;
  std::shared_ptr<const EnvAnalysis> analysis_;
  EquirectEnvironment excess_;
  std::string key_;
};
} // namespace

std::shared_ptr<Environment> residualEnvironment(std::shared_ptr<const Environment> env,
                                                 std::shared_ptr<const EnvAnalysis> analysis)
{
  if (!env)
    throw errorAbout("residual environment", "no environment");
  if (!analysis)
    throw errorAbout(env->key(), "no analysis for its residual");
  if (analysis->excess.empty() || analysis->excess.width != 2 * analysis->excess.height)
    throw errorAbout(analysis->key, "the analysis holds no excess image");
  if (analysis->key.rfind(env->key() + "|envsrc", 0) != 0)
    throw errorAbout(env->key(), "the analysis " + analysis->key + " is of another environment");
  return std::make_shared<ResidualEnvironment>(std::move(env), std::move(analysis));
}
} // namespace aniso
