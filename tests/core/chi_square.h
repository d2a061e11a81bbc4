#pragma once
// Pearson's chi-square test for the sampling tests: observed counts against the counts a density
// predicts, with the p-value from the regularised incomplete gamma function.
#include <cmath>
#include <cstddef>
#include <vector>

namespace aniso_test
{
// Regularised upper incomplete gamma Q(a, x): series for x < a + 1, Lentz's continued fraction
// otherwise (both to 1e-15). The chi-square p-value of statistic x with k degrees of freedom is
// Q(k/2, x/2).
inline double gammaQ(double a, double x)
{
  if (!(x > 0.0))
    return 1.0;
  const double logPrefix = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0)
  {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < 100000; ++n)
    {
      term *= x / (a + n);
      sum += term;
      if (term < sum * 1e-15)
        break;
    }
    return 1.0 - sum * std::exp(logPrefix);
  }
  const double tiny = 1e-300;
  double b = x + 1.0 - a;
  double c = 1.0 / tiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < 100000; ++i)
  {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny)
      d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny)
      c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15)
      break;
  }
  return std::exp(logPrefix) * h;
}

struct ChiSquareResult
{
  double pValue = 1.0;
  int bins = 0;                // after pooling
  double pooledObserved = 0.0; // counts in bins expected below 5, tested as one bin
  double pooledExpected = 0.0;
};

// Bins expected below 5 are pooled into one (tested as a bin when the pool reaches 5).
inline ChiSquareResult chiSquare(const std::vector<double>& observed,
                                 const std::vector<double>& expected)
{
  ChiSquareResult result;
  double statistic = 0.0;
  for (std::size_t i = 0; i < observed.size(); ++i)
  {
    if (expected[i] < 5.0)
    {
      result.pooledObserved += observed[i];
      result.pooledExpected += expected[i];
      continue;
    }
    const double d = observed[i] - expected[i];
    statistic += d * d / expected[i];
    ++result.bins;
  }
  if (result.pooledExpected >= 5.0)
  {
    const double d = result.pooledObserved - result.pooledExpected;
    statistic += d * d / result.pooledExpected;
    ++result.bins;
  }
  result.pValue = result.bins > 1 ? gammaQ(0.5 * (result.bins - 1), 0.5 * statistic) : 1.0;
  return result;
}
} // namespace aniso_test
