// `aniso render --model/--light/--sample-material` end to end: runs the built executable.
//  - --help lists the three options and every registered model and sample material.
//  - Bad values end with one line "aniso: SUBJECT: reason" (exit 2) and write nothing: an
//    unknown model, a malformed light, lights or a sample material for the environment model,
//    more lights than the shader holds.
//  - An EXR of a lit model holds the model's radiance: for the built-in sphere, a uniform
//    material from --nu/--nv/--f0/--albedo and one light, the covered pixels agree with the
//    core's CPU evaluation (core/models/models.h) of the same material, frame and light
//    (relative L2 below 5e-3, measured 7.6e-4: float shading on the default, coarser sphere mesh).
//  - --env-lights on adds the environment's sources: under the sun-sky, the sun's light.
//  - --compare M1,M2 writes the models' images side by side, each tile the same agreement with
//    its own model; --compare with --model, or with a model it cannot show, is a usage error.
#include "core/env/env_sources.h"
#include "core/env/environment.h"
#include "core/image/image.h"
#include "core/lights/env_lights.h"
#include "core/models/models.h"
#include "tests/app/cli_runner.h"
#include "tests/vtkpasses/render/render_test_helpers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace
{
using aniso_test::Outcome;
using RenderModelsCli = aniso_test::CliTest;

void expectOneLineError(const Outcome& r, const std::string& subject)
{
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err.rfind("aniso: " + subject + ":", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(RenderModelsCli, HelpListsModelsAndSampleMaterials)
{
  const Outcome r = run({"render", "--help"});
  EXPECT_EQ(r.exitCode, 0);
  for (const char* option : {"--model ", "--light ", "--sample-material "})
  {
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
  for (const aniso::ShadingModelInfo& model : aniso::shadingModels())
  {
    EXPECT_NE(r.out.find(std::string(model.name)), std::string::npos) << model.name;
  }
  for (const aniso::SampleMaterialInfo& sample : aniso::sampleMaterials())
  {
    EXPECT_NE(r.out.find(std::string(sample.name)), std::string::npos) << sample.name;
  }
}

TEST_F(RenderModelsCli, BadModelOptionsNameTheArgument)
{
  const std::string out = path("a.png").string();
  expectOneLineError(run({"render", "--builtin", "sphere", "--model", "phong", "-o", out}),
                     "--model");
  expectOneLineError(
      run({"render", "--builtin", "sphere", "--model", "banks", "--light", "sun:1", "-o", out}),
      "light \"sun:1\"");
  expectOneLineError(run({"render", "--builtin", "sphere", "--light", "dir:0,0,1:1", "-o", out}),
                     "--light");
  expectOneLineError(
      run({"render", "--builtin", "sphere", "--sample-material", "marble", "-o", out}),
      "--sample-material");
  std::vector<std::string> tooMany = {"render", "--builtin", "sphere", "--model", "ward"};
  for (int i = 0; i < 9; ++i)
  {
    tooMany.insert(tooMany.end(), {"--light", "dir:0,-1,1:1"});
  }
  tooMany.insert(tooMany.end(), {"-o", out});
  expectOneLineError(run(tooMany), "--light");
  EXPECT_TRUE(files().empty());
}

constexpr int kSize = 48;
const char* const kLight = "point:-1,-3,2:8";

// Relative L2 between the tile of IMAGE starting at column X0 and the CPU evaluation of MODEL
// for the uniform material of --nu 30 --nv 8 --f0 0.6 --albedo 0.2,0.3,0.4 under LIGHTS
// (kLight when empty).
double tileError(const aniso::Image& image, int x0, aniso::LitModel model,
                 std::vector<aniso::Light> lights = {})
{
  const aniso::SvTexel texel =
      aniso::uniformTexel({30.0, 8.0}, glm::dvec3(0.6), glm::dvec3(0.2, 0.3, 0.4));
  if (lights.empty())
  {
    lights = {aniso::parseLight(kLight)};
  }
  const aniso::CameraPlacement camera =
      aniso::placeCamera(aniso::defaultViewSettings(), glm::dvec3(0.0), 1.0);
  double diff = 0.0;
  double norm = 0.0;
  int pixels = 0;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      const aniso::test::Ray ray = aniso::test::pixelRay(camera, x, y, kSize, kSize);
      const auto hit = aniso::test::hitUnitSphere(ray);
      if (!hit || glm::dot(*hit, -ray.direction) < 0.2 || std::abs(hit->z) > 0.95)
      {
        continue;
      }
      const glm::dvec3 n = *hit;
      const aniso::Frame frame =
          aniso::svShadingFrame(n, glm::normalize(glm::dvec3(-n.y, n.x, 0.0)), texel);
      const glm::dvec3 expected =
          aniso::shadeLitModel(model, texel, frame, n, -ray.direction, lights);
      for (int c = 0; c < 3; ++c)
      {
        const double d = image.at(x0 + x, y, c) - expected[c];
        diff += d * d;
        norm += expected[c] * expected[c];
      }
      ++pixels;
    }
  }
  EXPECT_GT(pixels, kSize * kSize / 4);
  const double error = std::sqrt(diff / norm);
  std::printf("%s through the CLI: relative L2 %.2e over %d pixels\n",
              std::string(aniso::litModelName(model)).c_str(), error, pixels);
  return error;
}

std::vector<std::string> litArguments(const std::string& output)
{
  return {"--builtin",    "sphere",
          "--nu",         "30",
          "--nv",         "8",
          "--f0",         "0.6",
          "--albedo",     "0.2,0.3,0.4",
          "--light",      kLight,
          "--size",       std::to_string(kSize),
          "--frames",     "1",
          "--jitter",     "off",
          "--background", "none",
          "--env-lights", "off",
          "-o",           output};
}

TEST_F(RenderModelsCli, ExrHoldsTheModelRadiance)
{
  ANISO_REQUIRE_DISPLAY();
  const std::string exr = path("ward.exr").string();
  std::vector<std::string> args = {"render", "--model", "ward"};
  const std::vector<std::string> rest = litArguments(exr);
  args.insert(args.end(), rest.begin(), rest.end());
  const Outcome r = run(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const aniso::Image image = aniso::readImage(exr);
  ASSERT_EQ(image.width, kSize);
  EXPECT_EQ(aniso::test::nonFiniteValues(image), 0);
  EXPECT_LT(tileError(image, 0, aniso::LitModel::Ward), 5e-3);
}

// With --env-lights on, the environment's sources light the model too: under the built-in
// sun-sky turned by 30 degrees, the EXR holds the CPU evaluation under kLight and the sun's
// light as core/lights/env_lights.h makes it from the analysis (the same bound); without them
// (kLight alone) it differs by far more.
TEST_F(RenderModelsCli, EnvLightsAddTheSunSkysSun)
{
  ANISO_REQUIRE_DISPLAY();
  const std::string exr = path("ward_sun.exr").string();
  std::vector<std::string> args = {"render", "--model", "ward"};
  std::vector<std::string> rest = litArguments(exr);
  const auto option = std::find(rest.begin(), rest.end(), "--env-lights");
  ASSERT_NE(option, rest.end());
  *(option + 1) = "on";
  args.insert(args.end(), rest.begin(), rest.end());
  args.insert(args.end(), {"--env", "builtin:sunsky", "--env-rotation", "30"});
  const Outcome r = run(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("the environment's sources"), std::string::npos) << r.out;
  const aniso::Image image = aniso::readImage(exr);
  std::vector<aniso::Light> lights = {aniso::parseLight(kLight)};
  aniso::EnvLightOptions options;
  options.maxLights = 7;
  const std::vector<aniso::Light> sources = aniso::environmentSourceLights(
      *aniso::sharedEnvironmentAnalysis(*aniso::openEnvironment("builtin:sunsky")), 30.0, options);
  ASSERT_FALSE(sources.empty());
  lights.insert(lights.end(), sources.begin(), sources.end());
  const double with = tileError(image, 0, aniso::LitModel::Ward, lights);
  const double without = tileError(image, 0, aniso::LitModel::Ward);
  std::printf("env-lights through the CLI: %.2e against kLight and the sun, %.2e against kLight "
              "alone\n",
              with, without);
  EXPECT_LT(with, 5e-3);
  EXPECT_GT(without, 0.1);
}

// --compare puts one tile per model side by side, each the radiance of its model.
TEST_F(RenderModelsCli, CompareTilesHoldEachModel)
{
  ANISO_REQUIRE_DISPLAY();
  const std::string out = path("a.png").string();
  expectOneLineError(run({"render", "--builtin", "sphere", "--model", "ward", "--compare",
                          "ward,banks", "-o", out}),
                     "--compare");
  expectOneLineError(run({"render", "--builtin", "sphere", "--compare", "ward,phong", "-o", out}),
                     "--compare");
  const std::string exr = path("compare.exr").string();
  std::vector<std::string> args = {"render", "--compare", "banks,blinn-phong"};
  const std::vector<std::string> rest = litArguments(exr);
  args.insert(args.end(), rest.begin(), rest.end());
  const Outcome r = run(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const aniso::Image image = aniso::readImage(exr);
  ASSERT_EQ(image.width, 2 * kSize);
  ASSERT_EQ(image.height, kSize);
  EXPECT_EQ(aniso::test::nonFiniteValues(image), 0);
  EXPECT_LT(tileError(image, 0, aniso::LitModel::Banks), 5e-3);
  EXPECT_LT(tileError(image, kSize, aniso::LitModel::BlinnPhong), 5e-3);
}
} // namespace
