// The parameter declaration (core/parameters/parameters.h): the table every option, dock and
// session key is derived from must be self-consistent, and its parser strict.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/error.h"
#include "core/lut/lut.h"
#include "core/parameters/parameters.h"

#include <cctype>
#include <cmath>
#include <gtest/gtest.h>
#include <set>
#include <string>

namespace
{
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
} // namespace
