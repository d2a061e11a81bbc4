#pragma once
// Small pieces shared by the shift-variant models' implementations (not part of the API).
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <sstream>
#include <string>

namespace aniso
{
namespace sv
{
constexpr double kPi = 3.14159265358979323846;

inline void checkRange(const char* name, double value, double lo, double hi)
{
  if (!(value >= lo && value <= hi))
  {
    std::ostringstream reason;
    reason << "must be in [" << lo << ", " << hi << "] (got " << value << ")";
    throw errorAbout(name, reason.str());
  }
}

inline void checkColour(const char* name, const glm::dvec3& c, double hi)
{
  for (int i = 0; i < 3; ++i)
  {
    if (!(c[i] >= 0.0 && c[i] <= hi))
    {
      std::ostringstream reason;
      reason << "every channel must be in [0, " << hi << "] (got " << c[i] << ")";
      throw errorAbout(name, reason.str());
    }
  }
}

// normalize(x) that also works when |x|^2 underflows (v + l for nearly opposite grazing v and
// l can be 1e-200 long): scaled by its largest component first. x must not be zero.
inline glm::dvec3 normalizeScaled(const glm::dvec3& x)
{
  const double m = std::max(std::max(std::abs(x.x), std::abs(x.y)), std::abs(x.z));
  const glm::dvec3 y = x / m;
  return y / std::sqrt(y.x * y.x + y.y * y.y + y.z * y.z);
}

// ln(n.h) for unit h with h.z > 0; near the pole 1 - (n.h)^2 comes from the tangent components,
// which keep their relative precision where h.z rounds to 1.
inline double logCosTheta(const glm::dvec3& h)
{
  const double sin2 = h.x * h.x + h.y * h.y;
  return sin2 < 0.5 ? 0.5 * std::log1p(-sin2) : std::log(h.z);
}

// w_x cos^2(phi) + w_y sin^2(phi) for the tangent-plane direction (x, y), any non-zero length
// (scaled first so that tiny components do not underflow); the mean at (0, 0).
inline double azimuthalBlend(double wx, double wy, double x, double y)
{
  const double m = std::max(std::abs(x), std::abs(y));
  if (!(m > 0.0))
    return 0.5 * (wx + wy);
  const double a = x / m;
  const double b = y / m;
  return (wx * a * a + wy * b * b) / (a * a + b * b);
}
} // namespace sv
} // namespace aniso
