// Where a frame of the default scene goes, stage by stage, against VTK's own frame of the same
// scene (issue 17): the built-in torus from azimuth 30, elevation 35 (the application's default
// view), n_u = 1000, n_v = 50, under the built-in studio, at 800x600.
//
// Configurations, each drawn in every round, one after the other, in a window of 800x600 or, for
// the half-resolution ones, of 400x300:
//   ours N=16       the interactive setting (MaterialSettings' defaults: exact, filtered, LUT,
//                   16 samples), frames accumulating as a still view's do;
//   ours N=4, N=1   fewer samples, the same way;
//   ours moving     half resolution (400x300), one sample, each frame a new mean (a camera that
//                   moves starts the mean over at every frame);
//   VTK PBR (pass)  VTK's physically based anisotropy (image-based lighting of the same
//                   environment) drawn through the accumulation pass, as `aniso bench` draws it;
//   VTK PBR         the same drawn by VTK's own passes (VTK's frame as VTK draws it): the
//                   baseline of the goals, and again at 400x300.
// In each round every configuration draws a frame to warm up, then F timed frames (the median
// kept), then F frames with each stage of the accumulation pass waited for and timed (FrameStages:
// the medians of each stage; "VTK" is the timed frame less the pass's stages: VTK's render steps
// around the props and the window's buffers). The ratio to VTK's frame is taken per round; the
// tables print the median over the rounds and the range.
//
// Needs an X display (xvfb-run). Usage: bench_frame_stages [--rounds R] [--frames F]
#include "bench/bench_scenes.h"
#include "bench/render_session.h"
#include "core/env/environment.h"
#include "core/error.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/ViewSettings.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>
#include <vtkPolyData.h>

namespace
{
using aniso::bench::FrameStages;
using aniso::bench::FrameTime;
using aniso::bench::RenderSession;

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

struct Configuration
{
  std::string name;
  bool half = false;  // drawn in the 400x300 window
  bool fresh = false; // every frame a new mean (moving)
  std::function<void(RenderSession&)> use;
};

// One round's medians of a configuration.
struct RoundResult
{
  double frame = 0.0; // untimed stages
  double cpu = 0.0;
  FrameStages stages; // medians of each stage, frame = the timed frame
};

struct Summary
{
  std::vector<double> frames;
  std::vector<double> cpus;
  std::vector<double> ratios; // to VTK's own frame in the same round
  std::vector<FrameStages> stages;
};

std::string range(const std::vector<double>& values, double scale, const char* format)
{
  if (values.empty())
  {
    return "-";
  }
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  char text[96];
  std::snprintf(text, sizeof text, format, median(values) * scale, *low * scale, *high * scale);
  return text;
}
} // namespace

int main(int argc, char** argv)
{
  int rounds = 5;
  int frames = 7;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc)
      rounds = std::max(1, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc)
      frames = std::max(3, std::atoi(argv[++i]));
    else
    {
      std::fprintf(stderr, "usage: %s [--rounds R] [--frames F]\n", argv[0]);
      return 2;
    }
  }
  try
  {
    aniso::ViewSettings view;
    view.direction = aniso::viewDirectionFromAngles(30.0, 35.0);
    vtkSmartPointer<vtkPolyData> torus = aniso::makeTorus();
    auto studio = std::make_shared<aniso::StudioEnvironment>();
    const aniso::AsLobe lobe{1000.0, 50.0};
    const glm::dvec3 f0{0.913, 0.922, 0.924};

    RenderSession full(800, 600);
    RenderSession half(400, 300);
    for (RenderSession* session : {&full, &half})
    {
      session->setSurface(torus, view);
      session->setEnvironment(studio, 256);
    }
    auto ours = [&](int samples)
    {
      return [=](RenderSession& session)
      {
        aniso::MaterialSettings m;
        m.lobe = lobe;
        m.f0 = f0;
        m.samples = samples;
        session.setVtkPasses(false);
        session.useMaterial(m);
      };
    };
    const aniso::bench::VtkPbrMaterial pbr = aniso::bench::vtkPbrFor(lobe, f0);
    auto vtk = [&](bool ownPasses)
    {
      return [=](RenderSession& session)
      {
        session.useVtkPbr(pbr);
        session.setVtkPasses(ownPasses);
      };
    };
    const std::vector<Configuration> configurations = {
        {"VTK PBR (VTK's passes)", false, false, vtk(true)},
        {"ours N=16 (interactive)", false, false, ours(16)},
        {"ours N=4", false, false, ours(4)},
        {"ours N=1", false, false, ours(1)},
        {"ours moving (400x300, N=1, new mean each frame)", true, true, ours(1)},
        {"VTK PBR (accumulation pass)", false, false, vtk(false)},
        {"VTK PBR 400x300 (VTK's passes)", true, false, vtk(true)},
    };
    std::vector<Summary> summaries(configurations.size());
    for (int round = 0; round < rounds; ++round)
    {
      std::vector<RoundResult> results(configurations.size());
      for (std::size_t c = 0; c < configurations.size(); ++c)
      {
        const Configuration& config = configurations[c];
        RenderSession& session = config.half ? half : full;
        config.use(session);
        session.render(1); // compiles, uploads, the first frame's targets
        auto draw = [&](int count)
        {
          std::vector<FrameTime> times;
          for (int f = 0; f < count; ++f)
          {
            const std::vector<FrameTime> t =
                config.fresh ? session.render(1) : session.renderMore(1);
            times.push_back(t.front());
          }
          return times;
        };
        const std::vector<FrameTime> times = draw(frames);
        std::vector<double> wall;
        std::vector<double> cpu;
        for (const FrameTime& t : times)
        {
          wall.push_back(t.wall);
          cpu.push_back(t.cpu);
        }
        results[c].frame = median(wall);
        results[c].cpu = median(cpu);
        session.setStageTiming(true);
        draw(frames);
        const std::vector<FrameStages> timed = session.stages();
        session.setStageTiming(false);
        auto stage = [&](double FrameStages::*member)
        {
          std::vector<double> values;
          for (const FrameStages& s : timed)
          {
            values.push_back(s.*member);
          }
          return median(values);
        };
        FrameStages& s = results[c].stages;
        s.prepare = stage(&FrameStages::prepare);
        s.clear = stage(&FrameStages::clear);
        s.scene = stage(&FrameStages::scene);
        s.accumulate = stage(&FrameStages::accumulate);
        s.present = stage(&FrameStages::present);
        s.frame = stage(&FrameStages::frame);
      }
      const double baseline = results.front().frame;
      for (std::size_t c = 0; c < configurations.size(); ++c)
      {
        summaries[c].frames.push_back(results[c].frame);
        summaries[c].cpus.push_back(results[c].cpu);
        summaries[c].ratios.push_back(results[c].frame / baseline);
        summaries[c].stages.push_back(results[c].stages);
      }
      std::fprintf(stderr, "round %d of %d: ours N=16 %.1f ms, VTK %.1f ms\n", round + 1, rounds,
                   results[1].frame * 1e3, baseline * 1e3);
    }

    std::printf("## Frame of the default scene against VTK's (%d rounds, %d frames each)\n\n"
                "| Configuration | Frame (median, range) | CPU time | Ratio to VTK's frame |\n"
                "| --- | --- | --- | --- |\n",
                rounds, frames);
    for (std::size_t c = 0; c < configurations.size(); ++c)
    {
      const Summary& s = summaries[c];
      std::printf("| %s | %s | %s | %s |\n", configurations[c].name.c_str(),
                  range(s.frames, 1e3, "%.1f ms (%.1f-%.1f)").c_str(),
                  range(s.cpus, 1e3, "%.0f ms (%.0f-%.0f)").c_str(),
                  range(s.ratios, 1.0, "%.2f (%.2f-%.2f)").c_str());
    }
    std::printf("\n## Stages (each waited for; medians over the rounds of each round's median, "
                "ms)\n\n| Configuration | Prepare | Clear | Scene (VTK's passes, the props) | "
                "Accumulate (with the background) | Present | VTK around the pass | Timed frame |\n"
                "| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (std::size_t c = 0; c < configurations.size(); ++c)
    {
      const Summary& s = summaries[c];
      auto column = [&](double FrameStages::*member)
      {
        std::vector<double> values;
        for (const FrameStages& r : s.stages)
        {
          values.push_back(r.*member);
        }
        return median(values) * 1e3;
      };
      std::vector<double> rest;
      for (const FrameStages& r : s.stages)
      {
        rest.push_back(r.frame - (r.prepare + r.clear + r.scene + r.accumulate + r.present));
      }
      const bool passDrawn = column(&FrameStages::scene) > 0.0;
      if (!passDrawn)
      {
        std::printf("| %s | - | - | - | - | - | %.1f | %.1f |\n", configurations[c].name.c_str(),
                    median(rest) * 1e3, column(&FrameStages::frame));
        continue;
      }
      std::printf("| %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n",
                  configurations[c].name.c_str(), column(&FrameStages::prepare),
                  column(&FrameStages::clear), column(&FrameStages::scene),
                  column(&FrameStages::accumulate), column(&FrameStages::present),
                  median(rest) * 1e3, column(&FrameStages::frame));
    }
    std::printf("\nRenderer: %s\n", full.rendererName().c_str());
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "bench_frame_stages: %s\n", e.what());
    return 1;
  }
  return 0;
}
