#pragma once
// A data field that drives a material (docs/METHOD.md, "Fields"): a point or cell array of the
// mesh, or a component or the magnitude of a vector array, mapped over a range to t in [0, 1],
// then through a colour map to albedo or F0, or through (low, high) to a scale of the exponents
// (roughness) or to the lobe's anisotropy. GL-free and VTK-free: the arrays are plain numbers
// here; vtkpasses/mesh/FieldAttribute.h reads them from a mesh.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/fields/color_map.h"

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace aniso
{
class ParameterSet;

// "field-target": what the field's t sets.
enum class FieldTarget
{
  Albedo,     // the colour map's colour (decoded to linear RGB) is the diffuse albedo
  F0,         // the colour map's colour is F0
  Roughness,  // n_u and n_v times mix(low, high, t): sharper or broader lobes
  Anisotropy, // strength s = mix(low, high, t) in [0, 1]: n^(s) = m^(1 - s) n^s per exponent,
              // m = sqrt(n_u n_v), from isotropic (s = 0) to the material's own lobe (s = 1)
};

// Which value of an array's tuples: one component or the magnitude.
struct FieldSpec
{
  std::string array;
  int component = -1; // -1: the magnitude (the value itself for one component), else 0-based

  bool operator==(const FieldSpec& o) const { return array == o.array && component == o.component; }
};

// "none" (or empty) -> no field; "NAME", "NAME:magnitude", "NAME:x|y|z" or "NAME:N" (0-based
// component). Throws aniso::Error "SUBJECT: reason" for a malformed text.
std::optional<FieldSpec> parseFieldSpec(std::string_view text, const std::string& subject);
std::string formatFieldSpec(const FieldSpec& spec);

// "field-range": "auto" (the field's own finite range) or "MIN,MAX" with MIN < MAX, finite.
struct FieldRange
{
  bool automatic = true;
  double min = 0.0;
  double max = 1.0;
  bool operator==(const FieldRange& o) const
  {
    return automatic == o.automatic && (automatic || (min == o.min && max == o.max));
  }
};
FieldRange parseFieldRange(std::string_view text, const std::string& subject);

// Everything a material needs to draw a field, from the declared parameters.
struct FieldMapping
{
  FieldSpec spec;
  FieldTarget target = FieldTarget::Albedo;
  ColorMap colorMap = ColorMap::Viridis;
  FieldRange range; // automatic until resolved over the parts that show the field
  double low = 0.0; // the target's value at t = 0 (roughness scale or anisotropy strength)
  double high = 1.0;

  bool operator==(const FieldMapping& o) const
  {
    return spec == o.spec && target == o.target && colorMap == o.colorMap && range == o.range &&
           low == o.low && high == o.high;
  }
  bool operator!=(const FieldMapping& o) const { return !(*this == o); }
  bool colors() const { return target == FieldTarget::Albedo || target == FieldTarget::F0; }
};
// The mapping PARAMETERS ask for (field, field-target, field-colormap, field-range, field-low,
// field-high), or none when `field` is "none".
std::optional<FieldMapping> fieldMappingFromParameters(const ParameterSet& parameters);

// The value a tuple of COMPONENTS numbers gives under SPEC: the component, or the Euclidean
// magnitude; NaN when the component does not exist or any used number is not finite.
double fieldValue(const FieldSpec& spec, const double* tuple, int components);

// t = (value - min) / (max - min) clamped to [0, 1]; NaN stays NaN. MIN == MAX gives 0.5.
double fieldParameter(double value, double min, double max);

// The exponents at t for the lobe-changing targets (Roughness, Anisotropy); LOBE itself for the
// colour targets. The shader computes the same (material_fs_dec.glsl, anisoFieldLobe).
AsLobe fieldLobe(const AsLobe& lobe, FieldTarget target, double low, double high, double t);
} // namespace aniso
