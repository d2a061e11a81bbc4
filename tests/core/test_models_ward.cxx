// Ward's model: the factored evaluation of source 2 (S(p) E(m, d) from t/alpha_x, b/alpha_y)
// against the direct formula in the half vector's angles, the isotropic closed form, the two
// forms of the Gaussian factor (eq. 5a and 5b) against each other, reciprocity, energy and
// finiteness. References: closed forms written out here and quadrature over the sphere.
#include "core/brdf/ward.h"
#include "core/error.h"
#include "tests/core/test_models_quadrature.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <random>

namespace
{
using aniso::WardForm;
using aniso::WardMaterial;
using models_test::kPi;
using models_test::randomUpper;

WardMaterial ward(double ax, double ay, WardForm form, double rs = 1.0, double rd = 0.0)
{
  WardMaterial m;
  m.alphaX = ax;
  m.alphaY = ay;
  m.form = form;
  m.specular = glm::dvec3(rs);
  m.diffuse = glm::dvec3(rd);
  return m;
}

// Source 2's factored evaluation, from world-space vectors in a tilted frame, equals the direct
// formula in tangent-space angles, for both forms, isotropic and anisotropic.
TEST(Ward, FactoredEqualsDirect)
{
  const aniso::Frame frame =
      aniso::Frame::fromNormalTangent(glm::dvec3(-0.3, 0.5, 0.8), glm::dvec3(1.0, 0.2, 0.0));
  std::mt19937_64 rng(17);
  for (WardForm form : {WardForm::HalfVector, WardForm::Gaussian})
  {
    for (const auto& a : {glm::dvec2(0.1, 0.1), glm::dvec2(0.05, 0.4), glm::dvec2(0.7, 0.2)})
    {
      const WardMaterial m = ward(a.x, a.y, form, 0.7, 0.2);
      const aniso::ScaledTangents s = aniso::scaledTangents(frame, a.x, a.y);
      for (int i = 0; i < 300; ++i)
      {
        const glm::dvec3 v = randomUpper(rng);
        const glm::dvec3 l = randomUpper(rng);
        const double direct = aniso::evalWard(m, v, l).x;
        const double factored =
            aniso::evalWardFactored(m, s, frame.n, frame.toWorld(v), frame.toWorld(l)).x;
        EXPECT_NEAR(factored, direct, 1e-10 * direct) << a.x << " " << a.y;
      }
    }
  }
}

// The two lookups: S(p) = 1 / sqrt(p), E(m, d) = exp(-2 m / (1 + d)).
TEST(Ward, LookupFunctions)
{
  EXPECT_DOUBLE_EQ(aniso::wardS(0.25), 2.0);
  EXPECT_TRUE(std::isinf(aniso::wardS(0.0)));
  EXPECT_DOUBLE_EQ(aniso::wardE(0.0, 0.3), 1.0);
  EXPECT_NEAR(aniso::wardE(1.5, 0.5), std::exp(-2.0), 1e-16);
}

// alpha_x = alpha_y = alpha, eq. 5a: rho_s exp(-tan^2(theta_h) / alpha^2) /
// (4 pi alpha^2 sqrt(cos(theta_i) cos(theta_o))).
TEST(Ward, IsotropicClosedForm)
{
  std::mt19937_64 rng(23);
  for (double alpha : {0.05, 0.2, 0.6})
  {
    const WardMaterial m = ward(alpha, alpha, WardForm::Gaussian, 0.5);
    for (int i = 0; i < 200; ++i)
    {
      const glm::dvec3 v = randomUpper(rng);
      const glm::dvec3 l = randomUpper(rng);
      const glm::dvec3 h = glm::normalize(v + l);
      const double tan2 = (1.0 - h.z * h.z) / (h.z * h.z);
      const double expected = 0.5 * std::exp(-tan2 / (alpha * alpha)) /
                              (4.0 * kPi * alpha * alpha * std::sqrt(v.z * l.z));
      EXPECT_NEAR(aniso::evalWard(m, v, l).x, expected, 1e-10 * expected + 1e-300);
    }
  }
}

// Eq. 5b equals eq. 5a at the specular peak (h = n) and is never smaller elsewhere
// (2 (1 - cos) <= tan^2). Their directional albedos under a light sweep (40 degree view) differ
// by under 2% for alpha <= 0.1 and under 6% at alpha = 0.2 (printed), more for rough lobes.
TEST(Ward, HalfVectorFormApproximatesGaussianForm)
{
  std::mt19937_64 rng(29);
  const WardMaterial a5 = ward(0.1, 0.3, WardForm::Gaussian);
  const WardMaterial b5 = ward(0.1, 0.3, WardForm::HalfVector);
  for (int i = 0; i < 500; ++i)
  {
    const glm::dvec3 v = randomUpper(rng);
    const glm::dvec3 l = randomUpper(rng);
    EXPECT_GE(aniso::evalWard(b5, v, l).x, aniso::evalWard(a5, v, l).x * (1.0 - 1e-12));
    const glm::dvec3 mirror = models_test::mirrorOf(v);
    EXPECT_NEAR(aniso::evalWard(b5, v, mirror).x, aniso::evalWard(a5, v, mirror).x,
                1e-12 * aniso::evalWard(a5, v, mirror).x);
  }
  for (double alpha : {0.05, 0.1, 0.2, 0.4})
  {
    const glm::dvec3 v = models_test::fromAngles(40.0, 10.0);
    auto albedo = [&](WardForm form)
    {
      const WardMaterial m = ward(alpha, alpha, form);
      return models_test::hemisphereAlbedo([&](const glm::dvec3& vv, const glm::dvec3& l)
                                           { return aniso::evalWard(m, vv, l).x * l.z; },
                                           v, models_test::mirrorOf(v));
    };
    const double gaussian = albedo(WardForm::Gaussian);
    const double halfVector = albedo(WardForm::HalfVector);
    const double relative = (halfVector - gaussian) / gaussian;
    std::printf("alpha %.2f: albedo eq.5a %.4f, eq.5b %.4f (%+.2f%%)\n", alpha, gaussian,
                halfVector, 100.0 * relative);
    if (alpha <= 0.1)
    {
      EXPECT_LT(std::abs(relative), 0.02) << alpha;
    }
    else if (alpha <= 0.2)
    {
      EXPECT_LT(std::abs(relative), 0.06) << alpha;
    }
  }
}

// f(v, l) = f(l, v) in both forms.
TEST(Ward, IsReciprocal)
{
  std::mt19937_64 rng(31);
  for (WardForm form : {WardForm::HalfVector, WardForm::Gaussian})
  {
    const WardMaterial m = ward(0.08, 0.3, form, 0.9, 0.1);
    for (int i = 0; i < 500; ++i)
    {
      const glm::dvec3 v = randomUpper(rng);
      const glm::dvec3 l = randomUpper(rng);
      EXPECT_NEAR(aniso::evalWard(m, v, l).x, aniso::evalWard(m, l, v).x,
                  1e-12 * aniso::evalWard(m, v, l).x);
    }
  }
}

// White specular (rho_s = 1): the directional albedo stays at or below 1 for alpha <= 0.3 and
// views up to 60 degrees (it is about cos(theta_v) for narrow lobes). Towards grazing views the
// 1/sqrt(n.v) factor makes it grow without bound, a known property of Ward's model: the test
// requires the excess to appear (89.9 degrees, alpha = 1) so that the documented limitation
// stays true, and prints the albedos.
TEST(Ward, EnergyBoundedAwayFromGrazing)
{
  for (WardForm form : {WardForm::Gaussian, WardForm::HalfVector})
  {
    for (const auto& a : {glm::dvec2(0.05, 0.05), glm::dvec2(0.15, 0.15), glm::dvec2(0.3, 0.3),
                          glm::dvec2(0.05, 0.3)})
    {
      const WardMaterial m = ward(a.x, a.y, form);
      for (double theta : {0.0, 30.0, 60.0})
      {
        const glm::dvec3 v = models_test::fromAngles(theta, 30.0);
        const double albedo =
            models_test::hemisphereAlbedo([&](const glm::dvec3& vv, const glm::dvec3& l)
                                          { return aniso::evalWard(m, vv, l).x * l.z; },
                                          v, models_test::mirrorOf(v));
        EXPECT_LE(albedo, 1.0) << a.x << " " << a.y << " theta " << theta;
      }
    }
    const WardMaterial rough = ward(1.0, 1.0, form);
    const glm::dvec3 grazing = models_test::fromAngles(89.9, 0.0);
    const double excess =
        models_test::hemisphereAlbedo([&](const glm::dvec3& vv, const glm::dvec3& l)
                                      { return aniso::evalWard(rough, vv, l).x * l.z; },
                                      grazing, models_test::mirrorOf(grazing));
    std::printf("%s: albedo at 89.9 degrees, alpha 1: %.3f\n",
                form == WardForm::Gaussian ? "eq.5a" : "eq.5b", excess);
    EXPECT_GT(excess, 1.0);
  }
}

// Finite and non-negative over the whole parameter range, grazing directions included.
TEST(Ward, FiniteAcrossParameterRange)
{
  std::mt19937_64 rng(37);
  const double alphas[] = {aniso::kSvMinAlpha, 0.02, 0.5, aniso::kSvMaxAlpha};
  for (WardForm form : {WardForm::HalfVector, WardForm::Gaussian})
  {
    for (double ax : alphas)
    {
      for (double ay : alphas)
      {
        const WardMaterial m = ward(ax, ay, form, 1.0, 1.0);
        const aniso::Frame f;
        const aniso::ScaledTangents s = aniso::scaledTangents(f, ax, ay);
        for (int i = 0; i < 300; ++i)
        {
          glm::dvec3 v = randomUpper(rng);
          glm::dvec3 l = randomUpper(rng);
          if (i % 3 == 0)
            v = glm::normalize(glm::dvec3(v.x, v.y, 1e-200));
          if (i % 7 == 0)
            l = glm::normalize(glm::dvec3(-v.x, -v.y, 1e-200));
          const double direct = aniso::evalWard(m, v, l).x;
          const double factored = aniso::evalWardFactored(m, s, f.n, v, l).x;
          EXPECT_TRUE(std::isfinite(direct) && direct >= 0.0) << ax << " " << ay;
          EXPECT_TRUE(std::isfinite(factored) && factored >= 0.0) << ax << " " << ay;
        }
      }
    }
  }
}

// Out-of-range parameters are refused, naming the parameter.
TEST(Ward, ValidatesParameters)
{
  EXPECT_NO_THROW(aniso::validateWard(ward(0.1, 0.2, WardForm::HalfVector)));
  EXPECT_THROW(aniso::validateWard(ward(0.0, 0.2, WardForm::HalfVector)), aniso::Error);
  EXPECT_THROW(aniso::validateWard(ward(0.1, 11.0, WardForm::HalfVector)), aniso::Error);
  EXPECT_THROW(aniso::validateWard(ward(0.1, 0.1, WardForm::HalfVector, 1.2)), aniso::Error);
}
} // namespace
