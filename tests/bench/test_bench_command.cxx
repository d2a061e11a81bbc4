// `aniso bench` and the pieces it measures with.
//   - BenchCommand.QuickRunIsCompleteAndConsistent runs `aniso bench --quick` (an X display is
//     needed: ./test runs the suite under xvfb-run) and checks its CSV: every configuration of
//     the quick set is there for each of the four materials, with VTK's row and the progressive
//     rows; every error is finite; the error of `exact` falls as N grows; the references' own
//     error bounds lie below the smallest error reported; the report and both plots exist.
//     The other models' rows (bench_models.h) are complete and finite, each with its ratio to
//     the environment frame measured on its scene: the lit models match the core's CPU
//     evaluation within the render tests' bound, LEADR is closer to the supersampled reference
//     than plain normal mapping, and the microstructure's error against its converged CPU
//     evaluation (a 32 x 32 grid) does not rise with K beyond a stated tolerance and falls
//     overall; the LEADR and microstructure references' own error bounds lie below the errors
//     they measure; the models' plot and report section exist.
//   - BenchCommand.HdriQuickRunHasItsRows runs `aniso bench --models hdri --quick`: only the
//     hdri family's rows, each configuration at each checkpoint for both environments and
//     lobes, auto resolved as the environments' analyses say (off under the built-in studio,
//     sources under the sun-sky), and under the sun the default (the points the frame's pixels
//     share) and each pixel's own source samples far closer to the reference than lobe samples
//     alone (as test_render_sources finds on its own scene); the window's
//     still view of each stops by its own estimate (from 16 frames, within 3/4 of 1%) at or
//     below 1% against the reference; the report's section and the figure exist.
//   - `--models`: the families' list parsed, unknown and repeated names refused.
//   - The CPU pixel rays (the reference's geometry) against the analytic unit sphere.
//   - The flange part against its analytic volume (closed, outward-facing surface).
//   - The plot's raster and SVG outputs against each other and the series' colour.
#include "bench/bench_run.h"
#include "bench/bench_scenes.h"
#include "bench/flange_mesh.h"
#include "core/reference/pixel_geometry.h"
#include "bench/plot.h"
#include "core/error.h"
#include "core/image/image.h"
#include "tests/app/cli_runner.h"
#include "vtkpasses/mesh/MeshValidation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <optional>
#include <sstream>
#include <vtkPolyData.h>

namespace aniso_test
{
namespace
{
using namespace aniso;
using namespace aniso::bench;

bool haveDisplay()
{
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}

// One CSV line's fields: commas inside double quotes belong to the field, "" is a quote.
std::vector<std::string> csvFields(const std::string& line)
{
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i)
  {
    const char c = line[i];
    if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"')
    {
      fields.back() += '"';
      ++i;
    }
    else if (c == '"')
    {
      quoted = !quoted;
    }
    else if (c == ',' && !quoted)
    {
      fields.emplace_back();
    }
    else
    {
      fields.back() += c;
    }
  }
  return fields;
}

std::vector<std::map<std::string, std::string>> readCsv(const std::string& text)
{
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = csvFields(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line))
  {
    const std::vector<std::string> fields = csvFields(line);
    EXPECT_EQ(fields.size(), header.size()) << line;
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size(); ++i)
    {
      row[header[i]] = i < fields.size() ? fields[i] : std::string();
    }
    rows.push_back(row);
  }
  return rows;
}

using BenchCommand = CliTest;

TEST_F(BenchCommand, QuickRunIsCompleteAndConsistent)
{
  if (!haveDisplay())
  {
    GTEST_SKIP() << "no X display: run under xvfb-run (./test does)";
  }
  const Outcome r = run({"bench", "--quick", "--out", path("out").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  for (const char* file : {"bench.csv", "bench.md", "bench.svg", "bench.png", "quality_model.txt",
                           "bench_models.svg", "bench_models.png"})
  {
    EXPECT_TRUE(fs::is_regular_file(path("out") / file)) << file;
  }
  const auto allRows = readCsv(slurp(path("out") / "bench.csv"));
  // The environment set: the Ashikhmin-Shirley configurations and VTK's PBR beside them.
  std::vector<std::map<std::string, std::string>> rows;
  for (const auto& row : allRows)
  {
    if (row.at("model") == "as-env" && row.at("kind") != "baseline")
    {
      rows.push_back(row);
    }
  }

  // The quick set as documented in `aniso bench --help` and docs/BENCHMARKS.md: kind, method,
  // filtered, half vectors, N (frames for the progressive rows).
  struct Expected
  {
    std::string kind, method, filtered, halfVectors;
    int samples;
    int frames;
  };
  std::vector<Expected> expected;
  for (int n : {1, 4, 16, 64, 256})
  {
    expected.push_back({"sweep", "exact", "off", "lut", n, 1});
  }
  for (int n : {1, 4, 16, 64})
  {
    expected.push_back({"sweep", "exact", "on", "lut", n, 1});
  }
  expected.push_back({"sweep", "split-sum", "off", "lut", 16, 1});
  expected.push_back({"sweep", "split-sum", "off", "lut", 256, 1});
  expected.push_back({"sweep", "split-sum", "on", "lut", 16, 1});
  expected.push_back({"sweep", "exact", "off", "shader", 16, 1});
  expected.push_back({"sweep", "exact+mis", "off", "lut", 16, 1});
  for (int frames : {1, 2, 4, 8})
  {
    expected.push_back({"progressive", "exact", "on", "lut", 16, frames});
  }
  expected.push_back({"vtk", "vtk-pbr", "-", "-", 1, 1});

  double smallestError = INFINITY;
  double largestBound = 0.0;
  for (const std::string lobe : {"10,10", "100,10", "1000,100", "20000,70"})
  {
    for (const Expected& e : expected)
    {
      int found = 0;
      for (const auto& row : rows)
      {
        found += row.at("kind") == e.kind && row.at("nu") + "," + row.at("nv") == lobe &&
                 row.at("method") == e.method && row.at("filtered") == e.filtered &&
                 row.at("half_vectors") == e.halfVectors &&
                 std::stoi(row.at("samples")) == e.samples &&
                 std::stoi(row.at("frames")) == e.frames;
      }
      EXPECT_EQ(found, 1) << lobe << " " << e.kind << " " << e.method << " " << e.filtered << " "
                          << e.halfVectors << " N=" << e.samples << " x" << e.frames;
    }
  }
  EXPECT_EQ(rows.size(), 4 * expected.size());

  std::map<std::string, std::vector<std::pair<int, double>>> exactByFamily;
  for (const auto& row : rows)
  {
    const double error = std::stod(row.at("relative_l2"));
    const double p99 = std::stod(row.at("p99_error"));
    const double bound = std::stod(row.at("reference_bound"));
    EXPECT_TRUE(std::isfinite(error) && error > 0.0) << row.at("method") << " " << error;
    EXPECT_TRUE(std::isfinite(p99) && p99 > 0.0) << row.at("method") << " " << p99;
    EXPECT_GT(std::stod(row.at("median_frame_ms")), 0.0);
    EXPECT_GE(std::stoi(row.at("compared_pixels")), 40);
    smallestError = std::min(smallestError, error);
    largestBound = std::max(largestBound, bound);
    if (row.at("kind") == "sweep" && row.at("method") == "exact" && row.at("half_vectors") == "lut")
    {
      exactByFamily[row.at("nu") + "," + row.at("nv") + " filtered " + row.at("filtered")]
          .push_back({std::stoi(row.at("samples")), error});
    }
  }
  // exact is an unbiased estimator: more samples, less error (for the unfiltered one the
  // quasi-Monte-Carlo error; filtering adds a bias that shrinks with N as well).
  EXPECT_EQ(exactByFamily.size(), 8u);
  for (auto& [family, errors] : exactByFamily)
  {
    std::sort(errors.begin(), errors.end());
    for (std::size_t i = 1; i < errors.size(); ++i)
    {
      EXPECT_LT(errors[i].second, errors[i - 1].second)
          << family << ": N=" << errors[i].first << " against N=" << errors[i - 1].first;
    }
  }
  EXPECT_LT(largestBound, smallestError);

  const std::string md = slurp(path("out") / "bench.md");
  EXPECT_NE(md.find("### Goals"), std::string::npos);
  EXPECT_NE(md.find("### Nothing is redone when nothing changed"), std::string::npos);
  EXPECT_EQ(md.find("| **no** |"), std::string::npos) << "a counter step did something";
  const std::string svg = slurp(path("out") / "bench.svg");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);

  // The other models. Every row finite, compared on enough pixels, timed, and given its ratio
  // to the environment frame of its scene (one baseline row per scene, ratio 1).
  auto select = [&](const std::function<bool(const std::map<std::string, std::string>&)>& f)
  {
    std::vector<std::map<std::string, std::string>> found;
    for (const auto& row : allRows)
    {
      if (f(row))
      {
        found.push_back(row);
      }
    }
    return found;
  };
  const auto baselines = select([](const auto& x) { return x.at("kind") == "baseline"; });
  ASSERT_EQ(baselines.size(), 2u);
  EXPECT_EQ(baselines[0].at("mesh"), "sphere");
  EXPECT_EQ(baselines[1].at("mesh"), "plate");
  for (const auto& row : baselines)
  {
    EXPECT_DOUBLE_EQ(std::stod(row.at("baseline_ratio")), 1.0);
  }
  const auto models = select([](const auto& x) { return x.at("model") != "as-env"; });
  for (const auto& row : models)
  {
    const std::string what = row.at("kind") + " " + row.at("model") + " " + row.at("variant") +
                             " grid " + row.at("grid") + " " + row.at("method");
    const double error = std::stod(row.at("relative_l2"));
    const double p99 = std::stod(row.at("p99_error"));
    const double ratio = std::stod(row.at("baseline_ratio"));
    EXPECT_TRUE(std::isfinite(error) && error > 0.0) << what << " " << error;
    EXPECT_TRUE(std::isfinite(p99) && p99 > 0.0) << what << " " << p99;
    EXPECT_TRUE(std::isfinite(ratio) && ratio > 0.0) << what << " " << ratio;
    EXPECT_GT(std::stod(row.at("median_frame_ms")), 0.0) << what;
    EXPECT_GE(std::stoi(row.at("compared_pixels")), 40) << what;
    // The supersampled and converged references' own error (their distance to the same
    // quadrature at half the resolution) lies below every error they measure.
    if (row.at("kind") == "leadr" || row.at("kind") == "micro")
    {
      const double bound = std::stod(row.at("reference_bound"));
      EXPECT_TRUE(bound > 0.0 && bound < error) << what << ": bound " << bound;
    }
  }

  // Lit models: each of the five once, under 2 lights on the sphere. Against the same model on
  // the CPU the bound of test_render_lit_models holds (2e-2, Heidrich-Seidel's horizon).
  for (const char* model : {"ashikhmin-shirley", "banks", "blinn-phong", "ward", "heidrich-seidel"})
  {
    const auto lit =
        select([&](const auto& x) { return x.at("kind") == "lit" && x.at("model") == model; });
    ASSERT_EQ(lit.size(), 1u) << model;
    EXPECT_EQ(lit[0].at("mesh"), "sphere");
    EXPECT_EQ(lit[0].at("lights"), "2");
    EXPECT_LT(std::stod(lit[0].at("relative_l2")), 2e-2) << model;
  }

  // LEADR at grids 1 and 4 and normal mapping at 4, at one distance (a mip level above 0); with
  // the relief far below a pixel, LEADR keeps closer to the supersampled reference.
  const auto leadr = select([](const auto& x) { return x.at("model") == "leadr"; });
  const auto normalMap = select([](const auto& x) { return x.at("model") == "normal-map"; });
  ASSERT_EQ(leadr.size(), 2u);
  ASSERT_EQ(normalMap.size(), 1u);
  EXPECT_EQ(leadr[0].at("grid"), "1");
  EXPECT_EQ(leadr[1].at("grid"), "4");
  EXPECT_EQ(normalMap[0].at("grid"), "4");
  EXPECT_GT(std::stod(leadr[1].at("mip_level")), 1.0);
  EXPECT_LT(std::stod(leadr[1].at("relative_l2")), std::stod(normalMap[0].at("relative_l2")));

  // Microstructure: the full grid at K = 1, 2, 4, 8 and the jittered one at K = 4. The error
  // against the converged evaluation may not rise from one K to the next by more than 10% (a
  // regular grid can alias with the structure's period) and must halve from K = 1 to K = 8.
  const auto full = select([](const auto& x)
                           { return x.at("kind") == "micro" && x.at("method") == "full-grid"; });
  const auto jittered =
      select([](const auto& x) { return x.at("kind") == "micro" && x.at("method") == "jittered"; });
  ASSERT_EQ(full.size(), 4u);
  ASSERT_EQ(jittered.size(), 1u);
  EXPECT_EQ(jittered[0].at("grid"), "4");
  for (std::size_t i = 0; i < full.size(); ++i)
  {
    EXPECT_EQ(std::stoi(full[i].at("grid")), 1 << i);
    if (i > 0)
    {
      EXPECT_LT(std::stod(full[i].at("relative_l2")),
                1.1 * std::stod(full[i - 1].at("relative_l2")))
          << "K = " << full[i].at("grid") << " against K = " << full[i - 1].at("grid");
    }
  }
  EXPECT_LT(2.0 * std::stod(full[3].at("relative_l2")), std::stod(full[0].at("relative_l2")));

  EXPECT_NE(md.find("### Other shading models"), std::string::npos);
  const std::string modelsSvg = slurp(path("out") / "bench_models.svg");
  EXPECT_EQ(modelsSvg.rfind("<svg", 0), 0u);
}

TEST_F(BenchCommand, HdriQuickRunHasItsRows)
{
  if (!haveDisplay())
  {
    GTEST_SKIP() << "no X display: run under xvfb-run (./test does)";
  }
  const Outcome r = run({"bench", "--quick", "--models", "hdri", "--out", path("out").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  for (const char* file : {"bench.csv", "bench.md", "bench_hdri.svg", "bench_hdri.png"})
  {
    EXPECT_TRUE(fs::is_regular_file(path("out") / file)) << file;
  }
  const auto rows = readCsv(slurp(path("out") / "bench.csv"));
  // Per environment: its auto resolution and whether its analysis lists a sun.
  const std::map<std::string, std::pair<std::string, std::string>> environments{
      {"builtin:studio", {"exact+auto(off)", "no sun"}},
      {"builtin:sunsky", {"exact+auto(sources)", "sun"}}};
  auto count = [&](const std::function<bool(const std::map<std::string, std::string>&)>& f)
  { return std::count_if(rows.begin(), rows.end(), f); };
  std::size_t expected = 0;
  for (const auto& [environment, expectation] : environments)
  {
    for (const std::string lobe : {"10,10", "1000,100"})
    {
      const auto in = [&, environment = environment](const std::map<std::string, std::string>& x)
      {
        return x.at("environment") == environment && x.at("mesh") == "sphere" &&
               x.at("nu") + "," + x.at("nv") == lobe;
      };
      EXPECT_EQ(count(
                    [&](const auto& x)
                    {
                      return in(x) && x.at("kind") == "hdri" && x.at("method") == "split-sum" &&
                             x.at("filtered") == "off" && x.at("half_vectors") == "lut" &&
                             x.at("samples") == "256" && x.at("frames") == "1";
                    }),
                1)
          << environment << " " << lobe << ": the published method";
      std::map<std::string, std::map<int, double>> errors; // method, frames: error
      for (const std::string& method :
           {expectation.first, std::string("exact"), std::string("exact+mis"),
            std::string("exact+sources"), std::string("exact+sources(pixel)")})
      {
        for (int frames : {1, 4, 16})
        {
          EXPECT_EQ(count(
                        [&](const auto& x)
                        {
                          if (!(in(x) && x.at("kind") == "hdri-progressive" &&
                                x.at("method") == method && x.at("filtered") == "on" &&
                                x.at("half_vectors") == "lut" && x.at("samples") == "16" &&
                                std::stoi(x.at("frames")) == frames))
                          {
                            return false;
                          }
                          errors[method][frames] = std::stod(x.at("relative_l2"));
                          return true;
                        }),
                    1)
              << environment << " " << lobe << " " << method << " x " << frames;
        }
      }
      // The window's still view (the defaults: stopped by its own error estimate, from 16
      // frames, at most 256): at the stop the estimate within 3/4 of 1% (or the most reached),
      // and the error against the reference within 1% (bench G1).
      EXPECT_EQ(count(
                    [&](const auto& x)
                    {
                      if (!(in(x) && x.at("kind") == "hdri-still" &&
                            x.at("method") == expectation.first && x.at("samples") == "16"))
                      {
                        return false;
                      }
                      const int frames = std::stoi(x.at("frames"));
                      const double estimate = std::stod(x.at("estimated_error"));
                      EXPECT_GE(frames, 16) << environment << " " << lobe;
                      EXPECT_LE(frames, 256) << environment << " " << lobe;
                      EXPECT_GE(estimate, 0.0) << environment << " " << lobe;
                      EXPECT_TRUE(frames == 256 || estimate <= 0.75 * 0.01)
                          << environment << " " << lobe << ": " << estimate;
                      EXPECT_LE(std::stod(x.at("relative_l2")), 0.01) << environment << " " << lobe;
                      return true;
                    }),
                1)
          << environment << " " << lobe << ": the still view";
      expected += 1 + 5 * 3 + 1;
      // Under the sun lobe samples alone miss the disc; the default (sources, the points the
      // frame's pixels share) does not, nor each pixel's own source samples: at 16 frames of 16
      // samples at least 4 times closer (test_render_sources bounds its own scene the same way).
      if (expectation.second == "sun")
      {
        EXPECT_LT(4.0 * errors[expectation.first][16], errors["exact"][16]) << lobe;
        EXPECT_LT(4.0 * errors["exact+sources(pixel)"][16], errors["exact"][16]) << lobe;
      }
    }
  }
  EXPECT_EQ(rows.size(), expected) << "rows of other families or of the default scene";
  for (const auto& x : rows)
  {
    const std::string what = x.at("environment") + " " + x.at("nu") + "," + x.at("nv") + " " +
                             x.at("method") + " x " + x.at("frames");
    const double error = std::stod(x.at("relative_l2"));
    EXPECT_TRUE(std::isfinite(error) && error > 0.0) << what;
    EXPECT_LT(std::stod(x.at("reference_bound")), error) << what;
    EXPECT_GT(std::stod(x.at("median_frame_ms")), 0.0) << what;
    const auto found = environments.find(x.at("environment"));
    ASSERT_NE(found, environments.end()) << what;
    EXPECT_EQ(x.at("variant"), found->second.second) << what;
  }
  const std::string md = slurp(path("out") / "bench.md");
  EXPECT_NE(md.find("## Real HDRIs with the default settings (issue 14)"), std::string::npos);
  EXPECT_NE(md.find("G4: the default scene"), std::string::npos);
  EXPECT_EQ(slurp(path("out") / "bench_hdri.svg").rfind("<svg", 0), 0u);
}

// `--models` takes a comma-separated subset of the families in any order and refuses an
// unknown, repeated or missing name, naming the option. Without it every family but hdri runs.
TEST(BenchFamilies, ParsesTheListAndRefusesUnknownOrRepeatedNames)
{
  EXPECT_EQ(parseBenchFamilies("micro,lit"), (std::vector<std::string>{"micro", "lit"}));
  EXPECT_EQ(parseBenchFamilies("as-env,lit,leadr,micro"), defaultBenchFamilies());
  EXPECT_EQ(parseBenchFamilies("as-env,lit,leadr,micro,hdri"), benchFamilies());
  EXPECT_EQ(parseBenchFamilies("hdri"), (std::vector<std::string>{"hdri"}));
  for (const char* bad : {"lit,gpu", "lit,lit", "", "lit,,micro"})
  {
    try
    {
      parseBenchFamilies(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    }
    catch (const Error& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind("--models: ", 0), 0u) << e.what();
    }
  }
}

// The rays through the pixels of a perspective camera hit the faceted built-in sphere where
// they hit the analytic unit sphere, within the facets' sag, with the analytic normal and the
// tangent along the parallels.
TEST(PixelGeometry, MatchesTheAnalyticSphere)
{
  const BenchMesh sphere = makeBenchMesh("sphere");
  const glm::dmat4 worldToClip =
      glm::perspective(glm::radians(30.0), 1.0, 0.5, 10.0) *
      glm::lookAt(glm::dvec3(0.0, -4.0, 0.0), glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1.0));
  const glm::dmat4 clipToWorld = glm::inverse(worldToClip);
  const int size = 48;
  const std::vector<PixelSample> pixels = castPixels(sphere.triangles, clipToWorld, size, size);
  int compared = 0;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      const PixelRay ray = pixelRay(clipToWorld, x, y, size, size);
      const double b = glm::dot(ray.origin, ray.direction);
      const double discriminant = b * b - (glm::dot(ray.origin, ray.origin) - 1.0);
      const PixelSample& s = pixels[std::size_t(y) * size + x];
      if (discriminant < 0.0)
      {
        EXPECT_FALSE(s.hit) << x << "," << y;
        continue;
      }
      const glm::dvec3 hit = ray.origin + (-b - std::sqrt(discriminant)) * ray.direction;
      if (glm::dot(hit, -ray.direction) < 0.2 || std::abs(hit.z) > 0.95)
      {
        continue; // near the silhouette or the poles the facets decide
      }
      ASSERT_TRUE(s.hit) << x << "," << y;
      ++compared;
      // 128 segments around and 64 from pole to pole: a facet lies at most
      // (half its diagonal)^2 / 2 = 6.1e-4 inside the sphere, and the ray runs 1 / (n.v) times
      // that between the two surfaces.
      EXPECT_LT(glm::length(s.position - hit), 6.2e-4 / glm::dot(hit, -ray.direction));
      EXPECT_GT(glm::dot(s.normal, hit), 0.9999);
      EXPECT_NEAR(glm::dot(s.view, -ray.direction), 1.0, 1e-12);
      const glm::dvec3 parallel = glm::normalize(glm::dvec3(-hit.y, hit.x, 0.0));
      EXPECT_GT(glm::dot(s.tangent, parallel), 0.999);
      EXPECT_NEAR(glm::dot(s.tangent, s.normal), 0.0, 1e-12);
    }
  }
  EXPECT_GT(compared, 600);
}

// The flange is closed and manifold, wound outwards: its volume by the divergence theorem
// matches the volume of the solid computed from its dimensions (Pappus for the turned rings).
TEST(FlangeMesh, ClosedOutwardAndOfTheRightVolume)
{
  vtkSmartPointer<vtkPolyData> flange = makeFlange();
  const EdgeCounts edges = countEdges(flange);
  EXPECT_EQ(edges.boundary, 0);
  EXPECT_EQ(edges.nonManifold, 0);
  double volume = 0.0;
  for (vtkIdType c = 0; c < flange->GetNumberOfCells(); ++c)
  {
    double p[3][3];
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    flange->GetCellPoints(c, count, ids);
    ASSERT_EQ(count, 3);
    for (int i = 0; i < 3; ++i)
    {
      flange->GetPoint(ids[i], p[i]);
    }
    const glm::dvec3 a(p[0][0], p[0][1], p[0][2]);
    const glm::dvec3 b(p[1][0], p[1][1], p[1][2]);
    const glm::dvec3 d(p[2][0], p[2][1], p[2][2]);
    volume += glm::dot(a, glm::cross(b, d)) / 6.0;
  }
  // Flange disc r 0.25..1 x 0.18, minus the rim chamfer (a triangle of legs 0.03 at radius
  // 1 - 0.01), minus six holes of radius 0.07; hub r 0.25..0.42 from 0.18 to 0.55, minus its
  // chamfer (legs 0.03 at radius 0.42 - 0.01), plus the fillet (the square of side 0.06 in the
  // corner minus the quarter disc centred at its far corner).
  const double pi = M_PI;
  const double disc = pi * (1.0 - 0.25 * 0.25) * 0.18;
  const double rimChamfer = 2.0 * pi * (1.0 - 0.01) * 0.5 * 0.03 * 0.03;
  const double holes = 6.0 * pi * 0.07 * 0.07 * 0.18;
  const double hub = pi * (0.42 * 0.42 - 0.25 * 0.25) * (0.55 - 0.18);
  const double hubChamfer = 2.0 * pi * (0.42 - 0.01) * 0.5 * 0.03 * 0.03;
  const double filletArea = 0.06 * 0.06 * (1.0 - pi / 4.0);
  const double filletCentroid = 0.42 + 0.06 * (5.0 / 6.0 - pi / 4.0) / (1.0 - pi / 4.0);
  const double fillet = 2.0 * pi * filletCentroid * filletArea;
  const double expected = disc - rimChamfer - holes + hub - hubChamfer + fillet;
  // 192 segments around and 88-gon holes: the polygons hold about 0.02% less area; 8 segments
  // make the fillet's arc.
  EXPECT_NEAR(volume / expected, 1.0, 1e-3);
}

// The PNG shows what the SVG describes: the same size, and the series drawn in its colour.
TEST(Plot, RasterMatchesTheSvg)
{
  Figure figure;
  figure.title = "error against time";
  figure.columns = 1;
  PlotPanel panel;
  panel.title = "panel";
  panel.xLabel = "time [s]";
  panel.yLabel = "error";
  PlotSeries series;
  series.label = "series";
  series.color = {0.0, 0.0, 1.0};
  series.connect = true;
  series.points = {{0.01, 1.0}, {0.1, 0.1}, {1.0, 0.01}};
  panel.series = {series};
  figure.panels = {panel};
  const std::string svg = figureToSvg(figure);
  const Image image = figureToImage(figure);
  EXPECT_NE(svg.find("width=\"" + std::to_string(image.width) + "\""), std::string::npos);
  EXPECT_NE(svg.find("height=\"" + std::to_string(image.height) + "\""), std::string::npos);
  EXPECT_NE(svg.find("rgb(0,0,255)"), std::string::npos);
  int blue = 0;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      blue += image.at(x, y, 2) > 0.9f && image.at(x, y, 0) < 0.1f && image.at(x, y, 1) < 0.1f;
    }
  }
  // Two decades of a 2-pixel line on each axis and the markers: hundreds of pixels.
  EXPECT_GT(blue, 300);
}
} // namespace
} // namespace aniso_test
