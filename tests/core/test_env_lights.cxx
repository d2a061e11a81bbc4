// An environment's sources as directional lights (core/lights/env_lights.h), against
// independent references: the built-in sun-sky's sun (direction and power known analytically,
// the environment's rotation checked by reading the environment itself back along the light),
// the mean cosine of a uniform cap (closed form (1 + cos r) / 2), the Ward and Ashikhmin-Shirley
// lit models under the sun's light against a quadrature of the same BRDFs over the sun's disc,
// and the options (count, order, share) on an analysis written out here.
#include "core/brdf/ashikhmin_shirley_lights.h"
#include "core/brdf/ward.h"
#include "core/env/env_sources.h"
#include "core/env/sun_sky.h"
#include "core/error.h"
#include "core/lights/env_lights.h"
#include "core/models/models.h"
#include "core/models/sv_material.h"

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <string>

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

glm::dvec3 rotateZ(const glm::dvec3& d, double degrees)
{
  const double a = degrees * kDegree;
  return {std::cos(a) * d.x - std::sin(a) * d.y, std::sin(a) * d.x + std::cos(a) * d.y, d.z};
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b)
{
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

std::string errorOf(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch (const aniso::Error& e)
  {
    return e.what();
  }
  return "";
}

const glm::dvec3 kSunEnv = glm::normalize(glm::dvec3(0.35, -0.6, 0.5));
constexpr double kRotation = 37.0;

// The built-in sun-sky's sun and sky, at kSunEnv.
std::shared_ptr<const aniso::SunSkyEnvironment> sunSky()
{
  static const auto env = std::make_shared<const aniso::SunSkyEnvironment>(
      kSunEnv, aniso::SunSkyEnvironment::kSunAngularRadius, glm::dvec3(1e5), glm::dvec3(1.0));
  return env;
}

std::shared_ptr<const aniso::EnvAnalysis> sunSkyAnalysis()
{
  static const auto analysis = aniso::sharedEnvironmentAnalysis(*sunSky());
  return analysis;
}

// The sun becomes one light (sources of at least 1% of the power: the sky has none above T), from
// R_z(37 deg) of the sun's direction (within 0.2 deg), along which the environment turned as
// EnvironmentLighting turns it (world d sees radiance(R_z(-angle) d)) shows the sun; its
// irradiance at normal incidence is the sun's excess power: 1e5 x the disc's solid angle, plus
// (sky - T) over the source's texels (what the residual keeps: T per texel, of which the sky's 1
// was the sky's), within 2%, and within 2% of 1e5 x the disc's solid angle too.
TEST(EnvLights, SunSkySunIsOneDirectionalLight)
{
  const aniso::EnvAnalysis& analysis = *sunSkyAnalysis();
  aniso::EnvLightOptions options;
  options.minPowerShare = 0.01;
  const std::vector<aniso::Light> lights =
      aniso::environmentSourceLights(analysis, kRotation, options);
  ASSERT_EQ(lights.size(), 1u);
  ASSERT_FALSE(analysis.sources.empty());
  const aniso::EnvSource& sun = analysis.sources.front();
  EXPECT_EQ(sun.kind, aniso::EnvSourceKind::Sun);
  const aniso::Light& light = lights.front();
  EXPECT_EQ(light.type, aniso::LightType::Directional);
  const double error = angleBetween(light.vector, rotateZ(kSunEnv, kRotation)) / kDegree;
  EXPECT_LT(error, 0.2);
  // The convention read back from the environment itself.
  const glm::dvec3 seen = sunSky()->radiance(rotateZ(light.vector, -kRotation));
  EXPECT_GT(seen.x, 1e4);

  const double disc = sunSky()->sunSolidAngle();
  const double expected = 1e5 * disc + (1.0 - analysis.threshold) * sun.solidAngle;
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(light.intensity[c], expected, 0.02 * expected) << c;
    EXPECT_NEAR(light.intensity[c], 1e5 * disc, 0.02 * 1e5 * disc) << c;
  }
  std::printf("sun light: direction off by %.4f deg, irradiance %.6g, expected %.6g (%.3f%%), "
              "1e5 x disc %.6g (%.3f%%), T %.4g, source %.4g sr over disc %.4g sr\n",
              error, light.intensity.x, expected, 100.0 * (light.intensity.x / expected - 1.0),
              1e5 * disc, 100.0 * (light.intensity.x / (1e5 * disc) - 1.0), analysis.threshold,
              sun.solidAngle, disc);
  // Without the share limit the sun still comes first.
  const std::vector<aniso::Light> all = aniso::environmentSourceLights(analysis, kRotation);
  ASSERT_GE(all.size(), 1u);
  EXPECT_EQ(all.front().vector, light.vector);
}

// The mean cosine of a uniform cap of radius r about its centre is (1 + cos r) / 2: a bright
// cap of 0.3 rad on a 1024 x 512 grid (texels of 0.35 deg), its light's intensity the source's
// power times it. Agreement within the grid's resolution (2e-3).
TEST(EnvLights, MeanCosineOfAUniformCap)
{
  const int w = 1024;
  const int h = 512;
  const double radius = 0.3;
  const glm::dvec3 centre = glm::normalize(glm::dvec3(-0.2, 0.7, 0.4));
  aniso::Image image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      const glm::dvec3 d = aniso::equirectToDirection({(x + 0.5) / w, 1.0 - (y + 0.5) / h});
      const float value = glm::dot(d, centre) >= std::cos(radius) ? 1000.0f : 1.0f;
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = value;
    }
  const aniso::EnvAnalysis analysis = aniso::analyzeEquirect(image, "cap");
  ASSERT_FALSE(analysis.sources.empty());
  const aniso::EnvSource& cap = analysis.sources.front();
  const double meanCos = aniso::sourceMeanCosine(analysis, cap);
  const double expected = 0.5 * (1.0 + std::cos(radius));
  EXPECT_NEAR(meanCos, expected, 2e-3);
  std::printf("cap of 0.3 rad: mean cosine %.6f, (1 + cos r) / 2 = %.6f\n", meanCos, expected);
  const std::vector<aniso::Light> lights = aniso::environmentSourceLights(analysis, 0.0);
  ASSERT_FALSE(lights.empty());
  EXPECT_NEAR(lights.front().intensity.x, cap.power.x * meanCos, 1e-9 * cap.power.x);
  EXPECT_LT(angleBetween(lights.front().vector, centre) / kDegree, 0.2);
  // The sun's mean cosine: 1 - r^2 / 4 of a disc of r = 0.00465 is 1 - 5e-6; its texels reach
  // a little farther.
  EXPECT_NEAR(aniso::sourceMeanCosine(*sunSkyAnalysis(), sunSkyAnalysis()->sources.front()), 1.0,
              1e-4);
}

// The quadrature of BRDF(v, l) (n.l) L over the sun's disc of radiance 1e5 about the world
// direction SUN (midpoint rule in polar coordinates about its centre, 64 x 128 cells).
template <class Brdf>
glm::dvec3 discIntegral(const aniso::Frame& frame, const glm::dvec3& viewWorld,
                        const glm::dvec3& sun, const Brdf& brdf)
{
  const double r = aniso::SunSkyEnvironment::kSunAngularRadius;
  const aniso::Frame around = aniso::Frame::fromNormalTangent(sun, glm::dvec3(0.0, 0.0, 1.0));
  const glm::dvec3 v = frame.toLocal(viewWorld);
  const int nr = 64;
  const int nphi = 128;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < nr; ++i)
  {
    const double rho = (i + 0.5) * r / nr;
    for (int j = 0; j < nphi; ++j)
    {
      const double phi = (j + 0.5) * 2.0 * kPi / nphi;
      const glm::dvec3 local(std::sin(rho) * std::cos(phi), std::sin(rho) * std::sin(phi),
                             std::cos(rho));
      const glm::dvec3 l = frame.toLocal(around.toWorld(local));
      if (!(l.z > 0.0))
        continue;
      const double domega = std::sin(rho) * (r / nr) * (2.0 * kPi / nphi);
      sum += brdf(v, l) * l.z * 1e5 * domega;
    }
  }
  return sum;
}

// Ward and Ashikhmin-Shirley (lit models, shadeLitModel) under the sun's light equal the
// quadrature of their direct BRDFs (evalWard, evalAshikhminShirley) over the sun's disc, at the
// mirror direction and off it. Bound 0.5%: the light's irradiance is the disc's power less
// (T - 1) over the source's texels (0.1%), and a lobe of alpha 0.15 changes across the disc by
// about (r / alpha)^2 = 1e-3 after the linear term cancels over the disc.
TEST(EnvLights, LitModelsUnderTheSunMatchTheDiscIntegral)
{
  aniso::EnvLightOptions options;
  options.minPowerShare = 0.01;
  const std::vector<aniso::Light> lights =
      aniso::environmentSourceLights(*sunSkyAnalysis(), kRotation, options);
  ASSERT_EQ(lights.size(), 1u);
  const glm::dvec3 sunWorld = rotateZ(kSunEnv, kRotation);
  const aniso::Frame frame = aniso::Frame::fromNormalTangent(
      glm::normalize(glm::dvec3(0.1, -0.2, 1.0)), glm::dvec3(1.0, 0.3, 0.0));
  aniso::SvTexel texel;
  texel.alphaX = 0.15;
  texel.alphaY = 0.3;
  texel.diffuse = glm::dvec3(0.2, 0.3, 0.4);
  texel.specular = 0.6;
  const glm::dvec3 mirror = glm::normalize(2.0 * glm::dot(sunWorld, frame.n) * frame.n - sunWorld);
  const glm::dvec3 off = glm::normalize(mirror + 0.25 * frame.t);
  const aniso::WardMaterial ward = aniso::toWard(texel);
  const aniso::AsMaterial as = aniso::toAshikhminShirley(texel);
  for (const glm::dvec3& view : {mirror, off})
  {
    const glm::dvec3 wardLit =
        aniso::shadeLitModel(aniso::LitModel::Ward, texel, frame, glm::dvec3(0.0), view, lights);
    const glm::dvec3 wardRef = discIntegral(frame, view, sunWorld,
                                            [&](const glm::dvec3& v, const glm::dvec3& l)
                                            { return aniso::evalWard(ward, v, l); });
    const glm::dvec3 asLit = aniso::shadeLitModel(aniso::LitModel::AshikhminShirley, texel, frame,
                                                  glm::dvec3(0.0), view, lights);
    const glm::dvec3 asRef = discIntegral(frame, view, sunWorld,
                                          [&](const glm::dvec3& v, const glm::dvec3& l)
                                          { return aniso::evalAshikhminShirley(as, v, l); });
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(wardLit[c], wardRef[c], 5e-3 * wardRef[c]) << c;
      EXPECT_NEAR(asLit[c], asRef[c], 5e-3 * asRef[c]) << c;
    }
    std::printf("view %s: Ward %.6g vs disc %.6g (%.3f%%), AS %.6g vs disc %.6g (%.3f%%)\n",
                view == mirror ? "mirror" : "off", wardLit.x, wardRef.x,
                100.0 * (wardLit.x / wardRef.x - 1.0), asLit.x, asRef.x,
                100.0 * (asLit.x / asRef.x - 1.0));
  }
  // The highlight is where the sun's mirror direction says: far brighter than off it.
  const glm::dvec3 atMirror =
      aniso::shadeLitModel(aniso::LitModel::Ward, texel, frame, glm::dvec3(0.0), mirror, lights);
  const glm::dvec3 farOff = glm::normalize(mirror + 0.6 * frame.t);
  const glm::dvec3 atOff =
      aniso::shadeLitModel(aniso::LitModel::Ward, texel, frame, glm::dvec3(0.0), farOff, lights);
  EXPECT_GT(atMirror.x, 5.0 * atOff.x);
}

// An analysis written out here (no excess image: mean cosine 1): at most maxLights, by power,
// those under minPowerShare and those of no power left out; bad options refused.
TEST(EnvLights, OptionsCountOrderAndShare)
{
  aniso::EnvAnalysis analysis;
  auto source = [](const glm::dvec3& d, double power, double share)
  {
    aniso::EnvSource s;
    s.direction = glm::normalize(d);
    s.power = glm::dvec3(power);
    s.powerShare = share;
    return s;
  };
  analysis.sources = {source({1, 0, 0}, 5.0, 0.2), source({0, 1, 0}, 10.0, 0.4),
                      source({0, 0, 1}, 0.0, 0.0), source({0, -1, 0}, 1.0, 0.04)};
  const std::vector<aniso::Light> all = aniso::environmentSourceLights(analysis, 90.0);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].intensity, glm::dvec3(10.0));
  EXPECT_EQ(all[1].intensity, glm::dvec3(5.0));
  EXPECT_EQ(all[2].intensity, glm::dvec3(1.0));
  // +Y turned by 90 degrees about +Z is -X.
  EXPECT_NEAR(glm::length(all[0].vector - glm::dvec3(-1.0, 0.0, 0.0)), 0.0, 1e-12);
  aniso::EnvLightOptions two;
  two.maxLights = 2;
  EXPECT_EQ(aniso::environmentSourceLights(analysis, 0.0, two).size(), 2u);
  aniso::EnvLightOptions share;
  share.minPowerShare = 0.1;
  EXPECT_EQ(aniso::environmentSourceLights(analysis, 0.0, share).size(), 2u);
  aniso::EnvLightOptions none;
  none.maxLights = 0;
  EXPECT_TRUE(aniso::environmentSourceLights(analysis, 0.0, none).empty());

  aniso::EnvLightOptions bad;
  bad.maxLights = -1;
  EXPECT_EQ(errorOf([&] { aniso::environmentSourceLights(analysis, 0.0, bad); }),
            "env-lights: maxLights must be >= 0, got -1");
  bad = {};
  bad.minPowerShare = 2.0;
  EXPECT_EQ(errorOf([&] { aniso::environmentSourceLights(analysis, 0.0, bad); }),
            "env-lights: minPowerShare must be in [0, 1], got 2");
  EXPECT_EQ(errorOf([&] { aniso::environmentSourceLights(analysis, std::nan(""), {}); }),
            "env-lights: the environment's rotation is not finite");
}
} // namespace
