// Anisotropic Blinn-Phong: normalisation of its distribution, reduction to isotropic
// Blinn-Phong, the exponent read from the t/alpha_x, b/alpha_y textures, reciprocity, energy and
// finiteness. References: quadrature over the sphere (test_models_quadrature.h), closed forms of
// the isotropic model written out here, and world-space vectors built independently.
#include "core/brdf/blinn_phong_aniso.h"
#include "core/error.h"
#include "tests/core/test_models_quadrature.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <random>

namespace
{
using aniso::BlinnPhongAnisoMaterial;
using models_test::kPi;
using models_test::randomUpper;

BlinnPhongAnisoMaterial material(double ax, double ay, double ks = 1.0, double rd = 0.0)
{
  BlinnPhongAnisoMaterial m;
  m.alphaX = ax;
  m.alphaY = ay;
  m.specular = glm::dvec3(ks);
  m.diffuse = glm::dvec3(rd);
  return m;
}

// The integral of D(h) (n.h) over the hemisphere is 1 for isotropic and strongly anisotropic
// roughnesses (the normalisation sqrt((e_x+2)(e_y+2)) / (2 pi) is exact).
TEST(BlinnPhongAniso, DistributionIsProjectedNormalised)
{
  const double pairs[][2] = {{0.2, 0.2}, {0.05, 0.5}, {0.5, 0.02}, {1.0, 3.0}, {8.0, 8.0}};
  for (const auto& p : pairs)
  {
    const BlinnPhongAnisoMaterial m = material(p[0], p[1]);
    const double integral = models_test::sphereIntegral(
        [&](const glm::dvec3& h)
        { return h.z > 0.0 ? aniso::blinnPhongDistribution(m, h) * h.z : 0.0; },
        glm::dvec3(0.0, 0.0, 1.0), 200, 512, true);
    EXPECT_NEAR(integral, 1.0, 2e-6) << p[0] << " " << p[1];
  }
}

// alpha_x = alpha_y = alpha is isotropic Blinn-Phong: f = rho_d / pi + k_s (e + 2) / (8 pi)
// (n.h)^e with e = 1 / alpha^2.
TEST(BlinnPhongAniso, EqualRoughnessesReduceToIsotropic)
{
  std::mt19937_64 rng(7);
  for (double alpha : {0.03, 0.2, 0.7, 2.0})
  {
    const BlinnPhongAnisoMaterial m = material(alpha, alpha, 0.6, 0.3);
    const double e = 1.0 / (alpha * alpha);
    for (int i = 0; i < 200; ++i)
    {
      const glm::dvec3 v = randomUpper(rng);
      const glm::dvec3 l = randomUpper(rng);
      const glm::dvec3 h = glm::normalize(v + l);
      const double expected = 0.3 / kPi + 0.6 * (e + 2.0) / (8.0 * kPi) * std::pow(h.z, e);
      EXPECT_NEAR(aniso::evalBlinnPhongAniso(m, v, l).y, expected, 1e-12 * expected);
    }
  }
}

// The exponent from world-space t/alpha_x, b/alpha_y (a rotated frame) equals the exponent from
// the roughnesses in tangent space, e_x cos^2(phi_h) + e_y sin^2(phi_h).
TEST(BlinnPhongAniso, ExponentFromScaledTangentsMatches)
{
  const aniso::Frame frame =
      aniso::Frame::fromNormalTangent(glm::dvec3(0.3, -0.2, 0.9), glm::dvec3(0.2, 1.0, 0.0));
  const BlinnPhongAnisoMaterial m = material(0.07, 0.3);
  const aniso::ScaledTangents s = aniso::scaledTangents(frame, m.alphaX, m.alphaY);
  std::mt19937_64 rng(11);
  for (int i = 0; i < 200; ++i)
  {
    const glm::dvec3 h = randomUpper(rng);
    const double phi = std::atan2(h.y, h.x);
    const double expected =
        std::cos(phi) * std::cos(phi) / (0.07 * 0.07) + std::sin(phi) * std::sin(phi) / (0.3 * 0.3);
    EXPECT_NEAR(aniso::blinnPhongExponent(m, h), expected, 1e-11 * expected);
    EXPECT_NEAR(aniso::blinnPhongExponent(s, frame.n, frame.toWorld(h)), expected, 1e-9 * expected);
  }
}

// f(v, l) = f(l, v) to rounding for random pairs and anisotropic roughness.
TEST(BlinnPhongAniso, IsReciprocal)
{
  const BlinnPhongAnisoMaterial m = material(0.05, 0.4, 0.8, 0.2);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 1000; ++i)
  {
    const glm::dvec3 v = randomUpper(rng);
    const glm::dvec3 l = randomUpper(rng);
    const glm::dvec3 a = aniso::evalBlinnPhongAniso(m, v, l);
    const glm::dvec3 b = aniso::evalBlinnPhongAniso(m, l, v);
    EXPECT_NEAR(a.x, b.x, 1e-12 * a.x);
  }
}

// White specular (k_s = 1): the directional albedo stays below 1 from normal incidence to 89
// degrees, over roughnesses from 0.01 to 5, isotropic and anisotropic; its largest value is
// printed. Directional light sweep = quadrature over light directions of f (n.l).
TEST(BlinnPhongAniso, EnergyAtMostOne)
{
  double largest = 0.0;
  const double pairs[][2] = {{0.01, 0.01}, {0.05, 0.05}, {0.2, 0.2},  {0.6, 0.6},
                             {1.5, 1.5},   {5.0, 5.0},   {0.02, 0.5}, {1.0, 0.1}};
  for (const auto& p : pairs)
  {
    const BlinnPhongAnisoMaterial m = material(p[0], p[1]);
    for (double theta : {0.0, 30.0, 60.0, 80.0, 89.0})
    {
      const glm::dvec3 v = models_test::fromAngles(theta, 25.0);
      const double albedo =
          models_test::hemisphereAlbedo([&](const glm::dvec3& vv, const glm::dvec3& l)
                                        { return aniso::evalBlinnPhongAniso(m, vv, l).x * l.z; },
                                        v, models_test::mirrorOf(v));
      largest = std::max(largest, albedo);
      EXPECT_LE(albedo, 1.0) << p[0] << " " << p[1] << " theta " << theta;
      EXPECT_GT(albedo, 0.0);
    }
  }
  std::printf("largest Blinn-Phong specular albedo: %.4f\n", largest);
}

// Finite and non-negative everywhere, including grazing and the extreme roughnesses.
TEST(BlinnPhongAniso, FiniteAcrossParameterRange)
{
  std::mt19937_64 rng(5);
  const double alphas[] = {aniso::kSvMinAlpha, 0.01, 0.3, 3.0, aniso::kSvMaxAlpha};
  for (double ax : alphas)
  {
    for (double ay : alphas)
    {
      const BlinnPhongAnisoMaterial m = material(ax, ay, 1.0, 1.0);
      for (int i = 0; i < 300; ++i)
      {
        glm::dvec3 v = randomUpper(rng);
        glm::dvec3 l = randomUpper(rng);
        if (i % 3 == 0)
          v = glm::normalize(glm::dvec3(v.x, v.y, 1e-200)); // grazing
        if (i % 5 == 0)
          l = v; // h = v, possibly h = n
        if (i % 7 == 0)
          l = glm::normalize(glm::dvec3(-v.x, -v.y, 1e-200)); // |v + l| below 1e-150
        const glm::dvec3 f = aniso::evalBlinnPhongAniso(m, v, l);
        EXPECT_TRUE(std::isfinite(f.x) && f.x >= 0.0) << ax << " " << ay;
      }
      EXPECT_TRUE(std::isfinite(aniso::evalBlinnPhongAniso(m, {0, 0, 1}, {0, 0, 1}).x));
    }
  }
}

// Out-of-range parameters are refused, naming the parameter.
TEST(BlinnPhongAniso, ValidatesParameters)
{
  EXPECT_NO_THROW(aniso::validateBlinnPhongAniso(material(0.1, 0.2)));
  auto messageOf = [](const BlinnPhongAnisoMaterial& m) -> std::string
  {
    try
    {
      aniso::validateBlinnPhongAniso(m);
    }
    catch (const aniso::Error& e)
    {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(messageOf(material(0.0, 0.2)).rfind("alpha_x:", 0), 0u);
  EXPECT_EQ(messageOf(material(0.2, std::nan(""))).rfind("alpha_y:", 0), 0u);
  EXPECT_EQ(messageOf(material(0.2, 0.2, 1.5)).rfind("specular:", 0), 0u);
  EXPECT_EQ(messageOf(material(0.2, 0.2, 0.5, -0.1)).rfind("diffuse:", 0), 0u);
}
} // namespace
