#pragma once
// The lobe share of one-sample MIS used before misLobeFraction (core/env/env_sampling.h) took the
// environment into account, kept for the benchmarks that compare the two: 1/2 up to a lobe width
// sqrt((n_u + 1)(n_v + 1)) of 16, rising smoothly in log2 of it to 15/16 at 1024.
#include "core/brdf/ashikhmin_shirley.h"

#include <algorithm>
#include <cmath>

namespace aniso::bench
{
inline double widthRuleFraction(const AsLobe& lobe)
{
  const double width = std::sqrt((lobe.nu + 1.0) * (lobe.nv + 1.0));
  const double t = std::clamp((std::log2(width) - 4.0) / 6.0, 0.0, 1.0);
  return 0.5 + (15.0 / 16.0 - 0.5) * t * t * (3.0 - 2.0 * t);
}
} // namespace aniso::bench
