#include "core/fields/field_mapping.h"

#include "core/error.h"
#include "core/parameters/choices.h"
#include "core/parameters/parameters.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace aniso
{
namespace
{
// The whole of TEXT as a finite number, or nullopt.
std::optional<double> finiteNumber(std::string_view text)
{
  const std::string s(text);
  if (s.empty() || s.front() == ' ')
  {
    return std::nullopt;
  }
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(v))
  {
    return std::nullopt;
  }
  return v;
}
} // namespace

std::optional<FieldSpec> parseFieldSpec(std::string_view text, const std::string& subject)
{
  if (text.empty() || text == "none")
  {
    return std::nullopt;
  }
  FieldSpec spec;
  const std::size_t colon = text.rfind(':');
  std::string_view component;
  if (colon == std::string_view::npos)
  {
    spec.array = std::string(text);
  }
  else
  {
    spec.array = std::string(text.substr(0, colon));
    component = text.substr(colon + 1);
    if (component == "magnitude")
    {
      spec.component = -1;
    }
    else if (component == "x" || component == "y" || component == "z")
    {
      spec.component = component[0] - 'x';
    }
    else
    {
      const bool digits = !component.empty() && component.size() <= 2 &&
                          std::all_of(component.begin(), component.end(),
                                      [](char c) { return c >= '0' && c <= '9'; });
      if (!digits)
      {
        throw errorAbout(subject, "'" + std::string(component) +
                                      "' is not a component: magnitude, x, y, z or a number "
                                      "from 0");
      }
      spec.component = std::stoi(std::string(component));
    }
  }
  if (spec.array.empty())
  {
    throw errorAbout(subject, "no array name before ':'");
  }
  return spec;
}

std::string formatFieldSpec(const FieldSpec& spec)
{
  if (spec.component < 0)
  {
    return spec.array;
  }
  return spec.array + ":" + std::to_string(spec.component);
}

FieldRange parseFieldRange(std::string_view text, const std::string& subject)
{
  FieldRange range;
  if (text == "auto")
  {
    return range;
  }
  const std::size_t comma = text.find(',');
  const auto lo =
      comma == std::string_view::npos ? std::nullopt : finiteNumber(text.substr(0, comma));
  const auto hi =
      comma == std::string_view::npos ? std::nullopt : finiteNumber(text.substr(comma + 1));
  if (!lo || !hi)
  {
    throw errorAbout(subject, "'" + std::string(text) + "' is not auto or MIN,MAX");
  }
  if (!(*lo < *hi))
  {
    throw errorAbout(subject, "MIN must be below MAX in '" + std::string(text) + "'");
  }
  range.automatic = false;
  range.min = *lo;
  range.max = *hi;
  return range;
}

std::optional<FieldMapping> fieldMappingFromParameters(const ParameterSet& parameters)
{
  const auto spec = parseFieldSpec(parameters.text("field"), "field");
  if (!spec)
  {
    return std::nullopt;
  }
  FieldMapping m;
  m.spec = *spec;
  m.target = parseFieldTarget(parameters.text("field-target"));
  m.colorMap = parseColorMap(parameters.text("field-colormap"));
  m.range = parseFieldRange(parameters.text("field-range"), "field-range");
  m.low = parameters.real("field-low");
  m.high = parameters.real("field-high");
  return m;
}

double fieldValue(const FieldSpec& spec, const double* tuple, int components)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (spec.component >= 0)
  {
    if (spec.component >= components)
    {
      return nan;
    }
    const double v = tuple[spec.component];
    return std::isfinite(v) ? v : nan;
  }
  if (components == 1)
  {
    return std::isfinite(tuple[0]) ? tuple[0] : nan;
  }
  double sum = 0.0;
  for (int c = 0; c < components; ++c)
  {
    if (!std::isfinite(tuple[c]))
    {
      return nan;
    }
    sum += tuple[c] * tuple[c];
  }
  return std::sqrt(sum);
}

double fieldParameter(double value, double min, double max)
{
  if (std::isnan(value))
  {
    return value;
  }
  if (!(max > min))
  {
    return 0.5;
  }
  return std::clamp((value - min) / (max - min), 0.0, 1.0);
}

AsLobe fieldLobe(const AsLobe& lobe, FieldTarget target, double low, double high, double t)
{
  const double s = low + (high - low) * t;
  switch (target)
  {
  case FieldTarget::Roughness:
    return AsLobe{std::clamp(lobe.nu * s, 0.0, kMaxExponent),
                  std::clamp(lobe.nv * s, 0.0, kMaxExponent)};
  case FieldTarget::Anisotropy:
  {
    const double strength = std::clamp(s, 0.0, 1.0);
    const double mean = std::sqrt(lobe.nu * lobe.nv);
    return AsLobe{std::pow(mean, 1.0 - strength) * std::pow(lobe.nu, strength),
                  std::pow(mean, 1.0 - strength) * std::pow(lobe.nv, strength)};
  }
  default:
    return lobe;
  }
}
} // namespace aniso
