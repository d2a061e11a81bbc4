#include "vtkpasses/render/OffscreenRenderer.h"

#include "core/error.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/FieldValues.h"
#include "vtkpasses/render/OpenGlCapabilities.h"
#include "vtkpasses/render/RendererMatrices.h"
#include "vtkpasses/render/ShaderHook.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <X11/Xlib.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <mutex>
#include <thread>
#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderStepsPass.h>
#include <vtkScalarBarActor.h>
#include <vtkUnsignedCharArray.h>
#include <vtk_glew.h>

namespace aniso
{
namespace
{
constexpr int kMaxImageSide = 16384;
constexpr int kMaxFrames = 1 << 20;

// "part NAME" (or "part 3" for an unnamed one), for messages about one of several parts.
std::string partSubject(const RenderPart& part, std::size_t index)
{
  return "part " + (part.name.empty() ? std::to_string(index + 1) : "'" + part.name + "'");
}

void validate(const RenderSettings& s, const std::vector<RenderPart>& parts)
{
  if (!s.parts.empty() && s.surface)
  {
    throw errorAbout("mesh", "give either a surface or parts, not both");
  }
  const bool several = !s.parts.empty();
  bool anyVisible = false;
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    const RenderPart& part = parts[i];
    if (!part.visible)
    {
      continue;
    }
    anyVisible = true;
    try
    {
      validateLineStyle(part.lineStyle);
    }
    catch (const Error& e)
    {
      throw several ? errorAbout(partSubject(part, i), e.what()) : e;
    }
    if (!part.surface || part.surface->GetNumberOfPoints() == 0 ||
        part.surface->GetNumberOfCells() == 0)
    {
      throw several ? errorAbout(partSubject(part, i), "no surface to render")
                    : errorAbout("mesh", "no surface to render");
    }
  }
  if (!anyVisible)
  {
    throw errorAbout("mesh", "no surface to render (every part is hidden)");
  }
  if (!s.environment)
  {
    throw errorAbout("env", "no environment");
  }
  if (s.width < 1 || s.height < 1 || s.width > kMaxImageSide || s.height > kMaxImageSide)
  {
    throw errorAbout("size",
                     "width and height must be in [1, " + std::to_string(kMaxImageSide) + "]");
  }
  if (s.frames < 1 || s.frames > kMaxFrames)
  {
    throw errorAbout("frames", "must be in [1, " + std::to_string(kMaxFrames) + "]");
  }
  if (!std::isfinite(s.display.exposureEV))
  {
    throw errorAbout("exposure", "not a finite number");
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    if (!parts[i].visible)
    {
      continue;
    }
    try
    {
      AnisoMaterial::validate(parts[i].material);
    }
    catch (const Error& e)
    {
      if (!several)
      {
        throw;
      }
      throw errorAbout(partSubject(parts[i], i), e.what());
    }
  }
}
} // namespace

// VTK's X window aborts the process when it cannot reach a display: check first. The check's
// connection stays open for the life of the process: an X server resets when its last client
// leaves and refuses connections meanwhile, which would fail the next window at random.
void requireXDisplay()
{
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name)
  {
    throw errorAbout("render", "no X display (DISPLAY is not set); run under xvfb-run");
  }
  static std::mutex mutex;
  static Display* connection = nullptr;
  std::lock_guard<std::mutex> lock(mutex);
  for (int attempt = 0; !connection && attempt < 40; ++attempt)
  {
    connection = XOpenDisplay(nullptr);
    if (!connection)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(50)); // a server resetting
    }
  }
  if (!connection)
  {
    throw errorAbout("render", std::string("cannot open the X display ") + name);
  }
}

double medianSeconds(std::vector<double> seconds)
{
  if (seconds.empty())
  {
    return 0.0;
  }
  std::sort(seconds.begin(), seconds.end());
  const std::size_t n = seconds.size();
  return n % 2 ? seconds[n / 2] : 0.5 * (seconds[n / 2 - 1] + seconds[n / 2]);
}

std::vector<RenderPart> sceneParts(const RenderSettings& s)
{
  if (!s.parts.empty())
  {
    return s.parts;
  }
  RenderPart part;
  part.surface = s.surface;
  part.material = s.material;
  return {part};
}

RenderResult renderOffscreen(const RenderSettings& s)
{
  const std::vector<RenderPart> parts = sceneParts(s);
  validate(s, parts);
  requireXDisplay();

  auto lighting = std::make_shared<EnvironmentLighting>(s.environment, s.cubeSize);
  lighting->setRotationDegrees(s.environmentRotationDegrees);

  // Drawn in the frame of the visible surfaces' joint bounding sphere (DrawingFrame.h): any size
  // or distance from the origin draws like a unit mesh at the origin.
  std::vector<vtkPolyData*> visible;
  for (const RenderPart& part : parts)
  {
    if (part.visible)
    {
      visible.push_back(part.surface);
    }
  }
  const DrawingFrame drawing = drawingFrameOf(visible);

  vtkNew<vtkOpenGLRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0); // pixels are sampled at their centres (or jittered) only
  window->SetAlphaBitPlanes(1);
  window->SetSize(s.width, s.height);
  window->AddRenderer(renderer);
  // The context first, and what the renderer needs of it, before anything is drawn.
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  context->Initialize();
  requireRenderCapabilities(context);

  // One actor a visible part; hidden parts are not added at all.
  std::vector<vtkSmartPointer<vtkActor>> actors(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    if (!parts[i].visible)
    {
      continue;
    }
    vtkNew<vtkAnisoPolyDataMapper> mapper;
    mapper->SetInputData(inDrawingFrame(parts[i].surface, drawing));
    mapper->ScalarVisibilityOff();
    actors[i] = vtkSmartPointer<vtkActor>::New();
    actors[i]->SetMapper(mapper);
    setDrawingFrame(actors[i], drawing); // for the point lights of the materials installed on it
    setLineStyle(actors[i], parts[i].lineStyle); // for a line set's width
    renderer->AddActor(actors[i]);
  }

  // A given camera is in the mesh's coordinates, like the surface: mapped the same way.
  applyCamera(renderer, s.camera ? drawing.cameraToDrawing(*s.camera)
                                 : placeCamera(fittedToFrame(s.view, s.width, s.height),
                                               glm::dvec3(0.0), 1.0));

  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkAnisoAccumulationPass> pass;
  pass->SetDelegatePass(steps);
  pass->SetLighting(lighting);
  pass->SetDisplaySettings(s.display);
  pass->SetJitter(s.jitter);
  pass->SetTargetFrames(s.frames);
  pass->SetErrorTarget(s.errorTarget, s.errorStopFrames);
  renderer->SetPass(pass);

  // The parts' fields with automatic ranges mapped over every visible part that shows them.
  std::vector<MaterialSettings> settings(parts.size());
  std::vector<vtkPolyData*> fieldSurfaces;
  std::vector<MaterialSettings*> fieldMaterials;
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    settings[i] = parts[i].material;
    if (actors[i] && !parts[i].installMaterial && !s.installMaterial)
    {
      fieldSurfaces.push_back(parts[i].surface);
      fieldMaterials.push_back(&settings[i]);
    }
  }
  resolveFieldRanges(fieldSurfaces, fieldMaterials);
  // Their colour legends over the image, in a layer the accumulation does not touch.
  vtkNew<vtkRenderer> overlay;
  std::vector<vtkSmartPointer<vtkScalarBarActor>> legends;
  if (s.display.legend)
  {
    const auto shown = fieldLegends({fieldMaterials.begin(), fieldMaterials.end()});
    for (std::size_t k = 0; k < shown.size(); ++k)
    {
      legends.push_back(makeFieldLegendActor(shown[k], int(k)));
      overlay->AddViewProp(legends.back());
    }
  }
  if (!legends.empty())
  {
    window->SetNumberOfLayers(2);
    overlay->SetLayer(1);
    overlay->InteractiveOff();
    window->AddRenderer(overlay);
  }

  std::vector<std::unique_ptr<AnisoMaterial>> materials(parts.size());
  std::vector<std::shared_ptr<void>> otherMaterials;
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    if (!actors[i])
    {
      continue;
    }
    if (parts[i].installMaterial)
    {
      otherMaterials.push_back(parts[i].installMaterial(actors[i], renderer, lighting));
    }
    else if (s.installMaterial)
    {
      otherMaterials.push_back(s.installMaterial(actors[i], renderer, lighting));
    }
    else
    {
      materials[i] = std::make_unique<AnisoMaterial>(lighting, settings[i]);
      materials[i]->apply(actors[i], renderer);
    }
  }

  RenderResult result;
  result.frameSeconds.reserve(static_cast<std::size_t>(s.frames));
  for (int frame = 0; frame < s.frames && !pass->IsConverged(); ++frame)
  {
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    const auto end = std::chrono::steady_clock::now();
    result.frameSeconds.push_back(std::chrono::duration<double>(end - start).count());
  }
  // A part drawn with VTK's own shading because its material's shader did not compile is not the
  // image asked for.
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    const std::string failure = actors[i] ? shaderCompileFailure(actors[i]) : std::string();
    if (!failure.empty())
    {
      throw errorAbout(s.parts.empty() ? std::string("material") : partSubject(parts[i], i),
                       failure);
    }
  }
  result.estimatedError = pass->GetEstimatedError();
  result.estimatedErrorFrames = pass->GetEstimatedErrorFrames();
  result.frozenPixels = pass->GetFrozenPixels().count;
  if (pass->GetAccumulatedFrames() != static_cast<int>(result.frameSeconds.size()))
  {
    throw errorAbout("render", "the OpenGL context could not render the frames");
  }

  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  glWindow->MakeCurrent();
  if (const GLubyte* name = glGetString(GL_RENDERER))
  {
    result.renderer = reinterpret_cast<const char*>(name);
  }
  result.linear = pass->ReadAccumulation();
  result.drawing = drawing;
  result.clipToWorld = clipToWorld(renderer);
  result.worldToEnvironment = lighting->worldToEnvironment();
  if (result.linear.empty())
  {
    throw errorAbout("render", "no image was rendered");
  }

  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(0, 0, s.width - 1, s.height - 1, 0, pixels);
  result.display = Image(s.width, s.height, 4);
  for (int y = 0; y < s.height; ++y)
  {
    const int row = s.height - 1 - y; // GL's first row is the bottom one
    for (int x = 0; x < s.width; ++x)
    {
      for (int c = 0; c < 4; ++c)
      {
        result.display.at(x, y, c) =
            pixels->GetValue((vtkIdType(row) * s.width + x) * 4 + c) / 255.0f;
      }
    }
  }
  for (int y = 0; y < s.height; ++y)
  {
    for (int x = 0; x < s.width; ++x)
    {
      result.coveredPixels += result.linear.at(x, y, 3) > 0.0f ? 1 : 0;
    }
  }
  bool first = true;
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    RenderedPart drawn;
    drawn.name = parts[i].name;
    drawn.visible = parts[i].visible;
    if (materials[i])
    {
      drawn.variant = materials[i]->variant();
      drawn.mapsDropped = materials[i]->mapsDropped();
      if (first)
      {
        result.variant = drawn.variant;
        first = false;
      }
      result.mapsDropped = result.mapsDropped || drawn.mapsDropped;
    }
    result.parts.push_back(std::move(drawn));
  }
  return result;
}
} // namespace aniso
