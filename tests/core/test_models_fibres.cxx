// Fibre models (Banks, Heidrich-Seidel): the closed forms of N'.L and V.R' against the explicit
// construction (projection of l into the fibre's normal plane, the best mirror direction over
// all the fibre's normals), the diffuse
// albedo of Banks's model against its closed form 8 rho_d / (3 pi), reciprocity (Banks specular
// is, Banks diffuse and Heidrich-Seidel are not), the customary shading forms written out in
// world space, the Heidrich-Seidel specular albedo against a one-dimensional integral and its
// bound, and finiteness.
#include "core/brdf/banks.h"
#include "core/brdf/heidrich_seidel.h"
#include "core/env/quadrature.h"
#include "core/error.h"
#include "tests/core/test_models_quadrature.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <random>

namespace
{
using models_test::kPi;

glm::dvec3 randomSphere(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double z = u(rng);
  const double phi = kPi * u(rng);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

glm::dvec3 randomUpper(std::mt19937_64& rng)
{
  glm::dvec3 d = randomSphere(rng);
  d.z = std::abs(d.z);
  return d;
}

aniso::BanksMaterial banks(double rd, double ks, double e)
{
  aniso::BanksMaterial m;
  m.diffuse = glm::dvec3(rd);
  m.specular = glm::dvec3(ks);
  m.exponent = e;
  return m;
}

aniso::HeidrichSeidelMaterial hs(double rd, double ks, double e)
{
  aniso::HeidrichSeidelMaterial m;
  m.diffuse = glm::dvec3(rd);
  m.specular = glm::dvec3(ks);
  m.exponent = e;
  return m;
}

// N'.L against the explicit projection N' = normalize(l - (l.t) t); V.R' against a brute-force
// maximum of v.r over the mirror directions r = 2 (N.l) N - l of every normal N of the fibre's
// normal plane (20000 of them, so the maximum is found to ~1e-7), for directions over the sphere.
TEST(Fibres, ClosedFormsMatchConstruction)
{
  std::mt19937_64 rng(41);
  const glm::dvec3 t(1.0, 0.0, 0.0);
  for (int i = 0; i < 300; ++i)
  {
    const glm::dvec3 v = randomSphere(rng);
    const glm::dvec3 l = randomSphere(rng);
    const glm::dvec3 nPrime = glm::normalize(l - glm::dot(l, t) * t);
    EXPECT_NEAR(aniso::fibreDiffuseCosine(l), glm::dot(nPrime, l), 1e-12);
    double best = -2.0;
    for (int k = 0; k < 20000; ++k)
    {
      const double a = 2.0 * kPi * k / 20000.0;
      const glm::dvec3 n(0.0, std::cos(a), std::sin(a));
      best = std::max(best, glm::dot(v, 2.0 * glm::dot(n, l) * n - l));
    }
    EXPECT_NEAR(aniso::fibreSpecularCosine(v, l), best, 2e-7);
  }
}

// Banks's diffuse term rho_d / pi sqrt(1 - (l.t)^2) times (n.l) integrates to rho_d 8 / (3 pi)
// over the hemisphere, whatever the view (sin^3 times sin over a half sphere about t).
TEST(Fibres, BanksDiffuseAlbedoClosedForm)
{
  const aniso::BanksMaterial m = banks(0.7, 0.0, 10.0);
  for (double theta : {0.0, 45.0, 80.0})
  {
    const glm::dvec3 v = models_test::fromAngles(theta, 20.0);
    const double albedo = models_test::sphereIntegral(
        [&](const glm::dvec3& l) { return l.z > 0.0 ? aniso::evalBanks(m, v, l).x * l.z : 0.0; },
        glm::dvec3(0.0, 0.0, 1.0), 64, 512, false);
    EXPECT_NEAR(albedo, 0.7 * 8.0 / (3.0 * kPi), 1e-6) << theta;
  }
}

// Banks specular is reciprocal; Banks diffuse is not (N'.L depends on l only), nor is
// Heidrich-Seidel's f (its 1 / (n.l)).
TEST(Fibres, Reciprocity)
{
  std::mt19937_64 rng(43);
  const aniso::BanksMaterial specularOnly = banks(0.0, 0.8, 20.0);
  double banksDiffuseAsymmetry = 0.0;
  double hsAsymmetry = 0.0;
  for (int i = 0; i < 500; ++i)
  {
    const glm::dvec3 v = randomUpper(rng);
    const glm::dvec3 l = randomUpper(rng);
    const double a = aniso::evalBanks(specularOnly, v, l).x;
    EXPECT_NEAR(a, aniso::evalBanks(specularOnly, l, v).x, 1e-12 * std::max(a, 1e-300));
    const aniso::BanksMaterial diffuse = banks(1.0, 0.0, 1.0);
    banksDiffuseAsymmetry =
        std::max(banksDiffuseAsymmetry,
                 std::abs(aniso::evalBanks(diffuse, v, l).x - aniso::evalBanks(diffuse, l, v).x));
    const aniso::HeidrichSeidelMaterial h = hs(0.0, 1.0, 2.0);
    hsAsymmetry = std::max(hsAsymmetry, std::abs(aniso::evalHeidrichSeidel(h, v, l).x -
                                                 aniso::evalHeidrichSeidel(h, l, v).x));
  }
  EXPECT_GT(banksDiffuseAsymmetry, 0.05);
  EXPECT_GT(hsAsymmetry, 0.05);
}

// The customary forms in world space, for a tilted frame lit by a directional and a point light,
// against the explicit construction with world-space vectors (N' the projection of l, R' the
// mirror cone's direction closest to v):
//   Banks: E (n.l)+ [rho_d / pi N'.L + k_s (V.R')^e];  Heidrich-Seidel: E [rho_d / pi (n.l)+ +
//   k_s (V.R')^e]. The Heidrich-Seidel specular term is Banks's without the (n.l) factor.
TEST(Fibres, CustomaryShadingForms)
{
  const aniso::Frame frame =
      aniso::Frame::fromNormalTangent(glm::dvec3(0.2, -0.4, 0.9), glm::dvec3(0.3, 1.0, 0.1));
  const glm::dvec3 position(0.1, 0.2, 0.3);
  const std::vector<aniso::Light> lights = {aniso::parseLight("dir:0.3,-0.5,1:2,1,0.5"),
                                            aniso::parseLight("point:1,-1,2:4")};
  const glm::dvec3 view = glm::normalize(glm::dvec3(-0.5, 0.2, 1.0));
  const double rd = 0.6;
  const double ks = 0.9;
  const double e = 12.0;

  glm::dvec3 banksExpected(0.0);
  glm::dvec3 hsExpected(0.0);
  for (const aniso::Light& light : lights)
  {
    const aniso::LightArrival a = aniso::arriveAt(light, position);
    const glm::dvec3 l = a.direction;
    const double nl = glm::dot(frame.n, l);
    ASSERT_GT(nl, 0.0);
    const glm::dvec3 nPrime = glm::normalize(l - glm::dot(l, frame.t) * frame.t);
    // The cone of mirror directions: r.t = -l.t, normal-plane part of length |N'.l|; its point
    // closest to the view has the view's normal-plane direction.
    const glm::dvec3 w = glm::normalize(view - glm::dot(view, frame.t) * frame.t);
    const glm::dvec3 rPrime = -glm::dot(l, frame.t) * frame.t + glm::dot(nPrime, l) * w;
    const double specular = std::pow(std::max(glm::dot(view, rPrime), 0.0), e);
    banksExpected += a.irradiance * nl * (rd / kPi * glm::dot(nPrime, l) + ks * specular);
    hsExpected += a.irradiance * (rd / kPi * nl + ks * specular);
  }
  const glm::dvec3 banksValue = aniso::shadeBanks(banks(rd, ks, e), frame, position, view, lights);
  const glm::dvec3 hsValue =
      aniso::shadeHeidrichSeidel(hs(rd, ks, e), frame, position, view, lights);
  EXPECT_NEAR(glm::length(banksValue - banksExpected), 0.0, 1e-13 * glm::length(banksExpected));
  EXPECT_NEAR(glm::length(hsValue - hsExpected), 0.0, 1e-13 * glm::length(hsExpected));

  // f (n.l) is the customary term.
  const glm::dvec3 v = models_test::fromAngles(30.0, 10.0);
  const glm::dvec3 l = models_test::fromAngles(70.0, 200.0);
  EXPECT_NEAR(aniso::evalHeidrichSeidel(hs(rd, ks, e), v, l).x * l.z,
              aniso::heidrichSeidelTerm(hs(rd, ks, e), v, l).x, 1e-15);
}

// The Heidrich-Seidel specular albedo (no cosine: the fibre highlight is not attenuated) equals
// pi * integral over a in [0, pi] of sin(a) max(-cos(a + a_v), 0)^e (a = angle of l from t, a_v
// that of v; the highlight depends on a only and half of each circle about t is above the
// horizon), and stays below k_s 2 pi sqrt(pi) Gamma((e+1)/2) / Gamma(e/2 + 1).
TEST(Fibres, HeidrichSeidelSpecularAlbedo)
{
  for (double e : {1.0, 10.0, 100.0, 1000.0})
  {
    const aniso::HeidrichSeidelMaterial m = hs(0.0, 1.0, e);
    for (double theta : {20.0, 60.0})
    {
      const glm::dvec3 v = models_test::fromAngles(theta, 35.0);
      const double albedo = models_test::sphereIntegral(
          [&](const glm::dvec3& l)
          { return l.z > 0.0 ? aniso::heidrichSeidelTerm(m, v, l).x : 0.0; },
          glm::dvec3(1.0, 0.0, 0.0), 400, 256, false);
      const double av = std::acos(v.x);
      const aniso::QuadratureRule rule = aniso::compositeGaussLegendre(2000, 8, 0.0, kPi);
      double oneD = 0.0;
      for (std::size_t i = 0; i < rule.nodes.size(); ++i)
      {
        const double a = rule.nodes[i];
        oneD += rule.weights[i] * std::sin(a) * std::pow(std::max(-std::cos(a + av), 0.0), e);
      }
      oneD *= kPi;
      const double bound = 2.0 * kPi * std::sqrt(kPi) *
                           std::exp(std::lgamma(0.5 * (e + 1.0)) - std::lgamma(0.5 * e + 1.0));
      EXPECT_NEAR(albedo, oneD, 2e-3 * oneD) << e << " " << theta;
      EXPECT_LE(albedo, bound) << e;
    }
  }
}

// Finite and non-negative for exponents from 0 to 1e6, the largest k_s, grazing directions and
// directions along the fibre.
TEST(Fibres, FiniteAcrossParameterRange)
{
  std::mt19937_64 rng(47);
  for (double e : {0.0, 1e-3, 1.0, 1e3, aniso::kFibreMaxExponent})
  {
    const aniso::BanksMaterial b = banks(1.0, aniso::kFibreMaxSpecular, e);
    const aniso::HeidrichSeidelMaterial h = hs(1.0, aniso::kFibreMaxSpecular, e);
    for (int i = 0; i < 500; ++i)
    {
      glm::dvec3 v = randomUpper(rng);
      glm::dvec3 l = randomUpper(rng);
      if (i % 3 == 0)
        l = glm::normalize(glm::dvec3(l.x, l.y, 1e-300));
      if (i % 5 == 0)
        v = glm::normalize(glm::dvec3(1.0, 0.0, 1e-9)); // along the fibre
      for (double value : {aniso::evalBanks(b, v, l).x, aniso::evalHeidrichSeidel(h, v, l).x,
                           aniso::heidrichSeidelTerm(h, v, l).x})
      {
        EXPECT_TRUE(std::isfinite(value) && value >= 0.0) << e;
      }
    }
  }
}

// Out-of-range parameters are refused, naming the parameter.
TEST(Fibres, ValidatesParameters)
{
  EXPECT_NO_THROW(aniso::validateBanks(banks(0.5, 2.0, 30.0)));
  EXPECT_THROW(aniso::validateBanks(banks(1.5, 2.0, 30.0)), aniso::Error);
  EXPECT_THROW(aniso::validateBanks(banks(0.5, -1.0, 30.0)), aniso::Error);
  EXPECT_THROW(aniso::validateHeidrichSeidel(hs(0.5, 1.0, -1.0)), aniso::Error);
  EXPECT_THROW(aniso::validateHeidrichSeidel(hs(0.5, 1.0, std::nan(""))), aniso::Error);
}
} // namespace
