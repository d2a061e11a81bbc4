// Ashikhmin-Shirley under point and directional lights: the shading sum against
// evalSpecular x E x (n.l) computed by hand, the inverse-square falloff, the coupled diffuse
// term's albedo against its closed form, reciprocity and energy. References: the specular
// function of brdf/ashikhmin_shirley.h (tested on its own), closed forms, sphere quadrature.
#include "core/brdf/ashikhmin_shirley_lights.h"
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
using models_test::randomUpper;

aniso::AsMaterial as(double nu, double nv, double f0, double rd)
{
  aniso::AsMaterial m;
  m.lobe.nu = nu;
  m.lobe.nv = nv;
  m.f0 = glm::dvec3(f0);
  m.diffuse = glm::dvec3(rd);
  return m;
}

// A directional light of irradiance E on a tilted frame: radiance = evalSpecular(v, l) E (n.l),
// with v and l taken to tangent space by hand.
TEST(AsLights, DirectionalLightMatchesSpecularTimesIrradianceAndCosine)
{
  const aniso::Frame frame =
      aniso::Frame::fromNormalTangent(glm::dvec3(0.1, 0.3, 1.0), glm::dvec3(1.0, -0.2, 0.0));
  const aniso::AsMaterial m = as(800.0, 60.0, 0.9, 0.0);
  const aniso::Light light = aniso::parseLight("dir:0.4,-0.2,1:1,2,3");
  std::mt19937_64 rng(53);
  for (int i = 0; i < 200; ++i)
  {
    const glm::dvec3 vLocal = randomUpper(rng);
    const glm::dvec3 view = vLocal.x * frame.t + vLocal.y * frame.b + vLocal.z * frame.n;
    const glm::dvec3 l = glm::normalize(light.vector);
    const glm::dvec3 lLocal(glm::dot(l, frame.t), glm::dot(l, frame.b), glm::dot(l, frame.n));
    const glm::dvec3 expected =
        aniso::evalSpecular(m.lobe, m.f0, vLocal, lLocal) * glm::dvec3(1.0, 2.0, 3.0) * lLocal.z;
    const glm::dvec3 value = aniso::shadeAshikhminShirley(m, frame, glm::dvec3(0.0), view, {light});
    EXPECT_NEAR(glm::length(value - expected), 0.0, 1e-12 * (1.0 + glm::length(expected)));
  }
}

// Moving a point light twice as far along the same ray divides the radiance by 4.
TEST(AsLights, PointLightFallsOffAsInverseSquare)
{
  const aniso::AsMaterial m = as(100.0, 100.0, 0.5, 0.5);
  const aniso::Frame frame;
  const glm::dvec3 p(0.2, 0.1, 0.0);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.3, 0.1, 1.0));
  aniso::Light nearLight;
  nearLight.type = aniso::LightType::Point;
  nearLight.vector = p + dir;
  nearLight.intensity = glm::dvec3(5.0);
  aniso::Light farLight = nearLight;
  farLight.vector = p + 2.0 * dir;
  const glm::dvec3 view = glm::normalize(glm::dvec3(-0.2, 0.0, 1.0));
  const glm::dvec3 a = aniso::shadeAshikhminShirley(m, frame, p, view, {nearLight});
  const glm::dvec3 b = aniso::shadeAshikhminShirley(m, frame, p, view, {farLight});
  EXPECT_GT(a.x, 0.0);
  EXPECT_NEAR(a.x, 4.0 * b.x, 1e-13 * a.x);
}

// The coupled diffuse term's albedo is rho_d (1 - R_s) (1 - (1 - n.v/2)^5): 28 / (23 pi) is the
// normalisation of the light-side factor.
TEST(AsLights, DiffuseAlbedoClosedForm)
{
  const aniso::AsMaterial m = as(10.0, 10.0, 0.2, 0.9);
  for (double theta : {0.0, 40.0, 75.0, 89.0})
  {
    const glm::dvec3 v = models_test::fromAngles(theta, 0.0);
    const double albedo = models_test::sphereIntegral(
        [&](const glm::dvec3& l)
        { return l.z > 0.0 ? aniso::evalAsDiffuse(m, v, l).x * l.z : 0.0; },
        glm::dvec3(0.0, 0.0, 1.0), 32, 64, false);
    const double expected = 0.9 * 0.8 * (1.0 - std::pow(1.0 - 0.5 * v.z, 5.0));
    EXPECT_NEAR(albedo, expected, 1e-9) << theta;
  }
}

// The full model (specular + coupled diffuse) is reciprocal.
TEST(AsLights, IsReciprocal)
{
  const aniso::AsMaterial m = as(500.0, 20.0, 0.1, 0.7);
  std::mt19937_64 rng(59);
  for (int i = 0; i < 500; ++i)
  {
    const glm::dvec3 v = randomUpper(rng);
    const glm::dvec3 l = randomUpper(rng);
    const double a = aniso::evalAshikhminShirley(m, v, l).x;
    EXPECT_NEAR(a, aniso::evalAshikhminShirley(m, l, v).x, 1e-12 * a);
  }
}

// White furnace under a directional light sweep: specular (F0 = 1) and diffuse (rho_d = 1,
// F0 = 0) albedos stay at or below 1 from normal incidence to 85 degrees; the combined albedo
// for a white dielectric (rho_d = 1, F0 = 0.04) is printed.
TEST(AsLights, EnergyAtMostOne)
{
  double largestCombined = 0.0;
  for (const auto& n :
       {glm::dvec2(10.0, 10.0), glm::dvec2(1000.0, 1000.0), glm::dvec2(2000.0, 20.0)})
  {
    for (double theta : {0.0, 45.0, 70.0, 85.0})
    {
      const glm::dvec3 v = models_test::fromAngles(theta, 15.0);
      auto albedo = [&](const aniso::AsMaterial& m)
      {
        return models_test::hemisphereAlbedo(
            [&](const glm::dvec3& vv, const glm::dvec3& l)
            { return aniso::evalAshikhminShirley(m, vv, l).x * l.z; },
            v, models_test::mirrorOf(v));
      };
      EXPECT_LE(albedo(as(n.x, n.y, 1.0, 0.0)), 1.0) << n.x << " " << n.y << " " << theta;
      EXPECT_LE(albedo(as(n.x, n.y, 0.0, 1.0)), 1.0) << n.x << " " << n.y << " " << theta;
      largestCombined = std::max(largestCombined, albedo(as(n.x, n.y, 0.04, 1.0)));
    }
  }
  std::printf("largest AS albedo, rho_d = 1 and F0 = 0.04: %.4f\n", largestCombined);
}
} // namespace
