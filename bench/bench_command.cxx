#include "bench/bench_command.h"

#include "app/cli.h"
#include "bench/bench_run.h"

#include <algorithm>
#include <filesystem>

namespace aniso::cli
{
namespace
{
constexpr int kMaxSize = 4096;

Option flag(std::string name, std::string_view help)
{
  Option o;
  o.name = std::move(name);
  o.spec.type = ParameterType::Text;
  o.spec.help = help;
  return o;
}

Command benchCommand()
{
  Command c;
  c.usage = "aniso bench [--quick] [--models LIST] [--out DIR] [--size N]";
  c.summary =
      "Render the benchmark scene set (sphere, torus and a flange under the built-in studio and "
      "the Blender HDRIs, four materials) with every specular method, filtering, half-vector "
      "source and sample count, and VTK's own PBR anisotropy on the same scenes; time each and "
      "measure its error against the converged CPU reference integrator. The other shading "
      "models follow: the lit models under 1, 2 and 4 lights against the core's evaluation of "
      "the same model, LEADR against a supersampled reference over its slope grid and the "
      "distance, the microstructure over its K x K grid against its converged CPU evaluation, "
      "each timed also as a ratio to the environment frame on the same scene. Needs an X "
      "display; where there is none, run it under xvfb-run.";
  c.options.push_back(flag("--quick",
                           "the small set (the sphere under the studio at 128x128, 19 "
                           "configurations per material; each other model once or a few times "
                           "at 128x128 or 64x64): about a minute"));
  c.options.push_back(textOption(
      "--models", "LIST",
      "the families to run, comma-separated: as-env (the environment Ashikhmin-Shirley set, "
      "its goals and quality model), lit, leadr, micro, hdri (issue 14: the sphere under the "
      "studio and the eight Blender HDRIs, four lobes, the published method against progressive "
      "frames of the defaults (env-sampling auto) and of off, mis and sources; the default scene "
      "under four of them; the goals of issue 14. With --quick: the studio and the sun-sky, two lobes, 16 "
      "frames, no default scene) (default: as-env, lit, leadr, micro; hdri runs only when "
      "named: 14 min at --size 128 with an empty reference cache on two shared cores)"));
  c.options.push_back(textOption(
      "--out", "DIR", "where bench.csv, bench.md, bench.svg and bench.png go", "bench-out"));
  c.options.push_back(textOption(
      "--size", "N",
      "image side in pixels of the scene set and the lit models (default 128 with --quick, else "
      "256; LEADR and the microstructure draw the plate at half of it); the goal scenes keep "
      "their sizes (512x512, and the default scene at 800x600)"));
  c.options.push_back(
      textOption("--cache", "DIR", "reference images cache (default $XDG_CACHE_HOME/aniso/bench)"));
  c.details = "Output: bench.csv (one row per measurement, its model in the model column), "
              "bench.md (tables, the goals, the counters, the quality model, the other models), "
              "bench.svg and bench.png (error against time), bench_models.svg and "
              "bench_models.png (the other models' error against frame time), "
              "bench_hdri.svg and bench_hdri.png (with hdri: error against time per environment "
              "and lobe), "
              "quality_model.txt (the fitted table of core/quality).\n"
              "Examples:\n"
              "  xvfb-run -a aniso bench --quick --out /tmp/bench\n"
              "  xvfb-run -a -s \"-screen 0 1280x1024x24\" aniso bench --out bench-out\n"
              "  xvfb-run -a aniso bench --models lit,leadr,micro --out bench-models\n"
              "  xvfb-run -a -s \"-screen 0 1280x1024x24\" aniso bench --models hdri --out "
              "hdri-out\n";
  return c;
}
} // namespace

std::string benchSummary()
{
  return "time against error of every rendering configuration and of VTK's PBR";
}

int runBenchCommand(const std::vector<std::string>& args, std::ostream& out)
{
  const Command command = benchCommand();
  const Arguments a = parseArguments(command, args);
  if (a.helpRequested)
  {
    out << helpText(command);
    return 0;
  }
  bench::BenchOptions options;
  options.quick = a.has("--quick");
  if (a.has("--size"))
  {
    const auto [width, height] = parseImageSize(a.text("--size"), "--size", kMaxSize);
    options.size = width;
    if (height != width)
    {
      throw usageError("--size", "the benchmark renders square images: give one number");
    }
  }
  if (a.has("--models"))
  {
    options.families = bench::parseBenchFamilies(a.text("--models"));
  }
  options.outDirectory = a.text("--out");
  options.cacheDirectory = a.has("--cache") ? a.text("--cache") : std::string();
  options.commandLine = "aniso bench";
  for (const std::string& arg : args)
  {
    options.commandLine += " " + arg;
  }
  const bench::BenchResult result = bench::runBench(options, out);
  bench::writeBenchOutputs(result, options.outDirectory);
  const bool models = std::any_of(result.rows.begin(), result.rows.end(),
                                  [](const bench::BenchRow& r) { return r.model != "as-env"; });
  const bool hdri = std::any_of(result.rows.begin(), result.rows.end(),
                                [](const bench::BenchRow& r) { return r.kind.rfind("hdri", 0) == 0; });
  out << "\n"
      << bench::benchMarkdown(result, "bench.svg", models ? "bench_models.svg" : "",
                              hdri ? "bench_hdri.svg" : "");
  out << "\nbench: wrote " << (std::filesystem::path(options.outDirectory) / "bench.csv").string()
      << ", bench.md, bench.svg, bench.png, "
      << (models ? "bench_models.svg, bench_models.png, " : "")
      << (hdri ? "bench_hdri.svg, bench_hdri.png, " : "") << "quality_model.txt in "
      << options.outDirectory << " (" << result.rows.size() << " rows, " << result.seconds
      << " s)\n";
  return 0;
}
} // namespace aniso::cli
