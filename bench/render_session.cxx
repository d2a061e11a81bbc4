#include "bench/render_session.h"

#include "core/error.h"
#include "core/lut/lut_cache.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "vtkpasses/render/RendererMatrices.h"
#include "vtkpasses/render/TextureUpload.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <glm/geometric.hpp>
#include <limits>
#include <set>
#include <vtkActor.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkTexture.h>
#include <vtk_glew.h>

namespace aniso::bench
{
namespace
{
// The equirectangular image VTK's image-based lighting is given: the environment's own image
// when it has one, else the environment sampled at this size (VTK filters it itself).
constexpr int kVtkEquirectWidth = 1024;

vtkSmartPointer<vtkTexture> vtkEnvironmentTexture(const Environment& environment)
{
  Image equirect;
  if (auto* image = dynamic_cast<const EquirectEnvironment*>(&environment))
  {
    equirect = image->image();
  }
  else
  {
    equirect = renderEquirect(environment, kVtkEquirectWidth, kVtkEquirectWidth / 2);
  }
  vtkNew<vtkImageData> data;
  data->SetDimensions(equirect.width, equirect.height, 1);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetNumberOfComponents(3);
  scalars->SetNumberOfTuples(vtkIdType(equirect.width) * equirect.height);
  // vtkImageData's first row is the bottom one (v = 0), the image's first row the top one.
  for (int y = 0; y < equirect.height; ++y)
  {
    for (int x = 0; x < equirect.width; ++x)
    {
      const vtkIdType tuple = vtkIdType(equirect.height - 1 - y) * equirect.width + x;
      for (int c = 0; c < 3; ++c)
      {
        scalars->SetComponent(tuple, c, equirect.at(x, y, std::min(c, equirect.channels - 1)));
      }
    }
  }
  data->GetPointData()->SetScalars(scalars);
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(data);
  texture->SetColorModeToDirectScalars();
  texture->MipmapOn();
  texture->InterpolateOn();
  return texture;
}

double median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double processCpuSeconds()
{
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
} // namespace

FrameTime medianFrameTime(const std::vector<FrameTime>& frames)
{
  std::vector<double> wall;
  std::vector<double> cpu;
  for (const FrameTime& t : frames)
  {
    wall.push_back(t.wall);
    cpu.push_back(t.cpu);
  }
  return {median(wall), median(cpu)};
}

int64_t coveredPixels(const Image& image)
{
  int64_t count = 0;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      count += image.at(x, y, 3) > 0.0f ? 1 : 0;
    }
  }
  return count;
}

class RenderSession::Impl
{
public:
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkOpenGLRenderer> renderer;
  vtkNew<vtkAnisoPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkAnisoAccumulationPass> pass;
  std::shared_ptr<EnvironmentLighting> lighting;
  vtkSmartPointer<vtkTexture> vtkEnvironment;
  std::unique_ptr<AnisoMaterial> material;
  bool materialAttached = false;
  std::shared_ptr<void> installed; // a material of another model (useInstalled)
  std::set<vtkObject*> programs;
  uint64_t environmentBakes = 0;
  uint64_t uploadsAtStart = 0;
  uint64_t bakesAtStart = 0;
  bool vtkPasses = false;
  bool stageTiming = false;
  std::vector<FrameStages> stages;

  void onUpdateShader(vtkObject*, unsigned long, void* program)
  {
    programs.insert(static_cast<vtkObject*>(program));
  }

  std::vector<FrameTime> draw(int frames)
  {
    std::vector<FrameTime> seconds;
    seconds.reserve(static_cast<std::size_t>(std::max(frames, 0)));
    const int before = pass->GetAccumulatedFrames();
    for (int frame = 0; frame < frames; ++frame)
    {
      const double cpuStart = processCpuSeconds();
      const auto start = std::chrono::steady_clock::now();
      window->Render();
      window->WaitForCompletion();
      const auto end = std::chrono::steady_clock::now();
      seconds.push_back(
          {std::chrono::duration<double>(end - start).count(), processCpuSeconds() - cpuStart});
      if (stageTiming)
      {
        FrameStages st;
        if (!vtkPasses)
        {
          const vtkAnisoAccumulationPass::StageSeconds& t = pass->GetStageSeconds();
          st = {t.prepare, t.clear, t.scene, t.accumulate, t.present, 0.0};
        }
        st.frame = seconds.back().wall;
        stages.push_back(st);
      }
    }
    if (vtkPasses)
    {
      return seconds;
    }
    if (pass->GetAccumulatedFrames() != before + frames)
    {
      throw errorAbout("render", "the OpenGL context could not render the frames");
    }
    return seconds;
  }
};

RenderSession::RenderSession(int width, int height)
    : impl_(std::make_unique<Impl>()), width_(width), height_(height)
{
  requireXDisplay();
  Impl& s = *impl_;
  s.mapper->ScalarVisibilityOff();
  s.actor->SetMapper(s.mapper);
  s.renderer->AddActor(s.actor);
  // Image-based lighting only: no headlight or light kit adds to VTK's shading.
  s.renderer->AutomaticLightCreationOff();
  s.renderer->RemoveAllLights();
  s.window->SetOffScreenRendering(1);
  s.window->SetMultiSamples(0);
  s.window->SetAlphaBitPlanes(1);
  s.window->SetSize(width, height);
  s.window->AddRenderer(s.renderer);
  s.pass->SetDelegatePass(s.steps);
  DisplaySettings display;
  display.background = BackgroundMode::Transparent;
  s.pass->SetDisplaySettings(display);
  s.pass->SetJitter(false);
  s.pass->SetTargetFrames(0);
  s.renderer->SetPass(s.pass);
  s.mapper->AddObserver(vtkCommand::UpdateShaderEvent, impl_.get(), &Impl::onUpdateShader);
  s.uploadsAtStart = textureUploadCount();
  s.bakesAtStart = LutCache::shared().stats().bakes;
}

RenderSession::~RenderSession()
{
  impl_->installed.reset();
  impl_->material.reset();
  impl_->renderer->SetPass(nullptr);
  impl_->window->Finalize();
}

void RenderSession::setSurface(vtkSmartPointer<vtkPolyData> surface, const ViewSettings& view)
{
  if (!surface || surface->GetNumberOfCells() == 0)
  {
    throw errorAbout("mesh", "no surface to render");
  }
  glm::dvec3 centre;
  double radius = 0.0;
  boundingSphere(surface, centre, radius);
  setSurface(std::move(surface), placeCamera(view, centre, radius));
}

void RenderSession::setSurface(vtkSmartPointer<vtkPolyData> surface,
                               const CameraPlacement& placement)
{
  if (!surface || surface->GetNumberOfCells() == 0)
  {
    throw errorAbout("mesh", "no surface to render");
  }
  impl_->mapper->SetInputData(surface);
  applyCamera(impl_->renderer, placement);
}

glm::dmat4 RenderSession::clipToWorld() const
{
  return aniso::clipToWorld(impl_->renderer);
}

void RenderSession::setEnvironment(std::shared_ptr<const Environment> environment, int cubeSize)
{
  impl_->lighting = std::make_shared<EnvironmentLighting>(std::move(environment), cubeSize);
  ++impl_->environmentBakes;
  impl_->vtkEnvironment = nullptr;
  impl_->pass->SetLighting(impl_->lighting);
  if (impl_->material)
  {
    impl_->material->setLighting(impl_->lighting);
  }
  if (impl_->renderer->GetUseImageBasedLighting())
  {
    impl_->vtkEnvironment = vtkEnvironmentTexture(impl_->lighting->environment());
    impl_->renderer->SetEnvironmentTexture(impl_->vtkEnvironment);
  }
}

EnvironmentLighting& RenderSession::lighting()
{
  if (!impl_->lighting)
  {
    throw errorAbout("environment", "no environment set");
  }
  return *impl_->lighting;
}

void RenderSession::useMaterial(const MaterialSettings& settings)
{
  Impl& s = *impl_;
  if (!s.lighting)
  {
    throw errorAbout("environment", "set an environment before a material");
  }
  s.installed.reset();
  s.renderer->UseImageBasedLightingOff();
  s.actor->GetProperty()->SetInterpolationToPhong();
  if (!s.material)
  {
    s.material = std::make_unique<AnisoMaterial>(s.lighting, settings);
  }
  else
  {
    s.material->setSettings(settings);
  }
  if (s.material->lighting() != s.lighting)
  {
    s.material->setLighting(s.lighting);
  }
  if (!s.materialAttached)
  {
    s.material->apply(s.actor, s.renderer);
    s.materialAttached = true;
  }
}

void RenderSession::useVtkPbr(const VtkPbrMaterial& m)
{
  Impl& s = *impl_;
  if (!s.lighting)
  {
    throw errorAbout("environment", "set an environment before a material");
  }
  s.installed.reset();
  if (s.material)
  {
    s.material->detach();
    s.materialAttached = false;
  }
  vtkProperty* property = s.actor->GetProperty();
  property->SetInterpolationToPBR();
  property->SetMetallic(1.0);
  property->SetColor(m.baseColor.x, m.baseColor.y, m.baseColor.z);
  property->SetRoughness(m.roughness);
  property->SetAnisotropy(m.anisotropy);
  property->SetAnisotropyRotation(m.rotation);
  if (!s.vtkEnvironment)
  {
    s.vtkEnvironment = vtkEnvironmentTexture(s.lighting->environment());
    s.renderer->SetEnvironmentTexture(s.vtkEnvironment);
  }
  s.renderer->UseImageBasedLightingOn();
  // Z is up in the project's world; VTK's environment defaults to Y up.
  s.renderer->SetEnvironmentUp(0.0, 0.0, 1.0);
  s.renderer->SetEnvironmentRight(1.0, 0.0, 0.0);
}

void RenderSession::useInstalled(const MaterialInstaller& installer)
{
  Impl& s = *impl_;
  if (!s.lighting)
  {
    throw errorAbout("environment", "set an environment before a material");
  }
  if (s.material)
  {
    s.material->detach();
    s.materialAttached = false;
  }
  // The previous material detaches itself when released, before the new one hooks the actor.
  s.installed.reset();
  s.renderer->UseImageBasedLightingOff();
  s.actor->GetProperty()->SetInterpolationToPhong();
  s.installed = installer(s.actor, s.renderer, s.lighting);
}

std::vector<FrameTime> RenderSession::render(int frames)
{
  estimatedError_ = -1.0;
  impl_->pass->Reset();
  return impl_->draw(frames);
}

std::vector<FrameTime> RenderSession::renderMore(int frames)
{
  return impl_->draw(frames);
}

std::vector<FrameTime> RenderSession::renderToError(double errorTarget, int fromFrames, int most)
{
  vtkAnisoAccumulationPass* pass = impl_->pass;
  pass->SetErrorTarget(errorTarget, fromFrames);
  pass->Reset();
  std::vector<FrameTime> times;
  while (static_cast<int>(times.size()) < most && !pass->IsConverged())
  {
    const std::vector<FrameTime> one = impl_->draw(1);
    times.insert(times.end(), one.begin(), one.end());
  }
  estimatedError_ = pass->GetEstimatedError();
  // Later renders count frames only; the mean is kept (no reset when the target goes).
  pass->SetErrorTarget(0.0);
  return times;
}

void RenderSession::setStillRefinement(double errorTarget)
{
  impl_->pass->SetErrorTarget(errorTarget, std::numeric_limits<int>::max());
}

double RenderSession::estimatedError() const
{
  return estimatedError_;
}

int RenderSession::accumulatedFrames() const
{
  return impl_->pass->GetAccumulatedFrames();
}

Image RenderSession::read()
{
  if (impl_->vtkPasses)
  {
    throw errorAbout("render", "VTK's own passes keep no float image to read");
  }
  Image image = impl_->pass->ReadAccumulation();
  if (image.empty())
  {
    throw errorAbout("render", "no image was rendered");
  }
  return image;
}

void RenderSession::setVtkPasses(bool vtkPasses)
{
  impl_->vtkPasses = vtkPasses;
  impl_->renderer->SetPass(vtkPasses ? nullptr : impl_->pass.GetPointer());
}

void RenderSession::setStageTiming(bool timing)
{
  impl_->stageTiming = timing;
  impl_->pass->SetStageTiming(timing);
  impl_->stages.clear();
}

const std::vector<FrameStages>& RenderSession::stages() const
{
  return impl_->stages;
}

SessionCounters RenderSession::counters() const
{
  SessionCounters c;
  c.shaderPrograms = impl_->programs.size();
  c.textureUploads = textureUploadCount() - impl_->uploadsAtStart;
  c.lutBakes = LutCache::shared().stats().bakes - impl_->bakesAtStart;
  c.environmentBakes = impl_->environmentBakes;
  return c;
}

std::string RenderSession::rendererName()
{
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(impl_->window);
  glWindow->MakeCurrent();
  const GLubyte* name = glGetString(GL_RENDERER);
  return name ? reinterpret_cast<const char*>(name) : std::string();
}
} // namespace aniso::bench
