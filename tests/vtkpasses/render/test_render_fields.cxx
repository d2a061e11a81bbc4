// A data field that drives the material (core/fields/field_mapping.h), drawn by AnisoMaterial:
// - a point scalar mapped to albedo gives, at every pixel, the colour map's colour of the value
//   interpolated there (read back from the PNG-ready display image and the linear one), with the
//   preset's NaN colour where the vertices are NaN; the reference is core's colorMapColor,
//   itself checked against vtkColorTransferFunction (test_color_map). The scene makes the
//   displayed colour the albedo exactly: F0 = 0 and a sharp lobe (no specular), a uniform white
//   environment (irradiance pi, so the Lambert term is the albedo), tone mapping `clamp`, a
//   plate facing a parallel camera (n.v = 1: no Fresnel loss of the diffuse);
// - the automatic range is the field's finite range;
// - cell data is averaged to the points;
// - a constant field that scales the roughness, or sets the anisotropy strength, draws as the
//   material with the lobe core's fieldLobe gives (a render of that lobe without a field).
#include "core/fields/color_map.h"
#include "core/fields/field_mapping.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/render/FieldValues.h"

#include <limits>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>

namespace aniso::test
{
namespace
{
constexpr int kSize = 64;

CameraPlacement topCamera()
{
  CameraPlacement camera;
  camera.position = glm::dvec3(0.0, 0.0, 4.0);
  camera.focalPoint = glm::dvec3(0.0);
  camera.viewUp = glm::dvec3(0.0, 1.0, 0.0);
  camera.parallel = true;
  camera.parallelScale = 1.0; // the plate [-1, 1]^2 fills the image
  return camera;
}

// The plate (8 x 8 quads of triangles) with the point array "temperature" = x, NaN at x >= 0.75.
vtkSmartPointer<vtkPolyData> plateWithTemperature()
{
  vtkSmartPointer<vtkPolyData> plate = makePlate(8);
  vtkNew<vtkDoubleArray> temperature;
  temperature->SetName("temperature");
  temperature->SetNumberOfTuples(plate->GetNumberOfPoints());
  for (vtkIdType i = 0; i < plate->GetNumberOfPoints(); ++i)
  {
    const double x = plate->GetPoint(i)[0];
    temperature->SetValue(i, x >= 0.75 - 1e-9 ? std::numeric_limits<double>::quiet_NaN() : x);
  }
  plate->GetPointData()->AddArray(temperature);
  return plate;
}

RenderSettings albedoScene(vtkSmartPointer<vtkPolyData> plate, const FieldMapping& field)
{
  RenderSettings s;
  s.surface = std::move(plate);
  s.environment = openEnvironment("builtin:white");
  s.cubeSize = 32;
  s.material.lobe = AsLobe{10000.0, 10000.0};
  s.material.f0 = glm::dvec3(0.0);
  s.material.albedo = glm::dvec3(0.0);
  s.material.samples = 4;
  s.material.field = field;
  s.display.toneMapping = ToneMapping::Clamp;
  s.display.background = BackgroundMode::Transparent;
  s.display.legend = false; // the bar would cover the right of the plate
  s.camera = topCamera();
  s.width = kSize;
  s.height = kSize;
  s.frames = 1;
  s.jitter = false;
  return s;
}

struct ColourCheck
{
  int compared = 0;
  double worstDisplay = 0.0; // in 8-bit steps
  double worstLinear = 0.0;
};

// Compares every pixel whose plate point X satisfies USE with EXPECTED(x) (sRGB display colour).
template <class Use, class Expected>
ColourCheck compareColours(const RenderResult& r, Use use, Expected expected)
{
  ColourCheck c;
  for (int y = 1; y < kSize - 1; ++y)
  {
    for (int x = 1; x < kSize - 1; ++x)
    {
      const double px = planeHit(topCamera(), kSize, x, y).position.x;
      if (!use(px))
      {
        continue;
      }
      const glm::dvec3 colour = expected(px);
      for (int k = 0; k < 3; ++k)
      {
        c.worstDisplay =
            std::max(c.worstDisplay, std::abs(r.display.at(x, y, k) - colour[k]) * 255.0);
        c.worstLinear =
            std::max(c.worstLinear, std::abs(r.linear.at(x, y, k) - srgbToLinear(colour[k])));
      }
      ++c.compared;
    }
  }
  return c;
}

FieldMapping temperatureField(FieldRange range)
{
  FieldMapping f;
  f.spec.array = "temperature";
  f.target = FieldTarget::Albedo;
  f.colorMap = ColorMap::Viridis;
  f.range = range;
  return f;
}

TEST(RenderFields, AScalarOnAlbedoShowsTheColourMapsColours)
{
  ANISO_REQUIRE_DISPLAY();
  const RenderResult r =
      renderOffscreen(albedoScene(plateWithTemperature(), temperatureField({false, -1.0, 1.0})));
  ASSERT_TRUE(r.variant.field);
  // Quads between x = -1 and 0.5 have no NaN vertex: t = (x + 1) / 2 there.
  const ColourCheck valid = compareColours(
      r, [](double x) { return x < 0.5 - 0.02; },
      [](double x) { return colorMapColor(ColorMap::Viridis, (x + 1.0) / 2.0); });
  std::cout << "viridis over [-1, 1]: " << valid.compared << " pixels, worst " << valid.worstDisplay
            << " / 255, linear " << valid.worstLinear << "\n";
  EXPECT_GT(valid.compared, 1500);
  EXPECT_LE(valid.worstDisplay, 1.5);
  EXPECT_LE(valid.worstLinear, 3e-3);
  // The last column of quads has NaN at every vertex: the preset's NaN colour, red.
  const ColourCheck nan = compareColours(
      r, [](double x) { return x > 0.75 + 0.02; },
      [](double) { return colorMapNanColor(ColorMap::Viridis); });
  std::cout << "NaN: " << nan.compared << " pixels, worst " << nan.worstDisplay << " / 255\n";
  EXPECT_GT(nan.compared, 150);
  EXPECT_LE(nan.worstDisplay, 1.5);
  EXPECT_EQ(colorMapNanColor(ColorMap::Viridis), glm::dvec3(1.0, 0.0, 0.0));
}

TEST(RenderFields, TheAutomaticRangeIsTheFieldsFiniteRange)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings s = albedoScene(plateWithTemperature(), temperatureField({}));
  s.material.field->colorMap = ColorMap::CoolToWarm;
  const RenderResult r = renderOffscreen(s);
  // Finite values run from -1 to 0.5 (the vertices at 0.75 and 1 are NaN).
  const ColourCheck c = compareColours(
      r, [](double x) { return x < 0.5 - 0.02; },
      [](double x) { return colorMapColor(ColorMap::CoolToWarm, (x + 1.0) / 1.5); });
  std::cout << "cool to warm, automatic range: worst " << c.worstDisplay << " / 255\n";
  EXPECT_GT(c.compared, 1500);
  EXPECT_LE(c.worstDisplay, 1.5);
}

TEST(RenderFields, CellDataIsAveragedToThePoints)
{
  ANISO_REQUIRE_DISPLAY();
  vtkSmartPointer<vtkPolyData> plate = makePlate(8);
  vtkNew<vtkDoubleArray> side;
  side->SetName("side");
  side->SetNumberOfTuples(plate->GetNumberOfCells());
  for (vtkIdType c = 0; c < plate->GetNumberOfCells(); ++c)
  {
    double bounds[6];
    plate->GetCellBounds(c, bounds);
    side->SetValue(c, 0.5 * (bounds[0] + bounds[1]) < 0.0 ? 0.0 : 1.0);
  }
  plate->GetCellData()->AddArray(side);
  FieldMapping f = temperatureField({false, 0.0, 1.0});
  f.spec.array = "side";
  f.colorMap = ColorMap::Grayscale;
  const RenderResult r = renderOffscreen(albedoScene(plate, f));
  // Points left of x = 0 touch cells of 0 only, right of it cells of 1 only; the column at 0
  // averages both (0.5), so only the quads beside it blend.
  const ColourCheck left = compareColours(
      r, [](double x) { return x < -0.27; }, [](double) { return glm::dvec3(0.0); });
  const ColourCheck right = compareColours(
      r, [](double x) { return x > 0.27; }, [](double) { return glm::dvec3(1.0); });
  EXPECT_GT(left.compared, 700);
  EXPECT_GT(right.compared, 700);
  EXPECT_LE(left.worstDisplay, 1.5);
  EXPECT_LE(right.worstDisplay, 1.5);
}

// Relative L1 between two linear images over the pixels either covers.
double relativeL1(const Image& a, const Image& b)
{
  double difference = 0.0;
  double total = 0.0;
  for (int y = 0; y < a.height; ++y)
  {
    for (int x = 0; x < a.width; ++x)
    {
      if (a.at(x, y, 3) <= 0.0f && b.at(x, y, 3) <= 0.0f)
      {
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        difference += std::abs(double(a.at(x, y, c)) - b.at(x, y, c));
        total += std::abs(double(b.at(x, y, c)));
      }
    }
  }
  return total > 0.0 ? difference / total : 1.0;
}

TEST(RenderFields, AConstantFieldOnTheLobeDrawsTheLobeOfFieldLobe)
{
  ANISO_REQUIRE_DISPLAY();
  const AsLobe lobe{1000.0, 100.0};
  for (const FieldTarget target : {FieldTarget::Roughness, FieldTarget::Anisotropy})
  {
    RenderSettings withField = sphereScene(openEnvironment("builtin:studio"), lobe, 64);
    withField.cubeSize = 64;
    withField.material.halfVectors = HalfVectorSource::Shader;
    withField.material.samples = 16;
    vtkNew<vtkDoubleArray> k;
    k->SetName("k");
    k->SetNumberOfTuples(withField.surface->GetNumberOfPoints());
    k->Fill(0.25);
    withField.surface->GetPointData()->AddArray(k);
    FieldMapping f;
    f.spec.array = "k";
    f.target = target;
    f.range = FieldRange{false, 0.0, 1.0};
    f.low = 0.2;
    f.high = 1.0; // t = 0.25: 0.4
    withField.material.field = f;

    RenderSettings plain = withField;
    plain.material.field.reset();
    plain.material.lobe = fieldLobe(lobe, target, f.low, f.high, 0.25);
    RenderSettings unchanged = plain;
    unchanged.material.lobe = lobe;

    const RenderResult a = renderOffscreen(withField);
    const RenderResult b = renderOffscreen(plain);
    const RenderResult c = renderOffscreen(unchanged);
    const double same = relativeL1(a.linear, b.linear);
    const double control = relativeL1(a.linear, c.linear);
    std::cout << (target == FieldTarget::Roughness ? "roughness" : "anisotropy") << ": lobe ("
              << plain.material.lobe.nu << ", " << plain.material.lobe.nv
              << "), relative L1 against it " << same << ", against the material's own " << control
              << "\n";
    EXPECT_TRUE(a.variant.field);
    EXPECT_LT(same, 2e-3);
    EXPECT_GT(control, 20.0 * same);
  }
}

// No GL: the values a mesh gives, cell averaging with NaN, the offset, joint ranges, legends.
TEST(FieldValues, PointValuesRangesAndLegends)
{
  vtkSmartPointer<vtkPolyData> plate = plateWithTemperature();
  const FieldSpec spec{"temperature", -1};
  const auto stats = fieldStatistics(plate, spec);
  ASSERT_TRUE(stats);
  EXPECT_FALSE(stats->perCell);
  EXPECT_EQ(stats->nonFinite, 18); // two columns of 9 points
  EXPECT_DOUBLE_EQ(stats->minimum, -1.0);
  EXPECT_DOUBLE_EQ(stats->maximum, 0.5);
  EXPECT_FALSE(fieldStatistics(plate, FieldSpec{"missing", -1}));

  const auto offset = writeFieldValues(plate, spec, "values");
  ASSERT_TRUE(offset);
  vtkDataArray* written = plate->GetPointData()->GetArray("values");
  ASSERT_NE(written, nullptr);
  for (vtkIdType i = 0; i < plate->GetNumberOfPoints(); ++i)
  {
    const double x = plate->GetPoint(i)[0];
    if (x >= 0.75 - 1e-9)
    {
      EXPECT_EQ(written->GetComponent(i, 1), 1.0);
    }
    else
    {
      EXPECT_EQ(written->GetComponent(i, 1), 0.0);
      EXPECT_NEAR(written->GetComponent(i, 0) + *offset, x, 1e-6);
    }
  }
  EXPECT_FALSE(writeFieldValues(plate, FieldSpec{"missing", -1}, "values"));
  EXPECT_EQ(plate->GetPointData()->GetArray("values"), nullptr);

  // Two parts that show one array share its joint range; a third of an explicit range keeps it.
  vtkSmartPointer<vtkPolyData> other = plateWithTemperature();
  vtkDataArray* t = other->GetPointData()->GetArray("temperature");
  for (vtkIdType i = 0; i < t->GetNumberOfTuples(); ++i)
  {
    t->SetComponent(i, 0, t->GetComponent(i, 0) * 10.0);
  }
  MaterialSettings a, b, c;
  a.field = temperatureField({});
  b.field = temperatureField({});
  c.field = temperatureField({false, 2.0, 3.0});
  resolveFieldRanges({plate, other, other}, {&a, &b, &c});
  EXPECT_EQ(a.field->range, (FieldRange{false, -10.0, 5.0}));
  EXPECT_EQ(b.field->range, (FieldRange{false, -10.0, 5.0}));
  EXPECT_EQ(c.field->range, (FieldRange{false, 2.0, 3.0}));
  const auto legends = fieldLegends({&a, &b, &c});
  ASSERT_EQ(legends.size(), 2u);
  EXPECT_EQ(legends[0].title, "temperature");
  EXPECT_EQ(legends[0].minimum, -10.0);
  EXPECT_EQ(legends[1].maximum, 3.0);
}
} // namespace
} // namespace aniso::test
