// What `aniso bench` makes of its rows: the goals, the quality model's fit, and the CSV,
// Markdown and plot files.
#include "bench/bench_run.h"
#include "bench/plot.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace aniso::bench
{
namespace
{
namespace fs = std::filesystem;

constexpr int kPublishedSamples = 256;
// The built-in studio as rows name it (environmentName); HDRI files go by their stem.
constexpr const char* kStudio = "builtin:studio";
constexpr double kConvergedError = 0.01;
constexpr double kConvergenceSeconds = 2.0;
constexpr double kSpeedupGoal = 10.0;
constexpr double kVtkCostGoal = 2.0;

std::string lobeText(const AsLobe& lobe)
{
  char text[64];
  std::snprintf(text, sizeof text, "(%g, %g)", lobe.nu, lobe.nv);
  return text;
}

std::string number(double value, int digits = 3)
{
  if (!std::isfinite(value))
  {
    return std::isnan(value) ? "nan" : "inf";
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

// "83.1 ms", or "1.25 s" from a second on.
std::string milliseconds(double seconds)
{
  return seconds >= 1.0 ? number(seconds) + " s" : number(seconds * 1e3) + " ms";
}

bool sameLobe(const AsLobe& a, const AsLobe& b)
{
  return a.nu == b.nu && a.nv == b.nv;
}

std::string configText(const BenchRow& r)
{
  std::string text = r.method;
  if (r.method != "vtk-pbr")
  {
    text += std::string(r.filtered == "on" ? ", filtered" : ", unfiltered") +
            (r.halfVectors == "lut" ? ", LUT" : ", shader") + ", N = " + std::to_string(r.samples);
  }
  if (r.frames > 1)
  {
    text += " x " + std::to_string(r.frames) + " frames";
  }
  return text;
}

// A row of the environment set (the Ashikhmin-Shirley configurations and VTK's PBR beside
// them), as opposed to the other models' rows and their baselines.
bool environmentSet(const BenchRow& r)
{
  return r.model == "as-env" && r.kind != "baseline" && r.kind.rfind("hdri", 0) != 0;
}

// Frame time over the environment frame on the same scene (0 where none was measured).
double baselineRatio(const BenchRow& r)
{
  return r.baselineFrameSeconds > 0.0 ? r.medianFrameSeconds / r.baselineFrameSeconds : 0.0;
}

// The same with the process CPU time of both frames.
double baselineCpuRatio(const BenchRow& r)
{
  return r.baselineFrameCpuSeconds > 0.0 ? r.medianFrameCpuSeconds / r.baselineFrameCpuSeconds
                                         : 0.0;
}

// Time to the image a row measures: one frame, or the frames accumulated so far.
double timeOf(const BenchRow& r)
{
  return r.frames > 1 ? r.totalSeconds : r.medianFrameSeconds;
}

double cpuTimeOf(const BenchRow& r)
{
  return r.frames > 1 ? r.totalCpuSeconds : r.medianFrameCpuSeconds;
}

// The sphere under the studio at the run's image size (not the goal or default scenes).
bool mainScene(const BenchRow& r)
{
  return r.mesh == "sphere" && r.environment == kStudio &&
         (r.kind == "sweep" || r.kind == "progressive" || r.kind == "vtk");
}

const BenchRow* find(const std::vector<BenchRow>& rows,
                     const std::function<bool(const BenchRow&)>& f)
{
  for (const BenchRow& r : rows)
  {
    if (f(r))
    {
      return &r;
    }
  }
  return nullptr;
}

std::vector<AsLobe> lobesOf(const std::vector<BenchRow>& rows,
                            const std::function<bool(const BenchRow&)>& keep)
{
  std::vector<AsLobe> lobes;
  for (const BenchRow& r : rows)
  {
    if (keep(r) && std::none_of(lobes.begin(), lobes.end(),
                                [&](const AsLobe& l) { return sameLobe(l, r.lobe); }))
    {
      lobes.push_back(r.lobe);
    }
  }
  return lobes;
}

Goal publishedGoal(const BenchResult& result)
{
  // The goal scene at 512x512 when it was run, else the sphere at the run's size.
  const bool goalScene =
      find(result.rows, [](const BenchRow& r) { return r.kind == "goal"; }) != nullptr;
  const std::function<bool(const BenchRow&)> inScene = [goalScene](const BenchRow& r)
  { return goalScene ? r.kind == "goal" : mainScene(r); };
  const int size = goalScene ? find(result.rows, inScene)->width : result.size;
  Goal goal;
  goal.name = "The best mode reaches the error of the published method (split sum, LUT, "
              "unfiltered, 256 samples) in at most 1/10 of its time (" +
              std::to_string(size) + "², sphere, studio)";
  goal.met = true;
  std::ostringstream figures;
  const auto lobes = lobesOf(result.rows, inScene);
  int evaluated = 0;
  for (const AsLobe& lobe : lobes)
  {
    const BenchRow* published = find(result.rows,
                                     [&](const BenchRow& r)
                                     {
                                       return inScene(r) && r.frames == 1 &&
                                              sameLobe(r.lobe, lobe) && r.method == "split-sum" &&
                                              r.filtered == "off" && r.halfVectors == "lut" &&
                                              r.samples == kPublishedSamples;
                                     });
    if (!published)
    {
      continue;
    }
    const BenchRow* best = nullptr;
    for (const BenchRow& r : result.rows)
    {
      if (inScene(r) && sameLobe(r.lobe, lobe) && r.method != "vtk-pbr" &&
          r.relativeL2 <= published->relativeL2 && (!best || timeOf(r) < timeOf(*best)))
      {
        best = &r;
      }
    }
    ++evaluated;
    const double ratio = timeOf(*best) / timeOf(*published);
    const double cpuRatio = cpuTimeOf(*best) / cpuTimeOf(*published);
    goal.met = goal.met && ratio <= 1.0 / kSpeedupGoal;
    figures << lobeText(lobe) << ": published " << number(published->relativeL2) << " in "
            << milliseconds(timeOf(*published)) << "; best " << configText(*best) << " "
            << number(best->relativeL2) << " in " << milliseconds(timeOf(*best)) << ": "
            << number(ratio, 2) << " of the time (CPU time: " << number(cpuRatio, 2) << "). ";
  }
  goal.met = goal.met && evaluated > 0;
  goal.figures = figures.str();
  return goal;
}

// The default scene when it was measured, else the sphere under the studio with (1000, 100).
struct GoalScene
{
  std::string kind;
  std::function<bool(const BenchRow&)> in;
  std::string label;
};

GoalScene goalScene(const BenchResult& result)
{
  if (find(result.rows, [](const BenchRow& r) { return r.kind == "default"; }))
  {
    return {"default", [](const BenchRow& r) { return r.kind.rfind("default", 0) == 0; },
            "default scene (torus, (1000, 50), studio, 800x600)"};
  }
  const AsLobe lobe{1000.0, 100.0};
  return {"sweep", [lobe](const BenchRow& r) { return mainScene(r) && sameLobe(r.lobe, lobe); },
          "sphere, (1000, 100), studio, " + std::to_string(result.size) +
              "² (the default scene "
              "was not run)"};
}

Goal vtkCostGoal(const BenchResult& result)
{
  const GoalScene scene = goalScene(result);
  Goal goal;
  goal.name = "At the interactive setting (exact, filtered, LUT, 16 samples) a frame costs at "
              "most 2x VTK's anisotropic PBR: " +
              scene.label;
  const std::string vtkKind = scene.kind == "default" ? "default-vtk" : "vtk";
  const BenchRow* ours = find(result.rows,
                              [&](const BenchRow& r)
                              {
                                return scene.in(r) && r.kind == scene.kind && r.method == "exact" &&
                                       r.filtered == "on" && r.halfVectors == "lut" &&
                                       r.samples == 16 && r.frames == 1;
                              });
  const BenchRow* vtk =
      find(result.rows, [&](const BenchRow& r) { return scene.in(r) && r.kind == vtkKind; });
  if (!ours || !vtk)
  {
    goal.figures = "not measured in this run";
    return goal;
  }
  const double ratio = ours->medianFrameSeconds / vtk->medianFrameSeconds;
  const double cpuRatio = ours->medianFrameCpuSeconds / vtk->medianFrameCpuSeconds;
  goal.met = ratio <= kVtkCostGoal;
  goal.figures = "ours " + milliseconds(ours->medianFrameSeconds) + " (L2 " +
                 number(ours->relativeL2) + "), VTK " + milliseconds(vtk->medianFrameSeconds) +
                 " (L2 " + number(vtk->relativeL2) + " against its own GGX model; first frame " +
                 number(vtk->firstFrameSeconds) + " s with its prefiltering): " + number(ratio, 2) +
                 "x (CPU time: " + number(cpuRatio, 2) + "x)";
  // The most samples a frame within the bound could take, among those measured.
  const BenchRow* within = nullptr;
  for (const BenchRow& r : result.rows)
  {
    if (scene.in(r) && r.kind == scene.kind && r.method == "exact" && r.filtered == "on" &&
        r.halfVectors == "lut" && r.frames == 1 &&
        r.medianFrameSeconds <= kVtkCostGoal * vtk->medianFrameSeconds &&
        (!within || r.samples > within->samples))
    {
      within = &r;
    }
  }
  if (within && within != ours)
  {
    goal.figures += "; within 2x at N = " + std::to_string(within->samples) + ": " +
                    milliseconds(within->medianFrameSeconds) + ", L2 " + number(within->relativeL2);
  }
  return goal;
}

Goal convergenceGoal(const BenchResult& result)
{
  const GoalScene scene = goalScene(result);
  Goal goal;
  goal.name = "A still view converges to under 1% relative L2 within 2 s: " + scene.label;
  const std::string kind = scene.kind == "default" ? "default-progressive" : "progressive";
  std::ostringstream figures;
  for (const char* filtered : {"on", "off"})
  {
    const BenchRow* first = nullptr;
    const BenchRow* last = nullptr;
    for (const BenchRow& r : result.rows)
    {
      if (scene.in(r) && r.kind == kind && r.method == "exact" && r.filtered == filtered)
      {
        last = &r;
        if (!first && r.relativeL2 < kConvergedError)
        {
          first = &r;
        }
      }
    }
    if (!last)
    {
      continue;
    }
    const bool met = first && first->totalSeconds <= kConvergenceSeconds;
    goal.met = goal.met || met;
    figures << "exact, " << (std::string(filtered) == "on" ? "filtered" : "unfiltered")
            << ", 16 samples per frame: ";
    if (first)
    {
      figures << number(first->relativeL2) << " after " << first->frames << " frames, "
              << number(first->totalSeconds) << " s (CPU " << number(first->totalCpuSeconds)
              << " s)";
    }
    else
    {
      figures << "not under 1% after " << last->frames << " frames (" << number(last->relativeL2)
              << ", " << number(last->totalSeconds) << " s)";
    }
    figures << (met ? " (met). " : " (not met). ");
  }
  goal.figures = figures.str();
  if (goal.figures.empty())
  {
    goal.figures = "not measured in this run";
  }
  return goal;
}

std::string csvField(const std::string& text)
{
  if (text.find_first_of(",\"") == std::string::npos)
  {
    return text;
  }
  std::string quoted = "\"";
  for (char c : text)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return quoted + "\"";
}

// The Pareto front of POINTS (time, error): the points no other point beats in both.
std::vector<glm::dvec2> paretoFront(std::vector<glm::dvec2> points)
{
  std::sort(points.begin(), points.end(),
            [](const glm::dvec2& a, const glm::dvec2& b)
            { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<glm::dvec2> front;
  double best = std::numeric_limits<double>::infinity();
  for (const glm::dvec2& p : points)
  {
    if (p.y < best)
    {
      front.push_back(p);
      best = p.y;
    }
  }
  return front;
}

struct MethodStyle
{
  std::string method;
  std::string label;
  glm::dvec3 color;
  Marker marker;
};

const std::vector<MethodStyle>& methodStyles()
{
  static const std::vector<MethodStyle> styles{
      {"exact", "exact", {0.84, 0.37, 0.0}, Marker::Circle},
      {"exact+mis", "exact + MIS", {0.55, 0.25, 0.6}, Marker::Circle},
      {"split-sum", "split sum", {0.0, 0.45, 0.70}, Marker::Square},
      {"vtk-pbr", "VTK PBR (vs GGX)", {0.0, 0.62, 0.45}, Marker::Diamond},
  };
  return styles;
}

Figure errorAgainstTime(const BenchResult& result)
{
  Figure figure;
  figure.title = "Relative L2 error against time, sphere under the studio, " +
                 std::to_string(result.size) + "x" + std::to_string(result.size);
  const auto lobes = lobesOf(result.rows, [](const BenchRow& r) { return mainScene(r); });
  for (const AsLobe& lobe : lobes)
  {
    PlotPanel panel;
    panel.title = "(n_u, n_v) = " + lobeText(lobe);
    panel.xLabel = "time to the image [s]";
    panel.yLabel = "relative L2 error";
    for (const MethodStyle& style : methodStyles())
    {
      PlotSeries all;
      all.color = style.color;
      all.marker = style.marker;
      all.markerSize = 2.5;
      all.opacity = 0.35;
      for (const BenchRow& r : result.rows)
      {
        if (mainScene(r) && sameLobe(r.lobe, lobe) && r.method == style.method)
        {
          all.points.push_back({timeOf(r), r.relativeL2});
        }
      }
      if (all.points.empty())
      {
        continue;
      }
      PlotSeries front;
      front.label = style.label + (style.method == "vtk-pbr" ? "" : ", Pareto front");
      front.color = style.color;
      front.marker = style.marker;
      front.markerSize = style.method == "vtk-pbr" ? 5.0 : 3.5;
      front.connect = true;
      front.points = paretoFront(all.points);
      panel.series.push_back(all);
      panel.series.push_back(front);
    }
    figure.panels.push_back(panel);
  }
  return figure;
}

// One Markdown table per lobe: configurations down, sample counts across, "L2 (time)".
void sweepTables(std::ostream& md, const std::vector<BenchRow>& rows,
                 const std::function<bool(const BenchRow&)>& in, const std::string& kind = "sweep")
{
  for (const AsLobe& lobe : lobesOf(rows, in))
  {
    std::set<int> samples;
    std::vector<std::string> configs;
    std::map<std::pair<std::string, int>, const BenchRow*> cells;
    for (const BenchRow& r : rows)
    {
      if (!in(r) || !sameLobe(r.lobe, lobe) || r.kind != kind)
      {
        continue;
      }
      const std::string config = r.method + " | " + r.filtered + " | " + r.halfVectors;
      if (std::find(configs.begin(), configs.end(), config) == configs.end())
      {
        configs.push_back(config);
      }
      samples.insert(r.samples);
      cells[{config, r.samples}] = &r;
    }
    if (configs.empty())
    {
      continue;
    }
    md << "\n" << lobeText(lobe) << ", relative L2 (median frame time):\n\n";
    md << "| Method | Filtered | Half vectors |";
    for (int n : samples)
    {
      md << " N = " << n << " |";
    }
    md << "\n| --- | --- | --- |";
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      md << " --- |";
    }
    md << "\n";
    for (const std::string& config : configs)
    {
      md << "| " << config << " |";
      for (int n : samples)
      {
        const auto cell = cells.find({config, n});
        if (cell == cells.end())
        {
          md << " |";
        }
        else
        {
          md << " " << number(cell->second->relativeL2) << " ("
             << milliseconds(cell->second->medianFrameSeconds) << ") |";
        }
      }
      md << "\n";
    }
  }
}

std::string ratioText(const BenchRow& r)
{
  return r.baselineFrameSeconds > 0.0
             ? number(baselineRatio(r), 3) + "x; CPU " + number(baselineCpuRatio(r), 3) + "x"
             : std::string("-");
}

// "12.3 ms (0.41x; CPU 0.38x)": a frame and its ratios to the environment frame timed next to
// it, by wall time and by process CPU time.
std::string frameText(const BenchRow& r)
{
  return milliseconds(r.medianFrameSeconds) + " (" + ratioText(r) + ")";
}

const std::vector<glm::dvec3>& palette()
{
  static const std::vector<glm::dvec3> colors{
      {0.84, 0.37, 0.0}, {0.0, 0.45, 0.70}, {0.0, 0.62, 0.45},  {0.8, 0.47, 0.65},
      {0.55, 0.25, 0.6}, {0.9, 0.6, 0.0},   {0.34, 0.71, 0.91}, {0.2, 0.2, 0.2}};
  return colors;
}

std::vector<std::string> uniqueValues(const std::vector<BenchRow>& rows,
                                      const std::function<bool(const BenchRow&)>& keep,
                                      const std::function<std::string(const BenchRow&)>& value)
{
  std::vector<std::string> values;
  for (const BenchRow& r : rows)
  {
    if (keep(r) && std::find(values.begin(), values.end(), value(r)) == values.end())
    {
      values.push_back(value(r));
    }
  }
  return values;
}

// Error against frame time (as a ratio to the environment frame) of the other models: one panel
// per family.
Figure modelsErrorAgainstTime(const BenchResult& result)
{
  Figure figure;
  figure.title = "Other shading models: relative L2 error against frame time (ratio to the AS "
                 "environment frame on the same scene)";
  figure.columns = 3;
  const auto& colors = palette();
  auto addSeries = [&](PlotPanel& panel, const std::string& label, std::size_t color, Marker marker,
                       bool connect, double opacity, const std::function<bool(const BenchRow&)>& in)
  {
    PlotSeries series;
    series.label = label;
    series.color = colors[color % colors.size()];
    series.marker = marker;
    series.connect = connect;
    series.opacity = opacity;
    for (const BenchRow& r : result.rows)
    {
      if (in(r))
      {
        series.points.push_back({baselineRatio(r), r.relativeL2});
      }
    }
    if (!series.points.empty())
    {
      panel.series.push_back(series);
    }
  };
  auto newPanel = [](const std::string& title)
  {
    PlotPanel panel;
    panel.title = title;
    panel.xLabel = "frame time / environment frame";
    panel.yLabel = "relative L2 error";
    return panel;
  };
  {
    PlotPanel panel = newPanel("Lit models vs their CPU evaluation");
    const auto models = uniqueValues(
        result.rows, [](const BenchRow& r) { return r.kind == "lit"; },
        [](const BenchRow& r) { return r.model; });
    for (std::size_t i = 0; i < models.size(); ++i)
    {
      for (const char* mesh : {"sphere", "flange"})
      {
        const bool sphere = std::string(mesh) == "sphere";
        addSeries(panel, sphere ? models[i] : std::string(), i,
                  sphere ? Marker::Circle : Marker::Square, true, sphere ? 1.0 : 0.6,
                  [&](const BenchRow& r)
                  { return r.kind == "lit" && r.model == models[i] && r.mesh == mesh; });
      }
    }
    figure.panels.push_back(panel);
  }
  {
    PlotPanel panel = newPanel("LEADR vs supersampled (line: grid n)");
    const auto distances = uniqueValues(
        result.rows, [](const BenchRow& r) { return r.kind == "leadr"; },
        [](const BenchRow& r) { return r.variant; });
    for (std::size_t i = 0; i < distances.size(); ++i)
    {
      for (const char* model : {"leadr", "normal-map"})
      {
        const bool leadr = std::string(model) == "leadr";
        addSeries(panel, (leadr ? "LEADR, " : "normal map, ") + distances[i], i,
                  leadr ? Marker::Circle : Marker::Square, true, leadr ? 1.0 : 0.6,
                  [&](const BenchRow& r)
                  { return r.kind == "leadr" && r.model == model && r.variant == distances[i]; });
      }
    }
    figure.panels.push_back(panel);
  }
  {
    PlotPanel panel = newPanel("Microstructure vs converged CPU (line: K)");
    // Per structure: the dearest masking (POM with shadows) on the full and the jittered grid,
    // and the cheapest (normal) on the full grid; the other masking modes are in the table.
    auto structureOf = [](const BenchRow& r) { return r.variant.substr(0, r.variant.find(',')); };
    const auto structures = uniqueValues(
        result.rows, [](const BenchRow& r) { return r.kind == "micro"; }, structureOf);
    struct Line
    {
      const char* masking;
      const char* method;
      const char* label;
      Marker marker;
      double opacity;
    };
    const Line lines[] = {{"POM, shadows", "full-grid", ", POM + shadows", Marker::Circle, 1.0},
                          {"POM, shadows", "jittered", ", jittered", Marker::Diamond, 0.5},
                          {"normal", "full-grid", ", normal", Marker::Square, 0.5}};
    for (std::size_t i = 0; i < structures.size(); ++i)
    {
      for (const Line& line : lines)
      {
        addSeries(panel, structures[i] + line.label, i, line.marker, true, line.opacity,
                  [&](const BenchRow& r)
                  {
                    return r.kind == "micro" && structureOf(r) == structures[i] &&
                           r.variant == structures[i] + ", " + line.masking &&
                           r.method == line.method;
                  });
      }
    }
    figure.panels.push_back(panel);
  }
  figure.panels.erase(std::remove_if(figure.panels.begin(), figure.panels.end(),
                                     [](const PlotPanel& p) { return p.series.empty(); }),
                      figure.panels.end());
  figure.columns = std::max(1, int(figure.panels.size()));
  return figure;
}

std::string modelsMarkdown(const BenchResult& result, const std::string& plotFile)
{
  const auto& rows = result.rows;
  if (!find(rows, [](const BenchRow& r) { return r.model != "as-env"; }))
  {
    return {};
  }
  std::ostringstream md;
  md << "\n### Other shading models (issue 6)\n\n"
        "Every configuration is timed right after the environment frame of its scene "
        "(Ashikhmin-Shirley " +
            lobeText(AsLobe{1000.0, 100.0}) +
            ", exact, filtered, LUT, 16 samples, built-in studio, the median of 3 frames) in the "
            "same session; every frame time below is followed by its ratios to that neighbour "
            "(wall time, then process CPU time, which counts the driver's render threads), "
            "which a changing load moves far less than the times themselves. The table gives "
            "each scene's environment frame timed alone (9 frames). Times are medians of 2 to 5 "
            "frames "
            "after a warm-up frame; errors are the relative L2 over RGB and p99 (the 99th "
            "percentile of the per-pixel error over the image's RMS radiance) on the compared "
            "pixels.\n\n"
            "| Scene | Image | Environment frame | Its L2 (vs the reference integrator) |\n"
            "| --- | --- | --- | --- |\n";
  for (const BenchRow& r : rows)
  {
    if (r.kind == "baseline")
    {
      md << "| " << r.mesh << " | " << r.width << "x" << r.height << " | "
         << milliseconds(r.medianFrameSeconds) << " | " << number(r.relativeL2) << " |\n";
    }
  }
  if (find(rows, [](const BenchRow& r) { return r.kind == "lit"; }))
  {
    md << "\n#### Lit models under point and directional lights\n\n"
          "Brushed metal (a uniform sample material: alpha 0.05 along the tangent, i.e. the "
          "parallels of the sphere and the circles around Z of the flange, 0.35 across, k_s "
          "0.9) under the first 1, 2 or 4 of: dir:-1,-2,1.5, point:1.5,-2,1.5, "
          "dir:1.5,-1,0.4, point:-1.5,-1,2.5. Error against the core's CPU evaluation of the "
          "same model and lights (shadeLitModel) at every covered pixel away from the "
          "silhouette and the flange's creases (a pixel is compared when its 3x3 neighbours "
          "are covered and their normals lie within 10 degrees of its own), with the frame the "
          "shader builds from the interpolated normal and tangent.\n\n"
          "| Mesh | Model | Lights | Frame (/ env) | Relative L2 | p99 | Pixels |\n"
          "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const BenchRow& r : rows)
    {
      if (r.kind == "lit")
      {
        md << "| " << r.mesh << " | " << r.model << " | " << r.variant << " | " << frameText(r)
           << " | " << number(r.relativeL2) << " | " << number(r.percentile99) << " | "
           << r.comparedPixels << " |\n";
      }
    }
  }
  if (find(rows, [](const BenchRow& r) { return r.kind == "leadr"; }))
  {
    md << "\n#### LEADR against the supersampled reference, with plain normal mapping\n\n"
          "The plate under a parallel view at 50 degrees, a bumpy height map (96 random-phase "
          "waves, slope deviation 0.3) baked to LEADR moments, base roughness 0.1, F0 0.9, "
          "diffuse 0.05, under the studio (specular on the n x n slope grid, SH9 diffuse) and "
          "one directional light 25 degrees off the mirror direction. Distance is set by the "
          "relief's texels per pixel (the level is the mean mip level LEADR reads). The "
          "reference averages the fine-level shading over a grid of points in each pixel's "
          "footprint (at least 8 per period of the finest wave), each point's lobe integrated "
          "on an 8 x 8 slope grid reading the environment itself; its own error bound (in "
          "bench.csv) is its distance to the same average with half the points per axis and "
          "a 4 x 4 grid. Normal mapping is the same shader given only the filtered mean "
          "slope.\n\n"
          "| Distance | Level | n | LEADR L2 | LEADR p99 | LEADR frame (/ env) | Normal map L2 "
          "| Normal map p99 | Normal map frame (/ env) |\n"
          "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const BenchRow& r : rows)
    {
      if (r.kind != "leadr" || r.model != "leadr")
      {
        continue;
      }
      const BenchRow* plain = find(rows,
                                   [&](const BenchRow& x)
                                   {
                                     return x.kind == "leadr" && x.model == "normal-map" &&
                                            x.variant == r.variant && x.grid == r.grid;
                                   });
      md << "| " << r.variant << " | " << number(r.mipLevel, 2) << " | " << r.grid << " | "
         << number(r.relativeL2) << " | " << number(r.percentile99) << " | " << frameText(r)
         << " | " << (plain ? number(plain->relativeL2) : std::string("-")) << " | "
         << (plain ? number(plain->percentile99) : std::string("-")) << " | "
         << (plain ? frameText(*plain) : std::string("-")) << " |\n";
    }
  }
  if (find(rows, [](const BenchRow& r) { return r.kind == "micro"; }))
  {
    const BenchRow* any = find(rows, [](const BenchRow& r) { return r.kind == "micro"; });
    md << "\n#### Microstructure over its K x K grid against the converged CPU evaluation\n\n"
          "The plate under a parallel view at 50 degrees, "
       << any->width << "x" << any->height
       << ", 2.77 structure tiles across a pixel (structures of 64² texels, depth 0.4 tile: "
          "faces at 39 degrees), GGX alpha 0.2, F0 0.5, a directional light 27 degrees above "
          "the plate (low enough for self-shadowing) and a point light. The reference is the "
          "core's shadeMicroPixel with a full 64 x 64 grid (32 x 32 in the quick set) on the "
          "same footprints, its own error bound (in bench.csv) its distance to the half grid; "
          "the full grid samples cell centres, the jittered one a random "
          "point per cell (per-pixel seeds).\n\n"
          "| Structure, masking | K | Full L2 | Full p99 | Full frame (/ env) | Jittered L2 | "
          "Jittered p99 | Jittered frame (/ env) |\n"
          "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const std::string& variant : uniqueValues(
             rows, [](const BenchRow& r) { return r.kind == "micro"; },
             [](const BenchRow& r) { return r.variant; }))
    {
      for (int k : {1, 2, 4, 8})
      {
        auto cell = [&](const char* method)
        {
          return find(rows,
                      [&](const BenchRow& r) {
                        return r.kind == "micro" && r.variant == variant && r.grid == k &&
                               r.method == method;
                      });
        };
        const BenchRow* full = cell("full-grid");
        const BenchRow* jittered = cell("jittered");
        if (!full && !jittered)
        {
          continue;
        }
        const std::string none = "-";
        md << "| " << variant << " | " << k << " | " << (full ? number(full->relativeL2) : none)
           << " | " << (full ? number(full->percentile99) : none) << " | "
           << (full ? frameText(*full) : none) << " | "
           << (jittered ? number(jittered->relativeL2) : none) << " | "
           << (jittered ? number(jittered->percentile99) : none) << " | "
           << (jittered ? frameText(*jittered) : none) << " |\n";
      }
    }
  }
  if (!plotFile.empty())
  {
    md << "\n![Other models: error against frame time](" << plotFile << ")\n";
  }
  return md.str();
}
// Issue 14: the "hdri" family. Rows "hdri" (the published method, one frame),
// "hdri-progressive" (the sphere, frames of 16 samples accumulated) and
// "hdri-default-progressive" (the default scene under each environment).
bool hdriRow(const BenchRow& r)
{
  return r.kind.rfind("hdri", 0) == 0;
}

struct HdriConfig
{
  std::string label;
  glm::dvec3 color;
  std::function<bool(const std::string&)> method;
};

const std::vector<HdriConfig>& hdriConfigs()
{
  static const std::vector<HdriConfig> configs{
      {"default (auto)",
       {0.84, 0.37, 0.0},
       [](const std::string& m) { return m.rfind("exact+auto", 0) == 0; }},
      {"off (lobe only)", {0.0, 0.45, 0.70}, [](const std::string& m) { return m == "exact"; }},
      {"mis", {0.55, 0.25, 0.6}, [](const std::string& m) { return m == "exact+mis"; }},
      {"sources", {0.0, 0.62, 0.45}, [](const std::string& m) { return m == "exact+sources"; }},
      {"sources (per pixel)",
       {0.6, 0.6, 0.2},
       [](const std::string& m) { return m == "exact+sources(pixel)"; }},
  };
  return configs;
}

std::vector<std::string> hdriEnvironments(const std::vector<BenchRow>& rows)
{
  return uniqueValues(
      rows, [](const BenchRow& r) { return r.kind == "hdri-progressive"; },
      [](const BenchRow& r) { return r.environment; });
}

// The progressive rows of one environment, lobe and configuration, by frames.
std::vector<const BenchRow*> hdriSeries(const std::vector<BenchRow>& rows, const std::string& kind,
                                        const std::string& environment, const AsLobe& lobe,
                                        const HdriConfig& config)
{
  std::vector<const BenchRow*> series;
  for (const BenchRow& r : rows)
  {
    if (r.kind == kind && r.environment == environment && sameLobe(r.lobe, lobe) &&
        config.method(r.method))
    {
      series.push_back(&r);
    }
  }
  std::sort(series.begin(), series.end(),
            [](const BenchRow* a, const BenchRow* b) { return a->frames < b->frames; });
  return series;
}

const BenchRow* hdriPublished(const std::vector<BenchRow>& rows, const std::string& environment,
                              const AsLobe& lobe)
{
  return find(rows,
              [&](const BenchRow& r)
              {
                return r.kind == "hdri" && r.environment == environment &&
                       sameLobe(r.lobe, lobe) && r.method == "split-sum";
              });
}

// The first checkpoint from which on every one is at or below TARGET (an error that dips under
// it and rises again has not converged), or null.
const BenchRow* firstAtOrBelow(const std::vector<const BenchRow*>& series, double target)
{
  const BenchRow* first = nullptr;
  for (const BenchRow* r : series)
  {
    if (r->relativeL2 > target)
    {
      first = nullptr;
    }
    else if (!first)
    {
      first = r;
    }
  }
  return first;
}

// "0.84 s (F = 8, 0.0093)", or "not reached: 0.023 at F = 64 (5.2 s)".
std::string timeToText(const std::vector<const BenchRow*>& series, double target)
{
  if (series.empty())
  {
    return "-";
  }
  if (const BenchRow* r = firstAtOrBelow(series, target))
  {
    return milliseconds(r->totalSeconds) + " (F = " + std::to_string(r->frames) + ", " +
           number(r->relativeL2, 2) + ")";
  }
  const BenchRow* last = series.back();
  return "not reached: " + number(last->relativeL2, 2) + " at F = " +
         std::to_string(last->frames) + " (" + milliseconds(last->totalSeconds) + ")";
}

// "sources" from "exact+auto(sources)".
std::string autoChoice(const std::vector<BenchRow>& rows, const std::string& environment,
                       const std::string& kind = "hdri-progressive")
{
  const BenchRow* r = find(rows,
                           [&](const BenchRow& x)
                           {
                             return x.kind == kind && x.environment == environment &&
                                    x.method.rfind("exact+auto(", 0) == 0;
                           });
  if (!r)
  {
    return "-";
  }
  const std::size_t open = r->method.find('(');
  return r->method.substr(open + 1, r->method.size() - open - 2);
}

bool hasSun(const std::vector<BenchRow>& rows, const std::string& environment)
{
  return find(rows, [&](const BenchRow& r)
              { return hdriRow(r) && r.environment == environment && r.variant == "sun"; });
}

// The still view of ENV and LOBE stopped by its own error estimate (kind "hdri-still"), or null.
const BenchRow* hdriStill(const std::vector<BenchRow>& rows, const std::string& environment,
                          const AsLobe& lobe)
{
  return find(
      rows, [&](const BenchRow& r)
      { return r.kind == "hdri-still" && r.environment == environment && sameLobe(r.lobe, lobe); });
}

Goal hdriConvergenceGoal(const BenchResult& result)
{
  const auto& rows = result.rows;
  // With the still views' rows (the full set), the window's default still view: stopped by the
  // error it estimates from its own frames. Without them (the quick set), within the frames run.
  const bool still = find(rows, [](const BenchRow& r) { return r.kind == "hdri-still"; });
  Goal goal;
  goal.name = still ? "G1: with the defaults (exact, filtered, LUT, 16 samples per frame, "
                      "env-sampling auto, quality-mode error: the still view stops when the "
                      "error estimated from its own frames is within error-target 1% (at 3/4 of "
                      "it), at most target-samples) the still view of the sphere stops at <= 1% "
                      "relative L2 against the reference for every lobe under the studio and "
                      "every HDRI"
                    : "G1: with the defaults (exact, filtered, LUT, 16 samples per frame, "
                      "env-sampling auto) a still view of the sphere converges to <= 1% relative "
                      "L2 (within the frames run) for every lobe under the studio and every HDRI";
  std::ostringstream figures;
  int pairs = 0;
  int reached = 0;
  std::vector<std::string> missed;
  const HdriConfig& def = hdriConfigs().front();
  for (const std::string& env : hdriEnvironments(rows))
  {
    for (const AsLobe& lobe : lobesOf(rows, [&](const BenchRow& r)
                                      { return r.kind == "hdri-progressive" && r.environment == env; }))
    {
      if (still)
      {
        const BenchRow* r = hdriStill(rows, env, lobe);
        if (!r)
        {
          continue;
        }
        ++pairs;
        const std::string text = env + " " + lobeText(lobe) + " " + number(r->relativeL2, 2) +
                                 " at F = " + std::to_string(r->frames) + " (estimate " +
                                 number(r->estimatedError, 2) + ", " +
                                 milliseconds(r->totalSeconds) + ")";
        if (r->relativeL2 <= kConvergedError)
        {
          ++reached;
        }
        else
        {
          missed.push_back(text);
        }
        continue;
      }
      const auto series = hdriSeries(rows, "hdri-progressive", env, lobe, def);
      if (series.empty())
      {
        continue;
      }
      ++pairs;
      if (firstAtOrBelow(series, kConvergedError))
      {
        ++reached;
      }
      else
      {
        missed.push_back(env + " " + lobeText(lobe) + " " + number(series.back()->relativeL2, 2) +
                         " at F = " + std::to_string(series.back()->frames));
      }
    }
  }
  goal.met = pairs > 0 && reached == pairs;
  figures << reached << " of " << pairs << " environment x lobe pairs "
          << (still ? "stop at or below 1%" : "reach 1%");
  if (!missed.empty())
  {
    figures << "; not: ";
    for (std::size_t i = 0; i < missed.size(); ++i)
    {
      figures << (i ? "; " : "") << missed[i];
    }
  }
  goal.figures = pairs > 0 ? figures.str() : "not measured in this run";
  return goal;
}

Goal hdriSunGoal(const BenchResult& result)
{
  const auto& rows = result.rows;
  Goal goal;
  goal.name = "G2: one interactive frame (the defaults, 1 frame of 16 samples) under an HDRI with "
              "a sun has at most 2x its error under the studio (" +
              std::string(kStudio) + ", same lobe)";
  const HdriConfig& def = hdriConfigs().front();
  std::ostringstream figures;
  int compared = 0;
  goal.met = true;
  for (const std::string& env : hdriEnvironments(rows))
  {
    if (env == kStudio || !hasSun(rows, env))
    {
      continue;
    }
    figures << (compared ? "; " : "") << env << ":";
    for (const AsLobe& lobe : lobesOf(rows, [&](const BenchRow& r)
                                      { return r.kind == "hdri-progressive" && r.environment == env; }))
    {
      const auto ours = hdriSeries(rows, "hdri-progressive", env, lobe, def);
      const auto studio = hdriSeries(rows, "hdri-progressive", kStudio, lobe, def);
      if (ours.empty() || studio.empty() || ours.front()->frames != 1 ||
          studio.front()->frames != 1)
      {
        continue;
      }
      const double ratio = ours.front()->relativeL2 / studio.front()->relativeL2;
      goal.met = goal.met && ratio <= 2.0;
      ++compared;
      figures << " " << lobeText(lobe) << " " << number(ours.front()->relativeL2, 2) << "/"
              << number(studio.front()->relativeL2, 2) << " = " << number(ratio, 2) << "x"
              << (ratio <= 2.0 ? "" : " (over)");
    }
  }
  goal.met = goal.met && compared > 0;
  goal.figures = compared > 0 ? "error under the sun / under the studio: " + figures.str()
                              : "not measured in this run (no environment with a sun)";
  return goal;
}

Goal hdriSpeedupGoal(const BenchResult& result)
{
  const auto& rows = result.rows;
  Goal goal;
  goal.name = "G3: equal-error speed-up over the published method (split sum, LUT, unfiltered, "
              "256 samples, one frame) >= 10x for every lobe and environment: its time over the "
              "time the best configuration (progressive, any of the five) takes to reach its "
              "error";
  int pairs = 0;
  int met = 0;
  double worst = std::numeric_limits<double>::infinity();
  std::string worstText;
  double worstDefault = std::numeric_limits<double>::infinity();
  std::string worstDefaultText;
  std::vector<std::string> failed;
  for (const std::string& env : hdriEnvironments(rows))
  {
    for (const AsLobe& lobe : lobesOf(rows, [&](const BenchRow& r)
                                      { return r.kind == "hdri-progressive" && r.environment == env; }))
    {
      const BenchRow* published = hdriPublished(rows, env, lobe);
      if (!published)
      {
        continue;
      }
      ++pairs;
      const BenchRow* best = nullptr;
      const BenchRow* bestDefault = nullptr;
      for (const BenchRow& r : rows)
      {
        if (r.kind == "hdri-progressive" && r.environment == env && sameLobe(r.lobe, lobe) &&
            r.relativeL2 <= published->relativeL2)
        {
          if (!best || r.totalSeconds < best->totalSeconds)
          {
            best = &r;
          }
          if (hdriConfigs().front().method(r.method) &&
              (!bestDefault || r.totalSeconds < bestDefault->totalSeconds))
          {
            bestDefault = &r;
          }
        }
      }
      const std::string where = env + " " + lobeText(lobe);
      const double speedup = best ? published->medianFrameSeconds / best->totalSeconds : 0.0;
      const double speedupDefault =
          bestDefault ? published->medianFrameSeconds / bestDefault->totalSeconds : 0.0;
      const std::string text =
          where + ": published " + number(published->relativeL2, 2) + " in " +
          milliseconds(published->medianFrameSeconds) + "; " +
          (best ? best->method + " x " + std::to_string(best->frames) + " " +
                      number(best->relativeL2, 2) + " in " + milliseconds(best->totalSeconds) +
                      ": " + number(speedup, 2) + "x"
                : std::string("no configuration reaches it within the frames run"));
      if (speedup >= kSpeedupGoal)
      {
        ++met;
      }
      else
      {
        failed.push_back(where + " " + (best ? number(speedup, 2) + "x" : std::string("never")));
      }
      if (speedup < worst)
      {
        worst = speedup;
        worstText = text;
      }
      if (speedupDefault < worstDefault)
      {
        worstDefault = speedupDefault;
        worstDefaultText = where + ": " +
                           (bestDefault ? number(speedupDefault, 2) + "x (F = " +
                                              std::to_string(bestDefault->frames) + ")"
                                        : std::string("never within the frames run"));
      }
    }
  }
  goal.met = pairs > 0 && met == pairs;
  if (pairs == 0)
  {
    goal.figures = "not measured in this run";
    return goal;
  }
  std::ostringstream figures;
  figures << met << " of " << pairs << " pairs at >= 10x. Smallest: " << worstText
          << ". The default alone, smallest: " << worstDefaultText;
  if (!failed.empty())
  {
    figures << ". Under 10x: ";
    for (std::size_t i = 0; i < failed.size(); ++i)
    {
      figures << (i ? ", " : "") << failed[i];
    }
  }
  goal.figures = figures.str();
  return goal;
}

Goal hdriDefaultSceneGoal(const BenchResult& result)
{
  const auto& rows = result.rows;
  Goal goal;
  goal.name = "G4: the default scene (torus, (1000, 50), 800x600, the defaults) under every "
              "environment measured reaches <= 1% within 2 s of refinement";
  const HdriConfig& def = hdriConfigs().front();
  std::ostringstream figures;
  int scenes = 0;
  goal.met = true;
  for (const std::string& env : uniqueValues(
           rows, [](const BenchRow& r) { return r.kind == "hdri-default-progressive"; },
           [](const BenchRow& r) { return r.environment; }))
  {
    const auto series = hdriSeries(rows, "hdri-default-progressive", env, AsLobe{1000.0, 50.0}, def);
    if (series.empty())
    {
      continue;
    }
    const BenchRow* first = firstAtOrBelow(series, kConvergedError);
    const bool met = first && first->totalSeconds <= kConvergenceSeconds;
    goal.met = goal.met && met;
    figures << (scenes++ ? "; " : "") << env << " "
            << (first ? number(first->totalSeconds, 2) + " s (F = " +
                            std::to_string(first->frames) + ")"
                      : "not at F = " + std::to_string(series.back()->frames) + " (" +
                            number(series.back()->relativeL2, 2) + ", " +
                            number(series.back()->totalSeconds, 2) + " s)")
            << (met ? "" : " (not met)");
  }
  goal.met = goal.met && scenes > 0;
  goal.figures = scenes > 0 ? figures.str() : "not measured in this run";
  return goal;
}

// Rows: the environments, columns: the lobes; per panel the four configurations' error against
// the accumulated time, the published method's point and the 1% line.
Figure hdriErrorAgainstTime(const BenchResult& result)
{
  const auto& rows = result.rows;
  Figure figure;
  figure.title = "Sphere under the studio and the HDRIs: relative L2 against time (frames of 16 "
                 "samples accumulated), " +
                 std::to_string(result.size) + "x" + std::to_string(result.size);
  const auto lobes = lobesOf(rows, [](const BenchRow& r) { return r.kind == "hdri-progressive"; });
  figure.columns = std::max(1, int(lobes.size()));
  figure.panelWidth = 330;
  figure.panelHeight = 250;
  for (const std::string& env : hdriEnvironments(rows))
  {
    for (const AsLobe& lobe : lobes)
    {
      PlotPanel panel;
      panel.title = env + " " + lobeText(lobe) + ", auto: " + autoChoice(rows, env);
      panel.xLabel = "time [s]";
      panel.yLabel = "relative L2";
      double tMin = std::numeric_limits<double>::infinity();
      double tMax = 0.0;
      for (const HdriConfig& config : hdriConfigs())
      {
        PlotSeries s;
        s.label = config.label;
        s.color = config.color;
        s.connect = true;
        s.marker = Marker::Circle;
        s.markerSize = config.label == hdriConfigs().front().label ? 3.0 : 2.0;
        for (const BenchRow* r : hdriSeries(rows, "hdri-progressive", env, lobe, config))
        {
          s.points.push_back({r->totalSeconds, r->relativeL2});
          tMin = std::min(tMin, r->totalSeconds);
          tMax = std::max(tMax, r->totalSeconds);
        }
        panel.series.push_back(s);
      }
      if (const BenchRow* p = hdriPublished(rows, env, lobe))
      {
        PlotSeries s;
        s.label = "published (split sum, 256, 1 frame)";
        s.color = {0.1, 0.1, 0.1};
        s.marker = Marker::Square;
        s.markerSize = 4.0;
        s.points = {{p->medianFrameSeconds, p->relativeL2}};
        tMin = std::min(tMin, p->medianFrameSeconds);
        tMax = std::max(tMax, p->medianFrameSeconds);
        panel.series.push_back(s);
      }
      if (tMax > 0.0)
      {
        PlotSeries one;
        one.label = "1%";
        one.color = {0.6, 0.6, 0.6};
        one.connect = true;
        one.marker = Marker::None;
        one.points = {{tMin, kConvergedError}, {tMax, kConvergedError}};
        panel.series.push_back(one);
      }
      figure.panels.push_back(panel);
    }
  }
  return figure;
}

std::string hdriMarkdown(const BenchResult& result, const std::string& plotFile)
{
  const auto& rows = result.rows;
  if (!find(rows, hdriRow))
  {
    return {};
  }
  std::ostringstream md;
  md << "\n## Real HDRIs with the default settings (issue 14)\n\n"
        "The sphere at "
     << result.size << "x" << result.size
     << " under the built-in studio and the HDRIs, F0 = aluminium, no diffuse, "
        "cube map 256², no jitter. Per lobe: the published method (split sum, LUT, unfiltered, "
        "256 samples, one frame: the median of its timed frames) and progressive runs of frames "
        "of 16 samples (exact, filtered, LUT) accumulated, the frames' times summed after a "
        "warm-up accumulation: the default (env-sampling auto, as the environment's analysis "
        "resolves it), off (lobe samples only), mis and sources (forced; in the full set up to "
        "16 frames where the default runs to 64), and sources with each pixel's own source "
        "samples (per pixel) beside the points the frame's pixels share. Where auto resolves to "
        "off or sources, that forced configuration draws the same shader with the same uniforms, "
        "so its rows are the default's (rendered once). Error: relative L2 over RGB against the "
        "CPU reference integrator on "
     << (find(rows, [](const BenchRow& r) { return r.kind == "hdri-progressive"; })->comparedPixels)
     << " pixels (cached on disk); the references' own bounds are in bench.csv "
        "(reference_bound), at most ";
  double largestBound = 0.0;
  for (const BenchRow& r : rows)
  {
    if (hdriRow(r))
    {
      largestBound = std::max(largestBound, r.referenceBound);
    }
  }
  md << number(largestBound, 2)
     << " here. Time to 1%: the time of the first checkpoint (F = 1, 2, 4, ... frames) from "
        "which on every checkpoint is at or below 1% (between checkpoints it is not known, so "
        "an upper bound); 'not reached' gives the error at the last frame.\n\n";

  const std::vector<Goal> goals =
      result.hdriGoals.empty() ? evaluateHdriGoals(result) : result.hdriGoals;
  md << "### Goals (issue 14)\n\n| Goal | Met | Figures |\n| --- | --- | --- |\n";
  for (const Goal& g : goals)
  {
    md << "| " << g.name << " | " << (g.met ? "**met**" : "**not met**") << " | " << g.figures
       << " |\n";
  }
  if (!plotFile.empty())
  {
    md << "\n![Relative L2 against time under the HDRIs](" << plotFile << ")\n";
  }

  md << "\n### What auto resolves to\n\n| Environment | auto | Sun listed |\n| --- | --- | --- |\n";
  const auto environments = hdriEnvironments(rows);
  for (const std::string& env : environments)
  {
    md << "| " << env << " | " << autoChoice(rows, env) << " | "
       << (hasSun(rows, env) ? "yes" : "no") << " |\n";
  }

  if (find(rows, [](const BenchRow& r) { return r.kind == "hdri-still"; }))
  {
    md << "\n### The still view, stopped by its own error\n\nThe defaults as the window draws "
          "a still view (quality-mode error): frames of 16 samples until the error estimated "
          "from the frames themselves (the mean against the mean of its first half, at 4, 6, 8, "
          "12, 16, ... frames, from 256 samples a pixel on) is within error-target's default 1% "
          "(at 3/4 of it), at most target-samples' default; "
          "then the error against the reference. Frames at the stop, the estimate, the error "
          "(the time of the frames).\n\n| Environment |";
    const auto stillLobes = lobesOf(rows, [](const BenchRow& r) { return r.kind == "hdri-still"; });
    for (const AsLobe& lobe : stillLobes)
    {
      md << " " << lobeText(lobe) << " |";
    }
    md << "\n| --- |";
    for (std::size_t i = 0; i < stillLobes.size(); ++i)
    {
      md << " --- |";
    }
    md << "\n";
    for (const std::string& env : environments)
    {
      md << "| " << env << " |";
      for (const AsLobe& lobe : stillLobes)
      {
        const BenchRow* r = hdriStill(rows, env, lobe);
        md << " "
           << (r ? "F = " + std::to_string(r->frames) + ", " + number(r->estimatedError, 2) + ", " +
                       number(r->relativeL2, 2) + " (" + milliseconds(r->totalSeconds) + ")"
                 : std::string("-"))
           << " |";
      }
      md << "\n";
    }
  }

  const auto& configs = hdriConfigs();
  for (const std::string& env : environments)
  {
    md << "\n### " << env << " (auto: " << autoChoice(rows, env) << ")\n\n"
       << "| Lobe | published L2 (time) | default F = 1 L2 (time) | default at the last F |";
    for (const HdriConfig& c : configs)
    {
      md << " to 1%: " << c.label << " |";
    }
    md << "\n| --- | --- | --- | --- |";
    for (std::size_t i = 0; i < configs.size(); ++i)
    {
      md << " --- |";
    }
    md << "\n";
    for (const AsLobe& lobe : lobesOf(rows, [&](const BenchRow& r)
                                      { return r.kind == "hdri-progressive" && r.environment == env; }))
    {
      const BenchRow* published = hdriPublished(rows, env, lobe);
      const auto def = hdriSeries(rows, "hdri-progressive", env, lobe, configs.front());
      md << "| " << lobeText(lobe) << " | "
         << (published ? number(published->relativeL2) + " (" +
                             milliseconds(published->medianFrameSeconds) + ")"
                       : std::string("-"))
         << " | "
         << (def.empty() ? std::string("-")
                         : number(def.front()->relativeL2) + " (" +
                               milliseconds(def.front()->totalSeconds) + ")")
         << " | "
         << (def.empty() ? std::string("-")
                         : number(def.back()->relativeL2) + " (F = " +
                               std::to_string(def.back()->frames) + ", " +
                               milliseconds(def.back()->totalSeconds) + ")")
         << " |";
      for (const HdriConfig& c : configs)
      {
        md << " " << timeToText(hdriSeries(rows, "hdri-progressive", env, lobe, c), kConvergedError)
           << " |";
      }
      md << "\n";
    }
  }

  const auto torusEnvironments = uniqueValues(
      rows, [](const BenchRow& r) { return r.kind == "hdri-default-progressive"; },
      [](const BenchRow& r) { return r.environment; });
  if (!torusEnvironments.empty())
  {
    md << "\n### The default scene under the HDRIs\n\nTorus, (1000, 50), 800x600, the "
          "defaults, frames of 16 samples accumulated one by one until at or below 1% (at most "
          "32); in the full set under the studio, city (a sun), interior (lamps) and sunset (a "
          "weak sun) only.\n\n| Environment | auto | F = 1 L2 (time) | to 1% | last L2 (F, time) |\n"
          "| --- | --- | --- | --- | --- |\n";
    for (const std::string& env : torusEnvironments)
    {
      const auto series = hdriSeries(rows, "hdri-default-progressive", env, AsLobe{1000.0, 50.0},
                                     configs.front());
      if (series.empty())
      {
        continue;
      }
      md << "| " << env << " | " << autoChoice(rows, env, "hdri-default-progressive") << " | "
         << number(series.front()->relativeL2) << " (" +
                milliseconds(series.front()->totalSeconds) + ")"
         << " | " << timeToText(series, kConvergedError) << " | "
         << number(series.back()->relativeL2) << " (F = " << series.back()->frames << ", "
         << milliseconds(series.back()->totalSeconds) << ") |\n";
    }
  }
  return md.str();
}

} // namespace

std::vector<Goal> evaluateGoals(const BenchResult& result)
{
  return {publishedGoal(result), vtkCostGoal(result), convergenceGoal(result)};
}

std::vector<Goal> evaluateHdriGoals(const BenchResult& result)
{
  return {hdriConvergenceGoal(result), hdriSunGoal(result), hdriSpeedupGoal(result),
          hdriDefaultSceneGoal(result)};
}

std::vector<QualityFit> fitQuality(const std::vector<BenchRow>& rows)
{
  std::vector<QualityFit> fits;
  const auto lobes = lobesOf(rows, [](const BenchRow& r) { return mainScene(r); });
  for (const AsLobe& lobe : lobes)
  {
    for (bool filtered : {false, true})
    {
      double sx = 0.0;
      double sy = 0.0;
      double sxx = 0.0;
      double sxy = 0.0;
      int n = 0;
      for (const BenchRow& r : rows)
      {
        if (mainScene(r) && r.kind == "sweep" && sameLobe(r.lobe, lobe) && r.method == "exact" &&
            r.halfVectors == "lut" && r.filtered == (filtered ? "on" : "off") && r.samples >= 4 &&
            r.relativeL2 > 0.0 && std::isfinite(r.relativeL2))
        {
          const double x = std::log(double(r.samples));
          const double y = std::log(r.relativeL2);
          sx += x;
          sy += y;
          sxx += x * x;
          sxy += x * y;
          ++n;
        }
      }
      const double denominator = n * sxx - sx * sx;
      if (n < 2 || denominator <= 0.0)
      {
        continue;
      }
      const double slope = (n * sxy - sx * sy) / denominator;
      QualityFit fit;
      fit.lobe = lobe;
      fit.filtered = filtered;
      fit.p = -slope;
      fit.a = std::exp((sy - slope * sx) / n);
      fit.points = n;
      fits.push_back(fit);
    }
  }
  return fits;
}

std::string benchCsv(const BenchResult& result)
{
  std::ostringstream csv;
  csv << "kind,mesh,environment,nu,nv,method,filtered,half_vectors,samples,frames,width,height,"
         "covered_pixels,runs,median_frame_ms,first_frame_ms,total_ms,median_frame_cpu_ms,"
         "total_cpu_ms,samples_per_second,relative_l2,p99_error,reference_bound,"
         "compared_pixels,model,variant,lights,grid,mip_level,baseline_ratio,baseline_cpu_ratio,"
         "estimated_error\n";
  for (const BenchRow& r : result.rows)
  {
    csv << r.kind << "," << csvField(r.mesh) << "," << csvField(r.environment) << ","
        << number(r.lobe.nu, 10) << "," << number(r.lobe.nv, 10) << "," << r.method << ","
        << r.filtered << "," << r.halfVectors << "," << r.samples << "," << r.frames << ","
        << r.width << "," << r.height << "," << r.coveredPixels << "," << r.runs << ","
        << number(r.medianFrameSeconds * 1e3, 6) << "," << number(r.firstFrameSeconds * 1e3, 6)
        << "," << number(r.totalSeconds * 1e3, 6) << "," << number(r.medianFrameCpuSeconds * 1e3, 6)
        << "," << number(r.totalCpuSeconds * 1e3, 6) << "," << number(r.samplesPerSecond, 6) << ","
        << number(r.relativeL2, 6) << "," << number(r.percentile99, 6) << ","
        << number(r.referenceBound, 6) << "," << r.comparedPixels << "," << r.model << ","
        << csvField(r.variant) << "," << r.lights << "," << r.grid << "," << number(r.mipLevel, 4)
        << "," << number(baselineRatio(r), 6) << "," << number(baselineCpuRatio(r), 6) << ","
        << number(r.estimatedError, 6) << "\n";
  }
  return csv.str();
}

std::string benchMarkdown(const BenchResult& result, const std::string& plotFile,
                          const std::string& modelsPlotFile, const std::string& hdriPlotFile)
{
  std::ostringstream md;
  md << "## Time against error (`aniso bench`)\n\n";
  md << "Command: `" << result.commandLine << "` (Release build, under `xvfb-run -a -s \"-screen 0 "
     << "1280x1024x24\"`). Machine: " << result.machine << ", OpenGL " << result.renderer
     << "; load average " << number(result.loadBefore, 2) << " before and "
     << number(result.loadAfter, 2) << " after the run, which took "
     << number(result.seconds / 60.0, 3) << " min.";
  if (!find(result.rows, environmentSet))
  {
    md << (result.quick ? " Quick set." : "") << "\n";
    md << modelsMarkdown(result, modelsPlotFile);
    md << hdriMarkdown(result, hdriPlotFile);
    return md.str();
  }
  md << " Images " << result.size << "x" << result.size << (result.quick ? " (quick set)" : "")
     << ", F0 = aluminium (0.913, 0.922, 0.924), no "
     << "diffuse, cube map 256² per face, no jitter (pixel centres, as the reference). Times are "
     << "medians of 2 to 5 frames after a warm-up frame (GPU work included); error is the relative "
     << "L2 over RGB against the CPU reference integrator on a regular subset of the covered "
     << "pixels (its own error bound is in bench.csv), p99 the 99th percentile of the per-pixel "
     << "error over the image's RMS radiance.\n\n";

  double largestBound = 0.0;
  double smallestError = std::numeric_limits<double>::infinity();
  for (const BenchRow& r : result.rows)
  {
    if (environmentSet(r))
    {
      largestBound = std::max(largestBound, r.referenceBound);
      smallestError = std::min(smallestError, r.relativeL2);
    }
  }
  md << "The references' own error bounds reach at most " << number(largestBound, 2)
     << "; the smallest error reported is " << number(smallestError, 2) << ".\n\n";

  md << "### Goals (issue 5, item 3)\n\n| Goal | Met | Figures |\n| --- | --- | --- |\n";
  for (const Goal& g : result.goals)
  {
    md << "| " << g.name << " | " << (g.met ? "**met**" : "**not met**") << " | " << g.figures
       << " |\n";
  }

  if (!plotFile.empty())
  {
    md << "\n![Relative L2 error against time](" << plotFile << ")\n";
  }

  md << "\n### Sphere under the studio\n";
  sweepTables(md, result.rows, [](const BenchRow& r) { return mainScene(r); });
  if (const BenchRow* goal = find(result.rows, [](const BenchRow& r) { return r.kind == "goal"; }))
  {
    md << "\n### The published method against the best modes at " << goal->width << "x"
       << goal->height << "\n";
    sweepTables(
        md, result.rows, [](const BenchRow& r) { return r.kind == "goal"; }, "goal");
  }

  for (const char* mesh : {"torus", "flange"})
  {
    const auto in = [mesh](const BenchRow& r)
    { return r.mesh == mesh && r.environment == kStudio && r.kind == "sweep"; };
    if (find(result.rows, in))
    {
      md << "\n### " << (std::string(mesh) == "torus" ? "Torus" : "Flange (tangents around Z)")
         << " under the studio\n";
      sweepTables(md, result.rows, in);
    }
  }

  std::vector<std::string> hdris;
  for (const BenchRow& r : result.rows)
  {
    if (environmentSet(r) && r.environment != kStudio &&
        std::find(hdris.begin(), hdris.end(), r.environment) == hdris.end())
    {
      hdris.push_back(r.environment);
    }
  }
  if (!hdris.empty())
  {
    md << "\n### Sphere under the Blender HDRIs\n\nRelative L2 (median frame time); `+mis` is "
          "exact with multiple importance sampling of the environment.\n\n";
    std::vector<std::string> columns;
    for (const BenchRow& r : result.rows)
    {
      if (r.environment != kStudio && r.kind == "sweep")
      {
        const std::string c = configText(r);
        if (std::find(columns.begin(), columns.end(), c) == columns.end())
        {
          columns.push_back(c);
        }
      }
    }
    md << "| Environment | Lobe |";
    for (const std::string& c : columns)
    {
      md << " " << c << " |";
    }
    md << " VTK PBR |\n| --- | --- |";
    for (std::size_t i = 0; i <= columns.size(); ++i)
    {
      md << " --- |";
    }
    md << "\n";
    for (const std::string& environment : hdris)
    {
      for (const AsLobe& lobe :
           lobesOf(result.rows, [&](const BenchRow& r) { return r.environment == environment; }))
      {
        md << "| " << environment << " | " << lobeText(lobe) << " |";
        for (const std::string& c : columns)
        {
          const BenchRow* r = find(result.rows,
                                   [&](const BenchRow& x)
                                   {
                                     return x.environment == environment &&
                                            sameLobe(x.lobe, lobe) && x.kind == "sweep" &&
                                            configText(x) == c;
                                   });
          md << " "
             << (r ? number(r->relativeL2) + " (" + milliseconds(r->medianFrameSeconds) + ")"
                   : std::string())
             << " |";
        }
        const BenchRow* vtk = find(
            result.rows, [&](const BenchRow& x)
            { return x.environment == environment && sameLobe(x.lobe, lobe) && x.kind == "vtk"; });
        md << " "
           << (vtk ? number(vtk->relativeL2) + " (" + milliseconds(vtk->medianFrameSeconds) + ")"
                   : std::string())
           << " |\n";
      }
    }
  }

  md << "\n### VTK's own PBR anisotropy on the same scenes\n\n"
        "VTK 9.1's vtkProperty (PBR interpolation, metallic 1, base colour F0, roughness and "
        "anisotropy from each lobe: alpha = sqrt(2 / (n + 2)) per axis) with image-based "
        "lighting from the same environment, its error against the CPU reference integrating "
        "the GGX lobe VTK claims to render (ggxLobeFromVtk). Ours: exact, filtered, LUT, 16 "
        "samples (the interactive setting), against the Ashikhmin-Shirley reference.\n\n"
        "| Mesh | Environment | Lobe | VTK L2 | VTK frame | VTK first frame | Ours L2 | Ours "
        "frame |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const BenchRow& v : result.rows)
  {
    if (v.method != "vtk-pbr")
    {
      continue;
    }
    const std::string kind = v.kind == "vtk" ? "sweep" : "default";
    const BenchRow* ours =
        find(result.rows,
             [&](const BenchRow& r)
             {
               return r.kind == kind && r.mesh == v.mesh && r.environment == v.environment &&
                      sameLobe(r.lobe, v.lobe) && r.method == "exact" && r.filtered == "on" &&
                      r.halfVectors == "lut" && r.samples == 16;
             });
    md << "| " << v.mesh << (v.kind == "vtk" ? "" : " (800x600)") << " | " << v.environment << " | "
       << lobeText(v.lobe) << " | " << number(v.relativeL2) << " | "
       << milliseconds(v.medianFrameSeconds) << " | " << number(v.firstFrameSeconds) << " s | "
       << (ours ? number(ours->relativeL2) : std::string("-")) << " | "
       << (ours ? milliseconds(ours->medianFrameSeconds) : std::string("-")) << " |\n";
  }

  // One row per scene, lobe and mode; a column per frame count.
  std::set<int> frameCounts;
  std::vector<std::string> series;
  std::map<std::pair<std::string, int>, const BenchRow*> cells;
  for (const BenchRow& r : result.rows)
  {
    if (r.kind.find("progressive") == std::string::npos || !environmentSet(r))
    {
      continue;
    }
    const std::string key = r.mesh + " " + r.environment +
                            (r.kind == "progressive" ? "" : " 800x600") + " | " + lobeText(r.lobe) +
                            " | " + r.method + ", filtered " + r.filtered;
    if (std::find(series.begin(), series.end(), key) == series.end())
    {
      series.push_back(key);
    }
    frameCounts.insert(r.frames);
    cells[{key, r.frames}] = &r;
  }
  if (!series.empty())
  {
    md << "\n### Progressive refinement (a still view)\n\nRelative L2 after F frames of 16 "
          "samples each (the frames' times summed).\n\n| Scene | Lobe | Mode |";
    for (int f : frameCounts)
    {
      md << " F = " << f << " |";
    }
    md << "\n| --- | --- | --- |";
    for (std::size_t i = 0; i < frameCounts.size(); ++i)
    {
      md << " --- |";
    }
    md << "\n";
    for (const std::string& key : series)
    {
      md << "| " << key << " |";
      for (int f : frameCounts)
      {
        const auto cell = cells.find({key, f});
        md << (cell == cells.end() ? std::string(" |")
                                   : " " + number(cell->second->relativeL2) + " (" +
                                         number(cell->second->totalSeconds, 2) + " s) |");
      }
      md << "\n";
    }
  }

  if (!result.counters.empty())
  {
    md << "\n### Nothing is redone when nothing changed (counters)\n\n"
          "Each row changes one input of a rendered view and counts what the next frame "
          "did: shader programs compiled (distinct programs the actor was drawn with), textures "
          "uploaded (TextureUpload.h), LUTs baked (LutCache), environments baked.\n\n"
          "| Change | Expected | Compiles | Uploads | LUT bakes | Environment bakes | As "
          "expected |\n| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const CounterStep& s : result.counters)
    {
      md << "| " << s.change << " | " << s.expected << " | " << s.shaderPrograms << " | "
         << s.textureUploads << " | " << s.lutBakes << " | " << s.environmentBakes << " | "
         << (s.asExpected ? "yes" : "**no**") << " |\n";
    }
  }

  if (!result.qualityFits.empty())
  {
    md << "\n### Adaptive quality model\n\nRelative L2 = a N^-p fitted (least squares in "
          "log-log, N >= 4) to the sphere-under-the-studio rows of exact with LUT half "
          "vectors; core/quality/adaptive_quality.cxx holds the table.\n\n"
          "| Lobe | Filtered | a | p | N for 1% | N for 5% |\n| --- | --- | --- | --- | --- | --- "
          "|\n";
    for (const QualityFit& f : result.qualityFits)
    {
      auto samplesFor = [&](double target) { return std::ceil(std::pow(f.a / target, 1.0 / f.p)); };
      md << "| " << lobeText(f.lobe) << " | " << (f.filtered ? "on" : "off") << " | " << number(f.a)
         << " | " << number(f.p) << " | " << number(samplesFor(0.01), 4) << " | "
         << number(samplesFor(0.05), 4) << " |\n";
    }
  }
  md << modelsMarkdown(result, modelsPlotFile);
  md << hdriMarkdown(result, hdriPlotFile);
  return md.str();
}

void writeBenchOutputs(const BenchResult& result, const std::string& directory)
{
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (!fs::is_directory(directory))
  {
    throw errorAbout(directory, "cannot create the directory");
  }
  auto writeText = [&](const std::string& name, const std::string& text)
  {
    const std::string path = (fs::path(directory) / name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out)
    {
      throw errorAbout(path, "cannot be written");
    }
  };
  writeText("bench.csv", benchCsv(result));
  const Figure figure = errorAgainstTime(result);
  writeText("bench.svg", figureToSvg(figure));
  writeImage((fs::path(directory) / "bench.png").string(), figureToImage(figure));
  const bool models = find(result.rows, [](const BenchRow& r) { return r.model != "as-env"; });
  if (models)
  {
    const Figure modelsFigure = modelsErrorAgainstTime(result);
    writeText("bench_models.svg", figureToSvg(modelsFigure));
    writeImage((fs::path(directory) / "bench_models.png").string(), figureToImage(modelsFigure));
  }
  const bool hdri = find(result.rows, hdriRow);
  if (hdri)
  {
    const Figure hdriFigure = hdriErrorAgainstTime(result);
    writeText("bench_hdri.svg", figureToSvg(hdriFigure));
    writeImage((fs::path(directory) / "bench_hdri.png").string(), figureToImage(hdriFigure));
  }
  writeText("bench.md", benchMarkdown(result, "bench.svg", models ? "bench_models.svg" : "",
                                      hdri ? "bench_hdri.svg" : ""));
  std::ostringstream model;
  model << "// Fitted by: " << result.commandLine << "\n// {n_u, n_v, filtered, a, p}: relative "
        << "L2 = a N^-p\n";
  for (const QualityFit& f : result.qualityFits)
  {
    model << "{" << number(f.lobe.nu, 10) << ", " << number(f.lobe.nv, 10) << ", "
          << (f.filtered ? "true" : "false") << ", " << number(f.a, 4) << ", " << number(f.p, 4)
          << "},\n";
  }
  writeText("quality_model.txt", model.str());
}
} // namespace aniso::bench
