#pragma once
// Gauss-Legendre rules on [a, b], single and composite, for the SH projection and the reference
// integrator (deterministic quadrature, no sampling code involved).
#include <cmath>
#include <vector>

namespace aniso
{
struct QuadratureRule
{
  std::vector<double> nodes;
  std::vector<double> weights; // sum to b - a
};

// n-point Gauss-Legendre on [a, b] (exact for polynomials of degree 2n - 1); nodes by Newton
// iteration on the Legendre recurrence. n >= 1.
inline QuadratureRule gaussLegendre(int n, double a = 0.0, double b = 1.0)
{
  constexpr double kPi = 3.14159265358979323846;
  QuadratureRule rule;
  rule.nodes.assign(std::size_t(n), 0.0);
  rule.weights.assign(std::size_t(n), 0.0);
  const double half = 0.5 * (b - a);
  const double mid = 0.5 * (a + b);
  for (int i = 0; i < (n + 1) / 2; ++i)
  {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration)
    {
      double p1 = 1.0;
      double p2 = 0.0;
      for (int j = 1; j <= n; ++j)
      {
        const double p3 = p2;
        p2 = p1;
        p1 = ((2.0 * j - 1.0) * z * p2 - (j - 1.0) * p3) / j;
      }
      derivative = n * (z * p1 - p2) / (z * z - 1.0);
      const double step = p1 / derivative;
      z -= step;
      if (std::abs(step) < 1e-16)
        break;
    }
    const double weight = 2.0 / ((1.0 - z * z) * derivative * derivative);
    rule.nodes[std::size_t(i)] = mid - half * z;
    rule.nodes[std::size_t(n - 1 - i)] = mid + half * z;
    rule.weights[std::size_t(i)] = half * weight;
    rule.weights[std::size_t(n - 1 - i)] = half * weight;
  }
  return rule;
}

// `panels` equal panels of a `points`-point Gauss-Legendre rule on [a, b].
inline QuadratureRule compositeGaussLegendre(int panels, int points, double a, double b)
{
  const QuadratureRule unit = gaussLegendre(points);
  QuadratureRule rule;
  rule.nodes.reserve(std::size_t(panels) * std::size_t(points));
  rule.weights.reserve(rule.nodes.capacity());
  const double width = (b - a) / panels;
  for (int p = 0; p < panels; ++p)
  {
    for (int k = 0; k < points; ++k)
    {
      rule.nodes.push_back(a + width * (p + unit.nodes[std::size_t(k)]));
      rule.weights.push_back(width * unit.weights[std::size_t(k)]);
    }
  }
  return rule;
}
} // namespace aniso
