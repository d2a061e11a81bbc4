#include "core/quality/adaptive_quality.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace aniso
{
namespace
{
struct FittedLobe
{
  double nu;
  double nv;
  bool filtered;
  double a;
  double p;
};

// Fitted by `aniso bench --out bench-out` (its quality_model.txt; docs/BENCHMARKS.md, "Adaptive
// quality model"): relative L2 = a N^-p over N = 4 to 1024, the sphere under the built-in studio
// at 256x256, F0 aluminium, cube map 256^2.
constexpr FittedLobe kModel[] = {
    {10, 10, false, 3.259, 0.9757},     {10, 10, true, 1.258, 0.8558},
    {100, 10, false, 2.286, 1.086},     {100, 10, true, 0.8191, 0.9054},
    {1000, 100, false, 0.6393, 1.105},  {1000, 100, true, 0.3094, 0.9334},
    {20000, 70, false, 0.3255, 0.9664}, {20000, 70, true, 0.3555, 1.01},
};

double widthKey(double nu, double nv)
{
  return 0.5 * std::log((nu + 1.0) * (nv + 1.0));
}

// log a and p at the lobe's key, linear between the measured lobes of that filtering.
void modelAt(const AsLobe& lobe, bool filtered, double& logA, double& p)
{
  std::vector<const FittedLobe*> rows;
  for (const FittedLobe& row : kModel)
  {
    if (row.filtered == filtered)
    {
      rows.push_back(&row);
    }
  }
  std::sort(rows.begin(), rows.end(),
            [](const FittedLobe* x, const FittedLobe* y)
            { return widthKey(x->nu, x->nv) < widthKey(y->nu, y->nv); });
  const std::size_t count = rows.size();
  const double key = widthKey(lobe.nu, lobe.nv);
  std::size_t upper = 0;
  while (upper < count && widthKey(rows[upper]->nu, rows[upper]->nv) < key)
  {
    ++upper;
  }
  if (upper == 0 || upper == count)
  {
    const FittedLobe* nearest = rows[upper == 0 ? 0 : count - 1];
    logA = std::log(nearest->a);
    p = nearest->p;
    return;
  }
  const FittedLobe* lo = rows[upper - 1];
  const FittedLobe* hi = rows[upper];
  const double k0 = widthKey(lo->nu, lo->nv);
  const double k1 = widthKey(hi->nu, hi->nv);
  const double t = (key - k0) / (k1 - k0);
  logA = (1.0 - t) * std::log(lo->a) + t * std::log(hi->a);
  p = (1.0 - t) * lo->p + t * hi->p;
}
} // namespace

double predictedError(const AsLobe& lobe, bool filtered, int samples)
{
  validateLobe(lobe);
  double logA = 0.0;
  double p = 0.0;
  modelAt(lobe, filtered, logA, p);
  return std::exp(logA - p * std::log(std::max(samples, 1)));
}

QualityChoice chooseSamples(double errorTarget, const AsLobe& lobe, bool filtered, int maxSamples)
{
  if (!std::isfinite(errorTarget) || errorTarget <= 0.0 || errorTarget > 1.0)
  {
    throw errorAbout("quality", "the error target must be a number in (0, 1], e.g. 0.01 for 1%");
  }
  validateLobe(lobe);
  double logA = 0.0;
  double p = 0.0;
  modelAt(lobe, filtered, logA, p);
  // a N^-p <= target  <=>  N >= (a / target)^(1/p); rounding up, then one step back if the
  // count below meets the target too (the power's rounding).
  const double exact = std::exp((logA - std::log(errorTarget)) / p);
  QualityChoice choice;
  choice.samples =
      static_cast<int>(std::clamp(std::ceil(exact), 1.0, double(std::max(maxSamples, 1))));
  if (choice.samples > 1 && predictedError(lobe, filtered, choice.samples - 1) <= errorTarget)
  {
    --choice.samples;
  }
  choice.predictedError = predictedError(lobe, filtered, choice.samples);
  choice.reachable = choice.predictedError <= errorTarget;
  return choice;
}
} // namespace aniso
