#include "core/leadr/leadr.h"

#include "core/brdf/ashikhmin_shirley.h"
#include "core/brdf/sv_common.h"
#include "core/error.h"
#include "core/models/height_field.h"
#include "core/models/texture_sampling.h"
#include "core/sampling/hammersley.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <string>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kChannels = 5;

void storeMoments(Image& image, int x, int y, const std::array<double, kChannels>& m)
{
  for (int c = 0; c < kChannels; ++c)
    image.at(x, y, c) = float(m[std::size_t(c)]);
}

// Level k+1 texel i covers level-k texels [i W_k / W_k+1, (i+1) W_k / W_k+1); its level-0 range
// follows by composing those ranges, and its moments are the exact mean of that range (from
// summed-area tables in double), so odd sizes weigh every fine texel equally too.
LeadrMips chainFromLevel0(Image level0)
{
  const int w0 = level0.width;
  const int h0 = level0.height;
  const std::size_t stride = std::size_t(w0) + 1;
  std::vector<double> table(stride * (std::size_t(h0) + 1) * kChannels, 0.0);
  auto at = [&](int x, int y, int c) -> double&
  { return table[((std::size_t(y) * stride) + std::size_t(x)) * kChannels + std::size_t(c)]; };
  for (int y = 0; y < h0; ++y)
    for (int x = 0; x < w0; ++x)
      for (int c = 0; c < kChannels; ++c)
        at(x + 1, y + 1, c) = level0.at(x, y, c) + at(x, y + 1, c) + at(x + 1, y, c) - at(x, y, c);

  std::vector<int> xs(std::size_t(w0) + 1);
  std::vector<int> ys(std::size_t(h0) + 1);
  for (int i = 0; i <= w0; ++i)
    xs[std::size_t(i)] = i;
  for (int j = 0; j <= h0; ++j)
    ys[std::size_t(j)] = j;

  LeadrMips mips;
  mips.levels.push_back(std::move(level0));
  while (mips.levels.back().width > 1 || mips.levels.back().height > 1)
  {
    const int w = mips.levels.back().width;
    const int h = mips.levels.back().height;
    const int cw = std::max(1, w / 2);
    const int ch = std::max(1, h / 2);
    std::vector<int> nx(std::size_t(cw) + 1);
    std::vector<int> ny(std::size_t(ch) + 1);
    for (int i = 0; i <= cw; ++i)
      nx[std::size_t(i)] = xs[std::size_t(i * w / cw)];
    for (int j = 0; j <= ch; ++j)
      ny[std::size_t(j)] = ys[std::size_t(j * h / ch)];
    Image coarse(cw, ch, kChannels);
    for (int j = 0; j < ch; ++j)
    {
      const int y0 = ny[std::size_t(j)];
      const int y1 = ny[std::size_t(j) + 1];
      for (int i = 0; i < cw; ++i)
      {
        const int x0 = nx[std::size_t(i)];
        const int x1 = nx[std::size_t(i) + 1];
        const double count = double(x1 - x0) * (y1 - y0);
        std::array<double, kChannels> mean{};
        for (int c = 0; c < kChannels; ++c)
          mean[std::size_t(c)] =
              (at(x1, y1, c) - at(x0, y1, c) - at(x1, y0, c) + at(x0, y0, c)) / count;
        storeMoments(coarse, i, j, mean);
      }
    }
    mips.levels.push_back(std::move(coarse));
    xs = std::move(nx);
    ys = std::move(ny);
  }
  return mips;
}

bool consistent(const Image& image)
{
  return image.width > 0 && image.height > 0 && image.channels > 0 &&
         image.data.size() == std::size_t(image.width) * image.height * image.channels;
}

SlopeMoments fromArray(const std::array<double, kChannels>& m)
{
  return {m[0], m[1], m[2], m[3], m[4]};
}

std::array<double, kChannels> bilinearMoments(const Image& image, const glm::dvec2& uv)
{
  const BilinearTaps taps = bilinearTaps(image.width, image.height, uv);
  std::array<double, kChannels> out{};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      for (int c = 0; c < kChannels; ++c)
        out[std::size_t(c)] += taps.wx[i] * taps.wy[j] * image.at(taps.x[i], taps.y[j], c);
  return out;
}

// Slope variance of the distribution along the unit tangent-plane direction d.
double varianceAlong(const SlopeStatistics& s, const glm::dvec2& d)
{
  return s.varX * d.x * d.x + 2.0 * s.covXY * d.x * d.y + s.varY * d.y * d.y;
}

// The statistics a shading call works with: lifted view and silhouette micronormal.
struct Prepared
{
  glm::dvec3 v;
  SlopeStatistics stats;
};

Prepared prepare(const SlopeStatistics& stats, const Frame& frame, const glm::dvec3& viewWorld)
{
  Prepared p;
  p.v = liftedView(frame.toLocal(viewWorld));
  p.stats = withSilhouetteMicronormal(stats, p.v);
  return p;
}

// Grid normals (tangent space) of a distribution, row-major over (z1, z2).
std::vector<glm::dvec3> gridNormals(const SlopeStatistics& stats, const SlopeGrid& grid)
{
  std::vector<glm::dvec3> normals;
  normals.reserve(grid.quantiles.size() * grid.quantiles.size());
  for (double z1 : grid.quantiles)
    for (double z2 : grid.quantiles)
      normals.push_back(normalOfSlope(gridSlope(stats, z1, z2)));
  return normals;
}

// lod of one grid sample (see leadrSampleLod), from v.m.
double sampleLod(const SlopeStatistics& stats, double vm, const glm::dvec3& m, int gridN,
                 int cubeSize)
{
  const double density = beckmannDistribution(stats, m) * m.z; // per solid angle of m
  if (!(vm > 0.0) || !(density > 0.0) || gridN <= 0 || cubeSize <= 0)
    return 0.0;
  const double omega = 4.0 * vm / (double(gridN) * gridN * density);
  const double omega0 = 4.0 * kPi / (6.0 * double(cubeSize) * cubeSize);
  return 0.5 * std::log2(omega / omega0);
}

// The specular grid sum shared by the two environment versions; `lookup(l, m, vm, stats)`
// returns the radiance arriving from tangent-space direction l, reflected by normal m.
template <class Lookup>
glm::dvec3 environmentSum(const SlopeStatistics& statsIn, const glm::dvec3& f0, const Frame& frame,
                          const glm::dvec3& viewWorld, const SlopeGrid& grid, const Lookup& lookup)
{
  const Prepared p = prepare(statsIn, frame, viewWorld);
  const double g1v = leadrMasking(p.stats, p.v);
  if (!(g1v > 0.0) || grid.n <= 0)
    return glm::dvec3(0.0);
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& m : gridNormals(p.stats, grid))
  {
    const double vm = glm::dot(p.v, m);
    if (!(vm > 0.0))
      continue;
    const glm::dvec3 l = 2.0 * vm * m - p.v;
    if (!(l.z > 0.0))
      continue;
    const double g1l = leadrMasking(p.stats, l);
    const double weight = g1v * g1l * vm / (p.v.z * m.z);
    sum += schlickFresnel(f0, vm) * lookup(l, m, vm, p.stats) * weight;
  }
  return sum / double(grid.n * grid.n);
}

glm::dvec3 faceTexel(const Image& face, int x, int y)
{
  return {face.at(x, y, 0), face.at(x, y, 1), face.at(x, y, 2)};
}

glm::dvec3 sampleFace(const Image& face, double s, double t)
{
  const double fx = std::clamp(s * face.width - 0.5, 0.0, double(face.width - 1));
  const double fy = std::clamp(t * face.height - 0.5, 0.0, double(face.height - 1));
  const int x0 = int(fx);
  const int y0 = int(fy);
  const int x1 = std::min(x0 + 1, face.width - 1);
  const int y1 = std::min(y0 + 1, face.height - 1);
  const double ax = fx - x0;
  const double ay = fy - y0;
  return (1.0 - ay) * ((1.0 - ax) * faceTexel(face, x0, y0) + ax * faceTexel(face, x1, y0)) +
         ay * ((1.0 - ax) * faceTexel(face, x0, y1) + ax * faceTexel(face, x1, y1));
}
} // namespace

SlopeMoments momentsOfSlope(const glm::dvec2& s)
{
  return {s.x, s.y, s.x * s.x, s.y * s.y, s.x * s.y};
}

LeadrMips bakeLeadrFromSlopes(const Image& slopes)
{
  if (!consistent(slopes) || slopes.channels < 2)
    throw errorAbout("slope map", "needs a non-empty image with 2 channels (dh/du, dh/dv)");
  Image level0(slopes.width, slopes.height, kChannels);
  for (int y = 0; y < slopes.height; ++y)
  {
    for (int x = 0; x < slopes.width; ++x)
    {
      const glm::dvec2 s(slopes.at(x, y, 0), slopes.at(x, y, 1));
      if (!std::isfinite(s.x) || !std::isfinite(s.y))
        throw errorAbout("slope map", "texel (" + std::to_string(x) + ", " + std::to_string(y) +
                                          ") is not finite");
      const SlopeMoments m = momentsOfSlope(s);
      storeMoments(level0, x, y, {m.x, m.y, m.xx, m.yy, m.xy});
    }
  }
  return chainFromLevel0(std::move(level0));
}

LeadrMips bakeLeadrFromHeight(const Image& height, double scale)
{
  return bakeLeadrFromSlopes(slopesFromHeight(height, scale));
}

LeadrMips bakeLeadrFromNormals(const Image& normals, bool integerEncoded)
{
  if (!consistent(normals) || normals.channels < 3)
    throw errorAbout("normal map", "needs a non-empty image with 3 or 4 channels");
  Image slopes(normals.width, normals.height, 2);
  for (int y = 0; y < normals.height; ++y)
  {
    for (int x = 0; x < normals.width; ++x)
    {
      glm::dvec3 n;
      for (int c = 0; c < 3; ++c)
        n[c] = integerEncoded ? 2.0 * normals.at(x, y, c) - 1.0 : double(normals.at(x, y, c));
      const double len = glm::length(n);
      const glm::dvec2 s =
          std::isfinite(len) && len > 0.0 ? slopeOfNormal(n / len) : glm::dvec2(0.0);
      slopes.at(x, y, 0) = float(s.x);
      slopes.at(x, y, 1) = float(s.y);
    }
  }
  return bakeLeadrFromSlopes(slopes);
}

SlopeMoments leadrTexel(const LeadrMips& mips, int level, int x, int y)
{
  const Image& image = mips.levels.at(std::size_t(level));
  std::array<double, kChannels> m{};
  for (int c = 0; c < kChannels; ++c)
    m[std::size_t(c)] = image.at(x, y, c);
  return fromArray(m);
}

SlopeMoments sampleLeadr(const LeadrMips& mips, const glm::dvec2& uv, double lod)
{
  if (mips.levels.empty())
    return {};
  const double top = double(mips.levels.size() - 1);
  const double l = std::isfinite(lod) ? std::clamp(lod, 0.0, top) : 0.0;
  const int l0 = int(std::floor(l));
  const int l1 = std::min(l0 + 1, int(top));
  const double a = l - l0;
  const auto m0 = bilinearMoments(mips.levels[std::size_t(l0)], uv);
  const auto m1 = bilinearMoments(mips.levels[std::size_t(l1)], uv);
  std::array<double, kChannels> m{};
  for (std::size_t c = 0; c < kChannels; ++c)
    m[c] = (1.0 - a) * m0[c] + a * m1[c];
  return fromArray(m);
}

SlopeStatistics slopeStatistics(const SlopeMoments& moments, double baseAlphaX, double baseAlphaY)
{
  for (double alpha : {baseAlphaX, baseAlphaY})
    if (!(alpha >= kLeadrMinAlpha && alpha <= kLeadrMaxAlpha))
      throw errorAbout("base roughness", "must be in [" + std::to_string(kLeadrMinAlpha) + ", " +
                                             std::to_string(kLeadrMaxAlpha) + "] (got " +
                                             std::to_string(alpha) + ")");
  SlopeStatistics s;
  s.mean = {moments.x, moments.y};
  const double vx = std::max(moments.xx - moments.x * moments.x, 0.0);
  const double vy = std::max(moments.yy - moments.y * moments.y, 0.0);
  const double limit = 0.999 * std::sqrt(vx * vy);
  const double c = std::clamp(moments.xy - moments.x * moments.y, -limit, limit);
  s.varX = vx + 0.5 * baseAlphaX * baseAlphaX;
  s.varY = vy + 0.5 * baseAlphaY * baseAlphaY;
  s.covXY = c;
  return s;
}

SlopeStatistics statisticsFromAveragedNormal(const glm::dvec3& averagedNormal, double baseAlphaX,
                                             double baseAlphaY)
{
  const double len = glm::length(averagedNormal);
  const glm::dvec2 slope =
      std::isfinite(len) && len > 0.0 ? slopeOfNormal(averagedNormal / len) : glm::dvec2(0.0);
  return slopeStatistics(momentsOfSlope(slope), baseAlphaX, baseAlphaY);
}

double slopeDensity(const SlopeStatistics& s, const glm::dvec2& slope)
{
  const double det = s.varX * s.varY - s.covXY * s.covXY;
  const glm::dvec2 d = slope - s.mean;
  const double q = (s.varY * d.x * d.x - 2.0 * s.covXY * d.x * d.y + s.varX * d.y * d.y) / det;
  return std::exp(-0.5 * q) / (2.0 * kPi * std::sqrt(det));
}

double beckmannDistribution(const SlopeStatistics& stats, const glm::dvec3& m)
{
  // Below 1e-100 the slope is beyond 1e100, where the density is 0 for any valid statistics
  // (and z^4 would underflow to a 0 / 0).
  if (!(m.z > 1e-100))
    return 0.0;
  const double z2 = m.z * m.z;
  return slopeDensity(stats, {-m.x / m.z, -m.y / m.z}) / (z2 * z2);
}

double beckmannLambdaExact(double a)
{
  if (!(a > 0.0))
    return std::numeric_limits<double>::infinity();
  return 0.5 * (std::exp(-a * a) / (a * std::sqrt(kPi)) - std::erfc(a));
}

double beckmannLambdaWalter(double a)
{
  if (!(a > 0.0))
    return std::numeric_limits<double>::infinity();
  if (a >= 1.6)
    return 0.0;
  return (1.0 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a);
}

double maskingParameter(const SlopeStatistics& stats, const glm::dvec3& w)
{
  const double r = std::hypot(w.x, w.y);
  if (!(r > 0.0))
    return w.z > 0.0 ? std::numeric_limits<double>::infinity() : -1.0;
  const glm::dvec2 d(w.x / r, w.y / r);
  const double cotTheta = w.z / r;
  const double mean = glm::dot(stats.mean, d);
  return (cotTheta - mean) / std::sqrt(2.0 * varianceAlong(stats, d));
}

double leadrMasking(const SlopeStatistics& stats, const glm::dvec3& w, bool exactLambda)
{
  if (!(w.z > 0.0))
    return 0.0;
  const double a = maskingParameter(stats, w);
  if (!(a > 0.0))
    return 0.0;
  if (std::isinf(a))
    return 1.0;
  const double lambda = exactLambda ? beckmannLambdaExact(a) : beckmannLambdaWalter(a);
  return 1.0 / (1.0 + lambda);
}

glm::dvec3 evalLeadrSpecular(const SlopeStatistics& stats, const glm::dvec3& f0,
                             const glm::dvec3& v, const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return glm::dvec3(0.0);
  const glm::dvec3 h = sv::normalizeScaled(v + l);
  const double g = leadrMasking(stats, v) * leadrMasking(stats, l);
  if (!(g > 0.0))
    return glm::dvec3(0.0);
  const double vh = std::max(glm::dot(v, h), 0.0);
  // D is bounded (the base roughness floors the covariance), so the floor on the denominator
  // and the cap keep f finite at grazing angles.
  const double denominator = std::max(4.0 * v.z * l.z, 1e-300);
  const double value = beckmannDistribution(stats, h) * g / denominator;
  return schlickFresnel(f0, vh) * std::min(value, 1e300);
}

glm::dvec3 liftedView(const glm::dvec3& v)
{
  if (v.z >= kSilhouetteMinViewCosine)
    return v;
  const double r = std::hypot(v.x, v.y);
  const double s = std::sqrt(1.0 - kSilhouetteMinViewCosine * kSilhouetteMinViewCosine);
  if (!(r > 0.0))
    return {s, 0.0, kSilhouetteMinViewCosine};
  return {s * v.x / r, s * v.y / r, kSilhouetteMinViewCosine};
}

SlopeStatistics withSilhouetteMicronormal(const SlopeStatistics& stats, const glm::dvec3& v)
{
  const double r = std::hypot(v.x, v.y);
  if (!(r > 0.0) || !(v.z > 0.0))
    return stats;
  const glm::dvec2 d(v.x / r, v.y / r);
  const double cot = v.z / r;
  const double along = glm::dot(stats.mean, d);
  const double across = stats.mean.y * d.x - stats.mean.x * d.y;
  // The view kSilhouetteMinA deviations above the mean microsurface's horizon.
  const double byMasking = cot - kSilhouetteMinA * std::sqrt(2.0 * varianceAlong(stats, d));
  // The mirror direction of v about the mean normal normalize(-mean, 1) above the geometric
  // horizon: cot along^2 + 2 along - cot q <= 0 with q = 1 - across^2 (at least 0), whose upper
  // root (sqrt(1 + cot^2 q) - 1) / cot is written without the cancellation at grazing views.
  const double q = std::max(0.0, 1.0 - across * across);
  const double byReflection = cot * q / (std::sqrt(1.0 + cot * cot * q) + 1.0);
  const double limit = std::min(byMasking, byReflection);
  if (along <= limit)
    return stats;
  SlopeStatistics shifted = stats;
  shifted.mean -= (along - limit) * d;
  return shifted;
}

double inverseNormalCdf(double p)
{
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                             1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                             6.680131188771972e+01, -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                             -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                             3.754408661907416e+00};
  constexpr double low = 0.02425;
  double x = 0.0;
  if (p < low)
  {
    const double q = std::sqrt(-2.0 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  else if (p <= 1.0 - low)
  {
    const double q = p - 0.5;
    const double r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  }
  else
  {
    const double q = std::sqrt(-2.0 * std::log1p(-p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  // One Halley step on Phi(x) - p brings the 1e-9 approximation to full precision.
  const double e = 0.5 * std::erfc(-x / std::sqrt(2.0)) - p;
  const double u = e * std::sqrt(2.0 * kPi) * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

SlopeGrid makeSlopeGrid(int n)
{
  return makeShiftedSlopeGrid(n, 0.5);
}

glm::dvec2 slopeGridShift(uint32_t frame)
{
  const glm::dvec2 s = glm::dvec2(0.5) + frameShift(frame);
  return s - glm::floor(s);
}

SlopeGrid makeShiftedSlopeGrid(int n, double shift)
{
  if (!(n >= 1 && n <= 64))
    throw errorAbout("slope grid", "n must be in [1, 64] (got " + std::to_string(n) + ")");
  if (!(shift >= 0.0 && shift < 1.0))
    throw errorAbout("slope grid", "shift must be in [0, 1) (got " + std::to_string(shift) + ")");
  SlopeGrid grid;
  grid.n = n;
  for (int i = 0; i < n; ++i)
    grid.quantiles.push_back(inverseNormalCdf(std::clamp((i + shift) / n, 0x1p-24, 1.0 - 0x1p-24)));
  return grid;
}

glm::dvec2 gridSlope(const SlopeStatistics& s, double z1, double z2)
{
  const double l11 = std::sqrt(s.varX);
  const double l21 = s.covXY / l11;
  const double l22 = std::sqrt(std::max(s.varY - l21 * l21, 0.0));
  return s.mean + glm::dvec2(l11 * z1, l21 * z1 + l22 * z2);
}

glm::dvec3 shadeLeadr(const LeadrMaterial& material, const SlopeStatistics& stats,
                      const Frame& frame, const glm::dvec3& position, const glm::dvec3& viewWorld,
                      const std::vector<Light>& lights, const SlopeGrid& grid)
{
  const Prepared p = prepare(stats, frame, viewWorld);
  const std::vector<glm::dvec3> normals = gridNormals(p.stats, grid);
  glm::dvec3 sum(0.0);
  for (const Light& light : lights)
  {
    const LightArrival arrival = arriveAt(light, position);
    const glm::dvec3 l = frame.toLocal(arrival.direction);
    if (!(l.z > 0.0))
      continue;
    double lambert = 0.0;
    for (const glm::dvec3& m : normals)
      lambert += std::max(glm::dot(m, l), 0.0);
    lambert /= double(std::max<std::size_t>(normals.size(), 1));
    const glm::dvec3 term =
        evalLeadrSpecular(p.stats, material.f0, p.v, l) * l.z + material.diffuse * (lambert / kPi);
    sum += term * arrival.irradiance;
  }
  return sum;
}

glm::dvec3 leadrEnvironmentSpecular(const SlopeStatistics& stats, const glm::dvec3& f0,
                                    const Frame& frame, const glm::dvec3& viewWorld,
                                    const Environment& env, const SlopeGrid& grid)
{
  return environmentSum(stats, f0, frame, viewWorld, grid,
                        [&](const glm::dvec3& l, const glm::dvec3&, double, const SlopeStatistics&)
                        { return env.radiance(frame.toWorld(l)); });
}

double leadrSampleLod(const SlopeStatistics& stats, const glm::dvec3& v, const glm::dvec3& m,
                      int gridN, int cubeSize)
{
  return sampleLod(stats, glm::dot(v, m), m, gridN, cubeSize);
}

glm::dvec3 leadrEnvironmentSpecular(const SlopeStatistics& stats, const glm::dvec3& f0,
                                    const Frame& frame, const glm::dvec3& viewWorld,
                                    const Cubemap& cube, const SlopeGrid& grid)
{
  return environmentSum(
      stats, f0, frame, viewWorld, grid,
      [&](const glm::dvec3& l, const glm::dvec3& m, double vm, const SlopeStatistics& s)
      {
        const double lod = sampleLod(s, vm, m, grid.n, cube.size);
        return sampleCubemap(cube, frame.toWorld(l), lod);
      });
}

glm::dvec3 leadrEnvironmentDiffuse(const SlopeStatistics& stats, const glm::dvec3& diffuse,
                                   const Frame& frame, const Sh9& sh, const SlopeGrid& grid)
{
  glm::dvec3 sum(0.0);
  const std::vector<glm::dvec3> normals = gridNormals(stats, grid);
  for (const glm::dvec3& m : normals)
    sum += glm::max(irradianceSh9(sh, frame.toWorld(m)), glm::dvec3(0.0));
  return diffuse / kPi * sum / double(std::max<std::size_t>(normals.size(), 1));
}

glm::dvec3 sampleCubemap(const Cubemap& cube, const glm::dvec3& d, double lod)
{
  if (cube.mips.empty())
    return glm::dvec3(0.0);
  const double top = double(cube.mips.size() - 1);
  const double l = std::isfinite(lod) ? std::clamp(lod, 0.0, top) : 0.0;
  const int l0 = int(std::floor(l));
  const int l1 = std::min(l0 + 1, int(top));
  const double a = l - l0;
  double s = 0.5;
  double t = 0.5;
  const int face = cubeFaceOf(d, &s, &t);
  const glm::dvec3 c0 = sampleFace(cube.mips[std::size_t(l0)][std::size_t(face)], s, t);
  if (a == 0.0)
    return c0;
  const glm::dvec3 c1 = sampleFace(cube.mips[std::size_t(l1)][std::size_t(face)], s, t);
  return (1.0 - a) * c0 + a * c1;
}
} // namespace aniso
