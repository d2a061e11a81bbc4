// core/fields/field_mapping: the grammar of `field` and `field-range` (and that the declared
// parameters refuse what it refuses), the value of a tuple, t over a range, and the lobes of the
// roughness and anisotropy targets against their formulas worked out here.
#include "core/error.h"
#include "core/fields/field_mapping.h"
#include "core/parameters/parameters.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace aniso
{
namespace
{
TEST(FieldMapping, SpecGrammar)
{
  EXPECT_FALSE(parseFieldSpec("none", "field"));
  EXPECT_EQ(*parseFieldSpec("T", "field"), (FieldSpec{"T", -1}));
  EXPECT_EQ(*parseFieldSpec("velocity:magnitude", "field"), (FieldSpec{"velocity", -1}));
  EXPECT_EQ(*parseFieldSpec("velocity:y", "field"), (FieldSpec{"velocity", 1}));
  EXPECT_EQ(*parseFieldSpec("stress:5", "field"), (FieldSpec{"stress", 5}));
  // The last colon separates the component: names may hold colons.
  EXPECT_EQ(*parseFieldSpec("a:b:z", "field"), (FieldSpec{"a:b", 2}));
  EXPECT_EQ(formatFieldSpec(FieldSpec{"v", 2}), "v:2");
  for (const char* bad : {":x", "v:w", "v:", "v:-1", "v:123"})
  {
    EXPECT_THROW(parseFieldSpec(bad, "field"), Error) << bad;
  }
  ParameterSet p;
  EXPECT_THROW(p.setText("field", "v:w"), Error);
  p.setText("field", "v:x");
  EXPECT_EQ(p.text("field"), "v:x");
}

TEST(FieldMapping, RangeGrammar)
{
  EXPECT_TRUE(parseFieldRange("auto", "field-range").automatic);
  const FieldRange r = parseFieldRange("-2.5,1e3", "field-range");
  EXPECT_FALSE(r.automatic);
  EXPECT_EQ(r.min, -2.5);
  EXPECT_EQ(r.max, 1000.0);
  for (const char* bad : {"", "1", "1,1", "2,1", "a,b", "1,inf", "nan,2", "1,2,3"})
  {
    EXPECT_THROW(parseFieldRange(bad, "field-range"), Error) << bad;
  }
  ParameterSet p;
  EXPECT_THROW(p.setText("field-range", "3,1"), Error);
}

TEST(FieldMapping, ValuesOfTuples)
{
  const double v[3] = {3.0, 4.0, 12.0};
  EXPECT_EQ(fieldValue(FieldSpec{"v", -1}, v, 3), 13.0);
  EXPECT_EQ(fieldValue(FieldSpec{"v", -1}, v, 2), 5.0);
  EXPECT_EQ(fieldValue(FieldSpec{"v", 1}, v, 3), 4.0);
  EXPECT_EQ(fieldValue(FieldSpec{"v", -1}, v, 1), 3.0);
  EXPECT_TRUE(std::isnan(fieldValue(FieldSpec{"v", 3}, v, 3))); // no such component
  const double bad[2] = {1.0, std::numeric_limits<double>::infinity()};
  EXPECT_TRUE(std::isnan(fieldValue(FieldSpec{"v", -1}, bad, 2)));
  EXPECT_EQ(fieldValue(FieldSpec{"v", 0}, bad, 2), 1.0);
  const double negative = -2.0;
  EXPECT_EQ(fieldValue(FieldSpec{"s", -1}, &negative, 1), -2.0); // a scalar keeps its sign

  EXPECT_EQ(fieldParameter(5.0, 0.0, 10.0), 0.5);
  EXPECT_EQ(fieldParameter(-5.0, 0.0, 10.0), 0.0);
  EXPECT_EQ(fieldParameter(50.0, 0.0, 10.0), 1.0);
  EXPECT_EQ(fieldParameter(3.0, 3.0, 3.0), 0.5);
  EXPECT_TRUE(std::isnan(fieldParameter(std::nan(""), 0.0, 1.0)));
}

TEST(FieldMapping, LobesOfTheTargets)
{
  const AsLobe lobe{1000.0, 10.0};
  const AsLobe rough = fieldLobe(lobe, FieldTarget::Roughness, 0.1, 2.0, 0.5); // scale 1.05
  EXPECT_DOUBLE_EQ(rough.nu, 1050.0);
  EXPECT_DOUBLE_EQ(rough.nv, 10.5);
  EXPECT_DOUBLE_EQ(fieldLobe(lobe, FieldTarget::Roughness, 0.0, 1e4, 1.0).nu, kMaxExponent);
  // Anisotropy: strength 0 is isotropic at the geometric mean (100), 1 the lobe itself.
  const AsLobe iso = fieldLobe(lobe, FieldTarget::Anisotropy, 0.0, 1.0, 0.0);
  EXPECT_NEAR(iso.nu, 100.0, 1e-9);
  EXPECT_NEAR(iso.nv, 100.0, 1e-9);
  const AsLobe full = fieldLobe(lobe, FieldTarget::Anisotropy, 0.0, 1.0, 1.0);
  EXPECT_NEAR(full.nu, 1000.0, 1e-9);
  EXPECT_NEAR(full.nv, 10.0, 1e-9);
  const AsLobe half = fieldLobe(lobe, FieldTarget::Anisotropy, 0.0, 1.0, 0.5);
  EXPECT_NEAR(half.nu, std::sqrt(100.0 * 1000.0), 1e-9);
  EXPECT_NEAR(half.nu * half.nv, 1000.0 * 10.0, 1e-6); // the mean is kept
  // Strengths beyond [0, 1] are clamped; colour targets leave the lobe.
  EXPECT_NEAR(fieldLobe(lobe, FieldTarget::Anisotropy, 0.0, 5.0, 1.0).nu, 1000.0, 1e-9);
  EXPECT_EQ(fieldLobe(lobe, FieldTarget::Albedo, 0.0, 5.0, 1.0).nu, 1000.0);
}

TEST(FieldMapping, FromTheDeclaredParameters)
{
  ParameterSet p;
  EXPECT_FALSE(fieldMappingFromParameters(p)); // "none" by default
  p.setText("field", "T");
  p.setText("field-target", "roughness");
  p.setText("field-colormap", "cool-to-warm");
  p.setText("field-range", "0,10");
  const auto m = fieldMappingFromParameters(p);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->spec.array, "T");
  EXPECT_EQ(m->target, FieldTarget::Roughness);
  EXPECT_EQ(m->colorMap, ColorMap::CoolToWarm);
  EXPECT_EQ(m->range, (FieldRange{false, 0.0, 10.0}));
  EXPECT_EQ(m->low, 0.0);
  EXPECT_EQ(m->high, 1.0);
}
} // namespace
} // namespace aniso
