#pragma once
// How sliders move through a declared range, and the roughness view of the AS exponents.
//
// Slider positions are integers 0..kSliderSteps. Linear parameters map them proportionally.
// Logarithmic ones (the exponents, sample counts, the error target) map log10(c + value)
// proportionally, so position p gives value = (c + min)^(1 - p/S) (c + max)^(p/S) - c, with
// c = 1 when the range starts at 0 (for n in [0, 1e6] the slider spends a sixth of its length
// on each decade 1, 10, ... 1e6, and 0 stays reachable) and c = 0 when it starts above 0 (every
// decade of the error target's 1e-4..1 gets a quarter). Values chosen on a slider are rounded to
// three significant digits (and to whole numbers for integers, to powers of two where declared) so
// a drag lands on 20000 rather than 19952.6; the spin boxes beside the sliders take any exact
// value.
//
// Roughness view: alpha = sqrt(2 / (n + 2)), the Beckmann roughness whose slope distribution
// matches a Blinn-Phong lobe of exponent n (Walter et al. 2007, "Microfacet models for
// refraction", eq. 32, used per axis for the anisotropic lobe); inverse n = 2 / alpha^2 - 2.
// n in [0, 1e6] gives alpha in [0.0014142, 1].
#include "core/parameters/parameters.h"

namespace aniso
{
constexpr int kSliderSteps = 1000;

int sliderPosition(const ParameterSpec& spec, double value);
double sliderValue(const ParameterSpec& spec, int position);

// value rounded to `digits` significant digits (0 stays 0).
double roundToSignificant(double value, int digits);

double roughnessFromExponent(double n);
// Clamped to the exponent range [0, kMaxExponent].
double exponentFromRoughness(double alpha);
} // namespace aniso
