// Small-scale microstructure: the procedural structures against their analytic profiles, the
// parallax-occlusion ray march against analytic intersections with a plane and a V-groove, the
// self-shadowing test against the analytic shadow boundary of a V-groove, energy (white furnace:
// a sweep of directional lights integrating over the hemisphere, one light per quadrature node),
// and convergence of the K x K pixel sampling to a fine grid and to the analytic two-facet
// average of V-grooves.
#include "core/env/quadrature.h"
#include "core/error.h"
#include "core/microstructure/microstructure.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;

glm::dvec3 fromAngles(double thetaDegrees, double phiDegrees)
{
  const double t = thetaDegrees * kPi / 180.0;
  const double p = phiDegrees * kPi / 180.0;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// Directional lights on the quadrature nodes of the upper hemisphere (Gauss-Legendre in theta,
// equal steps in phi), each with its node weight as intensity: the light sum is then the integral
// over the hemisphere of the radiance a unit light would give.
std::vector<aniso::Light> hemisphereSweep(int panels, int azimuths)
{
  std::vector<aniso::Light> lights;
  const aniso::QuadratureRule rule = aniso::compositeGaussLegendre(panels, 8, 0.0, 0.5 * kPi);
  for (std::size_t i = 0; i < rule.nodes.size(); ++i)
  {
    const double theta = rule.nodes[i];
    for (int j = 0; j < azimuths; ++j)
    {
      aniso::Light light;
      light.vector = fromAngles(theta * 180.0 / kPi, 360.0 * (j + 0.5) / azimuths);
      light.intensity = glm::dvec3(rule.weights[i] * std::sin(theta) * 2.0 * kPi / azimuths);
      lights.push_back(light);
    }
  }
  return lights;
}

// Texel centres hold the analytic profiles: pyramids 1 - 2r, inverted pyramids flat (h = 0) and
// red inside r < 0.15, grooves 2|x - 1/2|; silk's warp (golden) lies over the weft (crimson) at
// the crossing (1/4, 1/4) and under it at (3/4, 1/4). All heights are in [0, 1], normals unit,
// and the structures tile.
TEST(Microstructure, PatternsMatchAnalyticProfiles)
{
  const int n = 64;
  const aniso::Microstructure pyramids =
      aniso::makeMicrostructure(aniso::MicroPattern::Pyramids, n, 0.1);
  const aniso::Microstructure pits =
      aniso::makeMicrostructure(aniso::MicroPattern::InvertedPyramids, n, 0.1);
  const aniso::Microstructure grooves =
      aniso::makeMicrostructure(aniso::MicroPattern::Grooves, n, 0.1);
  const aniso::Microstructure silk = aniso::makeMicrostructure(aniso::MicroPattern::Silk, n, 0.1);
  for (int y = 0; y < n; ++y)
  {
    for (int x = 0; x < n; ++x)
    {
      const double u = (x + 0.5) / n;
      const double v = 1.0 - (y + 0.5) / n;
      const double r = std::max(std::abs(u - 0.5), std::abs(v - 0.5));
      EXPECT_NEAR(pyramids.height.at(x, y, 0), 1.0 - 2.0 * r, 1e-6);
      EXPECT_NEAR(grooves.height.at(x, y, 0), 2.0 * std::abs(u - 0.5), 1e-6);
      if (r < 0.15)
      {
        EXPECT_EQ(pits.height.at(x, y, 0), 0.0f);
        EXPECT_GT(pits.albedo.at(x, y, 0), 3.0f * pits.albedo.at(x, y, 1)); // red bottom
      }
      for (const aniso::Microstructure* s : {&pyramids, &pits, &grooves, &silk})
      {
        const float h = s->height.at(x, y, 0);
        ASSERT_TRUE(h >= 0.0f && h <= 1.0f);
        const glm::dvec3 nn(s->normal.at(x, y, 0), s->normal.at(x, y, 1), s->normal.at(x, y, 2));
        ASSERT_NEAR(glm::length(nn), 1.0, 1e-6);
      }
    }
  }
  const aniso::MicroTexel warpOver = aniso::sampleMicrostructure(silk, {0.25, 0.25});
  const aniso::MicroTexel weftOver = aniso::sampleMicrostructure(silk, {0.75, 0.25});
  EXPECT_GT(warpOver.albedo.y, 0.5); // golden
  EXPECT_LT(weftOver.albedo.y, 0.2); // crimson
  EXPECT_GT(warpOver.height, 0.9);
  EXPECT_GT(weftOver.height, 0.9);
  // Tiling: the wrapped lookup at the tile edge equals the mean of the first and last texels,
  // whose heights are continuous across the edge for the pyramids (both near 0).
  EXPECT_NEAR(aniso::sampleMicrostructure(pyramids, {0.0, 0.5}).height,
              0.5 * (pyramids.height.at(0, n / 2, 0) + pyramids.height.at(n - 1, n / 2, 0)), 1e-6);
}

// A flat structure at height h0: the ray enters at p and meets the plane at depth
// D (1 - h0), at p - (v.xy / v.z) D (1 - h0), for views from 0 to 80 degrees.
TEST(Microstructure, ParallaxOcclusionHitsPlane)
{
  aniso::Image height(8, 8, 1);
  std::fill(height.data.begin(), height.data.end(), 0.3f);
  const aniso::Microstructure plane =
      aniso::microstructureFromImages(height, aniso::Image(8, 8, 1), 0.2);
  const glm::dvec2 p(0.37, 0.81);
  for (double theta : {0.0, 30.0, 60.0, 80.0})
  {
    const glm::dvec3 v = fromAngles(theta, 40.0);
    const aniso::MicroHit hit = aniso::marchParallaxOcclusion(plane, p, v, 16);
    const double depth = 0.2 * (1.0 - 0.3);
    EXPECT_NEAR(hit.depth, depth, 1e-7) << theta;
    const glm::dvec2 expected = p - glm::dvec2(v.x, v.y) / v.z * depth;
    EXPECT_NEAR(glm::length(hit.point - expected), 0.0, 1e-6) << theta;
  }
}

// A V-groove of depth D = 0.25 (surface depth 2 D x left of the valley, 2 D (1 - x) right of it).
// A ray entering at x0 = 0.1 and moving towards +x by t = tan(theta) per unit depth meets the
// left wall at d = 2 D x0 / (1 - 2 D t) when that point lies left of the valley, else the right
// wall at d = 2 D (1 - x0) / (1 + 2 D t).
TEST(Microstructure, ParallaxOcclusionHitsVGroove)
{
  const double depth = 0.25;
  const aniso::Microstructure groove =
      aniso::makeMicrostructure(aniso::MicroPattern::Grooves, 256, depth);
  const double x0 = 0.1;
  for (double theta : {20.0, 30.0, 50.0, 70.0, 80.0})
  {
    const double t = std::tan(theta * kPi / 180.0);
    double d = 2.0 * depth * x0 / (1.0 - 2.0 * depth * t);
    if (!(d > 0.0) || x0 + t * d > 0.5)
      d = 2.0 * depth * (1.0 - x0) / (1.0 + 2.0 * depth * t);
    const glm::dvec3 v = fromAngles(theta, 180.0); // looking from -x: the ray moves towards +x
    const aniso::MicroHit hit = aniso::marchParallaxOcclusion(groove, {x0, 0.4}, v, 32);
    EXPECT_NEAR(hit.depth, d, 2e-4) << theta;
    EXPECT_NEAR(hit.point.x, x0 + t * d, 2e-4 * std::max(1.0, t)) << theta;
    EXPECT_NEAR(hit.point.y, 0.4, 1e-12);
  }
}

// Self-shadowing in the same groove (D = 0.25), starting on the surface as the renderer does:
// from the valley bottom, a light from +x is hidden by the right wall when its elevation is
// below atan(2 D) = 26.57 degrees; from x = 0.4 (depth 0.2), below atan(1/3) = 18.43 degrees
// (each tested 2.5 to 3 degrees either side).
TEST(Microstructure, SelfShadowingMatchesGrooveWalls)
{
  const double depth = 0.25;
  const aniso::Microstructure groove =
      aniso::makeMicrostructure(aniso::MicroPattern::Grooves, 256, depth);
  auto light = [](double elevation) { return fromAngles(90.0 - elevation, 0.0); };
  auto shadowed = [&](const glm::dvec2& q, const glm::dvec3& l)
  {
    const double d = depth * (1.0 - aniso::sampleMicrostructure(groove, q).height);
    return aniso::shadowedTowards(groove, q, d, l, 64);
  };
  EXPECT_TRUE(shadowed({0.5, 0.3}, light(24.0)));
  EXPECT_FALSE(shadowed({0.5, 0.3}, light(29.0)));
  EXPECT_TRUE(shadowed({0.4, 0.3}, light(16.0)));
  EXPECT_FALSE(shadowed({0.4, 0.3}, light(21.0)));
  // From -x, the left wall (tilted 26.57 degrees towards +x) hides its own points from lights
  // below that elevation and shows them above it.
  EXPECT_TRUE(shadowed({0.4, 0.3}, fromAngles(90.0 - 20.0, 180.0)));
  EXPECT_FALSE(shadowed({0.4, 0.3}, fromAngles(90.0 - 33.0, 180.0)));
}

// White furnace: with a unit directional light swept over the hemisphere, the reflected
// radiance integrates to at most 1, for every structure, view (0 to 75 degrees), masking mode,
// with and without self-shadowing: specular only (F0 = 1; GGX alpha 0.3 and Blinn-Phong e = 50)
// and diffuse only (albedo 1). The largest values are printed.
TEST(Microstructure, EnergyAtMostOne)
{
  const std::vector<aniso::Light> sweep = hemisphereSweep(12, 48);
  const aniso::Frame frame;
  double largestSpecular = 0.0;
  double largestDiffuse = 0.0;
  for (aniso::MicroPattern pattern :
       {aniso::MicroPattern::Pyramids, aniso::MicroPattern::InvertedPyramids,
        aniso::MicroPattern::Grooves, aniso::MicroPattern::Silk})
  {
    aniso::Microstructure dark = aniso::makeMicrostructure(pattern, 32, 0.15);
    std::fill(dark.albedo.data.begin(), dark.albedo.data.end(), 0.0f);
    aniso::Microstructure white = dark;
    std::fill(white.albedo.data.begin(), white.albedo.data.end(), 1.0f);
    for (double theta : {0.0, 45.0, 75.0})
    {
      const glm::dvec3 v = fromAngles(theta, 20.0);
      for (aniso::MicroMasking masking :
           {aniso::MicroMasking::Normal, aniso::MicroMasking::ParallaxOcclusion})
      {
        for (bool shadows : {false, true})
        {
          aniso::MicroShadingOptions o;
          o.samplesPerAxis = 3;
          o.masking = masking;
          o.selfShadowing = shadows;
          o.marchSteps = 16;
          o.f0 = glm::dvec3(1.0);
          for (aniso::MicroBrdf brdf :
               {aniso::MicroBrdf::GgxSmithSchlick, aniso::MicroBrdf::BlinnPhong})
          {
            o.brdf = brdf;
            o.blinnExponent = 50.0;
            const double specular =
                aniso::shadeMicroPixel(dark, o, {}, frame, glm::dvec3(0.0), v, sweep).x;
            largestSpecular = std::max(largestSpecular, specular);
            EXPECT_LE(specular, 1.0) << int(pattern) << " " << theta;
          }
          o.f0 = glm::dvec3(0.0);
          const double diffuse =
              aniso::shadeMicroPixel(white, o, {}, frame, glm::dvec3(0.0), v, sweep).x;
          largestDiffuse = std::max(largestDiffuse, diffuse);
          EXPECT_LE(diffuse, 1.0 + 1e-9) << int(pattern) << " " << theta;
        }
      }
    }
  }
  std::printf("largest albedo: specular %.4f, diffuse %.4f\n", largestSpecular, largestDiffuse);
}

// K x K grid sampling of V-grooves under two lights (normal masking, GGX) converges to a 64 x 64
// reference as K grows: within 1% at K = 16, and the error at K = 16 is below that at K = 4;
// jittered sampling at K = 16 is within 3%. With the footprint exactly one tile, the 64 x 64
// result matches the analytic mean of the two facets' shading (normals (+-2D, 0, 1)) within 2%
// (the bilinear texture rounds the ridge and valley over about a texel).
TEST(Microstructure, GridSamplingConverges)
{
  const double depth = 0.2;
  const aniso::Microstructure grooves =
      aniso::makeMicrostructure(aniso::MicroPattern::Grooves, 256, depth);
  const std::vector<aniso::Light> lights = {aniso::parseLight("dir:0.6,0.1,1:3"),
                                            aniso::parseLight("dir:-0.5,-0.4,0.8:2")};
  const glm::dvec3 view = glm::normalize(glm::dvec3(-0.3, 0.2, 1.0));
  const aniso::Frame frame;
  aniso::MicroShadingOptions o;
  o.masking = aniso::MicroMasking::Normal;
  o.roughness = 0.25;
  o.f0 = glm::dvec3(0.5);
  auto shade = [&](int k, const aniso::PixelFootprint& f, bool jitter)
  {
    aniso::MicroShadingOptions options = o;
    options.samplesPerAxis = k;
    options.jittered = jitter;
    options.seed = 12345;
    return aniso::shadeMicroPixel(grooves, options, f, frame, glm::dvec3(0.0), view, lights).x;
  };
  aniso::PixelFootprint skew;
  skew.centre = {0.37, 0.61};
  skew.axisU = {1.3, 0.2};
  skew.axisV = {-0.1, 0.9};
  const double reference = shade(64, skew, false);
  std::printf("K x K relative error:");
  double e4 = 0.0;
  double e16 = 0.0;
  for (int k : {1, 2, 4, 8, 16})
  {
    const double e = std::abs(shade(k, skew, false) / reference - 1.0);
    std::printf(" K=%d %.2f%%", k, 100.0 * e);
    if (k == 4)
      e4 = e;
    if (k == 16)
      e16 = e;
  }
  const double jitter = std::abs(shade(16, skew, true) / reference - 1.0);
  std::printf("; jittered K=16 %.2f%%\n", 100.0 * jitter);
  EXPECT_LT(e16, 0.01);
  EXPECT_LT(e16, e4);
  EXPECT_LT(jitter, 0.03);

  // The analytic two-facet mean for one whole tile.
  const aniso::PixelFootprint tile;
  const double grid = shade(64, tile, false);
  double analytic = 0.0;
  for (double sign : {1.0, -1.0})
  {
    const glm::dvec3 n = glm::normalize(glm::dvec3(sign * 2.0 * depth, 0.0, 1.0));
    const aniso::Frame facet = aniso::Frame::fromNormalTangent(n, glm::dvec3(1.0, 0.0, 0.0));
    const glm::dvec3 v = facet.toLocal(view);
    for (const aniso::Light& light : lights)
    {
      const glm::dvec3 l = facet.toLocal(glm::normalize(light.vector));
      const glm::dvec3 h = glm::normalize(v + l);
      const double a = o.roughness;
      const double d = a * a / (kPi * std::pow(h.z * h.z * (a * a - 1.0) + 1.0, 2.0));
      const double k = 0.5 * a;
      const double g = v.z / (v.z * (1.0 - k) + k) * l.z / (l.z * (1.0 - k) + k);
      const double f = 0.5 + 0.5 * std::pow(1.0 - glm::dot(v, h), 5.0);
      const double albedo = 0.6; // the grooves' grey
      analytic += 0.5 * (albedo / kPi + f * d * g / (4.0 * v.z * l.z)) * l.z * light.intensity.x;
    }
  }
  std::printf("one tile: grid %.5f, two-facet mean %.5f\n", grid, analytic);
  EXPECT_NEAR(grid, analytic, 0.02 * analytic);
}

// Jitter depends on the seed only: the same seed repeats, another seed gives another estimate,
// and the mean of 64 seeds at K = 4 is within 1% of the 64 x 64 grid.
TEST(Microstructure, JitterIsSeededAndUnbiased)
{
  const aniso::Microstructure silk = aniso::makeMicrostructure(aniso::MicroPattern::Silk, 64, 0.1);
  const std::vector<aniso::Light> lights = {aniso::parseLight("dir:0.3,0.5,1:1")};
  const glm::dvec3 view = glm::normalize(glm::dvec3(0.1, -0.4, 1.0));
  aniso::MicroShadingOptions o;
  o.masking = aniso::MicroMasking::Normal;
  o.samplesPerAxis = 4;
  o.jittered = true;
  aniso::PixelFootprint f;
  f.centre = {0.2, 0.7};
  f.axisU = {0.7, 0.1};
  f.axisV = {0.0, 0.45};
  auto shade = [&](std::uint32_t seed, int k, bool jitter)
  {
    aniso::MicroShadingOptions options = o;
    options.seed = seed;
    options.samplesPerAxis = k;
    options.jittered = jitter;
    return aniso::shadeMicroPixel(silk, options, f, aniso::Frame{}, glm::dvec3(0.0), view, lights)
        .x;
  };
  EXPECT_EQ(shade(7, 4, true), shade(7, 4, true));
  EXPECT_NE(shade(7, 4, true), shade(8, 4, true));
  double mean = 0.0;
  for (std::uint32_t seed = 0; seed < 64; ++seed)
    mean += shade(seed, 4, true) / 64.0;
  const double reference = shade(0, 64, false);
  EXPECT_NEAR(mean, reference, 0.01 * reference);
}

// Finite and non-negative across the option ranges: depths 0.01 and 2, GGX roughness 1e-3 and
// 1, Blinn-Phong exponents 0 and 1e6, 1 and 64 march steps, every masking mode with shadows,
// grazing views and lights.
TEST(Microstructure, FiniteAcrossParameterRange)
{
  const std::vector<aniso::Light> lights = {aniso::parseLight("dir:1,0,1e-6:1"),
                                            aniso::parseLight("dir:0.2,-0.3,1:2"),
                                            aniso::parseLight("point:0.1,0.2,0.001:5")};
  const glm::dvec3 views[] = {glm::normalize(glm::dvec3(-1.0, 0.3, 1e-6)),
                              glm::dvec3(0.0, 0.0, 1.0), fromAngles(60.0, 100.0)};
  for (aniso::MicroPattern pattern :
       {aniso::MicroPattern::Pyramids, aniso::MicroPattern::InvertedPyramids,
        aniso::MicroPattern::Grooves, aniso::MicroPattern::Silk})
  {
    for (double depth : {0.01, aniso::kMicroMaxDepth})
    {
      const aniso::Microstructure s = aniso::makeMicrostructure(pattern, 16, depth);
      for (aniso::MicroMasking masking :
           {aniso::MicroMasking::Normal, aniso::MicroMasking::Parallax,
            aniso::MicroMasking::ParallaxOcclusion})
      {
        for (int variant = 0; variant < 4; ++variant)
        {
          aniso::MicroShadingOptions o;
          o.samplesPerAxis = 2;
          o.masking = masking;
          o.selfShadowing = true;
          o.brdf = variant < 2 ? aniso::MicroBrdf::GgxSmithSchlick : aniso::MicroBrdf::BlinnPhong;
          o.roughness = variant == 0 ? 1e-3 : 1.0;
          o.blinnExponent = variant == 2 ? 0.0 : 1e6;
          o.marchSteps = variant % 2 == 0 ? 1 : 64;
          o.f0 = glm::dvec3(1.0);
          aniso::validateMicroOptions(o);
          for (const glm::dvec3& v : views)
          {
            const glm::dvec3 c =
                aniso::shadeMicroPixel(s, o, {}, aniso::Frame{}, glm::dvec3(0.0), v, lights);
            EXPECT_TRUE(std::isfinite(c.x) && c.x >= 0.0) << int(pattern) << " " << depth;
          }
        }
      }
    }
  }
}

// Options and structures outside their ranges are refused, naming the subject.
TEST(Microstructure, ValidatesArguments)
{
  EXPECT_THROW(aniso::makeMicrostructure(aniso::MicroPattern::Silk, 2), aniso::Error);
  EXPECT_THROW(aniso::makeMicrostructure(aniso::MicroPattern::Silk, 64, 0.0), aniso::Error);
  EXPECT_THROW(aniso::microstructureFromImages(aniso::Image(4, 4, 1), aniso::Image(5, 4, 3), 0.1),
               aniso::Error);
  aniso::MicroShadingOptions o;
  EXPECT_NO_THROW(aniso::validateMicroOptions(o));
  o.samplesPerAxis = 0;
  EXPECT_THROW(aniso::validateMicroOptions(o), aniso::Error);
  o = {};
  o.roughness = 2.0;
  EXPECT_THROW(aniso::validateMicroOptions(o), aniso::Error);
  o = {};
  o.f0 = glm::dvec3(0.5, 1.5, 0.5);
  EXPECT_THROW(aniso::validateMicroOptions(o), aniso::Error);
}
} // namespace
