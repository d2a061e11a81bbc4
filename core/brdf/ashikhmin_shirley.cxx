#include "core/brdf/ashikhmin_shirley.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <sstream>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kLn2 = 0.69314718055994530942;

// Largest double below 1: where inputs meant to lie in [0, 1) are clamped.
constexpr double kBelowOne = 1.0 - std::numeric_limits<double>::epsilon() / 2.0;

// f_s grows like 1 / (n.v)^2 at grazing angles; this floor on its denominator keeps it finite
// for any unit input (p_h <= 1.6e5, so the quotient stays below 1e306).
constexpr double kMinSpecularDenominator = 1e-300;

// sqrt((n_u+1)(n_v+1)) / (2 pi), the normalisation of p_h.
double pdfScale(const AsLobe& lobe)
{
  return std::sqrt((lobe.nu + 1.0) * (lobe.nv + 1.0)) / (2.0 * kPi);
}

// ln(n.h) for a unit h with h.z > 0. Near the pole, 1 - (n.h)^2 is taken from the tangent
// components, which keep their relative precision where h.z itself is 1 - tiny.
double logCosTheta(const glm::dvec3& h)
{
  const double sin2 = h.x * h.x + h.y * h.y;
  return sin2 < 0.5 ? 0.5 * std::log1p(-sin2) : std::log(h.z);
}

// The exponent n_u cos^2(phi) + n_v sin^2(phi) for a tangent-plane direction (x, y) of any
// non-zero length; scaled first so that tiny (even subnormal) components do not underflow.
double exponentOfDirection(const AsLobe& lobe, double x, double y)
{
  const double m = std::max(std::abs(x), std::abs(y));
  if (!(m > 0.0))
  {
    return 0.5 * (lobe.nu + lobe.nv);
  }
  const double a = x / m;
  const double b = y / m;
  return (lobe.nu * a * a + lobe.nv * b * b) / (a * a + b * b);
}

double clampUnit(double x)
{
  return std::min(std::max(x, 0.0), kBelowOne);
}

void checkExponent(const char* name, double value)
{
  if (!(value >= 0.0 && value <= kMaxExponent))
  {
    std::ostringstream reason;
    reason << "must be in [0, " << kMaxExponent << "] (got " << value << ")";
    throw errorAbout(name, reason.str());
  }
}
} // namespace

void validateLobe(const AsLobe& lobe)
{
  checkExponent("n_u", lobe.nu);
  checkExponent("n_v", lobe.nv);
}

double roughnessFromExponent(double n)
{
  return std::sqrt(2.0 / (std::max(n, 0.0) + 2.0));
}

double exponentFromRoughness(double alpha)
{
  if (!(alpha > 0.0))
  {
    return kMaxExponent;
  }
  return std::clamp(2.0 / (alpha * alpha) - 2.0, 0.0, kMaxExponent);
}

double asExponent(const AsLobe& lobe, const glm::dvec3& h)
{
  return exponentOfDirection(lobe, h.x, h.y);
}

double pdfHalfVector(const AsLobe& lobe, const glm::dvec3& h)
{
  if (!(h.z > 0.0))
  {
    return 0.0;
  }
  // (n.h)^e as exp(e ln(n.h)): no pow(0, 0), and exact at the pole for any exponent.
  return pdfScale(lobe) * std::exp(asExponent(lobe, h) * logCosTheta(h));
}

double log2PdfHalfVector(const AsLobe& lobe, const glm::dvec3& h)
{
  if (!(h.z > 0.0))
  {
    return kLog2PdfFloor;
  }
  const double log2Scale =
      0.5 * (std::log2(lobe.nu + 1.0) + std::log2(lobe.nv + 1.0)) - std::log2(2.0 * kPi);
  const double value = log2Scale + asExponent(lobe, h) * logCosTheta(h) / kLn2;
  return std::max(value, kLog2PdfFloor);
}

glm::dvec3 sampleHalfVector(const AsLobe& lobe, const glm::dvec2& xi)
{
  const double xi1 = clampUnit(xi.x);
  const double xi2 = clampUnit(xi.y);

  // Quadrant q and the position u in [0, 1) inside it (both exact in binary floating point).
  const double scaled = 4.0 * xi1;
  const double quadrant = std::floor(scaled);
  const double u = scaled - quadrant;
  const double s = std::sin(0.5 * kPi * u);
  const double c = std::cos(0.5 * kPi * u);
  const double ru = std::sqrt(lobe.nu + 1.0);
  const double rv = std::sqrt(lobe.nv + 1.0);

  // phi = atan(sqrt((n_u+1)/(n_v+1)) tan(pi u / 2)) in atan2 form, never tan(pi/2). Odd
  // quadrants are mirrored (phi = pi - phi0(1 - u)), which is written as pi/2 plus the
  // complementary angle atan2(rv s, ru c), so that every quadrant starts exactly on its axis
  // and phi grows continuously with xi1 over [0, 2 pi).
  double dx = 0.0;
  double dy = 0.0;
  if (quadrant == 0.0 || quadrant == 2.0)
  {
    const double len = std::hypot(rv * c, ru * s);
    dx = rv * c / len;
    dy = ru * s / len;
    if (quadrant == 2.0)
    {
      dx = -dx;
      dy = -dy;
    }
  }
  else
  {
    const double len = std::hypot(ru * c, rv * s);
    const double cosPhi1 = ru * c / len;
    const double sinPhi1 = rv * s / len;
    dx = quadrant == 1.0 ? -sinPhi1 : sinPhi1;
    dy = quadrant == 1.0 ? cosPhi1 : -cosPhi1;
  }

  // cos(theta) = (1 - xi2)^(1/(e+1)) in log space; sin^2(theta) from expm1 keeps its
  // precision where cos(theta) rounds to 1 (large exponents, small xi2).
  const double e = lobe.nu * dx * dx + lobe.nv * dy * dy;
  const double logCos = std::log1p(-xi2) / (e + 1.0);
  const double cosTheta = std::exp(logCos);
  const double sinTheta = std::sqrt(std::max(-std::expm1(2.0 * logCos), 0.0));
  return {sinTheta * dx, sinTheta * dy, cosTheta};
}

glm::dvec2 invertHalfVector(const AsLobe& lobe, const glm::dvec3& h)
{
  const double x = h.x;
  const double y = h.y;
  const double ru = std::sqrt(lobe.nu + 1.0);
  const double rv = std::sqrt(lobe.nv + 1.0);

  // Quadrants are half-open like the sampler's: [0, pi/2) holds x > 0, y >= 0, and so on.
  // The scale of (x, y) cancels inside atan2.
  double xi1 = 0.0;
  if (x != 0.0 || y != 0.0)
  {
    double quadrant = 0.0;
    double angle = 0.0; // pi u / 2
    if (x > 0.0 && y >= 0.0)
    {
      angle = std::atan2(y / ru, x / rv);
    }
    else if (x <= 0.0 && y > 0.0)
    {
      quadrant = 1.0;
      angle = std::atan2(-x / rv, y / ru);
    }
    else if (x < 0.0 && y <= 0.0)
    {
      quadrant = 2.0;
      angle = std::atan2(-y / ru, -x / rv);
    }
    else
    {
      quadrant = 3.0;
      angle = std::atan2(x / rv, -y / ru);
    }
    const double u = std::min(std::max(angle / (0.5 * kPi), 0.0), 1.0);
    xi1 = 0.25 * (quadrant + u);
    if (xi1 >= 1.0)
    {
      xi1 = 0.0; // phi = 2 pi is phi = 0
    }
  }

  // 1 - xi2 = cos(theta)^(e+1).
  double xi2 = kBelowOne;
  if (h.z > 0.0)
  {
    const double e = asExponent(lobe, h);
    xi2 = -std::expm1((e + 1.0) * logCosTheta(h));
  }
  return {xi1, clampUnit(xi2)};
}

glm::dvec3 reflectAbout(const glm::dvec3& v, const glm::dvec3& h)
{
  return 2.0 * glm::dot(v, h) * h - v;
}

double pdfLight(const AsLobe& lobe, const glm::dvec3& v, const glm::dvec3& l)
{
  const glm::dvec3 sum = v + l;
  const double len = glm::length(sum);
  if (!(len > 0.0))
  {
    return 0.0;
  }
  const glm::dvec3 h = sum / len;
  const double vDotH = glm::dot(v, h);
  if (!(vDotH > 0.0))
  {
    return 0.0;
  }
  return pdfHalfVector(lobe, h) / std::max(4.0 * vDotH, kMinSpecularDenominator);
}

glm::dvec3 schlickFresnel(const glm::dvec3& f0, double vDotH)
{
  const double m = 1.0 - std::min(std::max(vDotH, 0.0), 1.0);
  const double m2 = m * m;
  const double chi = m2 * m2 * m;
  return f0 + (glm::dvec3(1.0) - f0) * chi;
}

glm::dvec3 evalSpecular(const AsLobe& lobe, const glm::dvec3& f0, const glm::dvec3& v,
                        const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
  {
    return glm::dvec3(0.0);
  }
  // Both are above the horizon, so v + l has a positive z and normalises safely.
  const glm::dvec3 h = glm::normalize(v + l);
  // v.h = l.h in exact arithmetic; the symmetric mean makes f_s(v, l) = f_s(l, v) bit for bit.
  const double vDotH = 0.5 * (glm::dot(v, h) + glm::dot(l, h));
  if (!(vDotH > 0.0))
  {
    return glm::dvec3(0.0);
  }
  const double denominator = std::max(4.0 * vDotH * std::max(v.z, l.z), kMinSpecularDenominator);
  return schlickFresnel(f0, vDotH) * (pdfHalfVector(lobe, h) / denominator);
}
} // namespace aniso
