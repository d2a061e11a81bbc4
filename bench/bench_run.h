#pragma once
// `aniso bench`: renders the fixed scene set over the renderer's configurations and VTK's own
// physically based anisotropy, times every configuration (median over several frames), and
// measures its error against the converged CPU reference integrator. Results: rows for a CSV
// file and a Markdown report, an error-against-time plot (SVG and PNG), the goals of the
// benchmark issue evaluated, the counters that show nothing is redone when nothing changed, and
// the fitted model of the adaptive quality control.
#include "core/brdf/ashikhmin_shirley.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace aniso::bench
{
struct BenchOptions
{
  bool quick = false;         // the small set: sphere under the studio, fewer configurations
  int size = 0;               // image side in pixels; 0: 128 quick, 256 full
  std::string outDirectory;   // where bench.csv, bench.md, bench.svg, bench.png go
  std::string cacheDirectory; // reference cache; empty: $XDG_CACHE_HOME/aniso/bench (or ~/.cache)
  std::string hdriDirectory;  // HDRIs of the full set; empty: the Blender studio lights
  std::string commandLine;    // as typed, for the report
  // Which families run: "as-env" (the environment Ashikhmin-Shirley set with its goals,
  // counters and quality model), "lit", "leadr", "micro" (bench_models.h), "hdri" (issue 14:
  // the default settings under the studio and the Blender HDRIs, with their goals). Empty:
  // defaultBenchFamilies().
  std::vector<std::string> families;
};

// The families `aniso bench --models` accepts, in the order they run.
const std::vector<std::string>& benchFamilies();
// Those a run without --models takes: all but "hdri" (which runs only when named: it takes
// about as long as the rest together).
const std::vector<std::string>& defaultBenchFamilies();
// The comma-separated LIST as families; throws aniso::Error "--models: reason" for an unknown or
// repeated name or an empty list.
std::vector<std::string> parseBenchFamilies(const std::string& list);

struct BenchRow
{
  // "sweep" (one frame of N samples), "progressive" (frames accumulated), "vtk" (VTK's PBR);
  // "default", "default-progressive", "default-vtk" for the default scene at 800x600; "hdri",
  // "hdri-progressive" for the sphere under the HDRIs (issue 14), "hdri-still" for its still
  // view stopped by its own error estimate, and "hdri-default-progressive" for the default scene
  // under them.
  std::string kind;
  std::string mesh;
  std::string environment;
  AsLobe lobe;
  // "exact", "exact+mis", "exact+sources", "exact+auto(sources)" / "exact+auto(off)" (auto as
  // the environment resolved it), "split-sum", "vtk-pbr"
  std::string method;
  std::string filtered;    // "on", "off", "-"
  std::string halfVectors; // "lut", "shader", "-"
  int samples = 0;         // per pixel and frame
  int frames = 1;          // accumulated into the measured image
  int width = 0;
  int height = 0;
  int64_t coveredPixels = 0;
  int runs = 0;                       // timed frames behind the median
  double medianFrameSeconds = 0.0;    // of one frame, after a warm-up frame
  double firstFrameSeconds = 0.0;     // the first frame of the configuration (compiles, uploads)
  double totalSeconds = 0.0;          // progressive: the frames up to this one, summed
  double medianFrameCpuSeconds = 0.0; // process CPU time of a frame (the driver renders on the
  double totalCpuSeconds = 0.0;       // CPU here), less sensitive to a loaded machine
  double samplesPerSecond = 0.0;      // covered pixels x samples x frames / time
  double relativeL2 = 0.0;
  double percentile99 = 0.0;
  double referenceBound = 0.0; // the reference's own relative L2 error bound
  // Kind "hdri-still" (the still view stopped by its own error): the estimate it stopped at.
  double estimatedError = -1.0;
  int comparedPixels = 0;
  // The shading model: "as-env" (the environment Ashikhmin-Shirley, and VTK's PBR beside it),
  // a lit model ("banks", "ward", ...), "leadr", "normal-map" (LEADR's baseline),
  // "microstructure"; kind "lit", "leadr", "micro", or "baseline" for the environment frame
  // timed on their scenes.
  std::string model = "as-env";
  // lit: the lights; microstructure: structure, masking and shadowing; hdri: "sun" or "no sun"
  // (whether the environment's analysis lists a sun)
  std::string variant;
  int lights = 0;        // point and directional lights
  int grid = 0;          // LEADR: slope grid n (n^2 samples); microstructure: K (K^2 samples)
  double mipLevel = 0.0; // LEADR: mean mip level of the moments over the compared pixels
  // The environment frame (exact, filtered, LUT, 16 samples) on the same scene in the same
  // run; the models' frame times are reported as ratios to it.
  double baselineFrameSeconds = 0.0;
  double baselineFrameCpuSeconds = 0.0; // its process CPU time
};

// One step of the counter check: what changed and what the session counted meanwhile.
struct CounterStep
{
  std::string change;
  std::string expected;
  uint64_t shaderPrograms = 0;
  uint64_t textureUploads = 0;
  uint64_t lutBakes = 0;
  uint64_t environmentBakes = 0;
  bool asExpected = false;
};

struct Goal
{
  std::string name;
  bool met = false;
  std::string figures; // the numbers behind the verdict
};

// The adaptive quality control's model for one lobe and filtering: relative L2 ~ a N^-p,
// fitted to the sweep rows of `exact` with half vectors from the LUT.
struct QualityFit
{
  AsLobe lobe;
  bool filtered = false;
  double a = 0.0;
  double p = 0.0;
  int points = 0;
};

struct BenchResult
{
  std::vector<BenchRow> rows;
  std::vector<CounterStep> counters;
  std::vector<Goal> goals;
  std::vector<Goal> hdriGoals; // issue 14's, from the "hdri" family
  std::vector<QualityFit> qualityFits;
  std::string renderer; // OpenGL renderer string
  std::string machine;  // CPU model and core count
  double seconds = 0.0; // the whole run
  double loadBefore = 0.0;
  double loadAfter = 0.0;
  int size = 0;
  bool quick = false;
  std::string commandLine;
};

// Progress lines go to LOG. Throws aniso::Error on a failed render or file.
BenchResult runBench(const BenchOptions& options, std::ostream& log);

// The goals of the benchmark issue (item 3) from the rows: the best mode against the published
// method at 256 samples, the interactive frame against VTK's, the time to converge to 1%.
std::vector<Goal> evaluateGoals(const BenchResult& result);
// The goals of issue 14 from the "hdri" rows: a still view under every environment converges to
// 1% with the defaults; an interactive frame under a sun has at most twice its error under the
// studio; equal-error speed-up of at least 10x over the published method; the default scene
// reaches 1% within 2 s under every environment.
std::vector<Goal> evaluateHdriGoals(const BenchResult& result);
// a and p of relative L2 = a N^-p per lobe and filtering, least squares in log-log over the
// sphere-under-the-studio rows of `exact` (LUT half vectors, lobe sampling) with N >= 4.
std::vector<QualityFit> fitQuality(const std::vector<BenchRow>& rows);

// bench.csv, bench.md, bench.svg, bench.png and quality_model.txt in DIRECTORY (created),
// bench_models.svg and bench_models.png when the run measured the other models, and
// bench_hdri.svg and bench_hdri.png when it measured the "hdri" family.
void writeBenchOutputs(const BenchResult& result, const std::string& directory);

std::string benchCsv(const BenchResult& result);
// The report; the other models' section embeds MODELSPLOTFILE and the HDRIs' section
// HDRIPLOTFILE when not empty.
std::string benchMarkdown(const BenchResult& result, const std::string& plotFile,
                          const std::string& modelsPlotFile = "",
                          const std::string& hdriPlotFile = "");
} // namespace aniso::bench
