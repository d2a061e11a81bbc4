#include "core/env/env_sampling.h"

#include "core/env/equirect_cache.h"
#include "core/env/parallel.h"
#include "core/error.h"
#include "core/sampling/hammersley.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <utility>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kFourPi = 4.0 * kPi;
constexpr double kBelowOne = 1.0 - 1.1102230246251565e-16;

// cos(pi y / H), the upper boundary of grid row y (row H: the nadir).
double rowCos(int y, int height)
{
  return std::cos(kPi * y / height);
}

// Index i with cdf[i] <= x < cdf[i + 1] for x in [0, 1): never an interval of zero width.
int findInterval(const double* cdf, int count, double x)
{
  const double* upper = std::upper_bound(cdf, cdf + count + 1, x);
  const int index = int(upper - cdf) - 1;
  return std::clamp(index, 0, count - 1);
}

// Texels whose 3 x 3 neighbourhood spans more than a factor kRefineContrast in luminance are
// sampled again, up to kMaxRefinement times more densely per side, within kRefineBudget times
// the samples of the first pass (an image full of contrast gets a milder refinement than a lone
// sun).
constexpr double kRefineContrast = 2.0;
constexpr int kMaxRefinement = 32;
constexpr double kRefineBudget = 4.0;

double luminanceOf(const Image& image, int x, int y)
{
  if (image.channels >= 3)
    return 0.2126 * image.at(x, y, 0) + 0.7152 * image.at(x, y, 1) + 0.0722 * image.at(x, y, 2);
  return image.at(x, y, 0);
}

// Mean radiance over texel (x, y) of a W x H equirect grid from n x n samples at the centres of
// equal (u, v) cells, weighted by sin(theta) (their solid angle), as renderEquirect does.
glm::dvec3 texelMean(const Environment& env, int x, int y, int w, int h, int n)
{
  glm::dvec3 sum(0.0);
  double weightSum = 0.0;
  for (int j = 0; j < n; ++j)
  {
    const double v = 1.0 - (y + (j + 0.5) / n) / h;
    const double weight = std::sin(kPi * (1.0 - v));
    for (int i = 0; i < n; ++i)
    {
      sum += weight * env.radiance(equirectToDirection({(x + (i + 0.5) / n) / w, v}));
      weightSum += weight;
    }
  }
  return sum / weightSum;
}

void validateOptions(const EnvSamplingOptions& options)
{
  if (options.width < 2 || options.width > 8192 || options.width % 2 != 0)
    throw errorAbout("width",
                     "must be even and in [2, 8192], got " + std::to_string(options.width));
  if (options.supersample < 1 || options.supersample > 16)
    throw errorAbout("supersample",
                     "must be in [1, 16], got " + std::to_string(options.supersample));
  if (!(options.uniformFraction >= 0.0 && options.uniformFraction <= 1.0))
    throw errorAbout("uniformFraction", "must be in [0, 1]");
}
} // namespace

EnvironmentDistribution::EnvironmentDistribution(const Image& equirect, double uniformFraction,
                                                 std::string key)
    : width_(equirect.width), height_(equirect.height), key_(std::move(key))
{
  if (equirect.width < 1 || equirect.height < 1 || equirect.channels < 1 ||
      equirect.data.size() != std::size_t(equirect.width) * std::size_t(equirect.height) *
                                  std::size_t(equirect.channels))
    throw errorAbout("environment image", "empty or inconsistent image");
  if (!(uniformFraction >= 0.0 && uniformFraction <= 1.0))
    throw errorAbout("uniformFraction", "must be in [0, 1]");
  const int w = width_;
  const int h = height_;
  const std::size_t texels = std::size_t(w) * std::size_t(h);

  // Texel probabilities: luminance times the texel's exact solid angle.
  std::vector<double> luminance(texels, 0.0);
  std::vector<double> rowSolidAngle(std::size_t(h), 0.0);
  double power = 0.0;
  for (int y = 0; y < h; ++y)
  {
    rowSolidAngle[std::size_t(y)] = kTwoPi / w * (rowCos(y, h) - rowCos(y + 1, h));
    for (int x = 0; x < w; ++x)
    {
      double value = luminanceOf(equirect, x, y);
      if (!std::isfinite(value))
        throw errorAbout("environment image", "texel (" + std::to_string(x) + ", " +
                                                  std::to_string(y) + ") is not finite");
      value = std::max(value, 0.0);
      luminance[std::size_t(y) * std::size_t(w) + std::size_t(x)] = value;
      power += value * rowSolidAngle[std::size_t(y)];
    }
  }
  const double share = power > 0.0 ? 1.0 - uniformFraction : 0.0;
  density_.assign(texels, 0.0);
  for (std::size_t i = 0; i < texels; ++i)
    density_[i] = (share > 0.0 ? share * luminance[i] / power : 0.0) + (1.0 - share) / kFourPi;

  // CDFs of probability = density x solid angle. Each is normalised by its own total, so the
  // last entry is exactly 1 whatever the rounding.
  conditional_.assign(std::size_t(h) * std::size_t(w + 1), 0.0);
  marginal_.assign(std::size_t(h) + 1, 0.0);
  std::vector<double> rowProbability(std::size_t(h), 0.0);
  for (int y = 0; y < h; ++y)
  {
    double* cdf = conditional_.data() + std::size_t(y) * std::size_t(w + 1);
    double sum = 0.0;
    for (int x = 0; x < w; ++x)
    {
      sum += density_[std::size_t(y) * std::size_t(w) + std::size_t(x)];
      cdf[x + 1] = sum;
    }
    for (int x = 1; x <= w; ++x)
      cdf[x] = sum > 0.0 ? cdf[x] / sum : double(x) / w;
    cdf[w] = 1.0;
    rowProbability[std::size_t(y)] = sum * rowSolidAngle[std::size_t(y)];
  }
  double total = 0.0;
  for (int y = 0; y < h; ++y)
  {
    total += rowProbability[std::size_t(y)];
    marginal_[std::size_t(y) + 1] = total;
  }
  for (int y = 1; y <= h; ++y)
    marginal_[std::size_t(y)] /= total;
  marginal_[std::size_t(h)] = 1.0;

  // Density levels half an octave wide, each with its solid-angle-weighted mean density.
  std::map<int, std::pair<double, double>> levels; // level -> (sum of omega p, sum of omega)
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      const double p = density_[std::size_t(y) * std::size_t(w) + std::size_t(x)];
      if (!(p > 0.0))
        continue;
      auto& level = levels[int(std::floor(2.0 * std::log2(p)))];
      level.first += p * rowSolidAngle[std::size_t(y)];
      level.second += rowSolidAngle[std::size_t(y)];
    }
  for (const auto& [index, sums] : levels)
    levels_.push_back({sums.first / sums.second, sums.second});
}

Image renderEquirectRefined(const Environment& env, int width, int height, int supersample)
{
  const int w = width;
  const int h = height;
  Image image = renderEquirect(env, w, h, supersample);

  // A texel beside a much brighter one may hold a sliver of a small source (a sun's edge) that
  // its supersamples missed: its density would be far below the radiance there, and the rare
  // samples landing on the sliver would carry huge weights. And a source smaller than a texel
  // gets its area from a handful of supersamples. So texels where the luminance jumps (see
  // kRefineContrast) are sampled again, more densely.
  std::vector<double> lum(std::size_t(w) * std::size_t(h), 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      lum[std::size_t(y) * std::size_t(w) + std::size_t(x)] = luminanceOf(image, x, y);
  std::vector<int> refine;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      double brightest = 0.0;
      double dimmest = std::numeric_limits<double>::infinity();
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
        {
          const int ny = std::clamp(y + dy, 0, h - 1);
          const int nx = (x + dx + w) % w;
          const double value = lum[std::size_t(ny) * std::size_t(w) + std::size_t(nx)];
          brightest = std::max(brightest, value);
          dimmest = std::min(dimmest, value);
        }
      if (brightest > kRefineContrast * dimmest)
        refine.push_back(y * w + x);
    }
  const double affordable = std::sqrt(kRefineBudget * double(w) * double(h) /
                                      double(std::max<std::size_t>(refine.size(), 1)));
  const int n = supersample * std::clamp(int(affordable), 1, kMaxRefinement);
  parallelFor(int(refine.size()),
              [&](int i)
              {
                const int x = refine[std::size_t(i)] % w;
                const int y = refine[std::size_t(i)] / w;
                const glm::dvec3 mean = texelMean(env, x, y, w, h, n);
                for (int c = 0; c < 3; ++c)
                  image.at(x, y, c) = float(mean[c]);
              });
  return image;
}

namespace
{
double cubeLuminance(const Image& face, int x, int y)
{
  return 0.2126 * face.at(x, y, 0) + 0.7152 * face.at(x, y, 1) + 0.0722 * face.at(x, y, 2);
}

// The largest cube texel (level 0) that a bilinear lookup from inside grid texel (x, y) of a
// W x H grid reads: the 2 x 2 texels around each of 5 x 5 points spread over the texel, which lie
// closer together than a cube texel wherever grid texels are at most twice as wide as cube
// texels (a 256 cube against the 1024 grid: 1.3 grid texels per cube texel at a face centre).
double shownLuminance(const Cubemap& cube, int x, int y, int w, int h)
{
  constexpr int kPoints = 5;
  const int size = cube.size;
  double largest = 0.0;
  for (int j = 0; j < kPoints; ++j)
    for (int i = 0; i < kPoints; ++i)
    {
      const double u = (x + double(i) / (kPoints - 1)) / w;
      const double v = 1.0 - (y + double(j) / (kPoints - 1)) / h;
      double s = 0.0;
      double t = 0.0;
      const int face = cubeFaceOf(equirectToDirection({u, v}), &s, &t);
      const Image& image = cube.mips[0][std::size_t(face)];
      const int x0 = std::clamp(int(std::floor(s * size - 0.5)), 0, size - 1);
      const int y0 = std::clamp(int(std::floor(t * size - 0.5)), 0, size - 1);
      const int x1 = std::min(x0 + 1, size - 1);
      const int y1 = std::min(y0 + 1, size - 1);
      largest = std::max({largest, cubeLuminance(image, x0, y0), cubeLuminance(image, x1, y0),
                          cubeLuminance(image, x0, y1), cubeLuminance(image, x1, y1)});
    }
  return largest;
}

// out[i] = the largest of in[i - radius .. i + radius] (wrapped around when `wrap`, clamped to
// the ends otherwise), for n values `stride` apart: a monotone queue, O(n) whatever the radius.
void slidingMax(const double* in, double* out, int n, int stride, int radius, bool wrap)
{
  if (wrap && 2 * radius + 1 >= n)
  {
    double largest = 0.0;
    for (int i = 0; i < n; ++i)
      largest = std::max(largest, in[std::size_t(i) * std::size_t(stride)]);
    for (int i = 0; i < n; ++i)
      out[std::size_t(i) * std::size_t(stride)] = largest;
    return;
  }
  auto at = [&](int i)
  {
    const int k = wrap ? (i % n + n) % n : std::clamp(i, 0, n - 1);
    return in[std::size_t(k) * std::size_t(stride)];
  };
  std::vector<std::pair<int, double>> queue; // decreasing values, as a deque in a vector
  std::size_t head = 0;
  int next = -radius;
  for (int i = 0; i < n; ++i)
  {
    for (; next <= i + radius; ++next)
    {
      const double value = at(next);
      while (queue.size() > head && queue.back().second <= value)
        queue.pop_back();
      queue.emplace_back(next, value);
    }
    while (queue[head].first < i - radius)
      ++head;
    out[std::size_t(i) * std::size_t(stride)] = queue[head].second;
  }
}
} // namespace

EnvironmentDistribution EnvironmentDistribution::bake(const Environment& env,
                                                      const EnvSamplingOptions& options)
{
  validateOptions(options);
  return EnvironmentDistribution(
      cachedEquirectRefined(env, options.width, options.width / 2, options.supersample),
      options.uniformFraction, distributionKey(env.key(), options));
}

EnvironmentDistribution EnvironmentDistribution::bake(const Environment& env,
                                                      const EnvSamplingOptions& options,
                                                      const Cubemap& shown)
{
  if (shown.size < 1 || shown.mips.empty())
    throw errorAbout("cube map", "empty");
  validateOptions(options);
  Image image = cachedEquirectRefined(env, options.width, options.width / 2, options.supersample);
  const int w = image.width;
  const int h = image.height;
  parallelFor(h,
              [&](int y)
              {
                for (int x = 0; x < w; ++x)
                {
                  const double cube = shownLuminance(shown, x, y, w, h);
                  if (cube > luminanceOf(image, x, y))
                    for (int c = 0; c < 3; ++c) // grey: the luminance weights sum to 1
                      image.at(x, y, c) = float(cube);
                }
              });
  return EnvironmentDistribution(image, options.uniformFraction,
                                 distributionKey(env.key(), options) + "|shown-by-cube" +
                                     std::to_string(shown.size));
}

EnvSample EnvironmentDistribution::sample(const glm::dvec2& xi) const
{
  const double xiRow = std::clamp(xi.y, 0.0, kBelowOne);
  const double xiColumn = std::clamp(xi.x, 0.0, kBelowOne);
  const int y = findInterval(marginal_.data(), height_, xiRow);
  const double rowWidth = marginal_[std::size_t(y) + 1] - marginal_[std::size_t(y)];
  const double t = std::clamp((xiRow - marginal_[std::size_t(y)]) / rowWidth, 0.0, 1.0);
  const double* cdf = conditional_.data() + std::size_t(y) * std::size_t(width_ + 1);
  const int x = findInterval(cdf, width_, xiColumn);
  const double s = std::clamp((xiColumn - cdf[x]) / (cdf[x + 1] - cdf[x]), 0.0, kBelowOne);

  // Uniform in (phi, cos theta) inside the texel: constant density per solid angle.
  const double u = (x + s) / width_;
  const double zTop = rowCos(y, height_);
  const double zBottom = rowCos(y + 1, height_);
  const double z = std::clamp(zTop + t * (zBottom - zTop), -1.0, 1.0);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = kPi - kTwoPi * u; // atan2(d.y, d.x) of the equirect mapping
  EnvSample result;
  result.direction = {sinTheta * std::cos(phi), sinTheta * std::sin(phi), z};
  result.pdf = density_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
  return result;
}

double EnvironmentDistribution::pdf(const glm::dvec3& direction) const
{
  const glm::dvec2 uv = directionToEquirect(direction);
  const double theta = kPi * (1.0 - uv.y);
  const int x = std::clamp(int(uv.x * width_), 0, width_ - 1);
  const int y = std::clamp(int(theta / kPi * height_), 0, height_ - 1);
  return density_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
}

Image EnvironmentDistribution::cdfTable() const
{
  // Wide enough for both CDFs (an equirect grid has W = 2 H, but any image is accepted).
  const int columns = std::max(width_, height_) + 1;
  Image table(columns, height_ + 1, 1);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < columns; ++x)
      table.at(x, y, 0) =
          x <= width_
              ? float(conditional_[std::size_t(y) * std::size_t(width_ + 1) + std::size_t(x)])
              : 1.0f;
  for (int x = 0; x < columns; ++x)
    table.at(x, height_, 0) = x <= height_ ? float(marginal_[std::size_t(x)]) : 1.0f;
  return table;
}

Image EnvironmentDistribution::pdfTable() const
{
  Image table(width_, height_, 1);
  for (std::size_t i = 0; i < density_.size(); ++i)
    table.data[i] = float(density_[i]);
  return table;
}

Image EnvironmentDistribution::lodBoundTable(int cubeSize, int maxLevel) const
{
  if (cubeSize < 1 || (cubeSize & (cubeSize - 1)) != 0)
    throw errorAbout("cubeSize", "must be a power of two, got " + std::to_string(cubeSize));
  constexpr double kLodBoundContrast = 4.0;
  const int w = width_;
  const int h = height_;
  const std::size_t texels = std::size_t(w) * std::size_t(h);
  const double rowAngle = kPi / h;
  Image table(w, h, 1);
  std::vector<bool> open(texels, true);
  std::vector<double> rows(texels, 0.0);
  std::vector<double> reach(texels, 0.0);
  for (int level = 0; level <= maxLevel; ++level)
  {
    // A bilinear lookup at `level` reads texels whose centres lie within one texel, and those
    // hold radiance from half a texel further: 1.5 texels of 2 / cubeSize radians at most (a
    // face's centre), plus half a grid texel for the lookup's own place inside its texel.
    const double angle = 1.5 * std::ldexp(2.0 / cubeSize, level) + 0.5 * rowAngle;
    const int rowRadius = int(std::ceil(angle / rowAngle));
    for (int x = 0; x < w; ++x)
      slidingMax(density_.data() + x, rows.data() + x, h, w, rowRadius, false);
    for (int y = 0; y < h; ++y)
    {
      // Columns are narrower towards the poles: the radius of the window's most polar row.
      const double thetaTop = std::max(0.0, (y - rowRadius) * rowAngle);
      const double thetaBottom = std::min(kPi, (y + 1 + rowRadius) * rowAngle);
      const double sinTheta = (thetaTop <= 0.5 * kPi && thetaBottom >= 0.5 * kPi)
                                  ? 1.0
                                  : std::min(std::sin(thetaTop), std::sin(thetaBottom));
      const double columnAngle = kTwoPi / w * std::max(sinTheta, 1e-9);
      const double columns = std::ceil(angle / columnAngle);
      const int columnRadius = columns >= w ? w : int(columns);
      slidingMax(rows.data() + std::size_t(y) * std::size_t(w),
                 reach.data() + std::size_t(y) * std::size_t(w), w, 1, columnRadius, true);
    }
    for (std::size_t i = 0; i < texels; ++i)
    {
      if (!open[i])
        continue;
      if (reach[i] > kLodBoundContrast * density_[i])
      {
        open[i] = false;
        table.data[i] = float(std::max(level - 1, 0));
      }
      else
        table.data[i] = float(level);
    }
  }
  return table;
}

namespace
{
double lobeFractionFor(const AsLobe& lobe, const EnvironmentDistribution& distribution)
{
  constexpr double kMinFraction = 1.0 / 16.0;
  constexpr double kMaxFraction = 15.0 / 16.0;
  // The lobe's density at its own samples (normal view): the sum over x of p_lobe(x)^2 G(x) is
  // the mean of p_lobe G over them. Directions below the horizon carry no integrand.
  constexpr uint32_t kLobeSamples = 64;
  const glm::dvec3 v(0.0, 0.0, 1.0);
  std::vector<double> lobeDensities;
  for (uint32_t i = 0; i < kLobeSamples; ++i)
  {
    const glm::dvec3 l = reflectAbout(v, sampleHalfVector(lobe, hammersley(i, kLobeSamples)));
    const double p = pdfLight(lobe, v, l);
    if (l.z > 0.0 && p > 0.0 && std::isfinite(p))
      lobeDensities.push_back(p);
  }
  const std::vector<DensityLevel>& levels = distribution.densityLevels();
  if (lobeDensities.empty() || levels.empty())
    return kMaxFraction;
  auto secondMoment = [&](double c)
  {
    double sum = 0.0;
    for (const double pLobe : lobeDensities)
      for (const DensityLevel& level : levels)
        sum += level.solidAngle * pLobe * level.density * level.density /
               (c * pLobe + (1.0 - c) * level.density);
    return sum;
  };
  // A sum of reciprocals of functions linear in c: convex, so golden-section search finds its
  // minimum on the interval.
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = kMinFraction;
  double hi = kMaxFraction;
  double a = hi - ratio * (hi - lo);
  double b = lo + ratio * (hi - lo);
  double fa = secondMoment(a);
  double fb = secondMoment(b);
  for (int iteration = 0; iteration < 40; ++iteration)
  {
    if (fa <= fb)
    {
      hi = b;
      b = a;
      fb = fa;
      a = hi - ratio * (hi - lo);
      fa = secondMoment(a);
    }
    else
    {
      lo = a;
      a = b;
      fa = fb;
      b = lo + ratio * (hi - lo);
      fb = secondMoment(b);
    }
  }
  // The model counts independent samples; the shader's lobe samples are a Hammersley set,
  // stratified, which converges faster where the light is smooth. So among the shares whose
  // modelled second moment is within kLobePreference of the minimum, the largest is taken (M
  // rises past the minimum: bisection).
  constexpr double kLobePreference = 1.1;
  const double best = 0.5 * (lo + hi);
  const double limit = kLobePreference * secondMoment(best);
  if (secondMoment(kMaxFraction) <= limit)
    return kMaxFraction;
  lo = best;
  hi = kMaxFraction;
  for (int iteration = 0; iteration < 40; ++iteration)
  {
    const double mid = 0.5 * (lo + hi);
    (secondMoment(mid) <= limit ? lo : hi) = mid;
  }
  return lo;
}
} // namespace

double misLobeFraction(const AsLobe& lobe, const EnvironmentDistribution& distribution)
{
  // Every frame of a still view asks again for the same lobe and environment: the last answer
  // of each thread is kept (by the distribution's content key; unkeyed ones are not kept).
  struct Last
  {
    double nu = -1.0;
    double nv = -1.0;
    std::string key;
    double fraction = 0.0;
  };
  thread_local Last last;
  if (!distribution.key().empty() && last.nu == lobe.nu && last.nv == lobe.nv &&
      last.key == distribution.key())
    return last.fraction;
  const double fraction = lobeFractionFor(lobe, distribution);
  last = {lobe.nu, lobe.nv, distribution.key(), fraction};
  return fraction;
}

std::string distributionKey(const std::string& environmentKey, const EnvSamplingOptions& options)
{
  std::ostringstream key;
  key.precision(17);
  key << environmentKey << "|envdist1|" << options.width << 'x' << options.width / 2 << "|ss"
      << options.supersample << "|u" << options.uniformFraction;
  return key.str();
}

std::shared_ptr<const EnvironmentDistribution> sharedDistribution(const Environment& env,
                                                                  const EnvSamplingOptions& options,
                                                                  const Cubemap* shown)
{
  validateOptions(options);
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const EnvironmentDistribution>> cache;
  const std::string key = distributionKey(env.key(), options) +
                          (shown ? "|shown-by-cube" + std::to_string(shown->size) : "");
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto existing = cache[key].lock())
      return existing;
  }
  // Baked outside the lock so other keys are not held up; two simultaneous first requests for
  // one key both bake, and the first stored result wins.
  auto baked = std::make_shared<const EnvironmentDistribution>(
      shown ? EnvironmentDistribution::bake(env, options, *shown)
            : EnvironmentDistribution::bake(env, options));
  std::lock_guard<std::mutex> lock(mutex);
  if (auto existing = cache[key].lock())
    return existing;
  cache[key] = baked;
  return baked;
}
} // namespace aniso
