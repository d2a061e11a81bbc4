// The parameter declaration (core/parameters/parameters.h): the table every option, dock and
// session key is derived from must be self-consistent, and its parser strict.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/error.h"
#include "core/lut/lut.h"
#include "core/parameters/choices.h"
#include "core/parameters/parameters.h"

#include <cctype>
#include <cmath>
#include <gtest/gtest.h>
#include <set>
#include <string>
#include <vector>

namespace
{
using aniso::Affects;
using aniso::ParameterSpec;
using aniso::ParameterType;
using aniso::ParameterValue;

// The message of the aniso::Error that body throws, or "" if it throws none.
template <typename F>
std::string errorOf(F body)
{
  try
  {
    body();
  }
  catch (const aniso::Error& e)
  {
    return e.what();
  }
  return {};
}

// Names are unique and usable as "--name" options and session keys: lower case, digits, '-'.
TEST(Parameters, NamesAreUniqueOptionSafeAndDocumented)
{
  std::set<std::string> names;
  for (const ParameterSpec& spec : aniso::parameterSpecs())
  {
    const std::string name(spec.name);
    EXPECT_TRUE(names.insert(name).second) << "duplicate " << name;
    ASSERT_FALSE(name.empty());
    EXPECT_TRUE(std::islower(static_cast<unsigned char>(name.front()))) << name;
    for (char c : name)
    {
      EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) ||
                  std::isdigit(static_cast<unsigned char>(c)) || c == '-')
          << name;
    }
    EXPECT_FALSE(spec.label.empty()) << name;
    EXPECT_FALSE(spec.help.empty()) << name;
    EXPECT_EQ(&aniso::parameterSpec(name), &spec) << name;
  }
  EXPECT_GE(names.size(), 8u);
}

// Every default lies in its range; ranges and steps are sensible; integer defaults are whole.
TEST(Parameters, DefaultsLieInTheirRanges)
{
  for (const ParameterSpec& spec : aniso::parameterSpecs())
  {
    const std::string name(spec.name);
    if (spec.type == ParameterType::Text)
    {
      EXPECT_FALSE(spec.defaultText.empty()) << name;
      continue;
    }
    EXPECT_LT(spec.minimum, spec.maximum) << name;
    EXPECT_GT(spec.step, 0.0) << name;
    EXPECT_LE(spec.step, spec.maximum - spec.minimum) << name;
    for (int c = 0; c < spec.components(); ++c)
    {
      const double v = spec.defaultValue[static_cast<std::size_t>(c)];
      EXPECT_GE(v, spec.minimum) << name;
      EXPECT_LE(v, spec.maximum) << name;
      if (spec.type == ParameterType::Integer)
      {
        EXPECT_EQ(v, std::floor(v)) << name;
      }
      if (spec.powerOfTwo)
      {
        EXPECT_EQ(std::exp2(std::round(std::log2(v))), v) << name;
      }
    }
    EXPECT_NO_THROW(aniso::checkParameterValue(spec, aniso::defaultParameterValue(spec), name));
  }
}

// The ranges the CLI and docks offer are exactly what the core bakers accept (lut.h and
// ashikhmin_shirley.h state those limits), so no accepted value fails later in a baker.
TEST(Parameters, RangesMatchTheCoreLimits)
{
  EXPECT_EQ(aniso::parameterSpec("nu").minimum, 0.0);
  EXPECT_EQ(aniso::parameterSpec("nu").maximum, aniso::kMaxExponent);
  EXPECT_EQ(aniso::parameterSpec("nv").maximum, aniso::kMaxExponent);
  EXPECT_EQ(aniso::parameterSpec("lut-size").minimum, aniso::kMinLutSize);
  EXPECT_EQ(aniso::parameterSpec("lut-size").maximum, aniso::kMaxLutSize);
  EXPECT_EQ(aniso::parameterSpec("lut-samples").minimum, 1.0);
  EXPECT_EQ(aniso::parameterSpec("lut-samples").maximum, aniso::kMaxLutSamples);
  EXPECT_EQ(aniso::parameterSpec("f0").minimum, 0.0);
  EXPECT_EQ(aniso::parameterSpec("f0").maximum, 1.0);
}

// The default material is brushed aluminium: F0 of aluminium (linear, ~0.91-0.92) and a lobe
// sharper along t than along b.
TEST(Parameters, DefaultMaterialIsBrushedAluminium)
{
  const aniso::ParameterSet set;
  const glm::dvec3 f0 = set.color("f0");
  EXPECT_NEAR(f0.x, 0.913, 1e-12);
  EXPECT_NEAR(f0.y, 0.922, 1e-12);
  EXPECT_NEAR(f0.z, 0.924, 1e-12);
  const aniso::AsLobe lobe = set.lobe();
  EXPECT_EQ(lobe.nu, aniso::parameterSpec("nu").defaultValue[0]);
  EXPECT_EQ(lobe.nv, aniso::parameterSpec("nv").defaultValue[0]);
  EXPECT_GT(lobe.nu, lobe.nv);
  EXPECT_EQ(set.text("env"), "builtin:studio");
}

// Text written by formatParameterValue reads back to the same value (sessions rely on it).
TEST(Parameters, FormatParseRoundTrip)
{
  for (const ParameterSpec& spec : aniso::parameterSpecs())
  {
    const ParameterValue v = aniso::defaultParameterValue(spec);
    const std::string text = aniso::formatParameterValue(spec, v);
    EXPECT_EQ(aniso::parseParameterValue(spec, text, "x"), v) << spec.name << " " << text;
  }
  ParameterValue awkward;
  awkward.number = {1.0 / 3.0, 0.1, 1e-7};
  const ParameterSpec& f0 = aniso::parameterSpec("f0");
  EXPECT_EQ(aniso::parseParameterValue(f0, aniso::formatParameterValue(f0, awkward), "x"), awkward);
  // Integers at the top of their range, and round ones: 200000 was spelled "2e5", which the
  // integer parser refuses (a fuzzing finding).
  for (const ParameterSpec& spec : aniso::parameterSpecs())
  {
    if (spec.type != aniso::ParameterType::Integer)
    {
      continue;
    }
    for (const double n :
         {spec.maximum, spec.minimum, std::floor((spec.minimum + spec.maximum) / 2)})
    {
      ParameterValue v;
      v.number.fill(n); // as the parser fills a number's value
      const std::string text = aniso::formatParameterValue(spec, v);
      EXPECT_EQ(aniso::parseParameterValue(spec, text, "x"), v) << spec.name << " " << text;
    }
  }
  EXPECT_EQ(aniso::formatParameterValue(
                aniso::parameterSpec("lut-samples"),
                aniso::parseParameterValue(aniso::parameterSpec("lut-samples"), "200000", "x")),
            "200000");
}

// formatNumber gives the shortest exact form, with compact exponents.
TEST(Parameters, FormatNumberIsShortAndExact)
{
  EXPECT_EQ(aniso::formatNumber(1e6), "1e6");
  EXPECT_EQ(aniso::formatNumber(1024.0), "1024");
  EXPECT_EQ(aniso::formatNumber(0.913), "0.913");
  EXPECT_EQ(aniso::formatNumber(-180.0), "-180");
  EXPECT_EQ(aniso::formatNumber(1e-5), "1e-5");
  EXPECT_EQ(aniso::formatNumber(0.0), "0");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::stod(aniso::formatNumber(third)), third);
}

// Accepted spellings: negative reals, exponents, one grey value for a colour.
TEST(Parameters, ParseAcceptsValidSpellings)
{
  EXPECT_EQ(aniso::parseParameterValue(aniso::parameterSpec("env-rotation"), "-30", "x").number[0],
            -30.0);
  EXPECT_EQ(aniso::parseParameterValue(aniso::parameterSpec("nu"), "2e4", "x").number[0], 2e4);
  // Underflow to a subnormal is still a finite number in range.
  EXPECT_EQ(aniso::parseParameterValue(aniso::parameterSpec("nu"), "1e-310", "x").number[0],
            1e-310);
  const ParameterValue grey =
      aniso::parseParameterValue(aniso::parameterSpec("albedo"), "0.5", "x");
  EXPECT_EQ(grey.number, (std::array<double, 3>{0.5, 0.5, 0.5}));
  const ParameterValue rgb =
      aniso::parseParameterValue(aniso::parameterSpec("f0"), "0.1,0.2,0.3", "x");
  EXPECT_EQ(rgb.number, (std::array<double, 3>{0.1, 0.2, 0.3}));
  EXPECT_EQ(aniso::parseParameterValue(aniso::parameterSpec("cube-size"), "512", "x").number[0],
            512.0);
}

// Rejected values: the error names the subject first and quotes the offending text.
TEST(Parameters, ParseRejectsBadValuesNamingTheSubject)
{
  struct Case
  {
    const char* parameter;
    const char* text;
    const char* reason;
  };
  const Case cases[] = {
      {"nu", "abc", "is not a number"},
      {"nu", "", "is not a number"},
      {"nu", " 5", "is not a number"},
      {"nu", "5x", "is not a number"},
      {"nu", "nan", "is not a finite number"},
      {"nu", "inf", "is not a finite number"},
      {"nu", "1e400", "is not a finite number"},
      {"nu", "-1", "out of range [0, 1e6]"},
      {"nv", "1e6.5", "is not a number"},
      {"nv", "1000001", "out of range [0, 1e6]"},
      {"lut-size", "64.5", "is not an integer"},
      {"lut-size", "-4", "out of range [2, 4096]"},
      {"lut-size", "99999999999999999999", "is too large"},
      {"cube-size", "100", "is not a power of two"},
      {"f0", "0.1,0.2", "is not a colour"},
      {"f0", "0.1,0.2,1.5", "out of range [0, 1]"},
      {"env-rotation", "181", "out of range [-180, 180]"},
      {"env", "", "empty value"},
  };
  for (const Case& c : cases)
  {
    const std::string message = errorOf(
        [&] { aniso::parseParameterValue(aniso::parameterSpec(c.parameter), c.text, "--opt"); });
    EXPECT_EQ(message.rfind("--opt: ", 0), 0u) << c.parameter << " '" << c.text << "' " << message;
    EXPECT_NE(message.find(c.reason), std::string::npos)
        << c.parameter << " '" << c.text << "' " << message;
  }
}

// A rejected assignment leaves the set unchanged; unknown names are errors that name them.
TEST(Parameters, SetRejectsAndKeepsPreviousValue)
{
  aniso::ParameterSet set;
  set.setText("nu", "20000");
  EXPECT_EQ(set.real("nu"), 20000.0);
  EXPECT_NE(errorOf([&] { set.setText("nu", "-5"); }).find("nu: -5 is out of range"),
            std::string::npos);
  EXPECT_EQ(set.real("nu"), 20000.0);
  ParameterValue tooMany;
  tooMany.number = {5000.0, 5000.0, 5000.0};
  EXPECT_FALSE(errorOf([&] { set.setValue("lut-size", tooMany); }).empty());
  EXPECT_EQ(set.integer("lut-size"), 64);
  EXPECT_EQ(errorOf([&] { aniso::parameterSpec("nope"); }), "nope: unknown parameter");
}

// What each parameter affects, against the lists the flags replaced: the view's material,
// display and frame-cost keys (app/gui/SceneView.cxx), the LUT scheduler's inputs, and the keys
// the lit and surface models' views redraw for. A parameter in none of them affects nothing.
TEST(Parameters, RolesAreTheListedOnes)
{
  using Names = std::set<std::string>;
  // line-width and its unit: the line parts' actors (vtkpasses/render/LineStyle.h).
  // The field's keys: its values are a vertex attribute the material writes, the rest uniforms
  // (core/fields/field_mapping.h).
  const Names uniforms = {"nu",
                          "nv",
                          "f0",
                          "albedo",
                          "samples",
                          "height-scale",
                          "line-width",
                          "line-width-unit",
                          "field",
                          "field-target",
                          "field-colormap",
                          "field-range",
                          "field-low",
                          "field-high"};
  // env-sampling is a variant too; the view applied the material for it beside its list.
  const Names variant = {"method", "filtered", "env-sampling", "half-vectors",
                         "bump",   "field",    "field-target"};
  const Names luts = {"nu", "nv", "lut-size", "lut-samples"};
  // The view's material keys: uniforms, variant and the LUT inputs.
  const Names material = {"nu",           "nv",           "f0",
                          "albedo",       "samples",      "lut-size",
                          "lut-samples",  "method",       "filtered",
                          "half-vectors", "bump",         "height-scale",
                          "env-sampling", "line-width",   "line-width-unit",
                          "field",        "field-target", "field-colormap",
                          "field-range",  "field-low",    "field-high"};
  const Names display = {"exposure", "tone-mapping", "background", "background-color", "legend"};
  const Names keepsFrameCost = {"nu",
                                "nv",
                                "f0",
                                "albedo",
                                "samples",
                                "lut-size",
                                "lut-samples",
                                "target-samples",
                                "env-rotation",
                                "height-scale",
                                "quality-mode",
                                "error-target",
                                "exposure",
                                "tone-mapping",
                                "background",
                                "background-color",
                                "field-colormap",
                                "field-range",
                                "field-low",
                                "field-high",
                                "legend"};
  // env-rotation turns the environment's sources, env-lights adds them (core/lights/env_lights.h).
  const Names litModels = {
      "nu",        "nv",           "f0",         "albedo",     "tangents",       "cad-deflection",
      "cad-angle", "env-rotation", "env-lights", "line-width", "line-width-unit"};
  const Names surfaceModels = {"f0",        "albedo",    "tangents", "cad-deflection",
                               "cad-angle", "env-lights"};
  // The tessellation of CAD files: their parts are read again.
  const Names meshes = {"cad-deflection", "cad-angle"};
  const Names none = {"target-samples", "quality-mode", "error-target"};

  for (const ParameterSpec& spec : aniso::parameterSpecs())
  {
    const std::string name(spec.name);
    EXPECT_EQ(spec.affects(Affects::Uniforms), uniforms.count(name) == 1) << name;
    EXPECT_EQ(spec.affects(Affects::Variant), variant.count(name) == 1) << name;
    EXPECT_EQ(spec.affects(Affects::Luts), luts.count(name) == 1) << name;
    EXPECT_EQ(spec.affects(Affects::Uniforms | Affects::Variant | Affects::Luts),
              material.count(name) == 1)
        << name;
    EXPECT_EQ(spec.affects(Affects::Display), display.count(name) == 1) << name;
    EXPECT_EQ(spec.affects(Affects::FrameCost), keepsFrameCost.count(name) == 0) << name;
    EXPECT_EQ(spec.affects(Affects::LitModels), litModels.count(name) == 1) << name;
    EXPECT_EQ(spec.affects(Affects::SurfaceModels), surfaceModels.count(name) == 1) << name;
    EXPECT_EQ(spec.affects(Affects::Meshes), meshes.count(name) == 1) << name;
    EXPECT_EQ(spec.roles == Affects::None, none.count(name) == 1) << name;
  }
  // Every name above is declared.
  for (const Names* names : {&uniforms, &variant, &luts, &material, &display, &keepsFrameCost,
                             &litModels, &surfaceModels, &meshes, &none})
  {
    for (const std::string& name : *names)
    {
      EXPECT_NO_THROW(aniso::parameterSpec(name)) << name;
    }
  }
}

// The choices of KEY are SPELLINGS, in that order, and its default DEFAULTTEXT (the spellings of
// options and sessions); each parses to a value of its own that spells back to it, and any other
// text is refused with the message checkParameterValue gives ("KEY: 'TEXT' is not one of A, B").
template <typename E, typename Parse>
void expectEnumChoices(std::set<std::string>& covered, const std::string& key, Parse parse,
                       const std::vector<std::string>& spellings, const std::string& defaultText)
{
  covered.insert(key);
  const ParameterSpec& spec = aniso::parameterSpec(key);
  ASSERT_EQ(spec.choices.size(), spellings.size()) << key;
  EXPECT_EQ(spec.defaultText, defaultText) << key;
  std::set<E> values;
  std::string allowed;
  for (std::size_t i = 0; i < spellings.size(); ++i)
  {
    EXPECT_EQ(spec.choices[i], spellings[i]) << key;
    const E value = parse(spellings[i]);
    EXPECT_TRUE(values.insert(value).second) << key << " " << spellings[i];
    EXPECT_EQ(aniso::spelling(value), spellings[i]) << key;
    allowed += (i ? ", " : "") + spellings[i];
  }
  const std::string refused = key + ": 'bogus' is not one of " + allowed;
  EXPECT_EQ(errorOf([&] { parse("bogus"); }), refused);
  ParameterValue bogus;
  bogus.text = "bogus";
  EXPECT_EQ(errorOf([&] { aniso::checkParameterValue(spec, bogus, key); }), refused);
}

// Every parameter with choices is backed by an enum whose values are exactly those choices.
TEST(Parameters, ChoicesParseToDistinctEnumsAndBack)
{
  using namespace aniso;
  std::set<std::string> covered;
  const auto onOff = [](const std::string& key)
  { return [key](std::string_view text) { return parseOnOff(key, text); }; };
  expectEnumChoices<SpecularMethod>(covered, "method", parseSpecularMethod, {"exact", "split-sum"},
                                    "exact");
  expectEnumChoices<OnOff>(covered, "filtered", onOff("filtered"), {"on", "off"}, "on");
  expectEnumChoices<EnvironmentSampling>(covered, "env-sampling", parseEnvironmentSampling,
                                         {"auto", "off", "mis", "sources"}, "auto");
  expectEnumChoices<OnOff>(covered, "env-lights", onOff("env-lights"), {"on", "off"}, "on");
  expectEnumChoices<HalfVectorSource>(covered, "half-vectors", parseHalfVectorSource,
                                      {"shader", "lut"}, "lut");
  expectEnumChoices<QualityMode>(covered, "quality-mode", parseQualityMode, {"samples", "error"},
                                 "error");
  expectEnumChoices<BumpMapping>(covered, "bump", parseBumpMapping,
                                 {"none", "normal", "quaternion"}, "none");
  expectEnumChoices<BackgroundMode>(covered, "background", parseBackgroundMode,
                                    {"env", "color", "none"}, "env");
  expectEnumChoices<LineWidthUnit>(covered, "line-width-unit", parseLineWidthUnit,
                                   {"pixels", "world"}, "pixels");
  expectEnumChoices<ToneMapping>(covered, "tone-mapping", parseToneMapping,
                                 {"aces", "reinhard", "clamp"}, "aces");
  expectEnumChoices<LeadrFilter>(covered, "leadr-filter", parseLeadrFilter,
                                 {"leadr", "normal-mapping"}, "leadr");
  expectEnumChoices<MicroPattern>(covered, "structure", parseMicroPattern,
                                  {"pyramids", "inverted-pyramids", "grooves", "silk"}, "pyramids");
  expectEnumChoices<OnOff>(covered, "jitter-grid", onOff("jitter-grid"), {"off", "on"}, "off");
  expectEnumChoices<MicroMasking>(covered, "masking", parseMicroMasking,
                                  {"pom", "parallax", "normal"}, "pom");
  expectEnumChoices<OnOff>(covered, "self-shadow", onOff("self-shadow"), {"off", "on"}, "off");
  expectEnumChoices<MicroBrdf>(covered, "micro-brdf", parseMicroBrdf, {"ggx", "blinn-phong"},
                               "ggx");
  expectEnumChoices<FieldTarget>(covered, "field-target", parseFieldTarget,
                                 {"albedo", "f0", "roughness", "anisotropy"}, "albedo");
  expectEnumChoices<ColorMap>(covered, "field-colormap", parseColorMap,
                              {"viridis", "cividis", "cool-to-warm", "grayscale"}, "viridis");
  expectEnumChoices<OnOff>(covered, "legend", onOff("legend"), {"on", "off"}, "on");
  for (const ParameterSpec& spec : parameterSpecs())
  {
    EXPECT_EQ(covered.count(std::string(spec.name)) == 1, !spec.choices.empty()) << spec.name;
  }
  // The values mean what their names say.
  EXPECT_EQ(parseSpecularMethod("split-sum"), SpecularMethod::SplitSum);
  EXPECT_EQ(parseHalfVectorSource("lut"), HalfVectorSource::Lut);
  EXPECT_EQ(parseBackgroundMode("none"), BackgroundMode::Transparent);
  EXPECT_EQ(parseMicroMasking("pom"), MicroMasking::ParallaxOcclusion);
  EXPECT_EQ(parseOnOff("filtered", "on"), OnOff::On);
  EXPECT_EQ(errorOf([] { parseBumpMapping(""); }), "bump: empty value");
}
} // namespace
