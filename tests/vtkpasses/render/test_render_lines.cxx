// Illuminated lines (vtkpasses/mesh/LineSet.h; docs/METHOD.md, "Lines"): a line set drawn by the
// materials' line variants, each against an independent reference.
//   - Banks under one directional light (LitModelMaterial) against the core's evaluation
//     (core/models shadeLitModel) in the line's frame, t the analytic tangent of the circle the
//     line follows at the pixel, n the part of the view perpendicular to t.
//   - The Ashikhmin-Shirley environment material (AnisoMaterial) against the CPU reference
//     integrator (core/reference) in the same frame, under the studio.
//   - Depth: a line in front of a surface shows, behind it is hidden, in one render.
//   - Width: the pixels covered, in pixels and in world units, against the ribbon's analytic
//     area on screen.
// The line: an arc of a circle of radius 1 (340 degrees of it, 256 segments) in a plane tilted
// 50 degrees from the view plane, so that both t and v vary along it. Each covered pixel is
// matched to the nearest of 4096 points of the analytic arc projected with the test's own
// camera model (pixelRay's inverse).
#include "core/env/environment.h"
#include "core/error.h"
#include "core/lights/light.h"
#include "core/models/models.h"
#include "core/models/sv_material.h"
#include "core/reference/reference_integrator.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/LineSet.h"
#include "vtkpasses/mesh/MeshValidation.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <memory>
#include <string>
#include <vector>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso::test
{
namespace
{
constexpr int kSize = 96;
constexpr int kSegments = 256;
constexpr double kArcStart = 10.0 * M_PI / 180.0;
constexpr double kArcEnd = 350.0 * M_PI / 180.0;
constexpr double kTilt = 50.0 * M_PI / 180.0;
// The pixels compared: those whose centre is within this many pixels of the line's. Across its
// width a line is shaded where the driver puts it: VTK's quads (ShaderHook.h, lineGeometryCode)
// at each pixel's own point, the hardware's wide lines (GL's rule: widened along the minor
// axis of the screen) with the values of the centre pixel of the column or row, which on a
// curve is not the nearest point of the line (measured on llvmpipe, which draws them: up to 10%
// off at 1.3 pixels from the centre where the arc turns fastest).
constexpr double kOnTheLine = 0.6;

// The arc's plane: e1 along X, e2 tilted from Z towards the camera side (+Y away from it).
const glm::dvec3 kE1(1.0, 0.0, 0.0);
const glm::dvec3 kE2(0.0, std::sin(kTilt), std::cos(kTilt));

glm::dvec3 arcPoint(double a)
{
  return std::cos(a) * kE1 + std::sin(a) * kE2;
}
glm::dvec3 arcTangent(double a)
{
  return -std::sin(a) * kE1 + std::cos(a) * kE2;
}

// The arc as a line set, through the loader's own sanitising (its tangents the line's).
vtkSmartPointer<vtkPolyData> arcLines()
{
  vtkNew<vtkPolyData> raw;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(kSegments + 1);
  for (int i = 0; i <= kSegments; ++i)
  {
    const glm::dvec3 p = arcPoint(kArcStart + (kArcEnd - kArcStart) * i / kSegments);
    lines->InsertCellPoint(points->InsertNextPoint(p.x, p.y, p.z));
  }
  raw->SetPoints(points);
  raw->SetLines(lines);
  MeshReport report;
  return sanitizeLines(raw, "arc", report);
}

// The camera every render here uses (in mesh coordinates), from the front (-Y).
CameraPlacement testCamera()
{
  return placeCamera(ViewSettings{}, glm::dvec3(0.0), 1.3);
}

// Pixel coordinates (x, y, row 0 at the top) of P and its depth along the view axis.
glm::dvec3 project(const CameraPlacement& camera, const glm::dvec3& p)
{
  const glm::dvec3 forward = glm::normalize(camera.focalPoint - camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.viewUp));
  const glm::dvec3 up = glm::cross(right, forward);
  const double t = std::tan(0.5 * camera.viewAngleDegrees * M_PI / 180.0);
  const glm::dvec3 d = p - camera.position;
  const double z = glm::dot(d, forward);
  const double sx = glm::dot(d, right) / (z * t);
  const double sy = glm::dot(d, up) / (z * t);
  return {(sx + 1.0) / 2.0 * kSize - 0.5, (1.0 - sy) / 2.0 * kSize - 0.5, z};
}

struct ArcSample
{
  double angle;
  glm::dvec3 pixel; // x, y, depth
};

std::vector<ArcSample> arcSamples(const CameraPlacement& camera)
{
  std::vector<ArcSample> samples;
  for (int i = 0; i < 4096; ++i)
  {
    const double a = kArcStart + (kArcEnd - kArcStart) * (i + 0.5) / 4096.0;
    samples.push_back({a, project(camera, arcPoint(a))});
  }
  return samples;
}

// The arc's angle nearest to pixel (x, y) on screen, and the distance in pixels.
std::pair<double, double> nearestAngle(const std::vector<ArcSample>& samples, int x, int y)
{
  double best = std::numeric_limits<double>::infinity();
  double angle = 0.0;
  for (const ArcSample& s : samples)
  {
    const double d = std::hypot(s.pixel.x - x, s.pixel.y - y);
    if (d < best)
    {
      best = d;
      angle = s.angle;
    }
  }
  return {angle, best};
}

// The line's shading frame at a pixel: t along the arc, n the view's part perpendicular to t.
glm::dvec3 lineNormal(const glm::dvec3& t, const glm::dvec3& v)
{
  return glm::normalize(v - glm::dot(v, t) * t);
}

RenderSettings lineScene(double width, LineWidthUnit unit)
{
  RenderSettings s;
  RenderPart part;
  part.name = "arc lines";
  part.surface = arcLines();
  part.lineStyle.width = width;
  part.lineStyle.unit = unit;
  s.parts.push_back(part);
  s.environment = std::make_shared<StudioEnvironment>();
  s.cubeSize = 64;
  s.display.background = BackgroundMode::Transparent;
  s.camera = testCamera();
  s.width = kSize;
  s.height = kSize;
  s.frames = 1;
  s.jitter = false;
  return s;
}

int covered(const Image& image)
{
  int count = 0;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      count += image.at(x, y, 3) > 0.0f ? 1 : 0;
    }
  }
  return count;
}

// Banks under one directional light, against shadeLitModel at every pixel on the line, drawn
// as the hardware's wide lines where it has them (3 pixels) and as VTK's quads (world units).
// The bound 2e-2 (measured on llvmpipe: 1.1e-2 in pixels over 196 pixels, 1.0e-3 in world
// units): the GPU interpolates the vertices' tangents along 256 chords, in float, and the
// hardware's lines shade a pixel at the point the rasteriser puts it (up to 0.6 pixels along the
// line from the nearest point, a turn of the tangent that the highlight's exponent of about 90
// magnifies). A wrong frame is far above it (measured with n the arc plane's normal instead of
// the view's part perpendicular to t: 0.116).
TEST(RenderLines, BanksUnderADirectionalLightMatchesTheCore)
{
  ANISO_REQUIRE_DISPLAY();
  LitModelSettings lit;
  lit.model = LitModel::Banks;
  lit.lights = {parseLight("dir:-1,-2,1.5:1,0.9,0.8")};
  SvTexel texel;
  texel.diffuse = {0.3, 0.2, 0.1};
  texel.specular = 0.6;
  texel.alphaX = texel.alphaY = 0.15;
  lit.maps = std::make_shared<const SvMaps>(uniformSvMaps(texel));
  // 3 pixels wide (the hardware's wide lines where it has them, as llvmpipe does), and 0.08
  // world units (about 3 pixels; always VTK's quads, through lineGeometryCode).
  for (const LineStyle style :
       {LineStyle{3.0, LineWidthUnit::Pixels}, LineStyle{0.08, LineWidthUnit::World}})
  {
    const char* what = style.unit == LineWidthUnit::World ? "world" : "pixels";
    RenderSettings s = lineScene(style.width, style.unit);
    s.parts[0].installMaterial = litModelInstaller(lit);
    const RenderResult result = renderOffscreen(s);
    EXPECT_EQ(nonFiniteValues(result.linear), 0);

    const CameraPlacement camera = testCamera();
    const std::vector<ArcSample> samples = arcSamples(camera);
    double diff = 0.0;
    double norm = 0.0;
    int pixels = 0;
    Image expectedImage(kSize, kSize, 4);
    for (int y = 0; y < kSize; ++y)
    {
      for (int x = 0; x < kSize; ++x)
      {
        if (result.linear.at(x, y, 3) < 1.0f)
        {
          continue;
        }
        const auto [angle, distance] = nearestAngle(samples, x, y);
        EXPECT_LT(distance, 2.5) << "pixel " << x << "," << y << " covered away from the line";
        if (distance > kOnTheLine)
        {
          continue;
        }
        const glm::dvec3 t = arcTangent(angle);
        const glm::dvec3 v = -pixelRay(camera, x, y, kSize, kSize).direction;
        const Frame frame = svShadingFrame(lineNormal(t, v), t, texel);
        const glm::dvec3 expected =
            shadeLitModel(lit.model, texel, frame, arcPoint(angle), v, lit.lights);
        for (int c = 0; c < 3; ++c)
        {
          const double d = result.linear.at(x, y, c) - expected[c];
          diff += d * d;
          norm += expected[c] * expected[c];
          expectedImage.at(x, y, c) = float(expected[c]);
        }
        expectedImage.at(x, y, 3) = 1.0f;
        ++pixels;
      }
    }
    const double error = std::sqrt(diff / norm);
    std::printf("Banks line (%s): relative L2 %.2e over %d pixels\n", what, error, pixels);
    EXPECT_GT(pixels, 150) << what;
    EXPECT_LT(error, 2e-2) << what;
    if (!(error < 2e-2))
    {
      keepImages(std::string("lines_banks_") + what, result.linear, expectedImage);
    }
  }
}

// The AS environment material on the line, against integrateSpecular in the line's frame at
// every pixel on the line (F0 = 1, no diffuse, the exact method, 16 x 32 samples). Bound 0.03
// (measured on llvmpipe: 0.019 over 196 pixels; the quasi-Monte-Carlo error of 512 samples and
// the tangent's placement as above); n turned 60 degrees about t from the view's part gives
// 0.95.
TEST(RenderLines, AshikhminShirleyEnvironmentMatchesTheReference)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings s = lineScene(3.0, LineWidthUnit::Pixels);
  MaterialSettings& m = s.parts[0].material;
  m.lobe = {200.0, 20.0};
  m.f0 = glm::dvec3(1.0);
  m.albedo = glm::dvec3(0.0);
  m.method = SpecularMethod::Exact;
  m.filtered = false;
  m.halfVectors = HalfVectorSource::Shader;
  m.samples = 16;
  s.frames = 32;
  s.cubeSize = 256;
  const RenderResult result = renderOffscreen(s);
  EXPECT_EQ(nonFiniteValues(result.linear), 0);
  ASSERT_EQ(result.parts.size(), 1u);
  EXPECT_TRUE(result.parts[0].variant.lines);

  const CameraPlacement camera = testCamera();
  const std::vector<ArcSample> samples = arcSamples(camera);
  const StudioEnvironment env;
  ReferenceOptions options;
  options.relativeTolerance = 4e-3;
  std::vector<Compared> pixels;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      if (result.linear.at(x, y, 3) < 1.0f)
      {
        continue;
      }
      const auto [angle, distance] = nearestAngle(samples, x, y);
      if (distance > kOnTheLine)
      {
        continue;
      }
      const glm::dvec3 t = arcTangent(angle);
      const glm::dvec3 v = -pixelRay(camera, x, y, kSize, kSize).direction;
      const Frame frame = Frame::fromNormalTangent(lineNormal(t, v), t);
      pixels.push_back({x, y, integrateSpecular(m.lobe, m.f0, frame, v, env, options).value});
    }
  }
  const double error = relativeL2(result.linear, pixels);
  std::printf("AS environment line: relative L2 %.4f over %zu pixels\n", error, pixels.size());
  EXPECT_GT(pixels.size(), 150u);
  EXPECT_LT(error, 0.03);
}

// A plate at y = 0 over the left half of the view: the arc's points with y < 0 are in front of
// it, those with y > 0 behind. In the render of both, a line pixel in front equals the line
// drawn alone, one behind equals the plate drawn alone (the same camera throughout).
TEST(RenderLines, LinesAreDepthTestedWithSurfaces)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings lineOnly = lineScene(3.0, LineWidthUnit::Pixels);
  lineOnly.parts[0].material.f0 = glm::dvec3(1.0);
  lineOnly.parts[0].material.albedo = glm::dvec3(0.0);
  lineOnly.parts[0].material.samples = 4;

  vtkNew<vtkPolyData> plate;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-2.0, 0.0, -2.0);
  points->InsertNextPoint(-0.1, 0.0, -2.0);
  points->InsertNextPoint(-0.1, 0.0, 2.0);
  points->InsertNextPoint(-2.0, 0.0, 2.0);
  plate->SetPoints(points);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType first[3] = {0, 1, 2};
  const vtkIdType second[3] = {0, 2, 3};
  triangles->InsertNextCell(3, first);
  triangles->InsertNextCell(3, second);
  plate->SetPolys(triangles);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (int i = 0; i < 4; ++i)
  {
    normals->InsertNextTuple3(0.0, -1.0, 0.0);
  }
  plate->GetPointData()->SetNormals(normals);
  RenderPart platePart;
  platePart.name = "plate";
  platePart.surface = plate;
  platePart.material.f0 = glm::dvec3(0.04);
  platePart.material.albedo = {0.1, 0.6, 0.2};
  platePart.material.samples = 4;

  RenderSettings plateOnly = lineOnly;
  plateOnly.parts = {platePart};
  RenderSettings both = lineOnly;
  both.parts.push_back(platePart);

  const Image line = renderOffscreen(lineOnly).linear;
  const Image alone = renderOffscreen(plateOnly).linear;
  const Image scene = renderOffscreen(both).linear;

  const CameraPlacement camera = testCamera();
  const std::vector<ArcSample> samples = arcSamples(camera);
  int inFront = 0;
  int hidden = 0;
  int distinct = 0; // hidden pixels where line and plate differ: the test can see the order
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      if (line.at(x, y, 3) < 1.0f || alone.at(x, y, 3) < 1.0f)
      {
        continue;
      }
      const double angle = nearestAngle(samples, x, y).first;
      const double depth = arcPoint(angle).y; // the plate is at y = 0
      if (std::abs(depth) < 0.1)
      {
        continue; // where the line pierces the plate
      }
      const Image& expected = depth < 0.0 ? line : alone;
      bool same = true;
      bool differs = false;
      for (int c = 0; c < 3; ++c)
      {
        const float e = expected.at(x, y, c);
        same = same && std::abs(scene.at(x, y, c) - e) <= 1e-4f * std::max(1.0f, std::abs(e));
        differs = differs || std::abs(line.at(x, y, c) - alone.at(x, y, c)) >
                                 0.1f * std::max(line.at(x, y, c), alone.at(x, y, c));
      }
      EXPECT_TRUE(same) << "pixel " << x << "," << y << (depth < 0.0 ? " in front" : " behind");
      (depth < 0.0 ? inFront : hidden) += 1;
      distinct += depth > 0.0 && differs ? 1 : 0;
    }
  }
  std::printf("depth: %d line pixels in front of the plate, %d hidden (%d distinct)\n", inFront,
              hidden, distinct);
  EXPECT_GT(inFront, 30);
  EXPECT_GT(hidden, 30);
  EXPECT_GT(distinct, 30);
}

// The pixels a line covers: its length on screen times its width there (a constant in pixels;
// WIDTH / depth times the focal length in pixels in world units), summed over the arc.
double ribbonArea(double width, LineWidthUnit unit)
{
  const CameraPlacement camera = testCamera();
  const double focal = 0.5 * kSize / std::tan(0.5 * camera.viewAngleDegrees * M_PI / 180.0);
  double area = 0.0;
  const int steps = 4096;
  for (int i = 0; i < steps; ++i)
  {
    const double a0 = kArcStart + (kArcEnd - kArcStart) * i / steps;
    const double a1 = kArcStart + (kArcEnd - kArcStart) * (i + 1) / steps;
    const glm::dvec3 p0 = project(camera, arcPoint(a0));
    const glm::dvec3 p1 = project(camera, arcPoint(a1));
    const double length = std::hypot(p1.x - p0.x, p1.y - p0.y);
    const double depth = 0.5 * (p0.z + p1.z);
    area += length * (unit == LineWidthUnit::Pixels ? width : width * focal / depth);
  }
  return area;
}

// Bound 12%: the pixel grid's coverage of a ribbon a few pixels wide, and the overlaps and gaps
// of the quads at the polyline's joints (a width in pixels drawn as the hardware's wide lines
// where it has them).
TEST(RenderLines, WidthsInPixelsAndWorldUnitsCoverTheirArea)
{
  ANISO_REQUIRE_DISPLAY();
  struct Case
  {
    double width;
    LineWidthUnit unit;
  };
  for (const Case c : {Case{4.0, LineWidthUnit::Pixels}, Case{0.06, LineWidthUnit::World},
                       Case{0.12, LineWidthUnit::World}})
  {
    RenderSettings s = lineScene(c.width, c.unit);
    s.parts[0].material.samples = 1;
    const int count = covered(renderOffscreen(s).linear);
    const double expected = ribbonArea(c.width, c.unit);
    std::printf("width %g %s: %d pixels covered, ribbon area %.0f\n", c.width,
                c.unit == LineWidthUnit::World ? "world" : "pixels", count, expected);
    EXPECT_NEAR(count / expected, 1.0, 0.12) << c.width;
  }
}

TEST(RenderLines, InvalidWidthIsRefused)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings s = lineScene(0.0, LineWidthUnit::Pixels);
  EXPECT_THROW(renderOffscreen(s), Error);
}
} // namespace
} // namespace aniso::test
