// `aniso render` end to end: runs the built executable.
//  - Bad command lines and bad inputs end with exactly one line "aniso: SUBJECT: reason" naming
//    the argument or the file (exit 2 for usage, 1 for run-time failures) and write nothing;
//    a degenerate mesh is refused, not rendered or crashed on.
//  - --help lists every option of the issue with its help text.
//  - An EXR holds linear radiance: for the built-in sphere with F0 = 1, the centre of the image
//    agrees with the CPU reference integrator for the same lobe, view and pixels; PNGs are 8-bit
//    RGB, or RGBA with --background none; --time reports the frame time.
//  - A flat part (the built-in plate) is seen by default: the share of covered pixels is the
//    pinhole projection's of its corners for the default (three-quarter) view, and near none
//    from the front view (edge-on).
//  - --converge stops by the frames' own error estimate (from 16 frames, before the most, the
//    estimate within 3/4 of the target) and says so; --frames caps it; 0 is refused.
//  - The environment's sources are printed: under builtin:sunsky one line names the sun at an
//    azimuth and elevation that, read as --azimuth and --elevation read them
//    (viewDirectionFromAngles), point at SunSkyEnvironment's own sun direction; under
//    builtin:white (uniform) nothing is printed of the environment.
#include "core/env/environment.h"
#include "core/env/sun_sky.h"
#include "core/frame.h"
#include "core/image/image.h"
#include "core/reference/reference_integrator.h"
#include "tests/app/cli_runner.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/render/ViewSettings.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using aniso_test::Outcome;
using RenderCli = aniso_test::CliTest;

// Exactly one line on stderr, starting with "aniso: SUBJECT:".
void expectOneLineError(const Outcome& r, int exitCode, const std::string& subject)
{
  EXPECT_EQ(r.exitCode, exitCode) << r.err;
  EXPECT_EQ(r.err.rfind("aniso: " + subject + ":", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(RenderCli, HelpListsEveryOption)
{
  const Outcome r = run({"render", "--help"});
  EXPECT_EQ(r.exitCode, 0);
  for (const char* option :
       {"--builtin",      "--env",        "--env-rotation",   "--nu",       "--nv",
        "--f0",           "--albedo",     "--method",         "--filtered", "--samples",
        "--frames",       "--normal-map", "--quaternion-map", "--tpr",      "--height-map",
        "--height-scale", "--tangents",   "--size",           "--view",     "--azimuth",
        "--elevation",    "--ortho",      "--background",     "--exposure", "--output",
        "--time"})
  {
    EXPECT_NE(r.out.find(std::string(option) + " "), std::string::npos) << option;
  }
}

TEST_F(RenderCli, UsageErrorsNameTheArgument)
{
  expectOneLineError(run({"render", "-o", path("a.png").string()}), 2, "MESH");
  expectOneLineError(run({"render", "--builtin", "cube", "-o", path("a.png").string()}), 2,
                     "--builtin");
  expectOneLineError(run({"render", "--builtin", "sphere", "-o", path("a.jpg").string()}), 2,
                     path("a.jpg").string());
  expectOneLineError(
      run({"render", "--builtin", "sphere", "--size", "0x4", "-o", path("a.png").string()}), 2,
      "--size");
  expectOneLineError(
      run({"render", "--builtin", "sphere", "--nu", "-3", "-o", path("a.png").string()}), 2,
      "--nu");
  expectOneLineError(
      run({"render", "--builtin", "sphere", "--view", "up", "-o", path("a.png").string()}), 2,
      "--view");
  expectOneLineError(
      run({"render", "--builtin", "sphere", "--background", "blue", "-o", path("a.png").string()}),
      2, "--background");
  expectOneLineError(
      run({"render", "--builtin", "sphere", "--ortho=1", "-o", path("a.png").string()}), 2,
      "--ortho");
  EXPECT_TRUE(files().empty());
}

TEST_F(RenderCli, InputErrorsNameTheFile)
{
  const std::string missing = path("missing.obj").string();
  expectOneLineError(run({"render", missing, "-o", path("a.png").string()}), 1, missing);

  // Every triangle has zero area: nothing is left to render.
  const std::string flat = path("flat.obj").string();
  std::ofstream(flat) << "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n";
  expectOneLineError(run({"render", flat, "-o", path("a.png").string()}), 1, flat);

  const std::string env = path("sky.exr").string();
  expectOneLineError(
      run({"render", "--builtin", "sphere", "--env", env, "-o", path("a.png").string()}), 1, env);
  EXPECT_EQ(files(), (std::set<std::string>{"flat.obj"}));
}

TEST_F(RenderCli, ExrIsLinearRadianceThatMatchesTheReference)
{
  ANISO_REQUIRE_DISPLAY();
  const std::string out = path("sphere.exr").string();
  const Outcome r = run({"render", "--builtin",
                         "sphere", "--nu",
                         "2000",   "--nv",
                         "200",    "--f0",
                         "1",      "--method",
                         "exact",  "--filtered",
                         "off",    "--half-vectors",
                         "shader", "--samples",
                         "16",     "--frames",
                         "16",     "--jitter",
                         "off",    "--background",
                         "none",   "--size",
                         "40x40",  "-o",
                         out});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const aniso::Image image = aniso::readImage(out);
  ASSERT_EQ(image.width, 40);
  ASSERT_EQ(image.height, 40);
  ASSERT_EQ(image.channels, 4);
  EXPECT_EQ(aniso::test::nonFiniteValues(image), 0);

  // The 8 x 8 pixels around the centre, averaged (the mean's sampling error is small).
  const aniso::CameraPlacement camera =
      aniso::placeCamera(aniso::defaultViewSettings(), glm::dvec3(0.0), 1.0);
  const aniso::StudioEnvironment env;
  glm::dvec3 rendered(0.0);
  glm::dvec3 expected(0.0);
  for (int y = 16; y < 24; ++y)
  {
    for (int x = 16; x < 24; ++x)
    {
      const aniso::test::Ray ray = aniso::test::pixelRay(camera, x, y, 40, 40);
      const glm::dvec3 n = *aniso::test::hitUnitSphere(ray);
      const aniso::Frame frame = aniso::Frame::fromNormalTangent(n, {-n.y, n.x, 0.0});
      expected +=
          aniso::integrateSpecular({2000.0, 200.0}, glm::dvec3(1.0), frame, -ray.direction, env)
              .value;
      for (int c = 0; c < 3; ++c)
      {
        rendered[c] += image.at(x, y, c);
      }
      EXPECT_EQ(image.at(x, y, 3), 1.0f);
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(rendered[c] / expected[c], 1.0, 0.02) << "channel " << c;
  }
  EXPECT_EQ(image.at(0, 0, 3), 0.0f); // a corner: background, no coverage
}

TEST_F(RenderCli, PngAndTimes)
{
  ANISO_REQUIRE_DISPLAY();
  const std::string opaque = path("torus.png").string();
  const Outcome r =
      run({"render", "--builtin", "torus", "--size", "32x24", "--frames", "2", "--samples", "2",
           "--azimuth", "30", "--elevation", "40", "--ortho", "--time", "-o", opaque});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("median frame"), std::string::npos) << r.out;
  aniso::ImageInfo info;
  const aniso::Image rgb = aniso::readImage(opaque, &info);
  EXPECT_EQ(rgb.width, 32);
  EXPECT_EQ(rgb.height, 24);
  EXPECT_EQ(info.fileChannels, 3);
  EXPECT_TRUE(info.integerFormat);

  const std::string transparent = path("plate.png").string();
  ASSERT_EQ(
      run({"render", "--builtin", "plate", "--tpr", "circular", "--view", "+z", "--background",
           "none", "--size", "24x24", "--frames", "1", "--samples", "2", "-o", transparent})
          .exitCode,
      0);
  const aniso::Image rgba = aniso::readImage(transparent, &info);
  EXPECT_EQ(info.fileChannels, 4);
  EXPECT_EQ(rgba.at(12, 12, 3), 1.0f); // the plate fills the centre
}

// --converge ERR stops by the error the frames estimate themselves (core/quality/
// error_estimate.h) as the window's still view does: not before 256 samples a pixel (16 frames
// of the default 16 samples), before the most (target-samples' default 4096 in frames: 256),
// with the estimate at 3/4 of the target; the written line says so. With --frames the most is
// that count, and a target out of reach is reported as not reached; a target of 0 is refused.
TEST_F(RenderCli, ConvergeStopsByItsOwnEstimate)
{
  ANISO_REQUIRE_DISPLAY();
  const std::string out = path("converged.png").string();
  const Outcome r = run({"render", "--builtin", "sphere", "--size", "48x48", "--nu", "1000",
                         "--nv", "100", "--jitter", "off", "--converge", "0.02", "-o", out});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::size_t at = r.out.find("converge: estimated error ");
  ASSERT_NE(at, std::string::npos) << r.out;
  std::istringstream line(r.out.substr(at + std::string("converge: estimated error ").size()));
  double estimate = -1.0;
  std::string after;
  int frames = 0;
  line >> estimate >> after >> frames;
  EXPECT_GE(frames, 16) << r.out;
  EXPECT_LT(frames, 256) << r.out;
  EXPECT_GE(estimate, 0.0) << r.out;
  EXPECT_LE(estimate, 0.75 * 0.02) << r.out;
  EXPECT_NE(r.out.find(", within the target 0.02 (" + std::to_string(frames) +
                       " of at most 256 frames; "),
            std::string::npos)
      << r.out;
  // Pixels that stopped before the view, of the covered ones (the sphere fills most of 48x48).
  const std::size_t stopped = r.out.find(" covered pixels stopped before the view)");
  ASSERT_NE(stopped, std::string::npos) << r.out;
  const std::size_t of = r.out.rfind(" of ", stopped);
  const std::size_t semicolon = r.out.rfind("; ", of);
  ASSERT_NE(semicolon, std::string::npos) << r.out;
  const int frozen = std::stoi(r.out.substr(semicolon + 2, of - semicolon - 2));
  const int covered = std::stoi(r.out.substr(of + 4, stopped - of - 4));
  EXPECT_GT(covered, 1000) << r.out;
  EXPECT_GE(frozen, 0) << r.out;
  EXPECT_LT(frozen, covered) << r.out;
  EXPECT_NE(r.out.find(": " + std::to_string(frames) + " frame(s) x 16 samples"),
            std::string::npos)
      << r.out;

  const Outcome capped = run({"render", "--builtin", "sphere", "--size", "48x48", "--frames", "6",
                              "--converge", "0.0001", "-o", out});
  ASSERT_EQ(capped.exitCode, 0) << capped.err;
  EXPECT_NE(capped.out.find("after 6 frames, not within the target 0.0001 (6 of at most 6 frames; "
                            "0 of "),
            std::string::npos)
      << capped.out;

  expectOneLineError(run({"render", "--builtin", "sphere", "--converge", "0", "-o", out}), 2,
                     "--converge");
}

// The fraction of a square image of CAMERA that the plate [-1, 1]^2 (z = 0) covers: its corners
// projected by a pinhole camera, the area of that quadrilateral over the image's.
double plateCoverage(const aniso::CameraPlacement& camera)
{
  const glm::dvec3 forward = glm::normalize(camera.focalPoint - camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.viewUp));
  const glm::dvec3 up = glm::cross(right, forward);
  const double t = std::tan(0.5 * camera.viewAngleDegrees * M_PI / 180.0);
  const glm::dvec3 corners[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  double x[4], y[4];
  for (int i = 0; i < 4; ++i)
  {
    const glm::dvec3 d = corners[i] - camera.position;
    x[i] = glm::dot(d, right) / glm::dot(d, forward) / t;
    y[i] = glm::dot(d, up) / glm::dot(d, forward) / t;
  }
  double area = 0.0; // shoelace, in the [-1, 1]^2 image
  for (int i = 0; i < 4; ++i)
  {
    area += x[i] * y[(i + 1) % 4] - x[(i + 1) % 4] * y[i];
  }
  return std::abs(area) / 2.0 / 4.0;
}

// The share of pixels of an RGBA image with alpha above one half.
double covered(const aniso::Image& rgba)
{
  int n = 0;
  for (int y = 0; y < rgba.height; ++y)
  {
    for (int x = 0; x < rgba.width; ++x)
    {
      n += rgba.at(x, y, 3) > 0.5f;
    }
  }
  return double(n) / (rgba.width * rgba.height);
}

// A flat part in the XY plane is seen by default (the three-quarter view from above, not the
// front view edge-on): its covered pixels are what the pinhole projection of its corners
// predicts for the default view's camera, far above the edge-on front view's.
TEST_F(RenderCli, FlatPartIsVisibleByDefault)
{
  ANISO_REQUIRE_DISPLAY();
  const std::string seen = path("seen.png").string();
  ASSERT_EQ(run({"render", "--builtin", "plate", "--background", "none", "--size", "48", "--frames",
                 "1", "--samples", "1", "--jitter", "off", "-o", seen})
                .exitCode,
            0);
  const double expected = plateCoverage(
      aniso::placeCamera(aniso::defaultViewSettings(), glm::dvec3(0.0), std::sqrt(2.0)));
  const double share = covered(aniso::readImage(seen));
  EXPECT_GT(expected, 0.2);
  EXPECT_NEAR(share, expected, 0.03) << "default view";

  const std::string edgeOn = path("edge-on.png").string();
  ASSERT_EQ(run({"render", "--builtin", "plate", "--view", "-y", "--background", "none", "--size",
                 "48", "--frames", "1", "--samples", "1", "--jitter", "off", "-o", edgeOn})
                .exitCode,
            0);
  EXPECT_LT(covered(aniso::readImage(edgeOn)), 0.05) << "the front view sees the plate edge-on";
}

TEST_F(RenderCli, PrintsTheEnvironmentsSources)
{
  ANISO_REQUIRE_DISPLAY();
  const auto env =
      std::dynamic_pointer_cast<aniso::SunSkyEnvironment>(aniso::openEnvironment("builtin:sunsky"));
  ASSERT_TRUE(env);
  // Within the sun's radius, and the print's rounding to 0.1 degree on each angle.
  const double tolerance = env->sun().angularRadius + 0.1 * 3.14159265358979 / 180.0;
  // The environment as it is, and turned by 30 degrees about Z (counter-clockwise seen from
  // above): the sun's world direction is R_z(30) of the environment's.
  for (const double rotation : {0.0, 30.0})
  {
    const Outcome r = run({"render", "--builtin", "sphere", "--env", "builtin:sunsky",
                           "--env-rotation", std::to_string(rotation), "--size", "16x16",
                           "--frames", "1", "--samples", "2", "-o", path("a.png").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::istringstream lines(r.out);
    std::string line;
    int summaries = 0;
    int suns = 0;
    double azimuth = 0.0;
    double elevation = 0.0;
    while (std::getline(lines, line))
    {
      summaries += line.rfind("render: environment builtin:sunsky: 1 source carries ", 0) == 0;
      if (std::sscanf(line.c_str(), "render:   sun at azimuth %lf, elevation %lf (", &azimuth,
                      &elevation) == 2)
      {
        ++suns;
      }
    }
    EXPECT_EQ(summaries, 1) << r.out;
    ASSERT_EQ(suns, 1) << r.out;
    const double a = rotation * 3.14159265358979 / 180.0;
    const glm::dvec3 d = env->sun().direction;
    const glm::dvec3 world(d.x * std::cos(a) - d.y * std::sin(a),
                           d.x * std::sin(a) + d.y * std::cos(a), d.z);
    const double angle = std::acos(
        std::min(1.0, glm::dot(aniso::viewDirectionFromAngles(azimuth, elevation), world)));
    EXPECT_LT(angle, tolerance) << rotation << "\n" << r.out;
  }

  const Outcome white =
      run({"render", "--builtin", "sphere", "--env", "builtin:white", "--size", "16x16", "--frames",
           "1", "--samples", "2", "-o", path("b.png").string()});
  ASSERT_EQ(white.exitCode, 0) << white.err;
  EXPECT_EQ(white.out.find("render: environment"), std::string::npos) << white.out;
  // What auto drew with: lobe samples only under a uniform environment, the sources under a sun.
  EXPECT_NE(white.out.find("environment sampling auto (off)"), std::string::npos) << white.out;
  const Outcome sun =
      run({"render", "--builtin", "sphere", "--env", "builtin:sunsky", "--size", "16x16", "--frames",
           "1", "--samples", "2", "-o", path("c.png").string()});
  ASSERT_EQ(sun.exitCode, 0) << sun.err;
  EXPECT_NE(sun.out.find("environment sampling auto (sources)"), std::string::npos) << sun.out;
}
} // namespace
