#include "core/reference/reference_integrator.h"

#include "core/env/env_sources.h"
#include "core/env/parallel.h"
#include "core/env/quadrature.h"
#include "core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr int kMaxLevel = 12;

double luminance(const glm::dvec3& c)
{
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// Level k: (32 << k) azimuths times (8 << k) panels of 4 Gauss-Legendre nodes along each
// azimuth (the specular rule splits its panels between two pieces); its cost counts the nodes.
int azimuthsAt(int level)
{
  return 32 << level;
}
int panelsAt(int level)
{
  return 8 << level;
}
uint64_t costAt(int level)
{
  return 1024ull << (2 * level);
}

void validate(const ReferenceOptions& options)
{
  if (!(options.relativeTolerance >= 0.0) || !std::isfinite(options.relativeTolerance))
    throw errorAbout("relativeTolerance", "must be finite and >= 0");
  if (!(options.absoluteTolerance >= 0.0) || !std::isfinite(options.absoluteTolerance))
    throw errorAbout("absoluteTolerance", "must be finite and >= 0");
  if (options.maxEvaluations < kReferenceMinEvaluations)
    throw errorAbout("maxEvaluations", "must be at least " +
                                           std::to_string(kReferenceMinEvaluations) + ", got " +
                                           std::to_string(options.maxEvaluations));
}

// Doubles the resolution until two successive differences between levels are both within
// tolerance (in luminance), so that a chance agreement of two coarse levels is not taken for
// convergence, or until the next level would exceed the evaluation budget. The error estimate is
// the larger of those two differences: under a bright source smaller than the coarse grids (a
// sun in an HDRI) the levels converge erratically, and the last difference alone understated the
// error (Blender's sunset, lobe (100, 10): converged at level 2 with a last difference of
// 1.5e-3, an error of 1.8e-3 against a 2^20-sample estimate, the difference before 2.7e-3;
// tests/bench/test_reference_image.cxx).
// COST gives a level's evaluations, MAX_LEVEL the finest level tried.
template <class LevelFn, class CostFn>
ReferenceResult refine(const LevelFn& evaluateLevel, const CostFn& costOf, int maxLevel,
                       const ReferenceOptions& options)
{
  ReferenceResult result;
  glm::dvec3 previous = evaluateLevel(0);
  result.value = previous;
  result.evaluations = costOf(0);
  double previousDifference = std::numeric_limits<double>::infinity();
  for (int level = 1; level <= maxLevel; ++level)
  {
    const uint64_t cost = costOf(level);
    if (result.evaluations + cost > options.maxEvaluations)
      break;
    const glm::dvec3 current = evaluateLevel(level);
    result.evaluations += cost;
    result.value = current;
    const double difference = luminance(glm::abs(current - previous));
    // At level 1 only one difference exists: the estimate takes it alone.
    result.errorEstimate = level > 1 ? std::max(difference, previousDifference) : difference;
    const double allowed = std::max(options.relativeTolerance * std::abs(luminance(current)),
                                    options.absoluteTolerance);
    if (difference <= allowed && previousDifference <= allowed)
    {
      result.converged = true;
      break;
    }
    previousDifference = difference;
    previous = current;
  }
  return result;
}

template <class LevelFn>
ReferenceResult refine(const LevelFn& evaluateLevel, const ReferenceOptions& options)
{
  return refine(evaluateLevel, costAt, kMaxLevel, options);
}

// Row sums of a (rows x columns) grid, in parallel once the grid is large enough to pay for the
// threads; summed in row order so the result does not depend on the thread count.
template <class RowFn>
glm::dvec3 sumRows(int rows, std::size_t columns, const RowFn& row)
{
  std::vector<glm::dvec3> sums(std::size_t(rows), glm::dvec3(0.0));
  const bool large = std::size_t(rows) * columns >= 16384;
  parallelFor(
      rows, [&](int i) { sums[std::size_t(i)] = row(i); }, large ? 1 : rows);
  glm::dvec3 total(0.0);
  for (const glm::dvec3& s : sums)
    total += s;
  return total;
}

// The specular integral over half vectors. With dw_l = 4 (v.h) dw_h, f_s L (n.l) dw_l becomes
// p_h(h) F(v.h) L(l) (n.l) / max(n.v, n.l) dw_h. In spherical coordinates of h,
// p_h dw_h = C mu^e(phi) dmu dphi with mu = cos(theta), e(phi) = nu cos^2 + nv sin^2 and
// C = sqrt(a b) / (2 pi), a = nu + 1, b = nv + 1. Two substitutions make this measure simple:
//   mu^(e + 1) = exp(-rho^2)    gives mu^e dmu = 2 rho exp(-rho^2) drho / (e + 1);
//   (cos phi, sin phi) ~ (sqrt(b) cos psi, sqrt(a) sin psi)
//                               gives dphi / (e + 1) = dpsi / sqrt(a b), and e + 1 = a b / R^2
//                               with R^2 = b cos^2 psi + a sin^2 psi.
// So p_h dw_h = 2 rho exp(-rho^2) drho dpsi / (2 pi): a unit Gaussian in the plane with polar
// coordinates (rho, psi), whatever the exponents; the lobe's width is gone from the grid, and
// rho > 6 holds less than 1e-15 of it. The integrand is smooth and periodic in psi (see
// specularAtLevel for where it is steep). Along each azimuth (a meridian of h), n.l = 2 (v.h)(n.h)
// - n.v = A cos(2 theta - alpha) with A cos(alpha) = n.v, A sin(alpha) = v.(cos phi, sin phi, 0): l
// reaches the horizon at theta = (alpha + pi/2) / 2 and, when alpha > 0, crosses n.l = n.v (the
// kink of max) at theta = alpha. The rho interval is split there, so each piece is smooth and
// Gauss-Legendre converges quickly on it.
constexpr double kRhoMax = 6.0;

struct SpecularSetup
{
  double sqrtA;
  double sqrtB;
  double ab;
  glm::dvec3 v; // tangent space, v.z > 0
  glm::dvec3 f0;
  Frame frame;
  const Environment* env;
};

// Integral over rho of F L (n.l) / max(n.v, n.l) 2 rho exp(-rho^2) along one azimuth.
glm::dvec3 specularRow(const SpecularSetup& s, double cosPhi, double sinPhi, double ePlusOne,
                       const QuadratureRule& unit)
{
  const double alpha = std::atan2(s.v.x * cosPhi + s.v.y * sinPhi, s.v.z);
  // rho of a polar angle: rho^2 = -(e + 1) ln cos(theta), written to stay exact for small theta.
  auto rhoOf = [&](double theta)
  {
    const double sn = std::sin(theta);
    return std::sqrt(-0.5 * ePlusOne * std::log1p(-sn * sn));
  };
  const double rhoEnd = std::min(rhoOf(0.5 * (alpha + 0.5 * kPi)), kRhoMax);
  const double rhoKink = alpha > 0.0 ? std::min(rhoOf(alpha), rhoEnd) : 0.0;
  const double bounds[3] = {0.0, rhoKink, rhoEnd};
  glm::dvec3 sum(0.0);
  for (int piece = 0; piece < 2; ++piece)
  {
    const double r0 = bounds[piece];
    const double width = bounds[piece + 1] - r0;
    if (!(width > 0.0))
      continue;
    for (std::size_t k = 0; k < unit.nodes.size(); ++k)
    {
      const double rho = r0 + width * unit.nodes[k];
      // mu and sin(theta) through logarithms and expm1, so that a lobe of exponent 1e6
      // (theta ~ 1e-3) keeps full relative precision.
      const double logMu = -rho * rho / ePlusOne;
      const double mu = std::exp(logMu);
      const double sinTheta = std::sqrt(std::max(0.0, -std::expm1(2.0 * logMu)));
      const glm::dvec3 h(sinTheta * cosPhi, sinTheta * sinPhi, mu);
      const double vDotH = glm::dot(s.v, h);
      const glm::dvec3 l = 2.0 * vDotH * h - s.v;
      const double nDotL = l.z;
      if (nDotL <= 0.0 || vDotH <= 0.0)
        continue; // only by rounding at the horizon end of the last piece
      const double m = 1.0 - vDotH;
      const double m5 = m * m * m * m * m;
      const glm::dvec3 fresnel = s.f0 + (glm::dvec3(1.0) - s.f0) * m5;
      const glm::dvec3 radiance = s.env->radiance(s.frame.toWorld(l));
      const double weight = width * unit.weights[k] * 2.0 * rho * std::exp(-rho * rho);
      sum += (weight * nDotL / std::max(s.v.z, nDotL)) * fresnel * radiance;
    }
  }
  return sum;
}

glm::dvec3 specularAtLevel(const SpecularSetup& s, int level)
{
  // Azimuths: where h's meridian is perpendicular to the view (v.(cos phi, sin phi, 0) = 0),
  // alpha swings from -pi/2 to pi/2 within an angle ~ n.v, so at grazing views the row integral
  // changes steeply there. The circle is cut at those two azimuths into two arcs, each mapped
  // by psi = psi0 + pi (t - sin(2 pi t) / (2 pi)), which crowds the nodes towards the cuts;
  // the midpoint rule in t stays high-order since the map's derivative vanishes at both ends.
  const double phiCut = std::atan2(s.v.y, s.v.x) + 0.5 * kPi;
  const double psiCut = std::atan2(std::sin(phiCut) / s.sqrtA, std::cos(phiCut) / s.sqrtB);
  const int perArc = azimuthsAt(level) / 2;
  // Each of the (at most two) rho pieces gets half the panels of the irradiance rule.
  const QuadratureRule unit = compositeGaussLegendre(panelsAt(level) / 2, 4, 0.0, 1.0);
  const glm::dvec3 total =
      sumRows(2 * perArc, 2 * unit.nodes.size(),
              [&](int i)
              {
                const double t = (i % perArc + 0.5) / perArc;
                const double psi =
                    psiCut + kPi * ((i / perArc) + t - std::sin(kTwoPi * t) / kTwoPi);
                const double dPsi = kPi * (1.0 - std::cos(kTwoPi * t)) / perArc;
                const double x = s.sqrtB * std::cos(psi);
                const double y = s.sqrtA * std::sin(psi);
                const double r2 = x * x + y * y;
                const double r = std::sqrt(r2);
                return dPsi * specularRow(s, x / r, y / r, s.ab / r2, unit);
              });
  return total / kTwoPi;
}

glm::dvec3 irradianceAtLevel(const Frame& frame, const Environment& env, int level)
{
  // E = integral over the hemisphere of L mu dmu dphi: Gauss-Legendre in mu = n.l, equally
  // spaced azimuths.
  const int azimuths = azimuthsAt(level);
  const QuadratureRule muRule = compositeGaussLegendre(panelsAt(level), 4, 0.0, 1.0);
  const glm::dvec3 total = sumRows(
      azimuths, muRule.nodes.size(),
      [&](int i)
      {
        const double phi = (i + 0.5) * kTwoPi / azimuths;
        const double c = std::cos(phi);
        const double sn = std::sin(phi);
        glm::dvec3 sum(0.0);
        for (std::size_t k = 0; k < muRule.nodes.size(); ++k)
        {
          const double mu = muRule.nodes[k];
          const double r = std::sqrt(std::max(0.0, 1.0 - mu * mu));
          sum += (muRule.weights[k] * mu) * env.radiance(frame.toWorld({r * c, r * sn, mu}));
        }
        return sum;
      });
  return total * (kTwoPi / azimuths);
}

bool finiteVector(const glm::dvec3& d)
{
  return std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z);
}
} // namespace

ReferenceResult integrateSpecular(const AsLobe& lobe, const glm::dvec3& f0, const Frame& frame,
                                  const glm::dvec3& viewWorld, const Environment& env,
                                  const ReferenceOptions& options)
{
  validate(options);
  validateLobe(lobe);
  for (int c = 0; c < 3; ++c)
    if (!(f0[c] >= 0.0 && f0[c] <= 1.0))
      throw errorAbout("F0", "must be in [0, 1] per channel");
  if (!finiteVector(viewWorld) || !(glm::length(viewWorld) > 0.0))
    throw errorAbout("view", "must be a finite non-zero vector");

  SpecularSetup setup;
  setup.sqrtA = std::sqrt(lobe.nu + 1.0);
  setup.sqrtB = std::sqrt(lobe.nv + 1.0);
  setup.ab = (lobe.nu + 1.0) * (lobe.nv + 1.0);
  setup.v = glm::normalize(frame.toLocal(glm::normalize(viewWorld)));
  setup.f0 = f0;
  setup.frame = frame;
  setup.env = &env;
  if (setup.v.z <= 0.0)
  {
    ReferenceResult below;
    below.converged = true; // f_s is zero for views below the surface
    return below;
  }
  return refine([&](int level) { return specularAtLevel(setup, level); }, options);
}

ReferenceResult integrateIrradiance(const glm::dvec3& normalWorld, const Environment& env,
                                    const ReferenceOptions& options)
{
  validate(options);
  if (!finiteVector(normalWorld) || !(glm::length(normalWorld) > 0.0))
    throw errorAbout("normal", "must be a finite non-zero vector");
  const Frame frame = Frame::fromNormalTangent(normalWorld, {1.0, 0.0, 0.0});
  return refine([&](int level) { return irradianceAtLevel(frame, env, level); }, options);
}

namespace
{
// Smith Lambda of the anisotropic GGX model, written out here so that the reference does not
// share code with brdf/ggx.cxx: (sqrt(1 + (ax^2 w.x^2 + ay^2 w.y^2) / w.z^2) - 1) / 2, w.z > 0.
double ggxLambdaOf(double ax, double ay, const glm::dvec3& w)
{
  const double x = ax * w.x;
  const double y = ay * w.y;
  const double a2 = (x * x + y * y) / (w.z * w.z);
  if (a2 > 1.0)
    return 0.5 * (std::sqrt(1.0 + a2) - 1.0); // +infinity when a2 overflows: G2 = 0
  return a2 / (2.0 * (1.0 + std::sqrt(1.0 + a2)));
}

glm::dvec3 schlick(const glm::dvec3& f0, double vDotH)
{
  const double m = 1.0 - vDotH;
  return f0 + (glm::dvec3(1.0) - f0) * (m * m * m * m * m);
}

void validateSpecularInputs(const glm::dvec3& f0, const glm::dvec3& viewWorld)
{
  for (int c = 0; c < 3; ++c)
    if (!(f0[c] >= 0.0 && f0[c] <= 1.0))
      throw errorAbout("F0", "must be in [0, 1] per channel");
  if (!finiteVector(viewWorld) || !(glm::length(viewWorld) > 0.0))
    throw errorAbout("view", "must be a finite non-zero vector");
}

// s = ln r below this holds less than exp(2 s) = 4e-18 of the slope measure.
constexpr double kLogRadiusMin = -20.0;

struct GgxSetup
{
  double ax;
  double ay;
  double lambdaV;
  glm::dvec3 v; // tangent space, v.z > 0
  glm::dvec3 f0;
  Frame frame;
  const Environment* env;
};

// Integral over s = ln r of G2 F L (v.h) / ((n.v)(n.h)) sech^2(s) / 2 along one azimuth psi of
// the stretched slope plane. The slope (ax r cos psi, ay r sin psi) gives h on the meridian of
// azimuth phi, (cos phi, sin phi) = (ax cos psi, ay sin psi) / R, at tan(theta) = r R. As for
// Ashikhmin-Shirley, l reaches the horizon at theta = (alpha + pi/2) / 2; the integrand falls to
// zero there (G2 vanishes with n.l), so the rule ends at that point and is smooth up to it.
glm::dvec3 ggxRow(const GgxSetup& s, double cosPsi, double sinPsi, const QuadratureRule& unit)
{
  const double mx = s.ax * cosPsi;
  const double my = s.ay * sinPsi;
  const double stretch = std::sqrt(mx * mx + my * my);
  const double cosPhi = mx / stretch;
  const double sinPhi = my / stretch;
  const double alpha = std::atan2(s.v.x * cosPhi + s.v.y * sinPhi, s.v.z);
  const double logRadiusEnd = std::log(std::tan(0.5 * (alpha + 0.5 * kPi)) / stretch);
  const double width = logRadiusEnd - kLogRadiusMin;
  glm::dvec3 sum(0.0);
  if (!(width > 0.0))
    return sum; // the whole visible part of this azimuth holds less than 4e-18 of the measure
  for (std::size_t k = 0; k < unit.nodes.size(); ++k)
  {
    const double r = std::exp(kLogRadiusMin + width * unit.nodes[k]);
    const double r2 = r * r;
    const double tanTheta = r * stretch;
    const double cosTheta = 1.0 / std::sqrt(1.0 + tanTheta * tanTheta);
    const double sinTheta = tanTheta * cosTheta;
    const glm::dvec3 h(sinTheta * cosPhi, sinTheta * sinPhi, cosTheta);
    const double vDotH = glm::dot(s.v, h);
    const glm::dvec3 l = 2.0 * vDotH * h - s.v;
    if (l.z <= 0.0 || vDotH <= 0.0)
      continue; // only by rounding at the horizon end
    const double g2 = 1.0 / (1.0 + s.lambdaV + ggxLambdaOf(s.ax, s.ay, l));
    const double measure = width * unit.weights[k] * 2.0 * r2 / ((1.0 + r2) * (1.0 + r2));
    const glm::dvec3 radiance = s.env->radiance(s.frame.toWorld(l));
    sum += (measure * g2 * vDotH / (s.v.z * cosTheta)) * schlick(s.f0, vDotH) * radiance;
  }
  return sum;
}

glm::dvec3 ggxAtLevel(const GgxSetup& s, int level)
{
  // The circle of psi is cut at four azimuths, and each arc mapped by
  // psi = start + length (t - sin(2 pi t) / (2 pi)), which crowds the nodes towards the cuts
  // (see specularAtLevel): where h's meridian is perpendicular to the view (steep at grazing
  // views), and on the axis of the smaller alpha. There, in a strongly anisotropic lobe, l's
  // azimuth and with it Lambda(l) swing over a psi-range of about (alpha_min / alpha_max)^2.
  const double phiCut = std::atan2(s.v.y, s.v.x) + 0.5 * kPi;
  const double viewCut = std::atan2(std::sin(phiCut) / s.ay, std::cos(phiCut) / s.ax);
  const double axisCut = s.ax <= s.ay ? 0.0 : 0.5 * kPi;
  std::array<double, 5> cuts = {std::remainder(viewCut, kPi) + kPi, axisCut, axisCut + kPi,
                                std::remainder(viewCut, kPi) + 2.0 * kPi, 0.0};
  for (int i = 0; i < 4; ++i)
    cuts[std::size_t(i)] -= kTwoPi * std::floor(cuts[std::size_t(i)] / kTwoPi);
  std::sort(cuts.begin(), cuts.begin() + 4);
  cuts[4] = cuts[0] + kTwoPi;
  const int perArc = azimuthsAt(level) / 4;
  const QuadratureRule unit = compositeGaussLegendre(panelsAt(level), 4, 0.0, 1.0);
  const glm::dvec3 total =
      sumRows(4 * perArc, unit.nodes.size(),
              [&](int i)
              {
                const std::size_t arc = std::size_t(i / perArc);
                const double start = cuts[arc];
                const double length = cuts[arc + 1] - start;
                const double t = (i % perArc + 0.5) / perArc;
                const double psi = start + length * (t - std::sin(kTwoPi * t) / kTwoPi);
                const double dPsi = length * (1.0 - std::cos(kTwoPi * t)) / perArc;
                return dPsi * ggxRow(s, std::cos(psi), std::sin(psi), unit);
              });
  return total / kTwoPi;
}

// Integral of brdfCos(l) = f(v, l)(n.l) (l in tangent space) over the cone of the disc, times
// its radiance: Gauss-Legendre panels in the angle beta from the centre (dw = sin(beta) dbeta
// dgamma), equally spaced angles gamma around it (periodic, so the midpoint rule is spectrally
// accurate). The disc's edge is the domain's edge, so the hard edge costs nothing.
template <class BrdfCos>
glm::dvec3 discAtLevel(const DiscSource& disc, const Frame& frame, const BrdfCos& brdfCos,
                       int level)
{
  const Frame around = Frame::fromNormalTangent(disc.direction, {1.0, 0.0, 0.0});
  const int azimuths = azimuthsAt(level);
  const QuadratureRule beta = compositeGaussLegendre(panelsAt(level), 4, 0.0, disc.angularRadius);
  const glm::dvec3 total =
      sumRows(azimuths, beta.nodes.size(),
              [&](int i)
              {
                const double gamma = (i + 0.5) * kTwoPi / azimuths;
                const glm::dvec3 across = std::cos(gamma) * around.t + std::sin(gamma) * around.b;
                glm::dvec3 sum(0.0);
                for (std::size_t k = 0; k < beta.nodes.size(); ++k)
                {
                  const double b = beta.nodes[k];
                  const glm::dvec3 l = std::cos(b) * around.n + std::sin(b) * across;
                  sum += (beta.weights[k] * std::sin(b)) * brdfCos(frame.toLocal(l));
                }
                return sum;
              });
  return total * (kTwoPi / azimuths) * disc.radiance;
}

// Sky part plus disc part, each refined on its own.
template <class SkyFn, class BrdfCos>
ReferenceResult sunSkySum(const SunSkyEnvironment& env, const Frame& frame, const SkyFn& sky,
                          const BrdfCos& brdfCos, const ReferenceOptions& options)
{
  ReferenceResult result;
  result.converged = true; // a black sky adds nothing and needs no integration
  if (env.sky() != glm::dvec3(0.0))
    result = sky(UniformEnvironment(env.sky()));
  const ReferenceResult disc =
      refine([&](int level) { return discAtLevel(env.sun(), frame, brdfCos, level); }, options);
  result.value += disc.value;
  result.errorEstimate += disc.errorEstimate;
  result.evaluations += disc.evaluations;
  result.converged = result.converged && disc.converged;
  return result;
}

// f_s (n.l) of Ashikhmin-Shirley written out (see the file's header comment), for a tangent-space
// light direction l and view v (v.z > 0).
struct AsBrdfCos
{
  AsLobe lobe;
  glm::dvec3 f0;
  glm::dvec3 v;
  glm::dvec3 operator()(const glm::dvec3& l) const
  {
    if (l.z <= 0.0)
      return glm::dvec3(0.0);
    const glm::dvec3 h = glm::normalize(v + l);
    const double vDotH = glm::dot(v, h);
    if (vDotH <= 0.0)
      return glm::dvec3(0.0);
    const double scale = std::sqrt((lobe.nu + 1.0) * (lobe.nv + 1.0)) / kTwoPi;
    const double tangential = h.x * h.x + h.y * h.y;
    const double exponent = tangential > 0.0
                                ? (lobe.nu * h.x * h.x + lobe.nv * h.y * h.y) / tangential
                                : 0.5 * (lobe.nu + lobe.nv);
    const double logCos = tangential < 0.5 ? 0.5 * std::log1p(-tangential) : std::log(h.z);
    const double ph = scale * std::exp(exponent * logCos);
    return (ph * l.z / (4.0 * vDotH * std::max(v.z, l.z))) * schlick(f0, vDotH);
  }
};

// The excess over its support at k x k cells a texel: midpoints in (phi, cos theta), each cell
// 1 / k^2 of its texel's solid angle.
template <class BrdfCos>
glm::dvec3 excessAtCells(const SourceQuadrature& q, const Frame& frame, const BrdfCos& brdfCos,
                         int k)
{
  const int w = q.width;
  const int h = q.height;
  return sumRows(int(q.support.size()), std::size_t(k) * std::size_t(k),
                 [&](int i)
                 {
                   const std::uint32_t texel = q.support[std::size_t(i)];
                   const int x = int(texel % std::uint32_t(w));
                   const int y = int(texel / std::uint32_t(w));
                   const double zTop = std::cos(kPi * y / h);
                   const double zBottom = std::cos(kPi * (y + 1) / h);
                   const double cell = kTwoPi / w * (zTop - zBottom) / (double(k) * k);
                   glm::dvec3 sum(0.0);
                   for (int j = 0; j < k; ++j)
                   {
                     const double z = zTop + (zBottom - zTop) * (j + 0.5) / k;
                     const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                     for (int c = 0; c < k; ++c)
                     {
                       const double phi = kPi - kTwoPi * (x + (c + 0.5) / k) / w;
                       const glm::dvec3 d(r * std::cos(phi), r * std::sin(phi), z);
                       const glm::dvec3 f = brdfCos(frame.toLocal(d));
                       if (f != glm::dvec3(0.0))
                         sum += f * q.excess->radiance(d);
                     }
                   }
                   return sum * cell;
                 });
}

// refine()'s rule over k = 2^level cells a side (up to 256), its cost the support's cells.
template <class BrdfCos>
ReferenceResult refineExcess(const SourceQuadrature& q, const Frame& frame,
                             const BrdfCos& brdfCos, const ReferenceOptions& options)
{
  const uint64_t texels = q.support.size();
  return refine([&](int level) { return excessAtCells(q, frame, brdfCos, 1 << level); },
                [&](int level) { return texels << (2 * level); }, 8, options);
}

// env less the excess: the residual the rules integrate.
class ResidualOf : public Environment
{
public:
  ResidualOf(const Environment& whole, const Environment& excess) : whole_(whole), excess_(excess)
  {
  }
  glm::dvec3 radiance(const glm::dvec3& d) const override
  {
    return whole_.radiance(d) - excess_.radiance(d);
  }
  std::string key() const override { return whole_.key() + ":less-excess"; }

private:
  const Environment& whole_;
  const Environment& excess_;
};

// The unit view in tangent space.
glm::dvec3 localView(const Frame& frame, const glm::dvec3& viewWorld)
{
  return glm::normalize(frame.toLocal(glm::normalize(viewWorld)));
}

// The exact result for a view below the surface, where nothing is reflected.
ReferenceResult reflectsNothing()
{
  ReferenceResult below;
  below.converged = true;
  return below;
}
} // namespace

ReferenceResult integrateSpecularGgx(const GgxLobe& lobe, const glm::dvec3& f0, const Frame& frame,
                                     const glm::dvec3& viewWorld, const Environment& env,
                                     const ReferenceOptions& options)
{
  validate(options);
  validateGgxLobe(lobe);
  validateSpecularInputs(f0, viewWorld);
  GgxSetup setup;
  setup.ax = lobe.alphaX;
  setup.ay = lobe.alphaY;
  setup.v = localView(frame, viewWorld);
  setup.f0 = f0;
  setup.frame = frame;
  setup.env = &env;
  if (setup.v.z <= 0.0)
    return reflectsNothing();
  setup.lambdaV = ggxLambdaOf(setup.ax, setup.ay, setup.v);
  return refine([&](int level) { return ggxAtLevel(setup, level); }, options);
}

ReferenceResult integrateSpecularSunSky(const AsLobe& lobe, const glm::dvec3& f0,
                                        const Frame& frame, const glm::dvec3& viewWorld,
                                        const SunSkyEnvironment& env,
                                        const ReferenceOptions& options)
{
  validate(options);
  validateLobe(lobe);
  validateSpecularInputs(f0, viewWorld);
  const glm::dvec3 v = localView(frame, viewWorld);
  if (v.z <= 0.0)
    return reflectsNothing();
  const AsBrdfCos brdfCos{lobe, f0, v};
  return sunSkySum(
      env, frame,
      [&](const Environment& sky)
      { return integrateSpecular(lobe, f0, frame, viewWorld, sky, options); },
      brdfCos, options);
}

ReferenceResult integrateSpecularGgxSunSky(const GgxLobe& lobe, const glm::dvec3& f0,
                                           const Frame& frame, const glm::dvec3& viewWorld,
                                           const SunSkyEnvironment& env,
                                           const ReferenceOptions& options)
{
  validate(options);
  validateGgxLobe(lobe);
  validateSpecularInputs(f0, viewWorld);
  const glm::dvec3 v = localView(frame, viewWorld);
  if (v.z <= 0.0)
    return reflectsNothing();
  const double lambdaV = ggxLambdaOf(lobe.alphaX, lobe.alphaY, v);
  // D G2 F / (4 (n.v)(n.l)) times n.l, written out.
  auto brdfCos = [&](const glm::dvec3& l) -> glm::dvec3
  {
    if (l.z <= 0.0)
      return glm::dvec3(0.0);
    const glm::dvec3 h = glm::normalize(v + l);
    const double vDotH = glm::dot(v, h);
    if (vDotH <= 0.0)
      return glm::dvec3(0.0);
    const double x = h.x / lobe.alphaX;
    const double y = h.y / lobe.alphaY;
    const double q = x * x + y * y + h.z * h.z;
    const double d = 1.0 / (kPi * lobe.alphaX * lobe.alphaY * q * q);
    const double g2 = 1.0 / (1.0 + lambdaV + ggxLambdaOf(lobe.alphaX, lobe.alphaY, l));
    return (d * g2 / (4.0 * v.z)) * schlick(f0, vDotH);
  };
  return sunSkySum(
      env, frame,
      [&](const Environment& sky)
      { return integrateSpecularGgx(lobe, f0, frame, viewWorld, sky, options); },
      brdfCos, options);
}

std::shared_ptr<const SourceQuadrature> sharedSourceQuadrature(const Environment& env)
{
  if (!dynamic_cast<const EquirectEnvironment*>(&env))
    return nullptr;
  // The last few environments' verdicts, null ones too (a reference asks pixel by pixel); one
  // thread computes while the others wait for it.
  static std::mutex mutex;
  static std::vector<std::pair<std::string, std::shared_ptr<const SourceQuadrature>>> recent;
  const std::string key = env.key();
  const std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [k, q] : recent)
    if (k == key)
      return q;
  const std::shared_ptr<const EnvAnalysis> analysis = sharedEnvironmentAnalysis(env);
  std::shared_ptr<SourceQuadrature> result;
  if (analysis->concentrated())
  {
    result = std::make_shared<SourceQuadrature>();
    result->width = analysis->width;
    result->height = analysis->height;
    const int w = result->width;
    const int h = result->height;
    const std::size_t texels = std::size_t(w) * std::size_t(h);
    // Only the sources whose peak reaches kConcentratedPeak x T (suns, lamps, bright panels):
    // a broad dim region above T (a bright sky) stays with the rules, which resolve it, where
    // its texels would make the quadrature long. Any subset of the excess keeps the sum exact.
    std::vector<double> peak;
    for (std::size_t i = 0; i < texels; ++i)
    {
      const int rank = analysis->sourceRank[i];
      if (rank < 0)
        continue;
      if (std::size_t(rank) >= peak.size())
        peak.resize(std::size_t(rank) + 1, 0.0);
      const float* e = &analysis->excess.data[i * 3];
      const float* r = &analysis->residual.data[i * 3];
      peak[std::size_t(rank)] = std::max(
          peak[std::size_t(rank)], luminance(glm::dvec3(e[0] + r[0], e[1] + r[1], e[2] + r[2])));
    }
    Image excess(w, h, 3);
    for (std::size_t i = 0; i < texels; ++i)
    {
      const int rank = analysis->sourceRank[i];
      if (rank >= 0 &&
          peak[std::size_t(rank)] >= EnvAnalysis::kConcentratedPeak * analysis->threshold)
        for (std::size_t c = 0; c < 3; ++c)
          excess.data[i * 3 + c] = analysis->excess.data[i * 3 + c];
    }
    std::vector<char> reached(texels, 0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
      {
        const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
        const float* e = &excess.data[i * 3];
        if (!(e[0] > 0.0f || e[1] > 0.0f || e[2] > 0.0f))
          continue;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
          {
            const int ny = std::clamp(y + dy, 0, h - 1);
            const int nx = (x + dx + w) % w;
            reached[std::size_t(ny) * std::size_t(w) + std::size_t(nx)] = 1;
          }
      }
    for (std::size_t i = 0; i < reached.size(); ++i)
      if (reached[i])
        result->support.push_back(std::uint32_t(i));
    result->excess =
        std::make_shared<EquirectEnvironment>(std::move(excess), analysis->key + ":excess");
  }
  recent.emplace_back(key, result);
  if (recent.size() > 4)
    recent.erase(recent.begin());
  return result;
}

ReferenceResult integrateSpecularSources(const AsLobe& lobe, const glm::dvec3& f0,
                                         const Frame& frame, const glm::dvec3& viewWorld,
                                         const Environment& env, const SourceQuadrature& sources,
                                         const ReferenceOptions& options)
{
  validate(options);
  validateLobe(lobe);
  validateSpecularInputs(f0, viewWorld);
  const glm::dvec3 v = localView(frame, viewWorld);
  if (v.z <= 0.0)
    return reflectsNothing();
  const ResidualOf residual(env, *sources.excess);
  ReferenceResult result = integrateSpecular(lobe, f0, frame, viewWorld, residual, options);
  const ReferenceResult excess = refineExcess(sources, frame, AsBrdfCos{lobe, f0, v}, options);
  result.value += excess.value;
  result.errorEstimate += excess.errorEstimate;
  result.evaluations += excess.evaluations;
  result.converged = result.converged && excess.converged;
  return result;
}
} // namespace aniso
