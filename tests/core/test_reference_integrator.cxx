// The reference integrator against independent references: closed forms (irradiance of
// band-limited radiance; the white-furnace albedo of an isotropic lobe at normal incidence),
// brute-force quadrature over the light direction with the Ashikhmin-Shirley formula written
// out here, and the mirror limit F0 L(reflect(v)). Plus its own promise: the requested tolerance
// is met for lobes from (10, 10) to (1e6, 1e6), and results stay finite and within [0, max L]
// over the whole stress grid of exponents and views down to n.v = 1e-6.
#include "core/env/environment.h"
#include "core/error.h"
#include "core/frame.h"
#include "core/reference/reference_integrator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;

double luminance(const glm::dvec3& c)
{
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// Radiance 1 + d.z: irradiance pi + (2 pi / 3) n.z (bands 0 and 1 of the clamped cosine).
class LinearEnvironment : public aniso::Environment
{
public:
  glm::dvec3 radiance(const glm::dvec3& d) const override { return glm::dvec3(1.0 + d.z); }
  std::string key() const override { return "test:1+z"; }
};

// View at n.v = cosTheta, azimuth phi in the tangent frame.
glm::dvec3 localView(double cosTheta, double phi)
{
  const double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

// Independent reference: f_s(v, l) (n.l) L(l) with the AS formula written out here,
//   p_h = sqrt((nu + 1)(nv + 1)) / (2 pi) (n.h)^((nu (t.h)^2 + nv (b.h)^2) / (1 - (n.h)^2)),
//   f_s = p_h F(v.h) / (4 (v.h) max(n.v, n.l)), F = F0 + (1 - F0)(1 - v.h)^5,
// summed over light directions with the midpoint rule in mu = n.l (split at mu = n.v, where
// max(n.v, n.l) has its kink) and in the azimuth. Only for lobes wide enough for the grid.
glm::dvec3 bruteForceOverLight(double nu, double nv, const glm::dvec3& f0,
                               const aniso::Frame& frame, const glm::dvec3& v,
                               const aniso::Environment& env, int muNodes, int phiNodes)
{
  const double norm = std::sqrt((nu + 1.0) * (nv + 1.0)) / (2.0 * kPi);
  glm::dvec3 total(0.0);
  auto addSegment = [&](double mu0, double mu1, int nodes)
  {
    const double dMu = (mu1 - mu0) / nodes;
    const double dPhi = 2.0 * kPi / phiNodes;
    for (int i = 0; i < nodes; ++i)
    {
      const double mu = mu0 + (i + 0.5) * dMu;
      const double r = std::sqrt(1.0 - mu * mu);
      for (int j = 0; j < phiNodes; ++j)
      {
        const double phi = (j + 0.5) * dPhi;
        const glm::dvec3 l(r * std::cos(phi), r * std::sin(phi), mu);
        const glm::dvec3 h = glm::normalize(v + l);
        const double vDotH = glm::dot(v, h);
        const double tangential = h.x * h.x + h.y * h.y;
        const double exponent =
            tangential > 0.0 ? (nu * h.x * h.x + nv * h.y * h.y) / tangential : 0.5 * (nu + nv);
        const double ph = norm * std::pow(h.z, exponent);
        const glm::dvec3 fresnel = f0 + (glm::dvec3(1.0) - f0) * std::pow(1.0 - vDotH, 5.0);
        const glm::dvec3 fs = ph * fresnel / (4.0 * vDotH * std::max(v.z, mu));
        total += (mu * dMu * dPhi) * fs * env.radiance(frame.toWorld(l));
      }
    }
  };
  const int below = std::max(8, int(muNodes * v.z));
  if (v.z < 1.0)
    addSegment(0.0, v.z, below);
  addSegment(v.z, 1.0, std::max(8, muNodes - below));
  return total;
}

aniso::Frame testFrame(int which)
{
  switch (which)
  {
  case 0:
    return aniso::Frame{};
  case 1:
    return aniso::Frame::fromNormalTangent({0.3, -0.5, 0.8}, {1, 1, 0});
  default:
    return aniso::Frame::fromNormalTangent({-0.7, 0.2, 0.1}, {0, 0, 1});
  }
}

// Largest radiance channel of the studio on a 0.1-degree grid; the soft boxes have flat tops,
// so the true maximum lies within 1e-3 (relative) of it.
double studioPeak()
{
  aniso::StudioEnvironment studio;
  double peak = 0.0;
  for (int i = 0; i < 3600; ++i)
    for (int j = 0; j < 1800; ++j)
    {
      const glm::dvec3 l =
          studio.radiance(aniso::equirectToDirection({(i + 0.5) / 3600, (j + 0.5) / 1800}));
      peak = std::max({peak, l.x, l.y, l.z});
    }
  return peak;
}
} // namespace

// Irradiance quadrature against closed forms: L = 1 gives pi, L = 1 + z gives pi + 2 pi/3 n.z.
TEST(ReferenceIrradiance, ClosedForms)
{
  aniso::UniformEnvironment one(glm::dvec3(1.0));
  LinearEnvironment linear;
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-10;
  for (const glm::dvec3& n :
       {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::dvec3(1, 0, 0),
        glm::normalize(glm::dvec3(0.2, -0.4, 0.7)), glm::normalize(glm::dvec3(-3, 1, -2))})
  {
    const aniso::ReferenceResult a = aniso::integrateIrradiance(n, one, options);
    EXPECT_TRUE(a.converged);
    EXPECT_NEAR(a.value.x, kPi, 1e-9);
    const aniso::ReferenceResult b = aniso::integrateIrradiance(n, linear, options);
    EXPECT_TRUE(b.converged);
    EXPECT_NEAR(b.value.y, kPi + 2.0 * kPi / 3.0 * n.z, 1e-8);
  }
}

// White furnace at normal incidence (v = n, F0 = 1, L = 1) for an isotropic lobe of exponent e:
// n.l = 2 mu^2 - 1 with mu = n.h and max(n.v, n.l) = 1, so the albedo is
// (e + 1) integral over [1/sqrt(2), 1] of mu^e (2 mu^2 - 1) dmu
//   = 2 (e + 1) / (e + 3) (1 - 2^(-(e+3)/2)) - (1 - 2^(-(e+1)/2)).
TEST(ReferenceSpecular, WhiteFurnaceNormalIncidenceClosedForm)
{
  aniso::UniformEnvironment one(glm::dvec3(1.0));
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-5;
  for (double e : {0.0, 1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6})
  {
    const double expected = 2.0 * (e + 1.0) / (e + 3.0) * (1.0 - std::pow(2.0, -(e + 3.0) / 2.0)) -
                            (1.0 - std::pow(2.0, -(e + 1.0) / 2.0));
    const aniso::ReferenceResult r =
        aniso::integrateSpecular({e, e}, glm::dvec3(1.0), aniso::Frame{}, {0, 0, 1}, one, options);
    EXPECT_TRUE(r.converged) << e;
    EXPECT_NEAR(r.value.x, expected, 2e-5 * expected) << "exponent " << e;
  }
}

// White furnace at oblique and grazing views (L = 1): the directional albedo by brute force over
// the light direction, for lobes wide enough for a 1024 x 1024 grid (accurate to ~1e-5 there);
// agreement within 1e-4, and never above 1.
TEST(ReferenceSpecular, WhiteFurnaceMatchesBruteForceOverLight)
{
  aniso::UniformEnvironment one(glm::dvec3(1.0));
  const aniso::Frame frame;
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-5;
  for (const glm::dvec2 lobe : {glm::dvec2(1, 1), glm::dvec2(10, 10), glm::dvec2(100, 10)})
    for (double cosTheta : {0.9, 0.5, 0.1, 0.01})
      for (const glm::dvec3& f0 : {glm::dvec3(1.0), glm::dvec3(0.04)})
      {
        if (f0.x < 1.0 && lobe.x != 10.0)
          continue; // Fresnel is checked on one lobe, to keep the brute force short
        const glm::dvec3 v = localView(cosTheta, 0.4);
        const aniso::ReferenceResult r =
            aniso::integrateSpecular({lobe.x, lobe.y}, f0, frame, v, one, options);
        const glm::dvec3 expected =
            bruteForceOverLight(lobe.x, lobe.y, f0, frame, v, one, 1024, 1024);
        EXPECT_TRUE(r.converged);
        EXPECT_NEAR(r.value.x, expected.x, 1e-4 * expected.x + 1e-7)
            << lobe.x << ',' << lobe.y << " n.v " << cosTheta << " F0 " << f0.x;
        EXPECT_LE(r.value.x, 1.0 + 1e-9);
      }
}

// Under the studio, through rotated frames: the integral matches the brute force over the
// light direction for wide lobes within 1e-4 of the luminance, including the anisotropic
// (100, 10) in two frames (a swap of t and b, or a mirrored azimuth, would move the result far
// beyond that).
TEST(ReferenceSpecular, StudioMatchesBruteForceOverLight)
{
  aniso::StudioEnvironment studio;
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-5;
  const glm::dvec3 f0(0.9, 0.6, 0.3);
  struct Case
  {
    double nu, nv, cosTheta, phi;
    int frame;
  };
  for (const Case& c :
       {Case{1, 1, 0.8, 0.3, 1}, Case{10, 10, 0.6, 2.0, 0}, Case{10, 10, 0.2, -1.0, 2},
        Case{100, 10, 0.7, 0.5, 1}, Case{100, 10, 0.4, 2.5, 2}, Case{10, 100, 0.4, 2.5, 2}})
  {
    const aniso::Frame frame = testFrame(c.frame);
    const glm::dvec3 v = localView(c.cosTheta, c.phi);
    const aniso::ReferenceResult r =
        aniso::integrateSpecular({c.nu, c.nv}, f0, frame, frame.toWorld(v), studio, options);
    const glm::dvec3 expected = bruteForceOverLight(c.nu, c.nv, f0, frame, v, studio, 1024, 2048);
    EXPECT_TRUE(r.converged);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(r.value[k], expected[k], 1e-4 * luminance(expected))
          << c.nu << ',' << c.nv << " n.v " << c.cosTheta << " frame " << c.frame;
  }
}

// The requested tolerance is reached (errorEstimate <= 1e-3 of the result) from wide to
// mirror-like lobes, views from normal to n.v = 0.1, within the default evaluation budget.
TEST(ReferenceSpecular, ConvergesToRequestedTolerance)
{
  aniso::StudioEnvironment studio;
  const glm::dvec3 f0(0.95, 0.64, 0.54);
  uint64_t most = 0;
  for (const glm::dvec2 lobe : {glm::dvec2(10, 10), glm::dvec2(100, 10), glm::dvec2(1000, 100),
                                glm::dvec2(20000, 70), glm::dvec2(1e6, 1e6)})
    for (double cosTheta : {1.0, 0.5, 0.1})
      for (int which = 0; which < 3; ++which)
      {
        const aniso::Frame frame = testFrame(which);
        const glm::dvec3 v = frame.toWorld(localView(cosTheta, 0.7 + which));
        const aniso::ReferenceResult r =
            aniso::integrateSpecular({lobe.x, lobe.y}, f0, frame, v, studio);
        EXPECT_TRUE(r.converged) << lobe.x << ',' << lobe.y << " n.v " << cosTheta;
        EXPECT_LE(r.errorEstimate, 1e-3 * luminance(r.value))
            << lobe.x << ',' << lobe.y << " n.v " << cosTheta;
        most = std::max(most, r.evaluations);
      }
  std::printf("most evaluations for 1e-3: %llu\n", static_cast<unsigned long long>(most));
}

// Mirror limit: a (1e6, 1e6) lobe spreads h by sigma = 1/sqrt(1e6) per axis around n and
// averages the radiance over ~2e-3 rad around the mirror direction, where the studio is smooth.
// At normal incidence max(n.v, n.l) = 1 and n.l = 1 - O(sigma^2): the result is F0 L(n).
// At oblique incidence (n.v = cos(theta_v)), n.l = n.v + 2 sin(theta_v) delta to first order,
// delta ~ N(0, sigma^2) the tilt of h in the plane of incidence, and the factor
// n.l / max(n.v, n.l) loses E[(n.v - n.l)+] / n.v = 2 sigma sin(theta_v) / (sqrt(2 pi) n.v):
// the result is F(n.v) L(reflect(v)) times one minus that (2.5e-3 at n.v = 0.3). What remains
// is second order: the curvature of L and F over the lobe, below 5e-4 here.
TEST(ReferenceSpecular, MirrorLimit)
{
  aniso::StudioEnvironment studio;
  const glm::dvec3 f0(0.9, 0.5, 0.2);
  const double sigma = 1e-3;
  for (int which = 0; which < 3; ++which)
    for (double cosTheta : {1.0, 0.7, 0.3})
    {
      const aniso::Frame frame = testFrame(which);
      const glm::dvec3 v = localView(cosTheta, 1.1);
      const glm::dvec3 mirror(-v.x, -v.y, v.z);
      const double m = 1.0 - cosTheta;
      const glm::dvec3 fresnel = f0 + (glm::dvec3(1.0) - f0) * (m * m * m * m * m);
      const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
      const double deficit = 2.0 * sigma * sinTheta / (std::sqrt(2.0 * kPi) * cosTheta);
      const glm::dvec3 expected =
          (1.0 - deficit) * fresnel * studio.radiance(frame.toWorld(mirror));
      const aniso::ReferenceResult r =
          aniso::integrateSpecular({1e6, 1e6}, f0, frame, frame.toWorld(v), studio);
      EXPECT_TRUE(r.converged);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(r.value[k], expected[k], 5e-4 * luminance(expected))
            << "frame " << which << " n.v " << cosTheta;
    }
}

// Stress grid: every exponent pair in {0, 1, 10, ..., 1e6}^2 and n.v in {1, 0.1, 1e-3, 1e-6}:
// results are finite, non-negative and at most the largest radiance (F0 = 1: the quadrature
// weights are a partition of the lobe's unit mass, each value at most max L).
TEST(ReferenceSpecular, StressGridStaysInRange)
{
  aniso::StudioEnvironment studio;
  const double peak = studioPeak();
  const aniso::Frame frame = testFrame(1);
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-2;
  options.maxEvaluations = 1u << 20;
  const double exponents[] = {0, 1, 10, 100, 1e3, 1e4, 1e5, 1e6};
  for (double nu : exponents)
    for (double nv : exponents)
      for (double cosTheta : {1.0, 0.1, 1e-3, 1e-6})
      {
        const glm::dvec3 v = frame.toWorld(localView(cosTheta, 0.9));
        const aniso::ReferenceResult r =
            aniso::integrateSpecular({nu, nv}, glm::dvec3(1.0), frame, v, studio, options);
        for (int k = 0; k < 3; ++k)
        {
          ASSERT_TRUE(std::isfinite(r.value[k])) << nu << ',' << nv << ' ' << cosTheta;
          EXPECT_GE(r.value[k], 0.0) << nu << ',' << nv << ' ' << cosTheta;
          EXPECT_LE(r.value[k], peak * (1.0 + 1e-3)) << nu << ',' << nv << ' ' << cosTheta;
        }
        EXPECT_TRUE(std::isfinite(r.errorEstimate));
      }
}

// Bad arguments are refused naming the argument; a view below the surface reflects nothing.
TEST(ReferenceSpecular, ArgumentsAndBelowHorizon)
{
  aniso::StudioEnvironment studio;
  const aniso::Frame frame;
  auto messageOf = [&](const aniso::AsLobe& lobe, const glm::dvec3& f0, const glm::dvec3& v,
                       const aniso::ReferenceOptions& options) -> std::string
  {
    try
    {
      aniso::integrateSpecular(lobe, f0, frame, v, studio, options);
    }
    catch (const aniso::Error& e)
    {
      return e.what();
    }
    return "";
  };
  const aniso::ReferenceOptions defaults;
  EXPECT_EQ(messageOf({-1, 1}, glm::dvec3(1), {0, 0, 1}, defaults).rfind("n_u: ", 0), 0u);
  EXPECT_EQ(
      messageOf({1, std::numeric_limits<double>::quiet_NaN()}, glm::dvec3(1), {0, 0, 1}, defaults)
          .rfind("n_v: ", 0),
      0u);
  EXPECT_EQ(messageOf({1, 1}, glm::dvec3(1.5), {0, 0, 1}, defaults).rfind("F0: ", 0), 0u);
  EXPECT_EQ(messageOf({1, 1}, glm::dvec3(1), {0, 0, 0}, defaults).rfind("view: ", 0), 0u);
  aniso::ReferenceOptions tiny;
  tiny.maxEvaluations = 100;
  EXPECT_EQ(messageOf({1, 1}, glm::dvec3(1), {0, 0, 1}, tiny).rfind("maxEvaluations: ", 0), 0u);
  EXPECT_THROW(aniso::integrateIrradiance({0, 0, 0}, studio), aniso::Error);

  const aniso::ReferenceResult below =
      aniso::integrateSpecular({10, 10}, glm::dvec3(1), frame, {0.5, 0, -0.5}, studio);
  EXPECT_EQ(below.value, glm::dvec3(0.0));
  EXPECT_TRUE(below.converged);
}

namespace
{
// A 64 x 32 grey sky (1) with a lamp of 3 x 3 texels (luminance 2000, warm) above the horizon:
// large enough in texels (5.6 degrees each) that the rules resolve it, so they are an
// independent reference for the split.
std::shared_ptr<aniso::EquirectEnvironment> lampImage(int lampTexels)
{
  aniso::Image image(64, 32, 3);
  for (float& v : image.data)
    v = 1.0f;
  for (int y = 10; y < 10 + lampTexels; ++y)
    for (int x = 20; x < 20 + lampTexels; ++x)
    {
      image.at(x, y, 0) = 2400.0f;
      image.at(x, y, 1) = 2000.0f;
      image.at(x, y, 2) = 1500.0f;
    }
  return std::make_shared<aniso::EquirectEnvironment>(image,
                                                      "test:lamp" + std::to_string(lampTexels));
}
} // namespace

// The support: the lamp's texels and their eight neighbours; none for an environment that is
// not an image or has no concentrated source.
TEST(ReferenceSources, SupportIsTheExcessAndItsNeighbours)
{
  const auto one = aniso::sharedSourceQuadrature(*lampImage(1));
  ASSERT_NE(one, nullptr);
  EXPECT_EQ(one->support.size(), 9u);
  EXPECT_EQ(one->width, 64);
  const auto three = aniso::sharedSourceQuadrature(*lampImage(3));
  ASSERT_NE(three, nullptr);
  EXPECT_EQ(three->support.size(), 25u);
  EXPECT_EQ(aniso::sharedSourceQuadrature(LinearEnvironment()), nullptr);
  aniso::Image grey(64, 32, 3);
  for (float& v : grey.data)
    v = 1.0f;
  EXPECT_EQ(aniso::sharedSourceQuadrature(aniso::EquirectEnvironment(grey, "test:grey")), nullptr);
}

// Residual by the rules plus the excess over its texels against the rules over the whole image
// at a tighter tolerance, for a wide and a sharp lobe looking at the lamp and beside it: equal
// within the two error estimates (and 1e-3 relative).
TEST(ReferenceSources, SplitAgreesWithTheRulesOverTheWholeImage)
{
  const auto env = lampImage(3);
  const auto sources = aniso::sharedSourceQuadrature(*env);
  ASSERT_NE(sources, nullptr);
  // The lamp's centre direction: texel (21.5, 11.5) of 64 x 32.
  const double phi = kPi - 2.0 * kPi * 21.5 / 64.0;
  const double theta = kPi * 11.5 / 32.0;
  const glm::dvec3 lamp(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                        std::cos(theta));
  const glm::dvec3 view(0.0, -1.0, 0.3);
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-4;
  aniso::ReferenceOptions tight = options;
  tight.relativeTolerance = 1e-5;
  tight.maxEvaluations = 1ull << 28;
  for (const aniso::AsLobe lobe : {aniso::AsLobe{10.0, 10.0}, aniso::AsLobe{300.0, 30.0}})
    for (const double turn : {0.0, 0.15})
    {
      // A normal halfway between the view and the lamp (turned away from it by `turn` rad).
      const glm::dvec3 v = glm::normalize(view);
      glm::dvec3 n = glm::normalize(v + lamp);
      n = glm::normalize(n + turn * glm::normalize(glm::cross(n, glm::dvec3(0.0, 0.0, 1.0))));
      const aniso::Frame frame = aniso::Frame::fromNormalTangent(n, glm::dvec3(0.0, 0.0, 1.0));
      const aniso::ReferenceResult split =
          aniso::integrateSpecularSources(lobe, glm::dvec3(1.0), frame, v, *env, *sources, options);
      const aniso::ReferenceResult whole =
          aniso::integrateSpecular(lobe, glm::dvec3(1.0), frame, v, *env, tight);
      std::printf("(%g, %g) turn %.2f: split %.8g (+- %.1e, %llu evaluations), rules %.8g (+- "
                  "%.1e, %llu)\n",
                  lobe.nu, lobe.nv, turn, luminance(split.value), split.errorEstimate,
                  static_cast<unsigned long long>(split.evaluations), luminance(whole.value),
                  whole.errorEstimate, static_cast<unsigned long long>(whole.evaluations));
      EXPECT_TRUE(split.converged);
      ASSERT_TRUE(whole.converged);
      const double difference = std::abs(luminance(split.value) - luminance(whole.value));
      EXPECT_LE(difference,
                std::max(split.errorEstimate + whole.errorEstimate, 1e-3 * luminance(whole.value)));
      EXPECT_GT(luminance(split.value), 2.0); // the lamp is in the lobe
    }
}
