// The culler of a one-pixel pick (PickCuller.h), against VTK's own CPU ray picker as the
// independent reference: a grid of spheres seen in perspective, and at each sphere's centre, at
// points on and beside their outlines and between them, the prop vtkCellPicker's ray hits is
// always among those the culler keeps (it never drops what the pick needs), and the culler
// keeps at most the props whose rectangles can hold the pixel: one at a sphere's centre, none
// between the spheres. A prop reaching behind the camera is kept (its projection is unbounded).
// Culling changes no prop's redraw time (what a view's accumulated mean watches).
#include "vtkpasses/render/PickCuller.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <vector>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>

namespace aniso
{
namespace
{
constexpr int kColumns = 5;
constexpr int kRows = 4;
constexpr double kRadius = 0.35;

struct Scene
{
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  std::vector<vtkSmartPointer<vtkActor>> actors;

  Scene()
  {
    window->SetOffScreenRendering(1);
    window->SetSize(320, 240);
    window->AddRenderer(renderer);
    for (int row = 0; row < kRows; ++row)
    {
      for (int column = 0; column < kColumns; ++column)
      {
        vtkNew<vtkSphereSource> sphere;
        sphere->SetCenter(column - 0.5 * (kColumns - 1), row - 0.5 * (kRows - 1), 0.0);
        sphere->SetRadius(kRadius);
        sphere->SetThetaResolution(24);
        sphere->SetPhiResolution(12);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputConnection(sphere->GetOutputPort());
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        renderer->AddActor(actor);
        actors.push_back(actor);
      }
    }
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.4, -0.3, 10.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    renderer->ResetCameraClippingRange();
  }

  // The props the culler keeps at (X, Y), of all the scene's.
  std::vector<vtkProp*> kept(int x, int y)
  {
    vtkNew<PickCuller> culler;
    culler->SetPixel(x, y);
    std::vector<vtkProp*> props(actors.begin(), actors.end());
    int count = static_cast<int>(props.size());
    int initialized = 0;
    culler->Cull(renderer, props.data(), count, initialized);
    props.resize(std::size_t(count));
    return props;
  }

  // The actor vtkCellPicker's ray through the centre of pixel (X, Y) hits first, or null.
  vtkProp* picked(int x, int y)
  {
    vtkNew<vtkCellPicker> picker;
    picker->SetTolerance(0.0);
    return picker->Pick(x + 0.5, y + 0.5, 0.0, renderer) ? picker->GetViewProp() : nullptr;
  }

  // The display position of world point P.
  void toDisplay(const double p[3], int& x, int& y)
  {
    renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
    renderer->WorldToDisplay();
    const double* d = renderer->GetDisplayPoint();
    x = static_cast<int>(d[0]);
    y = static_cast<int>(d[1]);
  }
};

bool contains(const std::vector<vtkProp*>& props, vtkProp* prop)
{
  return std::find(props.begin(), props.end(), prop) != props.end();
}

TEST(PickCuller, KeepsWhatTheRayPickerHitsAndLittleElse)
{
  Scene scene;
  int hits = 0;
  for (const auto& actor : scene.actors)
  {
    double bounds[6];
    actor->GetBounds(bounds);
    const double centre[3] = {0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                              0.5 * (bounds[4] + bounds[5])};
    int x = 0;
    int y = 0;
    scene.toDisplay(centre, x, y);
    // The centre, and points towards and beyond the outline in four directions.
    for (const auto& [dx, dy] : std::vector<std::pair<int, int>>{
             {0, 0}, {12, 0}, {-12, 0}, {0, 12}, {0, -12}, {20, 3}, {-3, -20}, {22, 22}})
    {
      const std::vector<vtkProp*> kept = scene.kept(x + dx, y + dy);
      vtkProp* hit = scene.picked(x + dx, y + dy);
      if (hit)
      {
        ++hits;
        EXPECT_TRUE(contains(kept, hit)) << "pixel " << x + dx << ", " << y + dy;
      }
      // A pixel in the rectangles of neighbours at most (spheres one unit apart, 0.7 across).
      EXPECT_LE(kept.size(), 4u);
    }
    // At the centre exactly this sphere's rectangle holds the pixel.
    const std::vector<vtkProp*> atCentre = scene.kept(x, y);
    ASSERT_EQ(atCentre.size(), 1u);
    EXPECT_EQ(atCentre.front(), actor.Get());
    EXPECT_EQ(scene.picked(x, y), actor.Get());
  }
  EXPECT_GE(hits, kColumns * kRows); // every centre at least
}

TEST(PickCuller, KeepsNothingBetweenTheSpheresAndChangesNoProp)
{
  Scene scene;
  scene.kept(0, 0); // the spheres' pipelines run once (their bounds)
  std::vector<vtkMTimeType> before;
  for (const auto& actor : scene.actors)
  {
    before.push_back(actor->GetRedrawMTime());
  }
  // Halfway between the first two spheres of the bottom row, and far outside the grid.
  const double between[3] = {0.5 - 0.5 * (kColumns - 1) + 0.0, -0.5 * (kRows - 1), 0.0};
  int x = 0;
  int y = 0;
  scene.toDisplay(between, x, y);
  EXPECT_TRUE(scene.kept(x, y).empty());
  EXPECT_TRUE(scene.kept(2, 2).empty());
  for (std::size_t i = 0; i < scene.actors.size(); ++i)
  {
    EXPECT_EQ(scene.actors[i]->GetRedrawMTime(), before[i]);
  }
  EXPECT_EQ(scene.picked(x, y), nullptr);
}

TEST(PickCuller, KeepsAPropReachingBehindTheCamera)
{
  Scene scene;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.4, -0.3, 10.0); // around the camera
  sphere->SetRadius(1.0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> around;
  around->SetMapper(mapper);
  scene.renderer->AddActor(around);
  scene.actors.push_back(around.Get());
  EXPECT_TRUE(contains(scene.kept(2, 2), around));
  EXPECT_TRUE(contains(scene.kept(300, 200), around));
}
} // namespace
} // namespace aniso
