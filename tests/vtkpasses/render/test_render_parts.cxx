// Scenes of several parts in the offscreen renderer (RenderSettings::parts), each checked
// against an identity or an analytic count, never against an earlier rendering:
//  - a surface split into two parts (its triangles by the sign of their centroid's x), both with
//    the surface's material, renders the image of the whole surface drawn as the one-part scene:
//    the same frame (the halves' joint bounding sphere is the whole's), the same fragments, so
//    the same pixels to float rounding (bound 1e-6 of the brightest value; measured 0); a third,
//    hidden part far away changes nothing (it is not drawn and the camera ignores it). The same
//    holds for a material installed through installMaterial, put on every visible part;
//  - two unit spheres at x = -1.5 and +1.5 seen in parallel projection: the camera fits their
//    joint bounding sphere (centre 0, radius 2.5), so the covered pixels are the area of two
//    discs of radius 1 over the view's (2 x 2.5 x margin)^2, within 2% (the faceted sphere's
//    outline is a polygon), none on the image's border, as many left as right; with the right
//    one hidden, the image is the left sphere's rendered alone (the camera fits it);
//  - 225 parts, more than a draw has texture units, of two lobes in turn render the image of
//    each lobe's spheres merged into one part (an identity: each part reads its own table);
//  - parts of one lobe share one half-vector table: LutCache::shared() makes (bakes or reads)
//    one table per distinct lobe and serves every further part of that lobe from memory;
//  - invalid scenes are refused before any drawing, naming the part.
#include "core/env/environment.h"
#include "core/error.h"
#include "core/lut/lut_cache.h"
#include "core/models/models.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>
#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso::test
{
namespace
{
constexpr int kSize = 64;

// The triangles of SURFACE whose centroid's x is negative (NEGATIVE) or not, with the points
// they use and those points' attributes.
vtkSmartPointer<vtkPolyData> half(vtkPolyData* surface, bool negative)
{
  vtkPoints* in = surface->GetPoints();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(in->GetDataType());
  vtkNew<vtkCellArray> polys;
  out->GetPointData()->CopyAllocate(surface->GetPointData());
  std::vector<vtkIdType> remap(std::size_t(in->GetNumberOfPoints()), -1);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    double x = 0.0;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      x += in->GetPoint(ids->GetId(k))[0];
    }
    if ((x < 0.0) != negative)
    {
      continue;
    }
    std::vector<vtkIdType> cell;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      const vtkIdType id = ids->GetId(k);
      if (remap[std::size_t(id)] < 0)
      {
        remap[std::size_t(id)] = points->InsertNextPoint(in->GetPoint(id));
        out->GetPointData()->CopyData(surface->GetPointData(), id, remap[std::size_t(id)]);
      }
      cell.push_back(remap[std::size_t(id)]);
    }
    polys->InsertNextCell(vtkIdType(cell.size()), cell.data());
  }
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

// SURFACE moved by OFFSET (normals and tangents unchanged).
vtkSmartPointer<vtkPolyData> moved(vtkPolyData* surface, const glm::dvec3& offset)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(surface);
  vtkPoints* points = out->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[0] + offset.x, p[1] + offset.y, p[2] + offset.z);
  }
  return out;
}

MaterialSettings testMaterial()
{
  MaterialSettings m;
  m.lobe = {1000.0, 100.0};
  m.f0 = glm::dvec3(0.9, 0.7, 0.4);
  m.albedo = glm::dvec3(0.1, 0.1, 0.1);
  m.samples = 8;
  return m;
}

RenderSettings sceneSettings()
{
  RenderSettings s;
  s.environment = std::make_shared<StudioEnvironment>();
  s.cubeSize = 64;
  s.display.background = BackgroundMode::Transparent;
  s.width = kSize;
  s.height = kSize;
  s.frames = 3;
  s.jitter = true;
  return s;
}

RenderPart part(std::string name, vtkSmartPointer<vtkPolyData> surface,
                const MaterialSettings& material, bool visible = true)
{
  RenderPart p;
  p.name = std::move(name);
  p.surface = std::move(surface);
  p.material = material;
  p.visible = visible;
  return p;
}

// The largest |a - b| over every channel of every pixel, and the largest colour value of A.
struct Difference
{
  double largest = 0.0;
  double peak = 0.0;
};

Difference difference(const Image& a, const Image& b)
{
  Difference d;
  for (std::size_t i = 0; i < a.data.size(); ++i)
  {
    d.largest = std::max(d.largest, double(std::abs(a.data[i] - b.data[i])));
    if (i % std::size_t(a.channels) != 3)
    {
      d.peak = std::max(d.peak, double(std::abs(a.data[i])));
    }
  }
  return d;
}

void expectSameImage(const RenderResult& rendered, const RenderResult& expected,
                     const std::string& name)
{
  ASSERT_EQ(rendered.linear.width, expected.linear.width);
  ASSERT_EQ(rendered.linear.height, expected.linear.height);
  EXPECT_EQ(rendered.coveredPixels, expected.coveredPixels) << name;
  const Difference d = difference(rendered.linear, expected.linear);
  std::printf("%s: largest difference %.3g of a peak %.3g\n", name.c_str(), d.largest, d.peak);
  EXPECT_GT(d.peak, 0.0) << name;
  EXPECT_LE(d.largest, 1e-6 * d.peak) << name;
  if (!(d.largest <= 1e-6 * d.peak))
  {
    keepImages("render_parts_" + name, rendered.linear, expected.linear);
  }
}

// Covered pixels (alpha > 0) in columns [x0, x1).
int64_t covered(const Image& image, int x0, int x1)
{
  int64_t n = 0;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      n += image.at(x, y, 3) > 0.0f ? 1 : 0;
    }
  }
  return n;
}

// Covered pixels on the image's border (none when the camera fits the scene).
int64_t coveredOnBorder(const Image& image)
{
  int64_t n = 0;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      const bool border = x == 0 || y == 0 || x == image.width - 1 || y == image.height - 1;
      n += border && image.at(x, y, 3) > 0.0f ? 1 : 0;
    }
  }
  return n;
}

TEST(RenderParts, TwoHalvesRenderLikeTheWhole)
{
  ANISO_REQUIRE_DISPLAY();
  const vtkSmartPointer<vtkPolyData> whole = makeSphere(64, 32);
  RenderSettings one = sceneSettings();
  one.surface = whole;
  one.material = testMaterial();
  const RenderResult expected = renderOffscreen(one);

  RenderSettings two = sceneSettings();
  two.parts = {part("left", half(whole, true), testMaterial()),
               part("right", half(whole, false), testMaterial()),
               part("far away", moved(whole, {40.0, 0.0, 0.0}), testMaterial(), false)};
  ASSERT_GT(two.parts[0].surface->GetNumberOfCells(), 0);
  ASSERT_GT(two.parts[1].surface->GetNumberOfCells(), 0);
  ASSERT_EQ(two.parts[0].surface->GetNumberOfCells() + two.parts[1].surface->GetNumberOfCells(),
            whole->GetNumberOfCells());
  const RenderResult rendered = renderOffscreen(two);
  expectSameImage(rendered, expected, "halves");

  ASSERT_EQ(rendered.parts.size(), 3u);
  EXPECT_EQ(rendered.parts[0].name, "left");
  EXPECT_EQ(rendered.parts[2].name, "far away");
  EXPECT_FALSE(rendered.parts[2].visible);
  EXPECT_TRUE(rendered.parts[0].variant == expected.variant);
  EXPECT_TRUE(rendered.parts[1].variant == expected.variant);
  EXPECT_TRUE(rendered.variant == expected.variant);
  ASSERT_EQ(expected.parts.size(), 1u); // the one-part scene reports its part too
}

TEST(RenderParts, AnInstalledMaterialGoesOnEveryVisiblePart)
{
  ANISO_REQUIRE_DISPLAY();
  LitModelSettings lit;
  lit.model = LitModel::Ward;
  lit.lights = {parseLight("dir:-1,-2,1.5:1,0.9,0.8"), parseLight("point:1.5,-2,1.5:4")};
  const MaterialInstaller ward = litModelInstaller(lit);
  int installs = 0;
  const MaterialInstaller counted = [&](vtkActor* actor, vtkRenderer* renderer,
                                        const std::shared_ptr<EnvironmentLighting>& lighting)
  {
    ++installs;
    return ward(actor, renderer, lighting);
  };
  const vtkSmartPointer<vtkPolyData> whole = makeSphere(64, 32);
  RenderSettings one = sceneSettings();
  one.surface = whole;
  one.installMaterial = counted;
  const RenderResult expected = renderOffscreen(one);
  EXPECT_EQ(installs, 1);

  RenderSettings two = sceneSettings();
  two.installMaterial = counted;
  two.parts = {part("left", half(whole, true), testMaterial()),
               part("right", half(whole, false), testMaterial()),
               part("hidden", moved(whole, {40.0, 0.0, 0.0}), testMaterial(), false)};
  installs = 0;
  const RenderResult rendered = renderOffscreen(two);
  EXPECT_EQ(installs, 2); // the visible parts
  expectSameImage(rendered, expected, "installed");
}

TEST(RenderParts, TheCameraFitsTheVisiblePartsTogether)
{
  ANISO_REQUIRE_DISPLAY();
  constexpr int kWide = 96;
  const vtkSmartPointer<vtkPolyData> sphere = makeSphere(64, 32);
  RenderSettings s = sceneSettings();
  s.width = kWide;
  s.height = kWide;
  s.jitter = false;
  s.frames = 1;
  s.view.parallel = true;
  s.parts = {part("left", moved(sphere, {-1.5, 0.0, 0.0}), testMaterial()),
             part("right", moved(sphere, {1.5, 0.0, 0.0}), testMaterial())};
  const RenderResult both = renderOffscreen(s);

  // Parallel projection: the view's half height is the joint radius 2.5 times the margin.
  const double halfHeight = 2.5 * s.view.margin;
  const double expected = 2.0 * M_PI / (4.0 * halfHeight * halfHeight) * kWide * kWide;
  std::printf("both spheres: %lld covered pixels, %.1f expected\n",
              static_cast<long long>(both.coveredPixels), expected);
  EXPECT_NEAR(double(both.coveredPixels) / expected, 1.0, 0.02);
  EXPECT_EQ(coveredOnBorder(both.linear), 0);
  const int64_t left = covered(both.linear, 0, kWide / 2);
  const int64_t right = covered(both.linear, kWide / 2, kWide);
  EXPECT_NEAR(double(left) / double(right), 1.0, 0.02);

  // The right one hidden: the image of the left one alone, the camera fitting it.
  s.parts[1].visible = false;
  const RenderResult hidden = renderOffscreen(s);
  RenderSettings alone = s;
  alone.parts = {s.parts[0]};
  const RenderResult leftAlone = renderOffscreen(alone);
  expectSameImage(hidden, leftAlone, "hidden");
  const double expectedAlone =
      M_PI / (4.0 * s.view.margin * s.view.margin) * kWide * kWide; // radius 1, fitted
  EXPECT_NEAR(double(hidden.coveredPixels) / expectedAlone, 1.0, 0.02);
  EXPECT_EQ(coveredOnBorder(hidden.linear), 0);
}

// Appends the points, point attributes and triangles of SURFACE to MERGED.
void append(vtkPolyData* merged, vtkPolyData* surface)
{
  if (!merged->GetPoints())
  {
    vtkNew<vtkPoints> points;
    merged->SetPoints(points);
    vtkNew<vtkCellArray> polys;
    merged->SetPolys(polys);
    merged->GetPointData()->CopyAllocate(surface->GetPointData());
  }
  vtkPoints* points = merged->GetPoints();
  const vtkIdType first = points->GetNumberOfPoints();
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    points->InsertNextPoint(surface->GetPoint(p));
    merged->GetPointData()->CopyData(surface->GetPointData(), p, first + p);
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    std::vector<vtkIdType> cell;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      cell.push_back(first + ids->GetId(k));
    }
    merged->GetPolys()->InsertNextCell(vtkIdType(cell.size()), cell.data());
  }
}

TEST(RenderParts, ManyPartsRenderLikeTheirMaterialsMerged)
{
  ANISO_REQUIRE_DISPLAY();
  // More parts than a draw has texture units, of two lobes in turn: each material's textures
  // must be let go once its part is drawn, or later parts find no unit for their lookup table
  // and read another's. The reference: the spheres of each lobe merged into one part.
  constexpr int kSide = 15;
  const vtkSmartPointer<vtkPolyData> sphere = makeSphere(12, 6);
  MaterialSettings materials[2] = {testMaterial(), testMaterial()};
  materials[1].lobe = {30.0, 8.0};
  RenderSettings s = sceneSettings();
  s.frames = 1;
  vtkSmartPointer<vtkPolyData> merged[2] = {vtkSmartPointer<vtkPolyData>::New(),
                                            vtkSmartPointer<vtkPolyData>::New()};
  for (int i = 0; i < kSide * kSide; ++i)
  {
    const vtkSmartPointer<vtkPolyData> one =
        moved(sphere, glm::dvec3(2.5 * (i % kSide), 0.0, 2.5 * (i / kSide)));
    s.parts.push_back(part("sphere " + std::to_string(i + 1), one, materials[i % 2]));
    append(merged[i % 2], one);
  }
  const RenderResult rendered = renderOffscreen(s);
  RenderSettings two = sceneSettings();
  two.frames = 1;
  two.parts = {part("first lobe", merged[0], materials[0]),
               part("second lobe", merged[1], materials[1])};
  expectSameImage(rendered, renderOffscreen(two), "many");
}

TEST(RenderParts, PartsOfOneLobeShareTheirLookupTable)
{
  ANISO_REQUIRE_DISPLAY();
  // Lobes no other test of this executable uses.
  MaterialSettings a = testMaterial();
  a.lobe = {1234.0, 56.0};
  MaterialSettings b = testMaterial();
  b.lobe = {987.0, 65.0};
  MaterialSettings aTinted = a;
  aTinted.f0 = glm::dvec3(0.5, 0.6, 0.7); // another material of the same lobe
  const vtkSmartPointer<vtkPolyData> sphere = makeSphere(32, 16);
  RenderSettings s = sceneSettings();
  s.frames = 1;
  s.parts = {part("a", moved(sphere, {-2.0, 0.0, 0.0}), a), part("b", sphere, b),
             part("a tinted", moved(sphere, {2.0, 0.0, 0.0}), aTinted)};
  const LutCacheStats before = LutCache::shared().stats();
  renderOffscreen(s);
  const LutCacheStats after = LutCache::shared().stats();
  const uint64_t made = (after.bakes - before.bakes) + (after.diskHits - before.diskHits);
  std::printf("tables made %llu, memory hits %llu\n", static_cast<unsigned long long>(made),
              static_cast<unsigned long long>(after.memoryHits - before.memoryHits));
  EXPECT_EQ(made, 2u); // one a distinct lobe
  EXPECT_GE(after.memoryHits - before.memoryHits, 1u);
}

TEST(RenderParts, InvalidScenesAreRefusedNamingThePart)
{
  const vtkSmartPointer<vtkPolyData> sphere = makeSphere(16, 8);
  const auto message = [](const RenderSettings& s)
  {
    try
    {
      renderOffscreen(s);
    }
    catch (const Error& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  MaterialSettings bad = testMaterial();
  bad.samples = 0;
  RenderSettings s = sceneSettings();
  s.parts = {part("good", sphere, testMaterial()), part("bolt", sphere, bad)};
  EXPECT_EQ(message(s).rfind("part 'bolt': samples:", 0), 0u) << message(s);
  // A hidden part is not drawn: its material and surface are not looked at.
  s.parts[1].visible = false;
  s.parts[1].surface = nullptr;
  s.environment = nullptr;
  EXPECT_EQ(message(s).rfind("env:", 0), 0u) << message(s);
  s.parts[0].visible = false;
  EXPECT_EQ(message(s), "mesh: no surface to render (every part is hidden)");
  s.parts[0].visible = true;
  s.parts[0].surface = vtkSmartPointer<vtkPolyData>::New();
  EXPECT_EQ(message(s), "part 'good': no surface to render");
  s.surface = sphere;
  EXPECT_EQ(message(s), "mesh: give either a surface or parts, not both");
}
} // namespace
} // namespace aniso::test
