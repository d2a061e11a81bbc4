#pragma once
// Adaptive quality: the user sets an error target instead of a sample count, and the sample
// count per pixel and frame follows from the material. The model is what `aniso bench`
// measured: the relative L2 error of one frame of the `exact` method (half vectors from the LUT,
// lobe sampling) against the converged CPU reference falls as a N^-p, with a and p fitted per
// lobe and filtering on the sphere under the built-in studio. Sharp lobes need few samples,
// rough ones more; filtering lowers a for rough lobes. Between the measured lobes, log a and p
// are interpolated in the logarithm of the lobe's mean exponent sqrt((n_u + 1)(n_v + 1)); beyond
// them the nearest measured lobe is used. GL-free, so the docks and the CLI share it.
#include "core/brdf/ashikhmin_shirley.h"

namespace aniso
{
// The largest sample count per frame the control chooses (the declared samples maximum).
constexpr int kMaxQualitySamples = 1024;

struct QualityChoice
{
  int samples = 1;             // per pixel, in [1, maxSamples]
  double predictedError = 0.0; // relative L2 of one frame at that count, by the model
  bool reachable = true;       // false: even maxSamples stays above the target
};

// The fewest samples whose predicted error is at most errorTarget (relative L2, e.g. 0.01), at
// most maxSamples (at least 1). Throws aniso::Error "quality: reason" unless errorTarget is
// finite and in (0, 1], and for an invalid lobe (validateLobe). For the `exact` method the mean
// of F frames of S samples is one estimate of F x S samples, so a still view's total follows
// from the same model (maxSamples then the largest total, e.g. target-samples' maximum).
QualityChoice chooseSamples(double errorTarget, const AsLobe& lobe, bool filtered,
                            int maxSamples = kMaxQualitySamples);

// The model's relative L2 of one frame of N >= 1 samples.
double predictedError(const AsLobe& lobe, bool filtered, int samples);
} // namespace aniso
