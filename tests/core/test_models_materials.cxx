// Sample materials and material maps: bilinear wrapping lookups against hand-computed texel
// mixes, slopes of a sinusoidal height map against the closed form of central differences,
// value ranges of every built-in map, the intended structure (scratches along both axes and
// carved, veins raised and darker, maps that tile), the brushing directions on the built-in
// sphere's parametrisation, and the per-model parameter mappings.
#include "core/error.h"
#include "core/models/height_field.h"
#include "core/models/samples.h"
#include "core/models/sv_material.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace
{
constexpr double kPi = 3.14159265358979323846;

// A 2x2 map: texel centres return their texel; the tile edge u = 0 mixes the first and last
// columns equally (wrapping); v = 1 (top) mixes the top and bottom rows.
TEST(Materials, BilinearLookupWraps)
{
  aniso::SvMaps maps;
  maps.tangentAlpha = aniso::Image(2, 2, 4);
  maps.albedoSpecular = aniso::Image(2, 2, 4);
  maps.normal = aniso::Image(2, 2, 3);
  // alpha_x = 0.1, 0.2 (top row), 0.3, 0.4 (bottom row); tangent +u everywhere.
  const float alphas[4] = {0.1f, 0.2f, 0.3f, 0.4f};
  for (int i = 0; i < 4; ++i)
  {
    maps.tangentAlpha.data[std::size_t(i) * 4 + 0] = 1.0f;
    maps.tangentAlpha.data[std::size_t(i) * 4 + 2] = alphas[i];
    maps.tangentAlpha.data[std::size_t(i) * 4 + 3] = 0.5f;
    maps.albedoSpecular.data[std::size_t(i) * 4 + 3] = alphas[i];
    maps.normal.data[std::size_t(i) * 3 + 2] = 1.0f;
  }
  EXPECT_NEAR(aniso::sampleSvMaps(maps, {0.25, 0.75}).alphaX, 0.1, 1e-7);
  EXPECT_NEAR(aniso::sampleSvMaps(maps, {0.75, 0.25}).alphaX, 0.4, 1e-7);
  EXPECT_NEAR(aniso::sampleSvMaps(maps, {0.0, 0.75}).alphaX, 0.15, 1e-7);
  EXPECT_NEAR(aniso::sampleSvMaps(maps, {0.25, 1.0}).alphaX, 0.2, 1e-7);
  EXPECT_NEAR(aniso::sampleSvMaps(maps, {1.25, -0.25}).specular, 0.1, 1e-7);
  EXPECT_NEAR(aniso::sampleSvMaps(maps, {std::nan(""), 0.75}).alphaX, 0.15, 1e-7);

  aniso::SvMaps broken = maps;
  broken.normal = aniso::Image(2, 2, 2);
  EXPECT_THROW(aniso::sampleSvMaps(broken, {0.5, 0.5}), aniso::Error);
}

// h = A sin(2 pi k u): central differences give dh/du = A W sin(2 pi k / W) cos(2 pi k u) exactly
// (and dh/dv = 0); a map varying along v has its slope sign from v growing upwards.
TEST(Materials, SlopesOfSinusoidMatchClosedForm)
{
  const int w = 64;
  const double amplitude = 0.01;
  const int k = 3;
  aniso::Image height(w, 16, 1);
  aniso::Image rising(16, w, 1); // h = v
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < w; ++x)
      height.at(x, y, 0) = float(amplitude * std::sin(2.0 * kPi * k * (x + 0.5) / w));
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < 16; ++x)
      rising.at(x, y, 0) = float(0.2 * std::sin(2.0 * kPi * (1.0 - (y + 0.5) / w)));
  const aniso::Image slopes = aniso::slopesFromHeight(height, 2.0);
  for (int x = 0; x < w; ++x)
  {
    const double expected =
        2.0 * amplitude * w * std::sin(2.0 * kPi * k / w) * std::cos(2.0 * kPi * k * (x + 0.5) / w);
    EXPECT_NEAR(slopes.at(x, 5, 0), expected, 1e-5);
    EXPECT_NEAR(slopes.at(x, 5, 1), 0.0, 1e-7);
  }
  const aniso::Image up = aniso::slopesFromHeight(rising, 1.0);
  // dh/dv at v = 0.5 - 0.5/w (row w/2): 0.2 w sin(2 pi / w) cos(2 pi v) < 0, at v near 0: > 0.
  EXPECT_GT(up.at(3, w - 1, 1), 0.0);
  EXPECT_LT(up.at(3, w / 2, 1), 0.0);
  const aniso::Image normals = aniso::normalsFromSlopes(slopes);
  EXPECT_NEAR(
      glm::length(glm::dvec3(normals.at(7, 0, 0), normals.at(7, 0, 1), normals.at(7, 0, 2))), 1.0,
      1e-6);
  EXPECT_THROW(aniso::slopesFromHeight(aniso::Image(), 1.0), aniso::Error);
}

// Every texel of the built-in maps is in range: unit tangents and normals (z > 0), roughness in
// the models' range, colours and k_s in [0, 1].
void expectValidMaps(const aniso::SvMaps& maps)
{
  const int w = maps.tangentAlpha.width;
  for (int y = 0; y < w; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const aniso::SvTexel t = aniso::sampleSvMaps(maps, {(x + 0.5) / w, 1.0 - (y + 0.5) / w});
      ASSERT_NEAR(glm::length(t.tangent), 1.0, 1e-9);
      ASSERT_NEAR(glm::length(t.normal), 1.0, 1e-9);
      ASSERT_GT(t.normal.z, 0.5);
      ASSERT_GE(t.alphaX, aniso::kSvMinAlpha);
      ASSERT_LE(t.alphaY, 1.0);
      ASSERT_TRUE(t.diffuse.x >= 0.0 && t.diffuse.x <= 1.0 && t.specular >= 0.0 &&
                  t.specular <= 1.0);
    }
  }
}

// Largest step across the tile edge versus inside the tile: tiling maps have no seam.
void expectTiles(const aniso::Image& image, int channel)
{
  double interior = 0.0;
  double seam = 0.0;
  const int w = image.width;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x + 1 < w; ++x)
      interior = std::max(interior,
                          double(std::abs(image.at(x + 1, y, channel) - image.at(x, y, channel))));
    seam = std::max(seam, double(std::abs(image.at(0, y, channel) - image.at(w - 1, y, channel))));
  }
  for (int x = 0; x < w; ++x)
    seam = std::max(
        seam, double(std::abs(image.at(x, 0, channel) - image.at(x, image.height - 1, channel))));
  EXPECT_LE(seam, interior);
  EXPECT_GT(interior, 0.0);
}

// Scratches along u and along v both cover a visible share of the plate (between 2% and 30% each),
// carve it (height < 0 where scratched, 0 elsewhere), and are smooth along themselves
// (alpha_x < alpha_y).
TEST(Materials, ScratchedPlateHasScratchesAlongBothAxes)
{
  const aniso::SvMaps maps = aniso::scratchedPlate(256, 3);
  expectValidMaps(maps);
  int alongU = 0;
  int alongV = 0;
  const int w = 256;
  for (int y = 0; y < w; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const double ax = maps.tangentAlpha.at(x, y, 2);
      const double ay = maps.tangentAlpha.at(x, y, 3);
      const bool scratched = maps.height.at(x, y, 0) < 0.0f;
      if (!scratched)
      {
        EXPECT_EQ(maps.height.at(x, y, 0), 0.0f);
        continue;
      }
      if (ax < ay)
        (maps.tangentAlpha.at(x, y, 1) > 0.5f ? alongV : alongU)++;
    }
  }
  const double share = 1.0 / (w * w);
  std::printf("scratched along u: %.1f%%, along v: %.1f%%\n", 100.0 * alongU * share,
              100.0 * alongV * share);
  EXPECT_GT(alongU * share, 0.02);
  EXPECT_GT(alongV * share, 0.02);
  EXPECT_LT(alongU * share, 0.3);
  EXPECT_LT(alongV * share, 0.3);
  expectTiles(maps.height, 0);
}

// Veins are raised and darker: the 5% highest texels are darker on average than the 50% lowest,
// heights are in [0, veinHeight], and the maps tile.
TEST(Materials, MarbleVeinsAreRaisedAndDarker)
{
  const double veinHeight = 0.004;
  const aniso::SvMaps maps = aniso::veinedMarble(128, veinHeight, 5);
  expectValidMaps(maps);
  std::vector<std::pair<double, double>> texels; // (height, luminance)
  for (int y = 0; y < 128; ++y)
  {
    for (int x = 0; x < 128; ++x)
    {
      const double h = maps.height.at(x, y, 0);
      EXPECT_GE(h, 0.0);
      EXPECT_LE(h, veinHeight * (1.0 + 1e-6));
      const double lum = (maps.albedoSpecular.at(x, y, 0) + maps.albedoSpecular.at(x, y, 1) +
                          maps.albedoSpecular.at(x, y, 2)) /
                         3.0;
      texels.emplace_back(h, lum);
    }
  }
  std::sort(texels.begin(), texels.end());
  auto meanLum = [&](std::size_t from, std::size_t to)
  {
    double s = 0.0;
    for (std::size_t i = from; i < to; ++i)
      s += texels[i].second;
    return s / double(to - from);
  };
  const std::size_t n = texels.size();
  const double high = meanLum(n - n / 20, n);
  const double low = meanLum(0, n / 2);
  std::printf("marble: luminance of the highest 5%% %.3f, of the lowest half %.3f\n", high, low);
  EXPECT_LT(high, 0.75 * low);
  expectTiles(maps.height, 0);
  expectTiles(maps.albedoSpecular, 0);
}

// On the built-in sphere (u = longitude, v = latitude), latitudinal brushing follows the
// parallels (horizontal tangents) and longitudinal brushing the meridians (tangents in the plane
// of the pole axis); both are smooth along the brushing.
TEST(Materials, BrushedSphereDirections)
{
  for (double lon : {0.3, 2.0, -2.5})
  {
    for (double lat : {-1.0, 0.2, 1.2})
    {
      const glm::dvec3 p(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                         std::sin(lat));
      const glm::dvec3 dPdu(-std::sin(lon), std::cos(lon), 0.0); // along +u, up to scale
      const aniso::Frame parallel =
          aniso::svShadingFrame(p, dPdu, aniso::brushedMetal(aniso::BrushDirection::Latitudinal));
      const aniso::Frame meridian =
          aniso::svShadingFrame(p, dPdu, aniso::brushedMetal(aniso::BrushDirection::Longitudinal));
      EXPECT_NEAR(parallel.t.z, 0.0, 1e-12);
      EXPECT_NEAR(glm::dot(meridian.t, glm::cross(glm::dvec3(0, 0, 1), p)), 0.0, 1e-12);
      EXPECT_GT(meridian.t.z * std::cos(lat), 0.0); // +v points north
    }
  }
  const aniso::SvTexel t = aniso::brushedMetal(aniso::BrushDirection::Longitudinal);
  EXPECT_LT(t.alphaX, t.alphaY);
  const aniso::SvTexel back = aniso::sampleSvMaps(aniso::uniformSvMaps(t), {0.3, 0.9});
  EXPECT_NEAR(back.alphaY, t.alphaY, 1e-7);
  EXPECT_NEAR(back.tangent.y, 1.0, 1e-7);
}

// One texel as each model's parameters, per the documented mappings.
TEST(Materials, ModelParameterMappings)
{
  aniso::SvTexel t;
  t.alphaX = 0.1;
  t.alphaY = 0.4;
  t.specular = 0.5;
  t.diffuse = glm::dvec3(0.3);
  const aniso::AsMaterial as = aniso::toAshikhminShirley(t);
  EXPECT_NEAR(as.lobe.nu, 198.0, 1e-9);
  EXPECT_NEAR(as.lobe.nv, 10.5, 1e-9);
  EXPECT_NO_THROW(aniso::validateAsMaterial(as));
  const aniso::BanksMaterial banks = aniso::toBanks(t);
  EXPECT_NEAR(banks.exponent, 50.0, 1e-9);
  EXPECT_NEAR(banks.specular.x, 0.5 * std::sqrt(50.0 / (2.0 * kPi)) / kPi, 1e-12);
  EXPECT_NO_THROW(aniso::validateBanks(banks));
  EXPECT_NO_THROW(aniso::validateHeidrichSeidel(aniso::toHeidrichSeidel(t)));
  EXPECT_NO_THROW(aniso::validateWard(aniso::toWard(t)));
  const aniso::BlinnPhongAnisoMaterial bp = aniso::toBlinnPhong(t);
  EXPECT_EQ(bp.alphaY, 0.4);
  EXPECT_NO_THROW(aniso::validateBlinnPhongAniso(bp));

  // The extreme roughness maps to valid parameters of every model.
  t.alphaX = aniso::kSvMinAlpha;
  t.alphaY = aniso::kSvMaxAlpha;
  EXPECT_NO_THROW(aniso::validateAsMaterial(aniso::toAshikhminShirley(t)));
  EXPECT_NO_THROW(aniso::validateBanks(aniso::toBanks(t)));
}

// Sizes and heights outside the documented ranges are refused.
TEST(Materials, ValidatesArguments)
{
  EXPECT_THROW(aniso::scratchedPlate(8), aniso::Error);
  EXPECT_THROW(aniso::veinedMarble(64, -0.1), aniso::Error);
  EXPECT_THROW(aniso::veinedMarble(5000), aniso::Error);
}
} // namespace
