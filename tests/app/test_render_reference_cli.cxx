// `aniso render --reference FILE --error-map FILE`: the CPU reference of the rendered view end to
// end, running the built executable. Small images and broad lobes (n_u, n_v of 100 to 200) keep
// the references fast (about a second each).
//  - The report agrees with the files: on the built-in sphere (64x64, builtin:studio, every 4th
//    pixel, 64 frames x 16 samples) the printed relative L2 is below 0.05 and equals, to 1e-9
//    relative, the one recomputed here from the written render (-o render.exr) and reference at
//    the centres of the reference's blocks of alpha 1 (each block one value, the centre's); the
//    printed pixel count is the number of those blocks.
//  - The reference is the integrator's at the pixel's own geometry: the built-in plate seen from
//    above in parallel projection (--view +z --ortho) has normal +z, tangent +x and view +z at
//    every pixel, exactly (a flat mesh: no faceting), so every computed pixel is core's
//    integrateSpecular of that frame and view with the same options (to the EXR's float
//    rounding), and within twice the requested tolerance of a reference 100 times tighter.
//  - The reported error follows the samples: 1 frame x 1 sample is farther from the reference
//    than 64 x 16 (by more than 3 times).
//  - --error-map: the EXR has one channel, |render - reference| / rms(reference) at the compared
//    pixels (recomputed here from the two files) and NaN at every other pixel; the PNG is RGBA,
//    transparent outside the compared blocks.
//  - Bad input: --reference x.png and --reference-step without --reference or --error-map are
//    command-line errors (exit 2) naming the option, as is --model other than as-env; a normal
//    map (a flat one written here) fails (exit 1) naming the mesh and the reason, before any
//    file is written.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/env/environment.h"
#include "core/frame.h"
#include "core/image/image.h"
#include "core/reference/reference_integrator.h"
#include "tests/app/cli_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using aniso_test::Outcome;

constexpr int kSize = 64;
constexpr int kStep = 4;

// The numbers of the line "reference: relative L2 X against the CPU reference at P pixels".
struct Reported
{
  double relativeL2 = -1.0;
  int pixels = -1;
};

Reported reportedOf(const std::string& out)
{
  // Plain parsing (no std::regex: gcc 12 warns inside <regex> under the sanitizers' flags).
  static const std::string head = "reference: relative L2 ";
  static const std::string middle = " against the CPU reference at ";
  Reported r;
  const std::size_t at = out.find(head);
  if (at == std::string::npos)
  {
    return r;
  }
  const std::size_t number = at + head.size();
  const std::size_t mid = out.find(middle, number);
  const std::size_t end = out.find(" pixels", mid == std::string::npos ? number : mid);
  if (mid == std::string::npos || end == std::string::npos)
  {
    return r;
  }
  try
  {
    r.relativeL2 = std::stod(out.substr(number, mid - number));
    r.pixels = std::stoi(out.substr(mid + middle.size(), end - mid - middle.size()));
  }
  catch (const std::exception&)
  {
    r = Reported{};
  }
  return r;
}

glm::dvec3 rgb(const aniso::Image& image, int x, int y)
{
  return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)};
}

// The centres of the reference's computed blocks: (S/2 + k S, S/2 + j S) with alpha 1.
std::vector<std::pair<int, int>> computedPixels(const aniso::Image& reference, int step)
{
  std::vector<std::pair<int, int>> pixels;
  for (int y = step / 2; y < reference.height; y += step)
  {
    for (int x = step / 2; x < reference.width; x += step)
    {
      if (reference.at(x, y, 3) == 1.0f)
      {
        pixels.emplace_back(x, y);
      }
    }
  }
  return pixels;
}

class RenderReferenceCli : public aniso_test::CliTest
{
protected:
  std::vector<std::string> sphere(int frames, int samples) const
  {
    return {"render",
            "--builtin",
            "sphere",
            "--size",
            std::to_string(kSize) + "x" + std::to_string(kSize),
            "--env",
            "builtin:studio",
            "--nu",
            "100",
            "--nv",
            "100",
            "--frames",
            std::to_string(frames),
            "--samples",
            std::to_string(samples),
            "--reference-step",
            std::to_string(kStep),
            "-o",
            path("render.exr").string()};
  }

  static std::vector<std::string> with(std::vector<std::string> args,
                                       const std::vector<std::string>& more)
  {
    args.insert(args.end(), more.begin(), more.end());
    return args;
  }
};

TEST_F(RenderReferenceCli, ReportAgreesWithTheWrittenFiles)
{
  const Outcome r = run(with(sphere(64, 16), {"--reference", path("ref.exr").string(),
                                              "--error-map", path("error.exr").string()}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::printf("%s", r.out.c_str());
  const Reported reported = reportedOf(r.out);
  ASSERT_GE(reported.relativeL2, 0.0) << r.out;
  EXPECT_LT(reported.relativeL2, 0.05);

  const aniso::Image render = aniso::readImage(path("render.exr").string());
  const aniso::Image reference = aniso::readImage(path("ref.exr").string());
  ASSERT_EQ(reference.width, kSize);
  ASSERT_EQ(reference.height, kSize);
  ASSERT_EQ(reference.channels, 4);
  const auto pixels = computedPixels(reference, kStep);
  EXPECT_EQ(int(pixels.size()), reported.pixels);
  // A good share of the sphere's disc (about half the image's blocks at this view).
  EXPECT_GT(pixels.size(), std::size_t(kSize / kStep * kSize / kStep / 4));

  double error = 0.0;
  double norm = 0.0;
  for (const auto& [x, y] : pixels)
  {
    const glm::dvec3 ref = rgb(reference, x, y);
    const glm::dvec3 d = rgb(render, x, y) - ref;
    error += glm::dot(d, d);
    norm += glm::dot(ref, ref);
    EXPECT_EQ(render.at(x, y, 3), 1.0f) << x << "," << y; // covered by the render
    // Nearest upscaling: the block holds the centre's value.
    const int x0 = x - kStep / 2;
    const int y0 = y - kStep / 2;
    for (int by = y0; by < y0 + kStep; ++by)
    {
      for (int bx = x0; bx < x0 + kStep; ++bx)
      {
        ASSERT_EQ(rgb(reference, bx, by), ref) << bx << "," << by;
        ASSERT_EQ(reference.at(bx, by, 3), 1.0f);
      }
    }
  }
  const double recomputed = std::sqrt(error / norm);
  std::printf("recomputed relative L2 %.12g over %zu pixels\n", recomputed, pixels.size());
  EXPECT_NEAR(reported.relativeL2, recomputed, 1e-9 * recomputed);

  // The error map: one channel, finite exactly at the compared pixels.
  aniso::ImageInfo info;
  const aniso::Image map = aniso::readImage(path("error.exr").string(), &info);
  ASSERT_EQ(info.fileChannels, 1);
  ASSERT_EQ(map.width, kSize);
  ASSERT_EQ(map.height, kSize);
  const double rms = std::sqrt(norm / double(pixels.size()));
  std::vector<char> compared(std::size_t(kSize) * kSize, 0);
  for (const auto& [x, y] : pixels)
  {
    compared[std::size_t(y) * kSize + x] = 1;
    const double expected = glm::length(rgb(render, x, y) - rgb(reference, x, y)) / rms;
    EXPECT_NEAR(map.at(x, y, 0), expected, 1e-5 * expected + 1e-7) << x << "," << y;
  }
  int finite = 0;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      const float value = map.at(x, y, 0);
      if (compared[std::size_t(y) * kSize + x])
      {
        ASSERT_TRUE(std::isfinite(value)) << x << "," << y;
        ASSERT_GE(value, 0.0f);
        ++finite;
      }
      else
      {
        ASSERT_TRUE(std::isnan(value)) << x << "," << y;
      }
    }
  }
  EXPECT_EQ(finite, int(pixels.size()));

  // Fewer samples, farther from the reference; the PNG heat map alone (no --reference).
  const Outcome few = run(with(sphere(1, 1), {"--error-map", path("error.png").string()}));
  ASSERT_EQ(few.exitCode, 0) << few.err;
  std::printf("%s", few.out.c_str());
  const Reported noisy = reportedOf(few.out);
  EXPECT_EQ(noisy.pixels, reported.pixels);
  EXPECT_GT(noisy.relativeL2, 3.0 * reported.relativeL2);
  const aniso::Image heat = aniso::readImage(path("error.png").string());
  ASSERT_EQ(heat.channels, 4);
  int opaque = 0;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      const bool inBlock = compared[std::size_t((y / kStep) * kStep + kStep / 2) * kSize +
                                    (x / kStep) * kStep + kStep / 2];
      EXPECT_EQ(heat.at(x, y, 3), inBlock ? 1.0f : 0.0f) << x << "," << y;
      opaque += heat.at(x, y, 3) == 1.0f ? 1 : 0;
    }
  }
  EXPECT_EQ(opaque, int(pixels.size()) * kStep * kStep);
}

TEST_F(RenderReferenceCli, ReferenceIsTheIntegratorsAtThePixelsGeometry)
{
  constexpr int kPlateSize = 32;
  const Outcome r = run({"render",
                         "--builtin",
                         "plate",
                         "--view",
                         "+z",
                         "--ortho",
                         "--size",
                         std::to_string(kPlateSize),
                         "--env",
                         "builtin:studio",
                         "--nu",
                         "200",
                         "--nv",
                         "50",
                         "--f0",
                         "0.9",
                         "--frames",
                         "1",
                         "--samples",
                         "1",
                         "--reference-step",
                         std::to_string(kStep),
                         "-o",
                         path("plate.exr").string(),
                         "--reference",
                         path("ref.exr").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::printf("%s", r.out.c_str());
  const aniso::Image reference = aniso::readImage(path("ref.exr").string());
  const auto pixels = computedPixels(reference, kStep);
  ASSERT_GE(pixels.size(), std::size_t(16));

  const auto environment = aniso::openEnvironment("builtin:studio");
  const aniso::AsLobe lobe{200.0, 50.0};
  const glm::dvec3 f0(0.9);
  const aniso::Frame frame =
      aniso::Frame::fromNormalTangent(glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(1.0, 0.0, 0.0));
  const glm::dvec3 view(0.0, 0.0, 1.0);
  aniso::ReferenceOptions options; // the command line's: --reference-tolerance's default
  options.relativeTolerance = 1e-3;
  options.maxEvaluations = 1ull << 24;
  const aniso::ReferenceResult same =
      aniso::integrateSpecular(lobe, f0, frame, view, *environment, options);
  aniso::ReferenceOptions tight = options;
  tight.relativeTolerance = 1e-5;
  const aniso::ReferenceResult truth =
      aniso::integrateSpecular(lobe, f0, frame, view, *environment, tight);
  ASSERT_TRUE(truth.converged);
  const auto luminance = [](const glm::dvec3& c)
  { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; };
  std::printf("plate: %zu pixels; integrateSpecular (%.9g, %.9g, %.9g), at 1e-5 %.9g (luminance)\n",
              pixels.size(), same.value.x, same.value.y, same.value.z, luminance(truth.value));
  for (const auto& [x, y] : pixels)
  {
    const glm::dvec3 value = rgb(reference, x, y);
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_NEAR(value[c], same.value[c], 1e-6 * same.value[c]) << x << "," << y << " " << c;
    }
    ASSERT_NEAR(luminance(value), luminance(truth.value), 2e-3 * luminance(truth.value));
  }
}

TEST_F(RenderReferenceCli, BadInputIsRefused)
{
  const Outcome png = run(with(sphere(1, 1), {"--reference", path("x.png").string()}));
  EXPECT_EQ(png.exitCode, 2);
  EXPECT_NE(png.err.find("--reference"), std::string::npos) << png.err;
  EXPECT_EQ(std::count(png.err.begin(), png.err.end(), '\n'), 1) << png.err;

  const Outcome alone = run(sphere(1, 1)); // --reference-step without --reference
  EXPECT_EQ(alone.exitCode, 2);
  EXPECT_NE(alone.err.find("--reference-step"), std::string::npos) << alone.err;

  const Outcome model =
      run(with(sphere(1, 1), {"--model", "ward", "--reference", path("ref.exr").string()}));
  EXPECT_EQ(model.exitCode, 2);
  EXPECT_NE(model.err.find("as-env"), std::string::npos) << model.err;

  aniso::Image flat(8, 8, 3);
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 8; ++x)
    {
      flat.at(x, y, 0) = flat.at(x, y, 1) = 0.5f;
      flat.at(x, y, 2) = 1.0f;
    }
  }
  aniso::writeImage(path("normals.png").string(), flat);
  const Outcome mapped = run(with(sphere(1, 1), {"--normal-map", path("normals.png").string(),
                                                 "--reference", path("ref.exr").string()}));
  EXPECT_EQ(mapped.exitCode, 1);
  EXPECT_NE(mapped.err.find("aniso: builtin:sphere: the reference does not integrate maps"),
            std::string::npos)
      << mapped.err;
  EXPECT_EQ(std::count(mapped.err.begin(), mapped.err.end(), '\n'), 1) << mapped.err;
  EXPECT_FALSE(std::filesystem::exists(path("render.exr")));
  EXPECT_FALSE(std::filesystem::exists(path("ref.exr")));
}
} // namespace
