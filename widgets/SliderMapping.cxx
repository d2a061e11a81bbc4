#include "widgets/SliderMapping.h"

#include "core/brdf/ashikhmin_shirley.h"

#include <algorithm>
#include <cmath>

namespace aniso
{
namespace
{
// Logarithmic sliders map log10(offset + value): a range that excludes 0 is purely logarithmic
// (offset 0); one that includes 0 keeps it reachable with offset 1.
double logOffset(const ParameterSpec& spec)
{
  return spec.minimum > 0.0 ? 0.0 : 1.0;
}

// Position as a fraction of the slider: where VALUE lies between the declared ends.
double fractionOf(const ParameterSpec& spec, double value)
{
  const double v = std::clamp(value, spec.minimum, spec.maximum);
  if (spec.scale == ParameterScale::Logarithmic)
  {
    const double c = logOffset(spec);
    const double lo = std::log10(c + spec.minimum);
    const double hi = std::log10(c + spec.maximum);
    return (std::log10(c + v) - lo) / (hi - lo);
  }
  return (v - spec.minimum) / (spec.maximum - spec.minimum);
}
} // namespace

double roundToSignificant(double value, int digits)
{
  if (value == 0.0 || !std::isfinite(value))
  {
    return value;
  }
  const double magnitude = std::floor(std::log10(std::abs(value)));
  const double scale = std::pow(10.0, static_cast<double>(digits - 1) - magnitude);
  return std::round(value * scale) / scale;
}

int sliderPosition(const ParameterSpec& spec, double value)
{
  if (!(spec.maximum > spec.minimum) || !std::isfinite(value))
  {
    return 0;
  }
  return static_cast<int>(std::lround(fractionOf(spec, value) * kSliderSteps));
}

double sliderValue(const ParameterSpec& spec, int position)
{
  const double f = std::clamp(static_cast<double>(position) / kSliderSteps, 0.0, 1.0);
  if (position <= 0)
  {
    return spec.minimum;
  }
  if (position >= kSliderSteps)
  {
    return spec.maximum;
  }
  double v = 0.0;
  if (spec.scale == ParameterScale::Logarithmic)
  {
    const double c = logOffset(spec);
    const double lo = std::log10(c + spec.minimum);
    const double hi = std::log10(c + spec.maximum);
    v = std::pow(10.0, lo + f * (hi - lo)) - c;
    v = roundToSignificant(v, 3);
  }
  else
  {
    v = spec.minimum + f * (spec.maximum - spec.minimum);
    v = spec.minimum + std::round((v - spec.minimum) / spec.step) * spec.step;
    // Undo the representation error of the multiplication (0.1 * 3 = 0.30000000000000004).
    v = roundToSignificant(v, 12);
  }
  if (spec.type == ParameterType::Integer)
  {
    v = std::round(v);
    if (spec.powerOfTwo)
    {
      v = std::exp2(std::round(std::log2(std::max(v, 1.0))));
    }
  }
  return std::clamp(v, spec.minimum, spec.maximum);
}

} // namespace aniso
