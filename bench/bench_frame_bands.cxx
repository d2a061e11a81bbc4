// What drawing a progressive frame in bands costs (vtkAnisoAccumulationPass::SetFrameBands):
// the default torus in an offscreen window, the AS material with and without environment MIS,
// frames of 1, 4 and 16 samples drawn whole and in 2, 4 and 8 bands. Per configuration: the
// mean time of one band's render (what the UI thread waits for at a time), the time of a whole
// frame (its bands together) and that time as a ratio to the same frame drawn whole in this
// run: the price of splitting, which a frame plan pays to keep each render within its budget.
// Every render ends with glFinish, so the times are the rasteriser's work, not only its queue.
// Run (X server needed): xvfb-run -a -s "-screen 0 1920x1080x24" bench_frame_bands [WxH]
#include "core/env/environment.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyData.h>
#include <vtkRenderStepsPass.h>
#include <vtk_glew.h>

namespace
{
struct Result
{
  double bandMs = 0.0;
  double frameMs = 0.0;
};

Result measure(vtkOpenGLRenderWindow* window, vtkAnisoAccumulationPass* pass,
               aniso::AnisoMaterial& material, int samples, int bands, bool mis)
{
  aniso::MaterialSettings settings = material.settings();
  settings.samples = samples;
  settings.environmentSampling =
      mis ? aniso::EnvironmentSampling::Mis : aniso::EnvironmentSampling::Off;
  material.setSettings(settings);
  pass->SetFrameBands(bands);
  pass->SetTargetFrames(0);
  pass->Reset();
  const auto render = [&]
  {
    window->Render();
    window->MakeCurrent();
    glFinish();
  };
  // The first frame builds the variant and sizes the targets: not measured.
  for (int i = 0; i < bands; ++i)
  {
    render();
  }
  const int frames = samples >= 16 ? 3 : 6;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < frames * bands; ++i)
  {
    render();
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return {ms / (frames * bands), ms / frames};
}
} // namespace

int main(int argc, char** argv)
{
  int width = 594;
  int height = 614;
  if (argc > 1 && std::sscanf(argv[1], "%dx%d", &width, &height) != 2)
  {
    std::fprintf(stderr, "usage: bench_frame_bands [WxH]\n");
    return 2;
  }
  auto lighting = std::make_shared<aniso::EnvironmentLighting>(
      std::make_shared<aniso::StudioEnvironment>(), 256);
  vtkNew<vtkAnisoPolyDataMapper> mapper;
  mapper->SetInputData(aniso::makeTorus());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkOpenGLRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkAnisoAccumulationPass> pass;
  pass->SetDelegatePass(steps);
  pass->SetLighting(lighting);
  renderer->SetPass(pass);
  vtkSmartPointer<vtkRenderWindow> created = vtkSmartPointer<vtkRenderWindow>::New();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(created);
  if (!window)
  {
    std::fprintf(stderr, "bench_frame_bands: no OpenGL render window\n");
    return 1;
  }
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(1.0, -3.0, 1.5);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();

  aniso::MaterialSettings settings;
  settings.lobe = {1000.0, 50.0};
  aniso::AnisoMaterial material(lighting, settings);
  material.apply(actor, renderer);

  std::printf("window %dx%d, torus, n_u = 1000, n_v = 50\n", width, height);
  std::printf("%-8s %7s %5s %10s %11s %14s\n", "sampling", "samples", "bands", "band ms",
              "frame ms", "frame / whole");
  for (const bool mis : {false, true})
  {
    for (const int samples : {1, 4, 16})
    {
      double whole = 0.0;
      for (const int bands : {1, 2, 4, 8})
      {
        const Result r = measure(window, pass, material, samples, bands, mis);
        if (bands == 1)
        {
          whole = r.frameMs;
        }
        std::printf("%-8s %7d %5d %10.1f %11.1f %14.2f\n", mis ? "mis" : "lobe", samples, bands,
                    r.bandMs, r.frameMs, r.frameMs / whole);
      }
    }
  }
  return 0;
}
