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
// Roughness view: alpha = sqrt(2 / (n + 2)), roughnessFromExponent and exponentFromRoughness
// (core/brdf/ashikhmin_shirley.h, the one place of that correspondence).
#include "core/brdf/ashikhmin_shirley.h"
#include "core/parameters/parameters.h"

namespace aniso
{
constexpr int kSliderSteps = 1000;

int sliderPosition(const ParameterSpec& spec, double value);
double sliderValue(const ParameterSpec& spec, int position);

// value rounded to `digits` significant digits (0 stays 0).
double roundToSignificant(double value, int digits);
} // namespace aniso
