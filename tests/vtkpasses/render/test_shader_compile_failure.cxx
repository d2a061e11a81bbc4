// A material whose shader does not compile with the driver (vtkAnisoPolyDataMapper, ShaderHook):
// VTK 9.1's own mapper dereferences the null program it gets for it (SIGSEGV); with the
// project's mapper the draw goes on with VTK's own shading and the failure is told.
//   - Broken fragment code: the render returns, the mapper counts one failure, the actor keeps
//     the compiler's complaint (shaderCompileFailure, naming the fragment stage), the hook has
//     nothing installed, one warning names the material, and the sphere is drawn (VTK's own
//     shading: the centre pixel is not the background).
//   - The same code installed again is refused: nothing installed, no further failure, and the
//     next render prints nothing (no compile is tried again).
//   - Valid code installed after it is drawn (the centre pixel takes the code's colour) and the
//     actor's failure is cleared.
//   - renderOffscreen with a material whose shader does not compile throws "material: its
//     shader does not compile ..." instead of returning VTK's shading as the image.
#include "core/error.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "vtkpasses/render/ShaderHook.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

namespace aniso
{
namespace
{
// VTK's errors and warnings while it is the output window, kept.
class CollectingOutputWindow : public vtkOutputWindow
{
public:
  static CollectingOutputWindow* New();
  vtkTypeMacro(CollectingOutputWindow, vtkOutputWindow)
  std::vector<std::string> errors;
  std::vector<std::string> warnings;
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override { errors.emplace_back(text ? text : ""); }
  void DisplayWarningText(const char* text) override { warnings.emplace_back(text ? text : ""); }
  void DisplayGenericWarningText(const char* text) override
  {
    warnings.emplace_back(text ? text : "");
  }
};
vtkStandardNewMacro(CollectingOutputWindow);

class Collecting
{
public:
  Collecting() : previous_(vtkOutputWindow::GetInstance()) { vtkOutputWindow::SetInstance(window); }
  ~Collecting() { vtkOutputWindow::SetInstance(previous_); }
  Collecting(const Collecting&) = delete;
  Collecting& operator=(const Collecting&) = delete;
  vtkNew<CollectingOutputWindow> window;

private:
  vtkSmartPointer<vtkOutputWindow> previous_;
};

ShaderCode fragmentCode(const std::string& implementation)
{
  ShaderCode code;
  code.fragment = {{tags::kFragmentImpl, implementation}};
  return code;
}

const char* kBroken = "this is not GLSL;";
const char* kRed = "gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0);";

// A sphere drawn by vtkAnisoPolyDataMapper in a 64 x 64 offscreen window on blue.
struct Scene
{
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkActor> actor;
  vtkNew<vtkAnisoPolyDataMapper> mapper;

  Scene()
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(16);
    sphere->Update();
    mapper->SetInputData(sphere->GetOutput());
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    renderer->SetBackground(0.0, 0.0, 1.0);
    window->SetOffScreenRendering(1);
    window->SetSize(64, 64);
    window->AddRenderer(renderer);
    renderer->ResetCamera();
  }

  // The centre pixel's RGB after a render.
  std::vector<int> renderCentre()
  {
    window->Render();
    vtkNew<vtkUnsignedCharArray> pixel;
    window->GetPixelData(32, 32, 32, 32, 0, pixel);
    return {pixel->GetValue(0), pixel->GetValue(1), pixel->GetValue(2)};
  }
};

TEST(ShaderCompileFailure, BrokenCodeIsTakenOutAndVtkDrawsTheActor)
{
  ANISO_REQUIRE_DISPLAY();
  Scene scene;
  ShaderHook hook("test material");
  hook.attach(
      scene.actor, scene.renderer, [](vtkPolyData*) {},
      [](vtkShaderProgram*, vtkOpenGLRenderWindow*) {});

  // Valid code first: the window works and the code draws.
  hook.install(fragmentCode(kRed));
  {
    const std::vector<int> red = scene.renderCentre();
    EXPECT_GT(red[0], 200);
    EXPECT_LT(red[1], 50);
    EXPECT_LT(red[2], 50);
  }
  EXPECT_EQ(scene.mapper->GetShaderCompileFailures(), 0);

  hook.install(fragmentCode(kBroken));
  ASSERT_TRUE(hook.installed());
  std::vector<int> centre;
  {
    Collecting output;
    centre = scene.renderCentre();
    EXPECT_EQ(scene.mapper->GetShaderCompileFailures(), 1);
    int named = 0;
    for (const std::string& w : output.window->warnings)
    {
      named += w.find("test material: its shader does not compile") != std::string::npos;
    }
    EXPECT_EQ(named, 1) << "one warning names the material";
  }
  EXPECT_FALSE(hook.installed()) << "the broken code is taken out";
  const std::string failure = shaderCompileFailure(scene.actor);
  EXPECT_NE(failure.find("does not compile"), std::string::npos) << failure;
  EXPECT_NE(failure.find("fragment shader"), std::string::npos) << failure;
  // VTK's own shading of a white sphere under its headlight: grey to white, not the blue
  // background, not the code's red.
  EXPECT_GT(centre[0], 100);
  EXPECT_GT(centre[1], 100);

  // The same code again: refused, nothing compiled, nothing printed.
  hook.install(fragmentCode(kBroken));
  EXPECT_FALSE(hook.installed());
  {
    Collecting output;
    scene.renderCentre();
    EXPECT_TRUE(output.window->errors.empty())
        << "a compile was tried again: " << output.window->errors.front();
    EXPECT_TRUE(output.window->warnings.empty()) << output.window->warnings.front();
  }
  EXPECT_EQ(scene.mapper->GetShaderCompileFailures(), 1);
  EXPECT_EQ(shaderCompileFailure(scene.actor), failure) << "the failure stays told";

  // Other code is installed as usual and clears the failure.
  hook.install(fragmentCode(kRed));
  EXPECT_TRUE(hook.installed());
  EXPECT_TRUE(shaderCompileFailure(scene.actor).empty());
  const std::vector<int> red = scene.renderCentre();
  EXPECT_GT(red[0], 200);
  EXPECT_LT(red[1], 50);
  EXPECT_LT(red[2], 50);
}

TEST(ShaderCompileFailure, OffscreenRenderRefusesTheImage)
{
  ANISO_REQUIRE_DISPLAY();
  auto hooks = std::make_shared<std::vector<std::shared_ptr<ShaderHook>>>();
  RenderSettings s = test::sphereScene(openEnvironment("builtin:studio"), AsLobe{100.0, 100.0}, 32);
  s.installMaterial = [hooks](vtkActor* actor, vtkRenderer* renderer,
                              const std::shared_ptr<EnvironmentLighting>&) -> std::shared_ptr<void>
  {
    auto hook = std::make_shared<ShaderHook>("test material");
    hook->attach(
        actor, renderer, [](vtkPolyData*) {}, [](vtkShaderProgram*, vtkOpenGLRenderWindow*) {});
    hook->install(fragmentCode(kBroken));
    return hook;
  };
  Collecting quiet; // VTK's compile errors, expected here
  try
  {
    renderOffscreen(s);
    FAIL() << "an image drawn without its material was returned";
  }
  catch (const Error& e)
  {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("material: its shader does not compile", 0), 0u) << what;
  }
}
} // namespace
} // namespace aniso
