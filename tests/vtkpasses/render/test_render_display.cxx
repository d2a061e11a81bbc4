// Render tests of what surrounds the material: the display transform, the backgrounds and the
// progressive accumulation pass's bookkeeping.
//  - The displayed 8-bit image equals the display transform (exposure, ACES / Reinhard / clamp,
//    sRGB), evaluated here on the CPU from its published formulas, of the linear image the pass
//    read back, within one 8-bit step.
//  - Background pixels hold the environment's radiance along each pixel's analytic view ray
//    (StudioEnvironment::radiance on the CPU, rotated as documented), a uniform colour, or
//    nothing with alpha 0; surfaces have alpha 1.
//  - Accumulation stops at the target frame count, starts over when the camera, the material
//    or the environment rotation change, and not when only the exposure changes.
//  - A frame drawn in bands (one band per render) accumulates the same mean as whole frames:
//    the images agree to float rounding whatever the band counts of the frames, and with bands
//    cut by the rows' measured cost; a band count changed within a frame applies from the next
//    frame, and a change within a frame starts the mean over. Bands take equal shares of given
//    row costs (worked out by hand), equal rows without them.
//  - Moving slider values (n_u, F0, albedo, samples, exposure) keeps the compiled shader
//    program; changing the specular method builds another one.
//  - With an error target, pixels that froze at a checkpoint keep their mean to the bit while
//    the others go on changing, the estimate then counts them (core/quality/error_estimate.h);
//    and every material (the anisotropic one, a lit model, LEADR, the microstructure) discards
//    the fragments of the pixels FROZEN_PIXELS marks (a mask of the left half: the background
//    there, the sphere on the right).
#include "core/error.h"
#include "core/image/image.h"
#include "core/leadr/leadr.h"
#include "core/lights/light.h"
#include "core/parameters/parameters.h"
#include "core/quality/error_estimate.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/SurfaceModelSettings.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkDataSetMapper.h>
#include <vtkInformation.h>
#include <vtkInformationObjectBaseKey.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkOpenGLState.h>
#include <vtkPolyData.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtkUnsignedCharArray.h>
#include <vtk_glew.h>

namespace aniso::test
{
namespace
{
double toneMap(double x, ToneMapping mapping)
{
  switch (mapping)
  {
  case ToneMapping::Aces:
    return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  case ToneMapping::Reinhard:
    return x / (1.0 + x);
  case ToneMapping::Clamp:
    return std::min(x, 1.0);
  }
  return 0.0;
}

double encodeSrgb(double c)
{
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

RenderSettings smallSphere()
{
  RenderSettings s;
  s.surface = makeSphere(64, 32);
  s.environment = std::make_shared<StudioEnvironment>();
  s.cubeSize = 128;
  s.material.lobe = {1000.0, 100.0};
  s.material.samples = 4;
  s.width = 48;
  s.height = 40;
  s.frames = 1;
  s.jitter = false;
  return s;
}

// The 8-bit display value the CPU expects for linear value x.
double expectedDisplay(double x, const DisplaySettings& d)
{
  return encodeSrgb(toneMap(std::max(x, 0.0) * std::exp2(d.exposureEV), d.toneMapping));
}

TEST(RenderDisplay, DisplayedImageIsTheDisplayTransformOfTheLinearOne)
{
  ANISO_REQUIRE_DISPLAY();
  for (ToneMapping mapping : {ToneMapping::Aces, ToneMapping::Reinhard, ToneMapping::Clamp})
  {
    RenderSettings s = smallSphere();
    s.display.toneMapping = mapping;
    s.display.exposureEV = 0.7;
    const RenderResult r = renderOffscreen(s);
    ASSERT_EQ(nonFiniteValues(r.linear), 0);
    double worst = 0.0;
    for (int y = 0; y < s.height; ++y)
    {
      for (int x = 0; x < s.width; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          const double expected = expectedDisplay(r.linear.at(x, y, c), s.display);
          worst = std::max(worst, std::abs(r.display.at(x, y, c) - expected));
        }
        EXPECT_EQ(r.display.at(x, y, 3), 1.0f);
      }
    }
    EXPECT_LE(worst, 1.0 / 255.0 + 1e-6) << "tone mapping " << static_cast<int>(mapping);
  }
}

TEST(RenderDisplay, TransparentBackgroundKeepsCoverageInAlpha)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings s = smallSphere();
  s.display.background = BackgroundMode::Transparent;
  const RenderResult r = renderOffscreen(s);
  const CameraPlacement camera = placeCamera(s.view, glm::dvec3(0.0), 1.0);
  int compared = 0;
  for (int y = 0; y < s.height; ++y)
  {
    for (int x = 0; x < s.width; ++x)
    {
      const auto hit = hitUnitSphere(pixelRay(camera, x, y, s.width, s.height));
      const float alpha = r.linear.at(x, y, 3);
      // Pixels near the silhouette may go either way between the mesh and the sphere.
      const glm::dvec3 d = pixelRay(camera, x, y, s.width, s.height).direction;
      const double closest = glm::length(glm::cross(d, camera.position));
      if (std::abs(closest - 1.0) < 0.05)
      {
        continue;
      }
      ++compared;
      EXPECT_EQ(alpha, hit ? 1.0f : 0.0f) << x << "," << y;
      EXPECT_EQ(r.display.at(x, y, 3), alpha);
      if (!hit)
      {
        for (int c = 0; c < 3; ++c)
        {
          EXPECT_EQ(r.linear.at(x, y, c), 0.0f);
        }
      }
    }
  }
  EXPECT_GT(compared, s.width * s.height / 2);
}

// Background radiance against the environment along the analytic pixel rays.
double backgroundError(double rotationDegrees)
{
  RenderSettings s = smallSphere();
  s.cubeSize = 256;
  s.environmentRotationDegrees = rotationDegrees;
  s.view.direction = viewDirectionFromAngles(30.0, 20.0);
  const RenderResult r = renderOffscreen(s);
  const CameraPlacement camera = placeCamera(s.view, glm::dvec3(0.0), 1.0);
  const StudioEnvironment env;
  const double a = -rotationDegrees * M_PI / 180.0;
  double error = 0.0;
  double norm = 0.0;
  for (int y = 0; y < s.height; ++y)
  {
    for (int x = 0; x < s.width; ++x)
    {
      const Ray ray = pixelRay(camera, x, y, s.width, s.height);
      if (r.linear.at(x, y, 3) != 0.0f ||
          glm::length(glm::cross(ray.direction, camera.position)) < 1.1)
      {
        continue; // the sphere or its silhouette
      }
      const glm::dvec3 d = ray.direction;
      const glm::dvec3 turned(std::cos(a) * d.x - std::sin(a) * d.y,
                              std::sin(a) * d.x + std::cos(a) * d.y, d.z);
      const glm::dvec3 expected = env.radiance(turned);
      for (int c = 0; c < 3; ++c)
      {
        error += std::pow(r.linear.at(x, y, c) - expected[c], 2);
        norm += expected[c] * expected[c];
      }
    }
  }
  return std::sqrt(error / norm);
}

TEST(RenderDisplay, EnvironmentBackgroundFollowsTheViewRaysAndTheRotation)
{
  ANISO_REQUIRE_DISPLAY();
  // Bound: bilinear lookups in a 256^2 cube of the smooth studio (measured below 0.5%);
  // a wrong face orientation or rotation sense gives tens of percent.
  const double straight = backgroundError(0.0);
  const double turned = backgroundError(75.0);
  std::printf("background relative L2: %.4f unrotated, %.4f rotated by 75 degrees\n", straight,
              turned);
  EXPECT_LT(straight, 0.02);
  EXPECT_LT(turned, 0.02);
}

TEST(RenderDisplay, ColorBackgroundIsTheGivenRadiance)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings s = smallSphere();
  s.display.background = BackgroundMode::Color;
  s.display.backgroundColor = {0.25, 0.5, 2.0};
  const RenderResult r = renderOffscreen(s);
  EXPECT_EQ(r.linear.at(0, 0, 0), 0.25f);
  EXPECT_EQ(r.linear.at(0, 0, 1), 0.5f);
  EXPECT_EQ(r.linear.at(0, 0, 2), 2.0f);
  EXPECT_EQ(r.linear.at(0, 0, 3), 0.0f);
}

// A scene built from the public classes, as an application would.
struct Scene
{
  std::shared_ptr<EnvironmentLighting> lighting;
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkOpenGLRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkAnisoAccumulationPass> pass;
  std::unique_ptr<AnisoMaterial> material;
  vtkShaderProgram* lastProgram = nullptr;

  Scene()
  {
    lighting = std::make_shared<EnvironmentLighting>(std::make_shared<StudioEnvironment>(), 64);
    mapper->SetInputData(makeSphere(32, 16));
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    window->SetSize(32, 32);
    window->AddRenderer(renderer);
    renderer->GetActiveCamera()->SetPosition(0.0, -5.0, 0.0);
    renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
    renderer->ResetCamera();
    pass->SetDelegatePass(steps);
    pass->SetLighting(lighting);
    pass->SetTargetFrames(3);
    renderer->SetPass(pass);
    MaterialSettings settings;
    settings.samples = 2;
    material = std::make_unique<AnisoMaterial>(lighting, settings);
    material->apply(actor, renderer);
    mapper->AddObserver(vtkCommand::UpdateShaderEvent, this, &Scene::onUpdateShader);
  }

  void onUpdateShader(vtkObject*, unsigned long, void* program)
  {
    lastProgram = static_cast<vtkShaderProgram*>(program);
  }

  int render()
  {
    if (scissorOff)
    {
      // As a window may leave it (a QOpenGLWidget's does): the pass must not rely on it.
      window->MakeCurrent();
      vtkOpenGLRenderWindow::SafeDownCast(window)->GetState()->vtkglDisable(GL_SCISSOR_TEST);
    }
    window->Render();
    return pass->GetAccumulatedFrames();
  }
  bool scissorOff = false;
};

TEST(RenderAccumulation, StopsAtTheTargetAndStartsOverOnChanges)
{
  ANISO_REQUIRE_DISPLAY();
  Scene scene;
  EXPECT_EQ(scene.render(), 1);
  EXPECT_EQ(scene.render(), 2);
  EXPECT_EQ(scene.render(), 3);
  EXPECT_TRUE(scene.pass->IsConverged());
  EXPECT_EQ(scene.render(), 3); // converged: shown again, not drawn again

  DisplaySettings brighter = scene.pass->GetDisplaySettings();
  brighter.exposureEV = 1.0;
  scene.pass->SetDisplaySettings(brighter);
  EXPECT_EQ(scene.render(), 3); // the display transform is applied to the same mean

  MaterialSettings settings = scene.material->settings();
  settings.f0 = {0.5, 0.5, 0.5};
  scene.material->setSettings(settings);
  EXPECT_EQ(scene.render(), 1);
  EXPECT_EQ(scene.render(), 2);

  scene.renderer->GetActiveCamera()->Azimuth(10.0);
  EXPECT_EQ(scene.render(), 1);

  scene.lighting->setRotationDegrees(30.0);
  EXPECT_EQ(scene.render(), 1);
  EXPECT_EQ(scene.render(), 2);
}

// Largest absolute difference between two images of the same size (infinity otherwise).
double largestDifference(const Image& a, const Image& b)
{
  if (a.width != b.width || a.height != b.height || a.data.size() != b.data.size() ||
      a.data.empty())
  {
    return INFINITY;
  }
  double largest = 0.0;
  for (std::size_t i = 0; i < a.data.size(); ++i)
  {
    largest = std::max(largest, double(std::fabs(a.data[i] - b.data[i])));
  }
  return largest;
}

TEST(RenderAccumulation, FramesInBandsAccumulateTheSameMean)
{
  ANISO_REQUIRE_DISPLAY();
  // Rows not a multiple of the band counts; jitter on (the default), so every frame differs.
  Scene whole;
  whole.window->SetSize(40, 37);
  for (int frame = 1; frame <= 3; ++frame)
  {
    ASSERT_EQ(whole.render(), frame);
  }
  const Image reference = whole.pass->ReadAccumulation();
  ASSERT_FALSE(reference.data.empty());

  Scene banded;
  banded.scissorOff = true;
  banded.window->SetSize(40, 37);
  banded.pass->SetFrameBands(3);
  EXPECT_EQ(banded.render(), 0);
  EXPECT_EQ(banded.pass->GetNextBand(), 1);
  // Within a frame a new count waits for the next frame.
  banded.pass->SetFrameBands(1);
  EXPECT_EQ(banded.render(), 0);
  EXPECT_EQ(banded.pass->GetNextBand(), 2);
  EXPECT_EQ(banded.render(), 1);
  EXPECT_EQ(banded.pass->GetNextBand(), 0);
  EXPECT_EQ(banded.render(), 2); // one band: a whole frame
  banded.pass->SetFrameBands(2);
  EXPECT_EQ(banded.render(), 2);
  EXPECT_EQ(banded.pass->GetNextBand(), 1);
  EXPECT_EQ(banded.render(), 3);
  EXPECT_TRUE(banded.pass->IsConverged());
  EXPECT_LE(largestDifference(banded.pass->ReadAccumulation(), reference), 1e-6);
  // The band's scissor does not outlive its frame: a whole frame after banded ones covers the
  // whole image, as the same frames drawn whole do.
  banded.pass->SetFrameBands(1);
  banded.pass->SetTargetFrames(4);
  whole.pass->SetTargetFrames(4);
  EXPECT_EQ(banded.render(), 4);
  EXPECT_EQ(whole.render(), 4);
  EXPECT_LE(largestDifference(banded.pass->ReadAccumulation(), whole.pass->ReadAccumulation()),
            1e-6);

  // Bands cut by the measured cost of the rows (after the first banded frame) cover the frame
  // as well.
  Scene measured;
  measured.window->SetSize(40, 37);
  measured.pass->SetFrameBands(3);
  for (int render = 0; render < 3 * 3; ++render)
  {
    measured.render();
  }
  ASSERT_TRUE(measured.pass->IsConverged());
  EXPECT_EQ(measured.pass->GetRowCosts().size(), 37u);
  EXPECT_LE(largestDifference(measured.pass->ReadAccumulation(), reference), 1e-6);
}

// A band leaves out the parts wholly above or below its rows, and the mean is that of whole
// frames: four spheres stacked one above the other, each its own actor and material.
TEST(RenderAccumulation, BandsDrawOnlyThePartsInTheirRows)
{
  ANISO_REQUIRE_DISPLAY();
  const auto stacked = [](Scene& scene, std::vector<std::unique_ptr<AnisoMaterial>>& materials,
                          std::vector<vtkSmartPointer<vtkActor>>& actors)
  {
    scene.renderer->RemoveActor(scene.actor);
    for (int k = 0; k < 4; ++k)
    {
      vtkSmartPointer<vtkPolyData> sphere = makeSphere(24, 12);
      vtkPoints* points = sphere->GetPoints();
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3];
        points->GetPoint(i, p);
        points->SetPoint(i, p[0], p[1], p[2] + 2.5 * (k - 1.5));
      }
      vtkNew<vtkOpenGLPolyDataMapper> mapper;
      mapper->SetInputData(sphere);
      auto actor = vtkSmartPointer<vtkActor>::New();
      actor->SetMapper(mapper);
      scene.renderer->AddActor(actor);
      MaterialSettings settings;
      settings.samples = 2;
      settings.f0 = glm::dvec3(0.3 + 0.2 * k, 0.5, 0.9 - 0.2 * k);
      materials.push_back(std::make_unique<AnisoMaterial>(scene.lighting, settings));
      materials.back()->apply(actor, scene.renderer);
      actors.push_back(actor);
    }
    scene.window->SetSize(24, 64);
    scene.renderer->ResetCamera();
  };
  Scene whole;
  std::vector<std::unique_ptr<AnisoMaterial>> wholeMaterials;
  std::vector<vtkSmartPointer<vtkActor>> wholeActors;
  stacked(whole, wholeMaterials, wholeActors);
  for (int frame = 1; frame <= 3; ++frame)
  {
    ASSERT_EQ(whole.render(), frame);
  }
  EXPECT_EQ(whole.pass->GetBandRenderedProps(), 4);

  Scene banded;
  std::vector<std::unique_ptr<AnisoMaterial>> bandedMaterials;
  std::vector<vtkSmartPointer<vtkActor>> bandedActors;
  stacked(banded, bandedMaterials, bandedActors);
  banded.pass->SetFrameBands(4);
  int fewest = 4;
  int most = 0;
  // The first frame's bands are cut by the rows' share of the geometry; later ones by their
  // measured costs (which may give one band every sphere), so only the first frame's are
  // checked for what they leave out.
  for (int render = 0; render < 4; ++render)
  {
    banded.render();
    fewest = std::min(fewest, banded.pass->GetBandRenderedProps());
    most = std::max(most, banded.pass->GetBandRenderedProps());
  }
  EXPECT_EQ(banded.pass->GetAccumulatedFrames(), 1);
  for (int render = 0; render < 40 && !banded.pass->IsConverged(); ++render)
  {
    banded.render();
  }
  ASSERT_TRUE(banded.pass->IsConverged());
  // No band of about a quarter of the rows reaches all four spheres (bands above or below
  // every sphere draw none).
  EXPECT_LT(most, 4);
  EXPECT_LT(fewest, most);
  EXPECT_LE(largestDifference(banded.pass->ReadAccumulation(), whole.pass->ReadAccumulation()),
            1e-6);
}

TEST(RenderAccumulation, BandsTakeEqualSharesOfTheRowsCost)
{
  ANISO_REQUIRE_DISPLAY();
  Scene scene;
  scene.window->SetSize(40, 40);
  // Rows 10..29 (GL) cost 9 each, the 20 others 1 each: 200 in all, a third is 66.7. From the
  // top, the first band takes rows until their sum reaches 66.7: rows 39..30 (10) and the costly
  // 29..23 (63), 73; the second until 133.3: rows 22..16, 136; the third the rest, rows 15..0.
  std::vector<double> costs(40, 1.0);
  for (int row = 10; row < 30; ++row)
  {
    costs[std::size_t(row)] = 9.0;
  }
  scene.pass->SetRowCosts(costs);
  scene.pass->SetFrameBands(3);
  scene.render();
  const std::vector<int>& edges = scene.pass->GetBandEdges();
  ASSERT_EQ(edges.size(), 4u);
  EXPECT_EQ(edges[0], 40);
  EXPECT_EQ(edges[1], 23);
  EXPECT_EQ(edges[2], 16);
  EXPECT_EQ(edges[3], 0);
  // Without measured costs (another height), bands of equal rows: 40 / 3 -> 14, 13, 13.
  Scene uniform;
  uniform.window->SetSize(40, 40);
  uniform.pass->SetRowCosts(std::vector<double>(12, 1.0));
  uniform.pass->SetFrameBands(3);
  uniform.render();
  const std::vector<int>& even = uniform.pass->GetBandEdges();
  ASSERT_EQ(even.size(), 4u);
  EXPECT_EQ(even[0] - even[1] + even[1] - even[2] + even[2] - even[3], 40);
  EXPECT_LE(std::abs((even[0] - even[1]) - (even[2] - even[3])), 1);
}

// Edges of BANDS bands cut from the top at equal shares of the weights (the documented rule).
std::vector<int> cutByWeights(const std::vector<double>& weights, int bands)
{
  const int height = static_cast<int>(weights.size());
  double total = 0.0;
  for (double w : weights)
  {
    total += w;
  }
  std::vector<int> edges{height};
  double sum = 0.0;
  int row = height;
  for (int b = 1; b < bands; ++b)
  {
    while (row - 1 >= bands - b && sum < total * b / bands)
    {
      sum += weights[std::size_t(--row)];
    }
    edges.push_back(row);
  }
  edges.push_back(0);
  return edges;
}

TEST(RenderAccumulation, MeasuredRowCostsBelongToTheirViewAndRun)
{
  ANISO_REQUIRE_DISPLAY();
  Scene scene;
  scene.window->SetSize(40, 40);
  scene.pass->SetTargetFrames(0);
  // Costs given for any view, far above what a band of this scene costs (seconds): the run's
  // first frame replaces them instead of averaging with them.
  scene.pass->SetRowCosts(std::vector<double>(40, 1000.0));
  scene.pass->SetFrameBands(3);
  for (int band = 0; band < 3; ++band)
  {
    scene.render();
  }
  ASSERT_EQ(scene.pass->GetAccumulatedFrames(), 1);
  const std::vector<double> first = scene.pass->GetRowCosts();
  ASSERT_EQ(first.size(), 40u);
  for (double cost : first)
  {
    EXPECT_LT(cost, 1.0);
  }

  // The camera moves back: the sphere now covers the middle third of the rows. The next frame is
  // cut by the rows' share of the geometry, not by costs measured in the view before: the
  // middle band, all sphere, takes fewer rows than the two holding background (bands of equal
  // rows would be 14, 13, 13).
  scene.renderer->GetActiveCamera()->Zoom(0.4);
  scene.render();
  ASSERT_EQ(scene.pass->GetNextBand(), 1);
  const std::vector<int> moved = scene.pass->GetBandEdges();
  ASSERT_EQ(moved.size(), 4u);
  const int top = moved[0] - moved[1];
  const int middle = moved[1] - moved[2];
  const int bottom = moved[2] - moved[3];
  EXPECT_LT(middle, top);
  EXPECT_LT(middle, bottom);
  EXPECT_LE(std::abs(top - bottom), 2) << "the sphere is in the middle";
  // In the view they were measured in, the costs alone cut the bands.
  for (int band = 1; band < 3; ++band)
  {
    scene.render();
  }
  const std::vector<double> second = scene.pass->GetRowCosts();
  scene.render();
  EXPECT_EQ(scene.pass->GetBandEdges(), cutByWeights(second, 3));
}

TEST(RenderAccumulation, ANewSizesFirstBandsShowThePreviousMeanBelow)
{
  ANISO_REQUIRE_DISPLAY();
  // A window at half size (as while things move), one whole frame, what it displays.
  Scene scene;
  scene.window->SetSize(20, 20);
  scene.pass->SetTargetFrames(0);
  ASSERT_EQ(scene.render(), 1);
  vtkNew<vtkUnsignedCharArray> small;
  scene.window->GetRGBACharPixelData(0, 0, 19, 19, 0, small);
  // Back to full size, the first frame in 4 bands: after its top band, the rows below show the
  // half-size picture scaled up (each of its pixels over 2 x 2), not an empty framebuffer.
  scene.window->SetSize(40, 40);
  scene.pass->SetFrameBands(4);
  ASSERT_EQ(scene.render(), 0);
  const int drawnFrom = scene.pass->GetBandEdges()[1];
  ASSERT_GT(drawnFrom, 4);
  vtkNew<vtkUnsignedCharArray> large;
  scene.window->GetRGBACharPixelData(0, 0, 39, 39, 0, large);
  int differing = 0;
  int lit = 0;
  for (int y = 0; y < drawnFrom; ++y)
  {
    for (int x = 0; x < 40; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const int shown = large->GetValue((y * 40 + x) * 4 + c);
        const int before = small->GetValue(((y / 2) * 20 + x / 2) * 4 + c);
        differing += shown != before ? 1 : 0;
        lit += shown > 0 ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(differing, 0) << "of " << drawnFrom * 40 * 3 << " values";
  EXPECT_GT(lit, drawnFrom * 40) << "the picture below is not dark";
  // Once the frame is whole, all of it is the new size's.
  for (int band = 1; band < 4; ++band)
  {
    scene.render();
  }
  EXPECT_EQ(scene.pass->GetAccumulatedFrames(), 1);
}

TEST(RenderAccumulation, ChangeWithinABandedFrameStartsOver)
{
  ANISO_REQUIRE_DISPLAY();
  Scene scene;
  scene.pass->SetFrameBands(4);
  for (int band = 0; band < 4; ++band)
  {
    scene.render();
  }
  EXPECT_EQ(scene.pass->GetAccumulatedFrames(), 1);
  scene.render();
  EXPECT_EQ(scene.pass->GetNextBand(), 1);
  scene.renderer->GetActiveCamera()->Azimuth(10.0);
  // The mean and the frame in progress are dropped: this render is the new first frame's top.
  EXPECT_EQ(scene.render(), 0);
  EXPECT_EQ(scene.pass->GetNextBand(), 1);
}

TEST(RenderAccumulation, SliderValuesNeverRebuildTheShader)
{
  ANISO_REQUIRE_DISPLAY();
  Scene scene;
  scene.render();
  vtkShaderProgram* first = scene.lastProgram;
  ASSERT_NE(first, nullptr);
  MaterialSettings settings = scene.material->settings();
  settings.lobe = {20000.0, 70.0};
  settings.f0 = {0.2, 0.3, 0.4};
  settings.albedo = {0.5, 0.5, 0.5};
  settings.samples = 7;
  settings.heightScale = 0.1;
  scene.material->setSettings(settings);
  scene.lighting->setRotationDegrees(45.0);
  scene.render();
  EXPECT_EQ(scene.lastProgram, first);
  EXPECT_EQ(first->GetHandle(), scene.lastProgram->GetHandle());

  settings.method = SpecularMethod::SplitSum;
  scene.material->setSettings(settings);
  scene.render();
  EXPECT_NE(scene.lastProgram, first);
}
// A second mapper the material serves (AnisoMaterial::addMapper, as a part's stand-in mapper is):
// swapped in on the actor, it draws the same geometry to the same converged mean as the first
// mapper (an identity: identical values), shaded by the material (VTK's own shading, with the
// material detached, gives another picture); swapped back, the first mapper draws its picture
// again. A mapper that is not an OpenGL polydata mapper, or one given before the material is on
// an actor, is refused.
TEST(RenderAccumulation, ASecondMapperSwappedInIsShadedAlike)
{
  ANISO_REQUIRE_DISPLAY();
  Scene first;
  for (int frame = 1; frame <= 3; ++frame)
  {
    ASSERT_EQ(first.render(), frame);
  }
  const Image expected = first.pass->ReadAccumulation();
  ASSERT_FALSE(expected.data.empty());

  Scene swapped;
  vtkNew<vtkOpenGLPolyDataMapper> other;
  other->SetInputData(makeSphere(32, 16));
  swapped.material->addMapper(other);
  swapped.actor->SetMapper(other);
  for (int frame = 1; frame <= 3; ++frame)
  {
    ASSERT_EQ(swapped.render(), frame);
  }
  EXPECT_EQ(largestDifference(swapped.pass->ReadAccumulation(), expected), 0.0);

  swapped.actor->SetMapper(swapped.mapper);
  for (int frame = 1; frame <= 3; ++frame)
  {
    ASSERT_EQ(swapped.render(), frame);
  }
  EXPECT_EQ(largestDifference(swapped.pass->ReadAccumulation(), expected), 0.0);

  Scene unshaded;
  unshaded.material->detach();
  for (int frame = 1; frame <= 3; ++frame)
  {
    ASSERT_EQ(unshaded.render(), frame);
  }
  EXPECT_GT(largestDifference(unshaded.pass->ReadAccumulation(), expected), 0.01);

  vtkNew<vtkDataSetMapper> notOpenGl;
  EXPECT_THROW(swapped.material->addMapper(notOpenGl), Error);
  AnisoMaterial loose(swapped.lighting);
  EXPECT_THROW(loose.addMapper(other), Error);
}
TEST(RenderAccumulation, FrozenPixelsKeepTheirMean)
{
  ANISO_REQUIRE_DISPLAY();
  Scene scene;
  scene.window->SetSize(96, 96);
  scene.renderer->ResetCamera();
  scene.renderer->GetActiveCamera()->Zoom(1.6); // the sphere fills most of the view
  scene.pass->SetTargetFrames(64);
  // Lenient, and never stopping before 64 frames: most of the sphere freezes at the first
  // checkpoint that freezes.
  scene.pass->SetErrorTarget(0.05, 64);
  MaterialSettings settings = scene.material->settings();
  settings.samples = 16;
  scene.material->setSettings(settings);
  for (int i = 0; i < kFreezeFromFrames && scene.render() < kFreezeFromFrames; ++i)
  {
  }
  ASSERT_EQ(scene.pass->GetAccumulatedFrames(), kFreezeFromFrames);
  const FrozenPixels frozen = scene.pass->GetFrozenPixels();
  ASSERT_GT(frozen.count, 0) << "nothing froze at " << kFreezeFromFrames << " frames";
  const Image atFreezing = scene.pass->ReadAccumulation();
  const int later = kFreezeFromFrames + 8;
  for (int i = 0; i < 8 && scene.render() < later; ++i)
  {
  }
  ASSERT_EQ(scene.pass->GetAccumulatedFrames(), later);
  const Image next = scene.pass->ReadAccumulation();
  int kept = 0;
  int changed = 0;
  for (int y = 0; y < next.height; ++y)
  {
    for (int x = 0; x < next.width; ++x)
    {
      bool same = true;
      for (int c = 0; c < 4; ++c)
      {
        same = same && next.at(x, y, c) == atFreezing.at(x, y, c);
      }
      if (frozen.frozen(x, y))
      {
        EXPECT_TRUE(same) << "frozen pixel (" << x << ", " << y << ") changed";
        kept += same;
      }
      else if (next.at(x, y, 3) >= 1.0f)
      {
        changed += !same;
      }
    }
  }
  EXPECT_EQ(kept, frozen.count);
  EXPECT_GT(changed, 0) << "the pixels still refining did not change";
}

TEST(RenderAccumulation, EveryMaterialDiscardsFrozenPixels)
{
  ANISO_REQUIRE_DISPLAY();
  // Each shading model alone (the scene without its accumulation pass), drawn on black with the
  // renderer carrying a mask of the left half of the window as the pass would: the anisotropic
  // material (the scene's own), a lit model, LEADR and the microstructure.
  LitModelSettings lit;
  lit.model = LitModel::Ward;
  lit.lights = {parseLight("dir:0,1,0.2:1,1,1"), parseLight("dir:0,-1,0.2:1,1,1")};
  const ParameterSet defaults;
  const DeclaredValues values = [&defaults](std::string_view key) -> const ParameterValue&
  { return defaults.value(key); };
  SurfaceModelInputs inputs;
  inputs.lights = [&lit] { return lit.lights; };
  inputs.tprMap = []() -> std::shared_ptr<const Image> { return nullptr; };
  inputs.leadrMoments = []
  { return std::make_shared<const LeadrMips>(bakeLeadrFromHeight(builtinLeadrRelief(), 1.0)); };
  const std::vector<std::pair<std::string, MaterialInstaller>> models = {
      {"as-env", nullptr},
      {"ward", litModelInstaller(lit)},
      {"leadr", surfaceModelInstaller("leadr", values, inputs)},
      {"microstructure", surfaceModelInstaller("microstructure", values, inputs)}};
  for (const auto& [name, install] : models)
  {
    SCOPED_TRACE(name);
    Scene scene;
    scene.renderer->SetPass(nullptr);
    scene.renderer->SetBackground(0.0, 0.0, 0.0);
    scene.renderer->GetActiveCamera()->Zoom(1.8);
    std::shared_ptr<void> material;
    if (install)
    {
      scene.material.reset();
      material = install(scene.actor, scene.renderer, scene.lighting);
    }
    vtkRenderWindow* window = scene.window;
    window->Render();

    std::vector<unsigned char> mask(32 * 32, 0);
    for (int y = 0; y < 32; ++y)
    {
      for (int x = 0; x < 16; ++x)
      {
        mask[std::size_t(y) * 32 + x] = 255;
      }
    }
    vtkNew<vtkTextureObject> texture;
    texture->SetContext(vtkOpenGLRenderWindow::SafeDownCast(window));
    texture->Create2DFromRaw(32, 32, 1, VTK_UNSIGNED_CHAR, mask.data());
    const auto litColumns = [&]
    {
      window->Render();
      vtkNew<vtkUnsignedCharArray> pixels;
      window->GetPixelData(0, 0, 31, 31, 0, pixels);
      std::array<int, 2> shaded{0, 0}; // left half, right half
      for (int y = 0; y < 32; ++y)
      {
        for (int x = 0; x < 32; ++x)
        {
          const vtkIdType i = 3 * (vtkIdType(y) * 32 + x);
          const int sum = pixels->GetValue(i) + pixels->GetValue(i + 1) + pixels->GetValue(i + 2);
          shaded[x < 16 ? 0 : 1] += sum > 0;
        }
      }
      return shaded;
    };
    const std::array<int, 2> before = litColumns();
    EXPECT_GT(before[0], 100);
    EXPECT_GT(before[1], 100);
    scene.renderer->GetInformation()->Set(vtkAnisoAccumulationPass::FROZEN_PIXELS(), texture);
    scene.actor->Modified();
    const std::array<int, 2> masked = litColumns();
    EXPECT_EQ(masked[0], 0) << "fragments of frozen pixels were shaded";
    EXPECT_EQ(masked[1], before[1]);
    scene.renderer->GetInformation()->Remove(vtkAnisoAccumulationPass::FROZEN_PIXELS());
    scene.actor->Modified();
    EXPECT_EQ(litColumns()[0], before[0]);
  }
}
} // namespace
} // namespace aniso::test
