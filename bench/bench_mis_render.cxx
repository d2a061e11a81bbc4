// The lobe share of the shader's environment MIS, on the GPU: the built-in sphere (256 x 128,
// front view, aluminium F0, exact, unfiltered, half vectors in the shader, cube 512) under the
// sun and sky (`builtin:sunsky`) and under the studio, for (10, 10), (100, 10), (1000, 100) and
// (20000, 70), drawn with lobe samples only, with MIS at the share of the lobe width alone (the
// rule used before) and with MIS at misLobeFraction's share, at the same N. Error: relative L2
// against the CPU reference integrator (the sun's disc integrated over its own cone) at about
// 1024 pixels. Each pixel rotates its sample set (pixel decorrelation), so that a single pixel's
// luck does not decide a row.
//
// Needs an X display (xvfb-run). Usage: bench_mis_render [--size S] [--samples N] [--frames F]
#include "bench/bench_scenes.h"
#include "bench/mis_width_rule.h"
#include "core/reference/pixel_geometry.h"
#include "core/reference/reference_image.h"
#include "bench/render_session.h"
#include "core/env/env_sampling.h"
#include "core/env/environment.h"
#include "core/env/sun_sky.h"
#include "core/reference/reference_integrator.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/MaterialSettings.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>
#include <vtkPolyData.h>

int main(int argc, char** argv)
{
  int size = 96;
  int samples = 16;
  int frames = 16;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--size") == 0 && i + 1 < argc)
      size = std::max(16, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--samples") == 0 && i + 1 < argc)
      samples = std::max(1, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc)
      frames = std::max(1, std::atoi(argv[++i]));
    else
    {
      std::fprintf(stderr, "usage: %s [--size S] [--samples N] [--frames F]\n", argv[0]);
      return 2;
    }
  }
  try
  {
    aniso::bench::RenderSession session(size, size);
    vtkSmartPointer<vtkPolyData> sphere = aniso::makeSphere(256, 128);
    session.setSurface(sphere, aniso::ViewSettings{});
    const std::vector<aniso::PixelSample> geometry = aniso::castPixels(
        aniso::triangleMesh(sphere), session.clipToWorld(), size, size);
    const std::vector<int> selected = aniso::selectPixels(geometry, size, size, 1024);
    std::printf("Sphere %dx%d, %zu pixels compared, %d samples x %d frames, pixel decorrelation "
                "on. Relative L2 against the reference integrator.\n\n"
                "| Environment | Lobe | c width rule | c new | lobe only | MIS, width rule | MIS, "
                "new share |\n| --- | --- | --- | --- | --- | --- | --- |\n",
                size, size, selected.size(), samples, frames);
    for (const char* name : {"builtin:sunsky", "builtin:studio"})
    {
      const std::shared_ptr<aniso::Environment> env = aniso::openEnvironment(name);
      const auto sun = std::dynamic_pointer_cast<aniso::SunSkyEnvironment>(env);
      session.setEnvironment(env, 512);
      for (const aniso::AsLobe lobe : {aniso::AsLobe{10.0, 10.0}, aniso::AsLobe{100.0, 10.0},
                                       aniso::AsLobe{1000.0, 100.0}, aniso::AsLobe{20000.0, 70.0}})
      {
        aniso::MaterialSettings m;
        m.lobe = lobe;
        m.albedo = glm::dvec3(0.0);
        m.samples = samples;
        m.method = aniso::SpecularMethod::Exact;
        m.filtered = false;
        m.halfVectors = aniso::HalfVectorSource::Shader;
        m.pixelDecorrelation = true;

        // The reference at the selected pixels, with the frames the shader shades there.
        aniso::ReferenceImage reference;
        reference.width = size;
        reference.height = size;
        aniso::ReferenceOptions options;
        options.relativeTolerance = 1e-4;
        for (const int index : selected)
        {
          const aniso::PixelSample& p = geometry[std::size_t(index)];
          const aniso::Frame frame = aniso::Frame::fromNormalTangent(p.normal, p.tangent);
          const aniso::ReferenceResult r =
              sun ? aniso::integrateSpecularSunSky(lobe, m.f0, frame, p.view, *sun, options)
                  : aniso::integrateSpecular(lobe, m.f0, frame, p.view, *env, options);
          reference.pixels.push_back(
              {index % size, index / size, r.value, r.errorEstimate, r.converged});
        }

        auto error = [&](const aniso::MaterialSettings& settings)
        {
          session.useMaterial(settings);
          session.render(frames);
          return aniso::compareToReference(session.read(), reference).relativeL2;
        };
        const double lobeOnly = error(m);
        m.environmentSampling = aniso::EnvironmentSampling::Mis;
        const double widthShare = aniso::bench::widthRuleFraction(lobe);
        m.misLobeShare = widthShare;
        const double widthRule = error(m);
        m.misLobeShare = 0.0;
        const double newShare = error(m);
        const double chosen = aniso::misLobeFraction(
            lobe, *aniso::sharedDistribution(*env, aniso::EnvSamplingOptions{1024, 4, 0.02}));
        std::printf("| %s | (%g, %g) | %.3f | %.3f | %.4g | %.4g | %.4g |\n", name, lobe.nu,
                    lobe.nv, widthShare, chosen, lobeOnly, widthRule, newShare);
        std::fflush(stdout);
      }
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "bench_mis_render: %s\n", e.what());
    return 1;
  }
}
