#pragma once
// The single declaration of the tunable parameters. Command-line options, dock sliders and
// session keys are all derived from this table, so a name, default or range is stated once.
// GL-free and Qt-free.
#include "core/brdf/ashikhmin_shirley.h"

#include <array>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace aniso
{
enum class ParameterType
{
  Integer, // whole number
  Real,    // floating point
  Color,   // linear RGB triple; a single number on input means grey
  Text     // free text (a path or a spec such as "builtin:studio"), or one of `choices`
};

// How a slider should move through the range: exponents span six decades, so they use a
// logarithmic scale (of 1 + value, since 0 is allowed).
enum class ParameterScale
{
  Linear,
  Logarithmic
};

// What a change of a parameter affects, as flags (combined with |): what has to follow when it
// changes. The view, the LUT scheduler and the lit and surface models' views read them.
enum class Affects : unsigned
{
  None = 0,
  Uniforms = 1u << 0,      // the material's uniforms: moving a slider never recompiles a shader
  Variant = 1u << 1,       // the material's shader variant (MaterialVariant)
  Luts = 1u << 2,          // the inputs of the half-vector and BRDF lookup-table bakes
  Display = 1u << 3,       // only the display transform of the accumulated image
  FrameCost = 1u << 4,     // what a frame costs per pixel and sample: learnt costs are forgotten
  LitModels = 1u << 5,     // what the lit models draw (their uniform material, lights, surface)
  SurfaceModels = 1u << 6, // what the surface models draw besides their own parameters
  Meshes = 1u << 7,        // how mesh files are read (a CAD file's tessellation): read them again
};

constexpr Affects operator|(Affects a, Affects b)
{
  return static_cast<Affects>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}

// Whose value a parameter is: the scene's (one value for the whole scene: environment, quality,
// display) or a material's (each part of a scene references a material of the library, which
// holds its own value: core/parameters/material_library.h).
enum class ParameterScope
{
  Scene,
  Material
};

struct ParameterSpec
{
  std::string_view name;  // option "--NAME", session key, identifier in code
  std::string_view label; // short human label for docks
  ParameterType type = ParameterType::Real;
  std::array<double, 3> defaultValue{0.0, 0.0, 0.0}; // Integer/Real use [0]
  std::string_view defaultText;                      // Text only
  double minimum = 0.0;                              // per component for Color
  double maximum = 0.0;
  double step = 0.0;
  ParameterScale scale = ParameterScale::Linear;
  bool powerOfTwo = false; // Integer only: also a power of two (mip chains down to 1x1)
  std::string_view unit;   // empty when dimensionless
  std::string_view help;   // one sentence
  // Text only: the accepted values when restricted to a few words (a combo box in the docks),
  // the first being the usual choice; empty = free text.
  std::vector<std::string_view> choices;
  Affects roles = Affects::None; // what a change of the value affects
  ParameterScope scope = ParameterScope::Scene;

  int components() const { return type == ParameterType::Color ? 3 : 1; }
  // Whether a change affects any of WHAT.
  bool affects(Affects what) const
  {
    return (static_cast<unsigned>(roles) & static_cast<unsigned>(what)) != 0;
  }
};

// Every declared parameter, in the order docks and help texts list them.
const std::vector<ParameterSpec>& parameterSpecs();

// The declaration of NAME; throws aniso::Error "NAME: unknown parameter".
const ParameterSpec& parameterSpec(std::string_view name);

// A value of any parameter type: numbers in `number` (Integer/Real in [0]), text in `text`.
struct ParameterValue
{
  std::array<double, 3> number{0.0, 0.0, 0.0};
  std::string text;

  bool operator==(const ParameterValue& other) const
  {
    return number == other.number && text == other.text;
  }
};

ParameterValue defaultParameterValue(const ParameterSpec& spec);

// Values as the parameter types hold them: a number in every component, a colour, a text.
ParameterValue numberValue(double value);
ParameterValue colorValue(double r, double g, double b);
ParameterValue textValue(std::string text);

// Parses TEXT as a value of spec (strictly: the whole text, finite numbers, integers without a
// fraction, colours as "R,G,B" or one grey value) and checks the range. Throws aniso::Error
// "SUBJECT: reason" so the caller decides whether the subject is an option or a session key.
ParameterValue parseParameterValue(const ParameterSpec& spec, std::string_view text,
                                   const std::string& subject);

// Checks a value against the range of spec; throws aniso::Error "SUBJECT: reason".
void checkParameterValue(const ParameterSpec& spec, const ParameterValue& value,
                         const std::string& subject);

// Text that parseParameterValue reads back to the same value (round trip for sessions).
std::string formatParameterValue(const ParameterSpec& spec, const ParameterValue& value);

// A number as help texts show it: shortest form that reads back exactly ("1e+06" -> "1e6").
std::string formatNumber(double value);

// The values of every declared parameter, starting at the defaults.
class ParameterSet
{
public:
  ParameterSet();

  const ParameterValue& value(std::string_view name) const;
  // Range-checked; throws aniso::Error "NAME: reason" and leaves the set unchanged.
  void setValue(std::string_view name, const ParameterValue& value);
  void setText(std::string_view name, std::string_view text);

  double real(std::string_view name) const;
  int integer(std::string_view name) const;
  glm::dvec3 color(std::string_view name) const;
  const std::string& text(std::string_view name) const;

  AsLobe lobe() const; // n_u, n_v

private:
  std::vector<ParameterValue> values_; // parallel to parameterSpecs()
};
} // namespace aniso
