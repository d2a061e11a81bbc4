// `aniso bake` end to end: runs the built executable, reads back what it wrote and compares it
// with the core functions called directly here (so the file must round-trip the bake), and with
// analytic forms where the header states one.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/env/cubemap.h"
#include "core/env/environment.h"
#include "core/image/image.h"
#include "core/lut/lut.h"
#include "core/maps/quaternion_map.h"
#include "tests/app/cli_runner.h"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using aniso_test::listing;
using aniso_test::Outcome;
using aniso_test::slurp;
using BakeCli = aniso_test::CliTest;

void expectSuccess(const Outcome& r)
{
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

// Relative agreement at float precision: the file stores 32-bit floats.
void expectFloatNear(double got, double expected, const std::string& where)
{
  EXPECT_LE(std::abs(got - expected), 1e-6 * std::max(1.0, std::abs(expected)))
      << where << ": got " << got << ", expected " << expected;
}

// Half-vector LUT file: texel (i, j), row j from the top of the file, holds the sample at
// xi = ((i + 0.5)/N, (j + 0.5)/N): RGB = sampleHalfVector, A = log2 p_h (lut.h).
TEST_F(BakeCli, HalfVectorFileHoldsTheSampledHalfVectorsAndLogPdf)
{
  const fs::path out = path("hv.exr");
  const Outcome r = run({"bake", "halfvector", "--nu", "200", "--nv=20", "--size", "16", "--cache",
                         "none", "-o", out.string()});
  expectSuccess(r);
  EXPECT_NE(r.out.find("hv.exr"), std::string::npos);
  EXPECT_NE(r.out.find(" ms"), std::string::npos) << "bake time printed";
  const aniso::Image image = aniso::readImage(out.string());
  ASSERT_EQ(image.width, 16);
  ASSERT_EQ(image.height, 16);
  ASSERT_EQ(image.channels, 4);
  aniso::AsLobe lobe;
  lobe.nu = 200.0;
  lobe.nv = 20.0;
  for (int j = 0; j < 16; ++j)
  {
    for (int i = 0; i < 16; ++i)
    {
      const glm::dvec2 xi((i + 0.5) / 16.0, (j + 0.5) / 16.0);
      const glm::dvec3 h = aniso::sampleHalfVector(lobe, xi);
      const std::string where = "texel " + std::to_string(i) + "," + std::to_string(j);
      for (int c = 0; c < 3; ++c)
      {
        expectFloatNear(image.at(i, j, c), h[c], where);
      }
      expectFloatNear(image.at(i, j, 3), aniso::log2PdfHalfVector(lobe, h), where);
    }
  }
}

// BRDF LUT file: texel (i, j) equals sizeBiasAt at the view of (u, v) = ((i+0.5)/N, (j+0.5)/N).
TEST_F(BakeCli, BrdfFileHoldsSizeAndBiasPerView)
{
  const fs::path out = path("brdf.exr");
  expectSuccess(run({"bake", "brdf", "--nu", "20000", "--nv", "70", "--size", "8", "--samples",
                     "256", "--cache", "none", "-o", out.string()}));
  const aniso::Image image = aniso::readImage(out.string());
  ASSERT_EQ(image.width, 8);
  ASSERT_EQ(image.height, 8);
  ASSERT_EQ(image.channels, 2);
  aniso::AsLobe lobe;
  lobe.nu = 20000.0;
  lobe.nv = 70.0;
  for (int j = 0; j < 8; ++j)
  {
    for (int i = 0; i < 8; ++i)
    {
      const glm::dvec3 view = aniso::brdfLutView({(i + 0.5) / 8.0, (j + 0.5) / 8.0});
      const glm::dvec2 sb = aniso::sizeBiasAt(lobe, view, 256);
      const std::string where = "texel " + std::to_string(i) + "," + std::to_string(j);
      expectFloatNear(image.at(i, j, 0), sb.x, where);
      expectFloatNear(image.at(i, j, 1), sb.y, where);
    }
  }
}

// With --cache DIR the second bake is read from the cache and writes the same bits.
TEST_F(BakeCli, SecondBakeIsReadFromTheCacheWithTheSameBits)
{
  const std::string cache = path("cache").string();
  const std::vector<std::string> args = {"bake", "brdf",    "--size", "8", "--samples",
                                         "64",   "--cache", cache,    "-o"};
  std::vector<std::string> first = args;
  first.push_back(path("a.exr").string());
  std::vector<std::string> second = args;
  second.push_back(path("b.exr").string());
  const Outcome r1 = run(first);
  expectSuccess(r1);
  EXPECT_EQ(r1.out.find("read from the cache"), std::string::npos) << r1.out;
  EXPECT_FALSE(fs::is_empty(cache));
  const Outcome r2 = run(second);
  expectSuccess(r2);
  EXPECT_NE(r2.out.find("read from the cache"), std::string::npos) << r2.out;
  EXPECT_EQ(aniso::readImage(path("a.exr").string()).data,
            aniso::readImage(path("b.exr").string()).data);
}

// Quaternion map from a float normal map: each texel is quaternionFromNormal of the normalised
// input, its frame reproduces that normal (frameFromQuaternion(q).n), and the printed counts
// match the texels built here: one non-unit, two invalid (zero, NaN), one antipodal.
TEST_F(BakeCli, QuaternionFileReproducesTheNormalsAndCountsTheOddTexels)
{
  const std::vector<glm::dvec3> normals = {
      {0, 0, 1}, {0.6, 0, 0.8}, {0, -0.6, 0.8},       {0.48, 0.6, 0.64},
      {0, 0, 2}, {0, 0, 0},     {std::nan(""), 0, 1}, {0, 0, -1}};
  aniso::Image map(4, 2, 3);
  for (std::size_t k = 0; k < normals.size(); ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      map.data[k * 3 + c] = static_cast<float>(normals[k][c]);
    }
  }
  aniso::writeImage(path("normals.exr").string(), map);
  const fs::path out = path("q.exr");
  const Outcome r = run({"bake", "quaternion", path("normals.exr").string(), "-o", out.string()});
  expectSuccess(r);
  EXPECT_NE(r.out.find("texels 8, non-unit 1, invalid 2, antipodal 1"), std::string::npos) << r.out;
  const aniso::Image q = aniso::readImage(out.string());
  ASSERT_EQ(q.width, 4);
  ASSERT_EQ(q.height, 2);
  ASSERT_EQ(q.channels, 4);
  for (std::size_t k = 0; k < normals.size(); ++k)
  {
    const int x = static_cast<int>(k % 4);
    const int y = static_cast<int>(k / 4);
    const glm::dvec3 abc(q.at(x, y, 0), q.at(x, y, 1), q.at(x, y, 2));
    const double len = glm::length(normals[k]);
    const bool valid = std::isfinite(len) && len > 0.0;
    const glm::dvec3 n = valid ? normals[k] / len : glm::dvec3(0, 0, 1);
    const glm::dvec3 expected = aniso::quaternionFromNormal(n);
    const std::string where = "texel " + std::to_string(k);
    for (int c = 0; c < 3; ++c)
    {
      expectFloatNear(abc[c], expected[c], where);
    }
    EXPECT_EQ(q.at(x, y, 3), 1.0f) << where;
    const glm::dvec3 frameNormal = aniso::frameFromQuaternion(abc).n;
    EXPECT_LT(glm::length(frameNormal - n), 1e-5) << where;
  }
}

// An 8-bit PNG is decoded n = 2 c - 1 by default (auto encoding).
TEST_F(BakeCli, QuaternionFromAnEightBitNormalMapDecodesUnorm)
{
  aniso::Image png(2, 1, 3);
  png.data = {128 / 255.0f, 128 / 255.0f, 1.0f, 230 / 255.0f, 128 / 255.0f, 200 / 255.0f};
  aniso::writeImage(path("n.png").string(), png);
  const fs::path out = path("q.exr");
  expectSuccess(run({"bake", "quaternion", path("n.png").string(), "-o", out.string()}));
  const aniso::Image q = aniso::readImage(out.string());
  ASSERT_EQ(q.width, 2);
  for (int x = 0; x < 2; ++x)
  {
    const glm::dvec3 n =
        glm::normalize(2.0 * glm::dvec3(png.at(x, 0, 0), png.at(x, 0, 1), png.at(x, 0, 2)) - 1.0);
    const glm::dvec3 frameNormal =
        aniso::frameFromQuaternion({q.at(x, 0, 0), q.at(x, 0, 1), q.at(x, 0, 2)}).n;
    EXPECT_LT(glm::length(frameNormal - n), 1e-5) << "texel " << x;
  }
}

// TPR circular pattern: the tangent at texel (col, row) is (-r.y, r.x)/|r| with
// r = (u, v) - centre, u = (col + 0.5)/W, v = 1 - (row + 0.5)/H (row 0 at the top).
TEST_F(BakeCli, TprCircularFileFollowsTheCircles)
{
  const fs::path out = path("tpr.exr");
  expectSuccess(run(
      {"bake", "tpr", "--pattern", "circular:0.25,0.5", "--size", "24x16", "-o", out.string()}));
  const aniso::Image map = aniso::readImage(out.string());
  ASSERT_EQ(map.width, 24);
  ASSERT_EQ(map.height, 16);
  ASSERT_EQ(map.channels, 2);
  for (int row = 0; row < 16; ++row)
  {
    for (int col = 0; col < 24; ++col)
    {
      const glm::dvec2 r((col + 0.5) / 24.0 - 0.25, 1.0 - (row + 0.5) / 16.0 - 0.5);
      const glm::dvec2 t = glm::dvec2(-r.y, r.x) / glm::length(r);
      const std::string where = std::to_string(col) + "," + std::to_string(row);
      expectFloatNear(map.at(col, row, 0), t.x, where);
      expectFloatNear(map.at(col, row, 1), t.y, where);
    }
  }
}

// TPR from an angle image: channel 0 = a maps to (cos(pi a), sin(pi a)), the image's size.
TEST_F(BakeCli, TprFromAngleImageUsesItsAnglesAndSize)
{
  aniso::Image angles(5, 3, 1);
  for (std::size_t k = 0; k < angles.data.size(); ++k)
  {
    angles.data[k] = static_cast<float>(k) / 14.0f;
  }
  aniso::writeImage(path("angles.exr").string(), angles);
  const fs::path out = path("tpr.exr");
  expectSuccess(
      run({"bake", "tpr", "--angle-image", path("angles.exr").string(), "-o", out.string()}));
  const aniso::Image map = aniso::readImage(out.string());
  ASSERT_EQ(map.width, 5);
  ASSERT_EQ(map.height, 3);
  ASSERT_EQ(map.channels, 2);
  for (std::size_t k = 0; k < angles.data.size(); ++k)
  {
    const double a = M_PI * angles.data[k];
    expectFloatNear(map.data[k * 2], std::cos(a), "texel " + std::to_string(k));
    expectFloatNear(map.data[k * 2 + 1], std::sin(a), "texel " + std::to_string(k));
  }
}

// Cubemap: 6 faces x 4 levels named PREFIX_F_mL.exr, equal to buildCubemap called directly;
// each level is the 2x2 mean of the one above (the box filter the header states).
TEST_F(BakeCli, CubemapFilesHoldEveryFaceAndLevel)
{
  const Outcome r = run({"bake", "cubemap", "--env", "builtin:studio", "--size", "8",
                         "--supersample", "1", "-o", path("studio").string()});
  expectSuccess(r);
  const aniso::Cubemap cube = aniso::buildCubemap(aniso::StudioEnvironment(), 8, 1);
  ASSERT_EQ(cube.mips.size(), 4u);
  const char* faces[6] = {"px", "nx", "py", "ny", "pz", "nz"};
  std::set<std::string> expectedFiles;
  for (int level = 0; level < 4; ++level)
  {
    const int size = 8 >> level;
    for (int f = 0; f < 6; ++f)
    {
      const std::string name =
          std::string("studio_") + faces[f] + "_m" + std::to_string(level) + ".exr";
      expectedFiles.insert(name);
      const aniso::Image face = aniso::readImage(path(name).string());
      ASSERT_EQ(face.width, size) << name;
      ASSERT_EQ(face.height, size) << name;
      ASSERT_EQ(face.channels, 3) << name;
      const aniso::Image& direct = cube.mips[level][f];
      for (std::size_t k = 0; k < face.data.size(); ++k)
      {
        expectFloatNear(face.data[k], direct.data[k], name);
      }
      if (level > 0)
      {
        const aniso::Image finer = aniso::readImage(
            path(std::string("studio_") + faces[f] + "_m" + std::to_string(level - 1) + ".exr")
                .string());
        for (int c = 0; c < 3; ++c)
        {
          const double mean =
              (finer.at(0, 0, c) + finer.at(1, 0, c) + finer.at(0, 1, c) + finer.at(1, 1, c)) / 4.0;
          EXPECT_NEAR(face.at(0, 0, c), mean, 1e-5 * std::max(1.0, mean)) << name;
        }
      }
    }
  }
  EXPECT_EQ(files(), expectedFiles) << "exactly the documented files, no staging left";
}

// -o naming an existing directory writes DIR/cube_F_mL.exr.
TEST_F(BakeCli, CubemapIntoADirectoryUsesTheCubePrefix)
{
  fs::create_directory(path("faces"));
  expectSuccess(run({"bake", "cubemap", "--size", "2", "-o", path("faces").string()}));
  EXPECT_TRUE(fs::exists(path("faces/cube_px_m0.exr")));
  EXPECT_TRUE(fs::exists(path("faces/cube_nz_m1.exr")));
  EXPECT_EQ(listing(path("faces")).size(), 12u);
}

// The real SH basis as the README and the file header write it out (constants typed from the
// formulas, not taken from the core).
std::array<double, 9> documentedShBasis(const glm::dvec3& d)
{
  return {0.282095,
          0.488603 * d.y,
          0.488603 * d.z,
          0.488603 * d.x,
          1.092548 * d.x * d.y,
          1.092548 * d.y * d.z,
          0.315392 * (3.0 * d.z * d.z - 1.0),
          1.092548 * d.x * d.z,
          0.546274 * (d.x * d.x - d.y * d.y)};
}

// SH9 text: 9 lines "l m R G B" in the documented order, equal to projectSh9 of the studio;
// and E(n) evaluated from the file with the documented basis and A_l agrees with the core's
// irradianceSh9 (to the 6 digits the documented constants carry), so the format description
// is enough to use the file.
TEST_F(BakeCli, IrradianceTextHoldsTheNineCoefficients)
{
  const fs::path out = path("sh9.txt");
  expectSuccess(run({"bake", "irradiance", "--env", "builtin:studio", "-o", out.string()}));
  const aniso::Sh9 sh = aniso::projectSh9(aniso::StudioEnvironment());
  std::istringstream in(slurp(out));
  std::string line;
  const int lm[9][2] = {{0, 0}, {1, -1}, {1, 0}, {1, 1}, {2, -2}, {2, -1}, {2, 0}, {2, 1}, {2, 2}};
  aniso::Sh9 fromFile{};
  std::size_t k = 0;
  while (std::getline(in, line))
  {
    if (line.empty() || line[0] == '#')
    {
      continue;
    }
    ASSERT_LT(k, 9u) << "more than 9 coefficient lines";
    std::istringstream fields(line);
    int l = -1;
    int m = -9;
    glm::dvec3 c;
    fields >> l >> m >> c.x >> c.y >> c.z;
    ASSERT_FALSE(fields.fail()) << line;
    EXPECT_EQ(l, lm[k][0]);
    EXPECT_EQ(m, lm[k][1]);
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(c[i], sh[k][i], 1e-12 * std::max(1.0, std::abs(sh[k][i]))) << line;
    }
    fromFile[k] = c;
    ++k;
  }
  ASSERT_EQ(k, 9u);
  const double a[3] = {M_PI, 2.0 * M_PI / 3.0, M_PI / 4.0};
  for (const glm::dvec3& n :
       {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::dvec3(1, 0, 0),
        glm::normalize(glm::dvec3(-1, 2, 0.5)), glm::normalize(glm::dvec3(0.3, -0.2, -0.9))})
  {
    const std::array<double, 9> y = documentedShBasis(n);
    glm::dvec3 e(0.0);
    for (std::size_t i = 0; i < 9; ++i)
    {
      e += a[lm[i][0]] * y[i] * fromFile[i];
    }
    const glm::dvec3 core = aniso::irradianceSh9(sh, n);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(e[c], core[c], 1e-5 * std::max(1.0, std::abs(core[c])));
    }
  }
}

// Irradiance EXR: texel (x, y) is irradianceSh9 at the equirectangular direction of its centre.
TEST_F(BakeCli, IrradianceImageIsTheShIrradianceOverTheSphere)
{
  const fs::path out = path("irr.exr");
  expectSuccess(run({"bake", "irradiance", "--size", "16x8", "-o", out.string()}));
  const aniso::Sh9 sh = aniso::projectSh9(aniso::StudioEnvironment());
  const aniso::Image image = aniso::readImage(out.string());
  ASSERT_EQ(image.width, 16);
  ASSERT_EQ(image.height, 8);
  ASSERT_EQ(image.channels, 3);
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 16; ++x)
    {
      const glm::dvec3 d = aniso::equirectToDirection({(x + 0.5) / 16.0, 1.0 - (y + 0.5) / 8.0});
      const glm::dvec3 e = aniso::irradianceSh9(sh, d);
      for (int c = 0; c < 3; ++c)
      {
        expectFloatNear(image.at(x, y, c), e[c], std::to_string(x) + "," + std::to_string(y));
      }
    }
  }
}

} // namespace
