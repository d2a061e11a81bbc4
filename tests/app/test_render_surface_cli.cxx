// `aniso render --model leadr|microstructure` end to end (runs the built executable):
//  - their options are refused with the wrong model, and LEADR takes one relief, each with one
//    line "aniso: SUBJECT: reason" and exit code 2; a mesh without texture coordinates is
//    refused by both models (exit code 1, "aniso: mesh: ...") and nothing is written;
//  - LEADR reads --height-map: on a flat map (no slope variance) plain normal mapping and LEADR
//    are the same model and render the same image, on a bumpy one they differ;
//  - the microstructure options reach the shader: the silk weave (crimson and gold threads)
//    renders redder than the grey pyramids (R/G of the image mean), under every option set.
// Every output is finite and covers pixels.
#include "core/image/image.h"
#include "tests/app/cli_runner.h"
#include "tests/vtkpasses/render/render_test_helpers.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace
{
using aniso_test::Outcome;
using SurfaceCli = aniso_test::CliTest;

void expectOneLineError(const Outcome& r, const std::string& subject)
{
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err.rfind("aniso: " + subject + ":", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// Mean RGB over covered pixels, and their count.
glm::dvec3 meanColour(const aniso::Image& image, int& covered)
{
  glm::dvec3 sum(0.0);
  covered = 0;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      if (image.at(x, y, 3) > 0.0f)
      {
        ++covered;
        sum += glm::dvec3(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
      }
    }
  }
  return covered > 0 ? sum / double(covered) : sum;
}

double largestDifference(const aniso::Image& a, const aniso::Image& b)
{
  double largest = 0.0;
  for (std::size_t i = 0; i < a.data.size() && i < b.data.size(); ++i)
  {
    largest = std::max(largest, double(std::abs(a.data[i] - b.data[i])));
  }
  return largest;
}

TEST_F(SurfaceCli, OptionsBelongToTheirModel)
{
  const std::string out = path("a.exr").string();
  expectOneLineError(
      run({"render", "--builtin", "plate", "--model", "leadr", "--structure", "silk", "-o", out}),
      "--structure");
  expectOneLineError(run({"render", "--builtin", "plate", "--leadr-tiles", "4", "-o", out}),
                     "--leadr-tiles");
  expectOneLineError(run({"render", "--builtin", "plate", "--model", "microstructure",
                          "--leadr-filter", "normal-mapping", "-o", out}),
                     "--leadr-filter");
  aniso::Image height(8, 8, 1);
  aniso::writeImage(path("h.exr").string(), height);
  aniso::Image normals(8, 8, 3);
  aniso::writeImage(path("n.exr").string(), normals);
  expectOneLineError(
      run({"render", "--builtin", "plate", "--model", "leadr", "--height-map",
           path("h.exr").string(), "--normal-map", path("n.exr").string(), "-o", out}),
      "--normal-map");
}

TEST_F(SurfaceCli, MeshesWithoutTextureCoordinatesAreRefused)
{
  ANISO_REQUIRE_DISPLAY();
  {
    std::ofstream off(path("tetra.off"));
    off << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  }
  for (const char* model : {"leadr", "microstructure"})
  {
    const std::string out = path(std::string(model) + ".png").string();
    const Outcome r = run({"render", path("tetra.off").string(), "--model", model, "--size", "16",
                           "--frames", "1", "-o", out});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err.rfind("aniso: mesh:", 0), 0u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << model;
  }
}

TEST_F(SurfaceCli, LeadrReadsTheHeightMap)
{
  ANISO_REQUIRE_DISPLAY();
  aniso::Image flat(16, 16, 1);
  aniso::Image bumpy(16, 16, 1);
  for (int y = 0; y < 16; ++y)
  {
    for (int x = 0; x < 16; ++x)
    {
      bumpy.at(x, y, 0) = float(0.05 * std::sin(2.0 * M_PI * 2.0 * x / 16.0) *
                                std::sin(2.0 * M_PI * 3.0 * y / 16.0));
    }
  }
  aniso::writeImage(path("flat.exr").string(), flat);
  aniso::writeImage(path("bumpy.exr").string(), bumpy);
  auto render = [&](const std::string& map, const std::string& filter)
  {
    const std::string out = path(map + "_" + filter + ".exr").string();
    const Outcome r = run({"render",
                           "--builtin",
                           "plate",
                           "--model",
                           "leadr",
                           "--height-map",
                           path(map + ".exr").string(),
                           "--leadr-filter",
                           filter,
                           "--leadr-tiles",
                           "16",
                           "--elevation",
                           "40",
                           "--background",
                           "none",
                           "--size",
                           "32",
                           "--frames",
                           "1",
                           "--jitter",
                           "off",
                           "-o",
                           out});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return aniso::readImage(out);
  };
  const aniso::Image flatLeadr = render("flat", "leadr");
  const aniso::Image flatNormals = render("flat", "normal-mapping");
  const aniso::Image bumpyLeadr = render("bumpy", "leadr");
  const aniso::Image bumpyNormals = render("bumpy", "normal-mapping");
  for (const aniso::Image* image : {&flatLeadr, &flatNormals, &bumpyLeadr, &bumpyNormals})
  {
    int covered = 0;
    const glm::dvec3 mean = meanColour(*image, covered);
    EXPECT_GT(covered, 100);
    EXPECT_GT(mean.x + mean.y + mean.z, 0.0);
    EXPECT_EQ(aniso::test::nonFiniteValues(*image), 0);
  }
  EXPECT_LT(largestDifference(flatLeadr, flatNormals), 1e-5);
  EXPECT_GT(largestDifference(bumpyLeadr, bumpyNormals), 1e-2);
}

TEST_F(SurfaceCli, MicrostructureOptionsReachTheShader)
{
  ANISO_REQUIRE_DISPLAY();
  const std::vector<std::vector<std::string>> optionSets = {
      {"--grid", "2", "--masking", "pom", "--self-shadow", "on"},
      {"--grid", "3", "--jitter-grid", "on", "--masking", "parallax", "--micro-brdf", "blinn-phong",
       "--blinn-exponent", "40"},
      {"--grid", "1", "--masking", "normal", "--micro-roughness", "0.1", "--structure-depth", "0.3",
       "--structure-tiles", "10"}};
  for (const auto& options : optionSets)
  {
    double redness[2] = {0.0, 0.0};
    int k = 0;
    for (const char* structure : {"silk", "pyramids"})
    {
      const std::string out = path(std::string(structure) + ".exr").string();
      std::vector<std::string> args = {"render",
                                       "--builtin",
                                       "sphere",
                                       "--model",
                                       "microstructure",
                                       "--structure",
                                       structure,
                                       "--background",
                                       "none",
                                       "--size",
                                       "32",
                                       "--frames",
                                       "1",
                                       "-o",
                                       out};
      args.insert(args.end(), options.begin(), options.end());
      const Outcome r = run(args);
      ASSERT_EQ(r.exitCode, 0) << r.err;
      const aniso::Image image = aniso::readImage(out);
      EXPECT_EQ(aniso::test::nonFiniteValues(image), 0);
      int covered = 0;
      const glm::dvec3 mean = meanColour(image, covered);
      EXPECT_GT(covered, 100);
      redness[k++] = mean.x / std::max(mean.y, 1e-12);
    }
    EXPECT_GT(redness[0], 1.2 * redness[1]) << options[1];
  }
}
} // namespace
