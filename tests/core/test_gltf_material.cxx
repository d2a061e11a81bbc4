// The glTF material mapping (core/models/gltf_material.h) against the formulas of the glTF
// specification and KHR_materials_anisotropy worked by hand, and its export against its import
// over a grid of materials.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/models/gltf_material.h"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

void expectColor(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance)
{
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(GltfMaterial, RoughnessAndStrengthGiveTheSpecificationsAlphasAndTheirExponents)
{
  // Checks: alpha = r^2, alpha_t = mix(alpha, 1, s^2), alpha_b = alpha, n = 2 / alpha^2 - 2.
  // Reference: r = 0.5, s = 0.6 by hand: alpha = 0.25, alpha_t = 0.25 + 0.75 * 0.36 = 0.52,
  // n_t = 2 / 0.2704 - 2 = 5.39645..., n_b = 2 / 0.0625 - 2 = 30.
  const GltfAlphas alphas = gltfAlphas(0.5, 0.6);
  EXPECT_DOUBLE_EQ(alphas.alphaB, 0.25);
  EXPECT_NEAR(alphas.alphaT, 0.52, 1e-15);
  GltfFactors f;
  f.roughness = 0.5;
  f.anisotropyStrength = 0.6;
  const GltfAsValues as = gltfToAs(f);
  EXPECT_NEAR(as.nu, 2.0 / (0.52 * 0.52) - 2.0, 1e-12);
  EXPECT_NEAR(as.nv, 30.0, 1e-12);
  EXPECT_EQ(as.tangentRotation, 0.0);
  // Strength 1 makes the anisotropy direction fully rough (n 0); roughness 0 the smooth limit.
  f.anisotropyStrength = 1.0;
  EXPECT_DOUBLE_EQ(gltfToAs(f).nu, 0.0);
  f.roughness = 0.0;
  f.anisotropyStrength = 0.0;
  EXPECT_DOUBLE_EQ(gltfToAs(f).nu, kMaxExponent);
  EXPECT_DOUBLE_EQ(gltfToAs(f).nv, kMaxExponent);
}

TEST(GltfMaterial, MetallicMixesF0AndTakesTheAlbedo)
{
  // Checks: F0 = mix(0.04, baseColor, metallic), albedo = baseColor (1 - metallic); with
  // KHR_materials_specular the dielectric F0 is min(0.04 specularColor, 1) specularFactor.
  // Reference: by hand for baseColor (0.8, 0.1, 0.2), metallic 0.25.
  GltfFactors f;
  f.baseColor = {0.8, 0.1, 0.2};
  f.metallic = 0.25;
  const GltfAsValues as = gltfToAs(f);
  expectColor(as.f0, {0.03 + 0.2, 0.03 + 0.025, 0.03 + 0.05}, 1e-15);
  expectColor(as.albedo, {0.6, 0.075, 0.15}, 1e-15);
  f.metallic = 0.0;
  f.specularColor = {2.0, 30.0, 0.5};
  f.specularFactor = 0.5;
  expectColor(gltfToAs(f).f0, {0.04, 0.5, 0.01}, 1e-15);
  // ior 2: ((2 - 1) / (2 + 1))^2 = 1/9.
  f.specularColor = glm::dvec3(1.0);
  f.specularFactor = 1.0;
  f.ior = 2.0;
  expectColor(gltfToAs(f).f0, glm::dvec3(1.0 / 9.0), 1e-15);
}

TEST(GltfMaterial, RotationTurnsTheTangentOrSwapsTheExponents)
{
  // Checks: a rotation of pi/2 (or -pi/2, 3pi/2) swaps n_u and n_v and leaves no rotation; pi
  // leaves the lobe as it is (a tangent line repeats every pi); 0.3 is kept as a rotation of the
  // tangent; 1.2 (beyond pi/4) swaps and leaves 1.2 - pi/2.
  GltfFactors f;
  f.roughness = 0.5;
  f.anisotropyStrength = 0.8;
  const GltfAsValues straight = gltfToAs(f);
  ASSERT_LT(straight.nu, straight.nv);
  for (double rotation : {kPi / 2.0, -kPi / 2.0, 3.0 * kPi / 2.0})
  {
    f.anisotropyRotation = rotation;
    const GltfAsValues turned = gltfToAs(f);
    EXPECT_DOUBLE_EQ(turned.nu, straight.nv) << rotation;
    EXPECT_DOUBLE_EQ(turned.nv, straight.nu) << rotation;
    EXPECT_EQ(turned.tangentRotation, 0.0) << rotation;
  }
  f.anisotropyRotation = kPi;
  EXPECT_DOUBLE_EQ(gltfToAs(f).nu, straight.nu);
  EXPECT_NEAR(gltfToAs(f).tangentRotation, 0.0, 1e-12);
  f.anisotropyRotation = 0.3;
  EXPECT_DOUBLE_EQ(gltfToAs(f).nu, straight.nu);
  EXPECT_NEAR(gltfToAs(f).tangentRotation, 0.3, 1e-15);
  f.anisotropyRotation = 1.2;
  EXPECT_DOUBLE_EQ(gltfToAs(f).nu, straight.nv);
  EXPECT_NEAR(gltfToAs(f).tangentRotation, 1.2 - kPi / 2.0, 1e-15);
}

TEST(GltfMaterial, ExportOfTheAnalyticCaseGivesTheSpecificationsFactors)
{
  // Checks: export of n_u = 2 / 0.52^2 - 2, n_v = 30 (the first test's lobe) gives back
  // roughness 0.5, strength 0.6, rotation 0; with the exponents swapped, rotation pi/2; a metal
  // (albedo 0) is metallic 1 with baseColor F0; a dielectric of F0 0.04 metallic 0 without
  // KHR_materials_specular.
  const double nt = 2.0 / (0.52 * 0.52) - 2.0;
  GltfFactors f = asToGltf(nt, 30.0, {0.9, 0.6, 0.3}, glm::dvec3(0.0));
  EXPECT_NEAR(f.roughness, 0.5, 1e-12);
  EXPECT_NEAR(f.anisotropyStrength, 0.6, 1e-12);
  EXPECT_EQ(f.anisotropyRotation, 0.0);
  EXPECT_EQ(f.metallic, 1.0);
  expectColor(f.baseColor, {0.9, 0.6, 0.3}, 0.0);
  EXPECT_FALSE(f.hasSpecular);
  f = asToGltf(30.0, nt, glm::dvec3(0.04), {0.5, 0.2, 0.1});
  EXPECT_NEAR(f.anisotropyRotation, kPi / 2.0, 1e-15);
  EXPECT_NEAR(f.anisotropyStrength, 0.6, 1e-12);
  EXPECT_EQ(f.metallic, 0.0);
  expectColor(f.baseColor, {0.5, 0.2, 0.1}, 0.0);
  EXPECT_FALSE(f.hasSpecular);
}

TEST(GltfMaterial, ImportOfExportGivesTheMaterialBackOverAGrid)
{
  // Checks: gltfToAs(asToGltf(m)) == m for n_u, n_v over [0, 1e6] (both orders, equal ones),
  // metals, dielectrics and coloured specular with a diffuse albedo. Reference: m itself.
  const std::vector<double> exponents = {0.0, 0.5, 1.0, 10.0, 100.0, 1000.0, 12345.0, 1e5, 1e6};
  const std::vector<glm::dvec3> f0s = {glm::dvec3(0.04), {0.913, 0.922, 0.924}, {1.0, 0.7, 0.3},
                                       glm::dvec3(0.0), glm::dvec3(1.0)};
  const std::vector<glm::dvec3> albedos = {glm::dvec3(0.0), {0.8, 0.1, 0.05}, glm::dvec3(1.0)};
  int cases = 0;
  for (double nu : exponents)
  {
    for (double nv : exponents)
    {
      for (const glm::dvec3& f0 : f0s)
      {
        for (const glm::dvec3& albedo : albedos)
        {
          const GltfAsValues back = gltfToAs(asToGltf(nu, nv, f0, albedo));
          const auto close = [](double a, double b) { return std::abs(a - b) <= 1e-8 * (1.0 + b); };
          EXPECT_TRUE(close(back.nu, nu) && close(back.nv, nv))
              << nu << " " << nv << " came back " << back.nu << " " << back.nv;
          EXPECT_EQ(back.tangentRotation, 0.0);
          expectColor(back.f0, f0, 1e-14);
          expectColor(back.albedo, albedo, 1e-14);
          ++cases;
        }
      }
    }
  }
  EXPECT_EQ(cases, 9 * 9 * 5 * 3);
}

TEST(GltfMaterial, AnisotropyTextureDirectionAndTextureTransform)
{
  // Checks: RG (1, 0.5) is +t, (0.5, 1) is +b; the rotation turns it counter-clockwise; a zero
  // RG falls back to the turned tangent. KHR_texture_transform: offset + R (scale uv) with the
  // extension's matrix; rotation pi/2 takes (1, 0) to (0, -1).
  const glm::dvec2 t = gltfAnisotropyDirection({1.0, 0.5}, 0.0);
  EXPECT_NEAR(t.x, 1.0, 1e-15);
  EXPECT_NEAR(t.y, 0.0, 1e-15);
  const glm::dvec2 b = gltfAnisotropyDirection({0.5, 1.0}, 0.0);
  EXPECT_NEAR(b.x, 0.0, 1e-15);
  EXPECT_NEAR(b.y, 1.0, 1e-15);
  const glm::dvec2 turned = gltfAnisotropyDirection({1.0, 0.5}, kPi / 2.0);
  EXPECT_NEAR(turned.x, 0.0, 1e-15);
  EXPECT_NEAR(turned.y, 1.0, 1e-15);
  const glm::dvec2 none = gltfAnisotropyDirection({0.5, 0.5}, kPi / 6.0);
  EXPECT_NEAR(none.x, std::cos(kPi / 6.0), 1e-15);
  EXPECT_NEAR(none.y, std::sin(kPi / 6.0), 1e-15);

  GltfTextureTransform transform;
  EXPECT_TRUE(transform.isIdentity());
  transform.offset = {0.25, 0.5};
  transform.scale = {2.0, 3.0};
  glm::dvec2 uv = applyTextureTransform(transform, {0.5, 0.5});
  EXPECT_NEAR(uv.x, 1.25, 1e-15);
  EXPECT_NEAR(uv.y, 2.0, 1e-15);
  transform = {};
  transform.rotation = kPi / 2.0;
  uv = applyTextureTransform(transform, {1.0, 0.0});
  EXPECT_NEAR(uv.x, 0.0, 1e-15);
  EXPECT_NEAR(uv.y, -1.0, 1e-15);
}
TEST(GltfMaterial, TextureTransformTurnsAsBlendersImporterAndExporterDo)
{
  // Checks: the rotation's direction and the order translation * rotation * scale against an
  // independent reference, the conversion of glTF-Blender-IO (texture_transform_blender_to_gltf):
  // a Mapping node in Blender's UV space (origin bottom left, V up) maps (U, V) to
  // offset + Rccw(rotation) (scale * (U, V)) and is written as glTF offset
  // (offset.x - scale.y sin r, 1 - offset.y - scale.y cos r), the same rotation and scale.
  // glTF's texture coordinate of (U, V) is (U, 1 - V). Both sides must map every point alike.
  struct Mapping
  {
    glm::dvec2 offset;
    double rotation;
    glm::dvec2 scale;
  };
  for (const Mapping& blender :
       {Mapping{{0.0, 0.0}, kPi / 8.0, {1.0, 1.0}}, Mapping{{0.3, -0.2}, 1.1, {2.0, 1.5}},
        Mapping{{-0.5, 0.7}, -2.4, {0.5, 3.0}}})
  {
    const double c = std::cos(blender.rotation);
    const double s = std::sin(blender.rotation);
    GltfTextureTransform gltf;
    gltf.offset = {blender.offset.x - blender.scale.y * s,
                   1.0 - blender.offset.y - blender.scale.y * c};
    gltf.rotation = blender.rotation;
    gltf.scale = blender.scale;
    for (const glm::dvec2 in : {glm::dvec2(0.0, 0.0), glm::dvec2(1.0, 0.0), glm::dvec2(0.25, 0.8)})
    {
      const glm::dvec2 scaled = blender.scale * in;
      const glm::dvec2 out =
          blender.offset + glm::dvec2(c * scaled.x - s * scaled.y, s * scaled.x + c * scaled.y);
      const glm::dvec2 uv = applyTextureTransform(gltf, {in.x, 1.0 - in.y});
      EXPECT_NEAR(uv.x, out.x, 1e-12) << blender.rotation;
      EXPECT_NEAR(uv.y, 1.0 - out.y, 1e-12) << blender.rotation;
    }
  }
}
} // namespace
} // namespace aniso
