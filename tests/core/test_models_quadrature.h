#pragma once
// Deterministic quadrature over the sphere of directions for the model tests (and random
// directions for the pointwise checks): composite
// Gauss-Legendre in the polar angle around a chosen axis (optionally graded towards the axis,
// where narrow lobes live) times equally spaced azimuths (spectrally accurate for smooth periodic
// integrands). It shares no code with the models it checks.
#include "core/env/quadrature.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <random>

namespace models_test
{
constexpr double kPi = 3.14159265358979323846;

// Two unit vectors completing `axis` (unit) to an orthonormal basis.
inline void basisAround(const glm::dvec3& axis, glm::dvec3* u, glm::dvec3* w)
{
  const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  *u = glm::normalize(helper - glm::dot(helper, axis) * axis);
  *w = glm::cross(axis, *u);
}

// Integral of g(d) over the unit sphere, d = cos(theta) axis + sin(theta)(cos(phi) u + sin(phi) w).
// With `graded`, polar panel k spans pi [(k/P)^2, ((k+1)/P)^2], so the first panels are
// pi / P^2 wide (lobes down to that width are resolved).
template <class G>
double sphereIntegral(const G& g, const glm::dvec3& axis, int thetaPanels, int azimuths,
                      bool graded)
{
  glm::dvec3 u;
  glm::dvec3 w;
  basisAround(axis, &u, &w);
  const aniso::QuadratureRule unit = aniso::gaussLegendre(8);
  double total = 0.0;
  for (int k = 0; k < thetaPanels; ++k)
  {
    const double s0 = double(k) / thetaPanels;
    const double s1 = double(k + 1) / thetaPanels;
    const double a = graded ? kPi * s0 * s0 : kPi * s0;
    const double b = graded ? kPi * s1 * s1 : kPi * s1;
    for (std::size_t q = 0; q < unit.nodes.size(); ++q)
    {
      const double theta = a + (b - a) * unit.nodes[q];
      const double weight = (b - a) * unit.weights[q] * std::sin(theta) * (2.0 * kPi / azimuths);
      double ring = 0.0;
      for (int j = 0; j < azimuths; ++j)
      {
        const double phi = 2.0 * kPi * (j + 0.5) / azimuths;
        const glm::dvec3 d =
            std::cos(theta) * axis + std::sin(theta) * (std::cos(phi) * u + std::sin(phi) * w);
        ring += g(d);
      }
      total += weight * ring;
    }
  }
  return total;
}

// Directional albedo of a BRDF-like term for view v (tangent space, n = +Z): the integral over
// the upper hemisphere of term(v, l), where term already includes the model's cosine. The lobe
// axis `axis` (e.g. the mirror direction of v) gets the graded polar panels.
template <class Term>
double hemisphereAlbedo(const Term& term, const glm::dvec3& v, const glm::dvec3& axis,
                        int thetaPanels = 160, int azimuths = 256)
{
  return sphereIntegral([&](const glm::dvec3& l) { return l.z > 0.0 ? term(v, l) : 0.0; }, axis,
                        thetaPanels, azimuths, true);
}

inline glm::dvec3 mirrorOf(const glm::dvec3& v)
{
  return {-v.x, -v.y, v.z};
}

// A direction uniform over the upper hemisphere (uniform in cos(theta) and phi).
inline glm::dvec3 randomUpper(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double z = u(rng);
  const double phi = 2.0 * kPi * u(rng);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

inline glm::dvec3 fromAngles(double thetaDegrees, double phiDegrees)
{
  const double t = thetaDegrees * kPi / 180.0;
  const double p = phiDegrees * kPi / 180.0;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}
} // namespace models_test
