#include "core/parameters/parameters.h"

#include "core/error.h"
#include "core/leadr/leadr.h"
#include "core/lut/lut.h"
#include "core/microstructure/microstructure.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace aniso
{
namespace
{
ParameterSpec number(std::string_view name, std::string_view label, ParameterType type,
                     double defaultValue, double minimum, double maximum, double step,
                     ParameterScale scale, std::string_view unit, std::string_view help)
{
  ParameterSpec s;
  s.name = name;
  s.label = label;
  s.type = type;
  s.defaultValue = {defaultValue, defaultValue, defaultValue};
  s.minimum = minimum;
  s.maximum = maximum;
  s.step = step;
  s.scale = scale;
  s.unit = unit;
  s.help = help;
  return s;
}

ParameterSpec color(std::string_view name, std::string_view label, std::array<double, 3> value,
                    double step, std::string_view help)
{
  ParameterSpec s = number(name, label, ParameterType::Color, 0.0, 0.0, 1.0, step,
                           ParameterScale::Linear, {}, help);
  s.defaultValue = value;
  return s;
}

ParameterSpec text(std::string_view name, std::string_view label, std::string_view value,
                   std::string_view help)
{
  ParameterSpec s;
  s.name = name;
  s.label = label;
  s.type = ParameterType::Text;
  s.defaultText = value;
  s.help = help;
  return s;
}

ParameterSpec choice(std::string_view name, std::string_view label,
                     std::vector<std::string_view> choices, std::string_view value,
                     std::string_view help)
{
  ParameterSpec s = text(name, label, value, help);
  s.choices = std::move(choices);
  return s;
}

ParameterSpec powerOfTwo(ParameterSpec s)
{
  s.powerOfTwo = true;
  return s;
}

std::vector<ParameterSpec> declare()
{
  using T = ParameterType;
  using S = ParameterScale;
  // The default material is brushed aluminium: sharp across the brushing (n_u, along t) and
  // broad along it (n_v), so highlights stretch along b as on a brushed plate.
  return {
      number("nu", "n_u", T::Real, 1000.0, 0.0, kMaxExponent, 1.0, S::Logarithmic, {},
             "Ashikhmin-Shirley exponent along the tangent t; higher is sharper"),
      number("nv", "n_v", T::Real, 50.0, 0.0, kMaxExponent, 1.0, S::Logarithmic, {},
             "Ashikhmin-Shirley exponent along the bitangent b; higher is sharper"),
      color("f0", "F0", {0.913, 0.922, 0.924}, 0.001,
            "Fresnel reflectance at normal incidence, linear RGB; the default is aluminium"),
      color("albedo", "Albedo", {0.0, 0.0, 0.0}, 0.01,
            "diffuse Lambert albedo, linear RGB; metals have none"),
      number("samples", "Samples", T::Integer, 16.0, 1.0, 1024.0, 1.0, S::Logarithmic, {},
             "importance samples per pixel and frame"),
      number("lut-size", "LUT size", T::Integer, 64.0, kMinLutSize, kMaxLutSize, 1.0,
             S::Logarithmic, "texels",
             "width and height of the half-vector and BRDF lookup tables"),
      number("lut-samples", "LUT samples", T::Integer, 1024.0, 1.0, kMaxLutSamples, 1.0,
             S::Logarithmic, {}, "importance samples per texel of the BRDF lookup table"),
      text("env", "Environment", "builtin:studio",
           "environment: an equirectangular HDR/EXR file, builtin:studio, builtin:white or "
           "builtin:sunsky"),
      number("env-rotation", "Rotation", T::Real, 0.0, -180.0, 180.0, 1.0, S::Linear, "deg",
             "rotation of the environment about the world Z axis"),
      number("exposure", "Exposure", T::Real, 0.0, -16.0, 16.0, 0.1, S::Linear, "EV",
             "exposure applied before tone mapping"),
      powerOfTwo(number("cube-size", "Cube size", T::Integer, 256.0, 1.0, 2048.0, 1.0,
                        S::Logarithmic, "texels", "edge of a level-0 environment cubemap face")),
      // How a material is shaded and a scene shown (the application's docks and sessions).
      choice("method", "Specular method", {"exact", "split-sum"}, "exact",
             "specular integration: exact per-sample AS weights, or the split sum with the BRDF "
             "lookup table"),
      choice("filtered", "Filtered sampling", {"on", "off"}, "on",
             "read each sample at the environment mip level its pdf and the sample count call for"),
      choice("env-sampling", "Environment sampling", {"off", "mis"}, "off",
             "exact method: also sample the environment by its luminance and combine with the "
             "lobe samples by multiple importance sampling (small bright sources, rough lobes)"),
      // The LUT is the default: equally accurate, and 1.7x faster than computing the half
      // vectors at 64 samples on llvmpipe (docs/BENCHMARKS.md, "Frame time").
      choice("half-vectors", "Half vectors", {"shader", "lut"}, "lut",
             "where the importance-sampled half vectors come from: computed in the shader or "
             "fetched from the half-vector lookup table"),
      number("target-samples", "Quality", T::Integer, 256.0, 1.0, 65536.0, 1.0, S::Logarithmic, {},
             "samples per pixel a still view accumulates by progressive refinement"),
      // The quality as an error target instead (core/quality/adaptive_quality.h): the samples
      // follow from the lobe and filtering by the error model that `aniso bench` fitted.
      choice("quality-mode", "Quality by", {"samples", "error"}, "samples",
             "what sets a still view's quality: target-samples, or error-target by the error "
             "model of the material's lobe and filtering"),
      number("error-target", "Error target", T::Real, 0.01, 1e-4, 1.0, 1e-4, S::Logarithmic, {},
             "relative L2 error a still view refines to with quality-mode error (0.01 = 1%); "
             "also 'aniso render --quality'"),
      choice("bump", "Bump mapping", {"none", "normal", "quaternion"}, "none",
             "how the maps perturb the shading frame: not at all, by the normal map, or by the "
             "quaternion map (baked from the normal map when none is given)"),
      number("height-scale", "Height scale", T::Real, 0.02, 0.0, 0.5, 0.001, S::Linear, "uv",
             "relief depth of parallax occlusion mapping, in texture-coordinate units"),
      text("tangents", "Tangents", "auto",
           "tangent field: auto (the mesh's, else from UVs, else axis:1,0,0), uv, axis:X,Y,Z, "
           "around:X,Y,Z or radial:X,Y,Z"),
      choice("background", "Background", {"env", "color", "none"}, "env",
             "what lies behind the surfaces: the environment, background-color, or nothing "
             "(transparent)"),
      color("background-color", "Background colour", {0.18, 0.18, 0.18}, 0.01,
            "linear radiance of a plain background"),
      choice("tone-mapping", "Tone mapping", {"aces", "reinhard", "clamp"}, "aces",
             "display transform from linear radiance for the screen and PNG files"),
      // The LEADR and microstructure models (core/leadr, core/microstructure; model key).
      number("leadr-scale", "Relief scale", T::Real, 1.0, 0.0, 1e6, 0.01, S::Linear, {},
             "leadr: heights of the relief times this"),
      number("leadr-tiles", "Relief tiles", T::Real, 8.0, 1e-3, 1e6, 1.0, S::Logarithmic, {},
             "leadr: repeats of the relief per unit of texture coordinate"),
      number("leadr-roughness", "Base roughness", T::Real, 0.15, kLeadrMinAlpha, kLeadrMaxAlpha,
             0.01, S::Linear, {}, "leadr: base Beckmann roughness added to every texel"),
      number("leadr-grid", "Slope grid", T::Integer, 4.0, 1.0, 16.0, 1.0, S::Linear, {},
             "leadr: slope-space grid N x N for the environment and diffuse"),
      choice("leadr-filter", "Filtering", {"leadr", "normal-mapping"}, "leadr",
             "leadr: the slope moments, or only their mean (plain normal mapping)"),
      choice("structure", "Structure", {"pyramids", "inverted-pyramids", "grooves", "silk"},
             "pyramids", "microstructure: the repeating structure (it turns with the TPR map)"),
      number("micro-grid", "Grid", T::Integer, 4.0, 1.0, 64.0, 1.0, S::Linear, {},
             "microstructure: K x K samples per pixel"),
      choice("jitter-grid", "Jittered grid", {"off", "on"}, "off",
             "microstructure: one random point per grid cell"),
      choice("masking", "Masking", {"pom", "parallax", "normal"}, "pom",
             "microstructure: parallax occlusion, parallax or normal mapping"),
      choice("self-shadow", "Self-shadowing", {"off", "on"}, "off",
             "microstructure: shadows of the structure per light"),
      choice("micro-brdf", "BRDF", {"ggx", "blinn-phong"}, "ggx",
             "microstructure: GGX with Smith-Schlick or normalised Blinn-Phong"),
      number("micro-roughness", "Roughness", T::Real, 0.3, 1e-3, 1.0, 0.01, S::Linear, {},
             "microstructure: GGX alpha"),
      number("blinn-exponent", "Exponent", T::Real, 100.0, 0.0, 1e6, 1.0, S::Logarithmic, {},
             "microstructure: Blinn-Phong exponent"),
      number("structure-depth", "Depth", T::Real, 0.1, 1e-3, kMicroMaxDepth, 0.01, S::Linear,
             "tiles", "microstructure: relief depth in tile widths"),
      number("structure-tiles", "Tiles", T::Real, 64.0, 1e-3, 1e6, 1.0, S::Logarithmic, {},
             "microstructure: tiles per unit of texture coordinate"),
  };
}

std::size_t indexOf(std::string_view name)
{
  const auto& specs = parameterSpecs();
  for (std::size_t i = 0; i < specs.size(); ++i)
  {
    if (specs[i].name == name)
    {
      return i;
    }
  }
  throw errorAbout(std::string(name), "unknown parameter");
}

std::string quoted(std::string_view text)
{
  return "'" + std::string(text) + "'";
}

bool startsWithSpace(std::string_view text)
{
  return !text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\n');
}

// The whole of TEXT as an integer (decimal digits, optional sign) or as a finite real.
double parseNumber(std::string_view text, bool integer, const std::string& subject)
{
  const std::string s(text);
  const std::string notA = quoted(text) + (integer ? " is not an integer" : " is not a number");
  if (s.empty() || startsWithSpace(s))
  {
    throw errorAbout(subject, notA);
  }
  char* end = nullptr;
  errno = 0;
  const double v = integer ? static_cast<double>(std::strtoll(s.c_str(), &end, 10))
                           : std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size())
  {
    throw errorAbout(subject, notA);
  }
  if (integer && errno == ERANGE)
  {
    throw errorAbout(subject, quoted(text) + " is too large");
  }
  // ERANGE also flags underflow to a tiny or zero value, which is a fine number.
  if (!std::isfinite(v) || (errno == ERANGE && std::abs(v) > 1.0))
  {
    throw errorAbout(subject, quoted(text) + " is not a finite number");
  }
  return v;
}
} // namespace

const std::vector<ParameterSpec>& parameterSpecs()
{
  static const std::vector<ParameterSpec> specs = declare();
  return specs;
}

const ParameterSpec& parameterSpec(std::string_view name)
{
  return parameterSpecs()[indexOf(name)];
}

ParameterValue defaultParameterValue(const ParameterSpec& spec)
{
  ParameterValue v;
  v.number = spec.defaultValue;
  v.text = std::string(spec.defaultText);
  return v;
}

std::string formatNumber(double value)
{
  // Scientific: the fewest digits that read back exactly, exponent without "+" or leading
  // zeros (1e+06 -> 1e6, 1.5e-05 -> 1.5e-5).
  char buffer[512];
  for (int digits = 0; digits <= 17; ++digits)
  {
    std::snprintf(buffer, sizeof buffer, "%.*e", digits, value);
    if (std::strtod(buffer, nullptr) == value)
    {
      break;
    }
  }
  std::string scientific(buffer);
  const std::size_t e = scientific.find('e');
  std::string exponent = scientific.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, 1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  scientific = scientific.substr(0, e) + "e" + (negative ? "-" : "") + exponent;

  // Fixed: the fewest decimals that read back exactly, if that is not much longer, since
  // "1000" and "-180" read better than "1e3" and "-1.8e2".
  if (std::abs(value) < 1e17)
  {
    for (int decimals = 0; decimals <= 20; ++decimals)
    {
      std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
      if (std::strtod(buffer, nullptr) == value)
      {
        const std::string fixed(buffer);
        return fixed.size() < scientific.size() + 3 ? fixed : scientific;
      }
    }
  }
  return scientific;
}

void checkParameterValue(const ParameterSpec& spec, const ParameterValue& value,
                         const std::string& subject)
{
  if (spec.type == ParameterType::Text)
  {
    if (value.text.empty())
    {
      throw errorAbout(subject, "empty value");
    }
    if (!spec.choices.empty() &&
        std::find(spec.choices.begin(), spec.choices.end(), value.text) == spec.choices.end())
    {
      std::string allowed;
      for (std::size_t i = 0; i < spec.choices.size(); ++i)
      {
        allowed += (i ? ", " : "") + std::string(spec.choices[i]);
      }
      throw errorAbout(subject, quoted(value.text) + " is not one of " + allowed);
    }
    return;
  }
  const int n = spec.components();
  for (int i = 0; i < n; ++i)
  {
    const double v = value.number[static_cast<std::size_t>(i)];
    const std::string shown = formatNumber(v);
    if (!std::isfinite(v))
    {
      throw errorAbout(subject, shown + " is not a finite number");
    }
    if (spec.type == ParameterType::Integer && v != std::floor(v))
    {
      throw errorAbout(subject, shown + " is not an integer");
    }
    if (v < spec.minimum || v > spec.maximum)
    {
      throw errorAbout(subject, shown + " is out of range [" + formatNumber(spec.minimum) + ", " +
                                    formatNumber(spec.maximum) + "]");
    }
    if (spec.powerOfTwo && (v < 1.0 || std::exp2(std::round(std::log2(v))) != v))
    {
      throw errorAbout(subject, shown + " is not a power of two");
    }
  }
}

ParameterValue parseParameterValue(const ParameterSpec& spec, std::string_view text,
                                   const std::string& subject)
{
  ParameterValue v;
  switch (spec.type)
  {
  case ParameterType::Text:
    v.text = std::string(text);
    break;
  case ParameterType::Integer:
    v.number.fill(parseNumber(text, true, subject));
    break;
  case ParameterType::Real:
    v.number.fill(parseNumber(text, false, subject));
    break;
  case ParameterType::Color:
  {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    while (true)
    {
      const std::size_t comma = text.find(',', start);
      parts.push_back(text.substr(start, comma == std::string_view::npos ? comma : comma - start));
      if (comma == std::string_view::npos)
      {
        break;
      }
      start = comma + 1;
    }
    if (parts.size() != 1 && parts.size() != 3)
    {
      throw errorAbout(subject, quoted(text) + " is not a colour (R,G,B or one grey value)");
    }
    for (std::size_t i = 0; i < 3; ++i)
    {
      v.number[i] = parseNumber(parts[parts.size() == 1 ? 0 : i], false, subject);
    }
    break;
  }
  }
  checkParameterValue(spec, v, subject);
  return v;
}

std::string formatParameterValue(const ParameterSpec& spec, const ParameterValue& value)
{
  switch (spec.type)
  {
  case ParameterType::Text:
    return value.text;
  case ParameterType::Integer:
  case ParameterType::Real:
    return formatNumber(value.number[0]);
  case ParameterType::Color:
    break;
  }
  return formatNumber(value.number[0]) + "," + formatNumber(value.number[1]) + "," +
         formatNumber(value.number[2]);
}

ParameterSet::ParameterSet()
{
  for (const auto& spec : parameterSpecs())
  {
    values_.push_back(defaultParameterValue(spec));
  }
}

const ParameterValue& ParameterSet::value(std::string_view name) const
{
  return values_[indexOf(name)];
}

void ParameterSet::setValue(std::string_view name, const ParameterValue& value)
{
  const std::size_t i = indexOf(name);
  checkParameterValue(parameterSpecs()[i], value, std::string(name));
  values_[i] = value;
}

void ParameterSet::setText(std::string_view name, std::string_view text)
{
  const std::size_t i = indexOf(name);
  values_[i] = parseParameterValue(parameterSpecs()[i], text, std::string(name));
}

double ParameterSet::real(std::string_view name) const
{
  return value(name).number[0];
}

int ParameterSet::integer(std::string_view name) const
{
  return static_cast<int>(value(name).number[0]);
}

glm::dvec3 ParameterSet::color(std::string_view name) const
{
  const auto& n = value(name).number;
  return {n[0], n[1], n[2]};
}

const std::string& ParameterSet::text(std::string_view name) const
{
  return value(name).text;
}

AsLobe ParameterSet::lobe() const
{
  AsLobe lobe;
  lobe.nu = real("nu");
  lobe.nv = real("nv");
  return lobe;
}
} // namespace aniso
