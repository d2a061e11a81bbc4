// The anisotropic GGX model and its reference integral against independent references:
// D normalised (projected area 1, by quadrature over the hemisphere), Smith Lambda consistent
// with D (the visible projected area of the microfacets equals that of the surface),
// G2 between the uncorrelated product and min(G1), reciprocity, VTK 9.1's mapping worked by
// hand, visible-normal samples against their density (chi-square), the reference integral
// against brute force over the light direction and never above 1 in the white furnace, and
// finite values over the whole stress range.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/brdf/ggx.h"
#include "core/env/environment.h"
#include "core/env/quadrature.h"
#include "core/error.h"
#include "core/frame.h"
#include "core/reference/reference_integrator.h"
#include "tests/core/chi_square.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;

glm::dvec3 direction(double cosTheta, double phi)
{
  const double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

// Integral over the upper hemisphere of fn(h) dw by spherical coordinates, theta = atan(e^s)
// with Gauss-Legendre panels in s (so a lobe is resolved around tan(theta) ~ alpha, whatever
// alpha) over [ln(alpha_min) - 12, ln(alpha_max) + 12], beyond which a GGX lobe holds less
// than e^-24 of its mass, and equally spaced azimuths (periodic: spectrally accurate once the
// azimuthal width alpha_min / alpha_max of an anisotropic lobe is resolved).
template <class Fn>
double hemisphereIntegral(const aniso::GgxLobe& lobe, const Fn& fn, int azimuths)
{
  const double low = std::log(std::min(lobe.alphaX, lobe.alphaY)) - 12.0;
  const double high = std::log(std::max(lobe.alphaX, lobe.alphaY)) + 12.0;
  const aniso::QuadratureRule rule = aniso::compositeGaussLegendre(120, 4, low, high);
  double total = 0.0;
  for (int j = 0; j < azimuths; ++j)
  {
    const double phi = (j + 0.5) * 2.0 * kPi / azimuths;
    for (std::size_t k = 0; k < rule.nodes.size(); ++k)
    {
      const double e = std::exp(rule.nodes[k]);
      const double cosTheta = 1.0 / std::sqrt(1.0 + e * e);
      const double sinTheta = e * cosTheta;
      const double dThetaDs = e / (1.0 + e * e);
      const glm::dvec3 h(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
      total += rule.weights[k] * dThetaDs * sinTheta * fn(h);
    }
  }
  return total * 2.0 * kPi / azimuths;
}

const std::vector<aniso::GgxLobe>& testLobes()
{
  static const std::vector<aniso::GgxLobe> lobes = {
      {0.3, 0.3}, {0.05, 0.5}, {1e-4, 1e-4}, {1e-3, 0.2}, {10.0, 10.0}, {2.0, 0.01}, {1.0, 1.0}};
  return lobes;
}

// Azimuths enough for the lobe's azimuthal width alpha_min / alpha_max.
int azimuthsFor(const aniso::GgxLobe& lobe)
{
  const double ratio = std::min(lobe.alphaX, lobe.alphaY) / std::max(lobe.alphaX, lobe.alphaY);
  return std::clamp(int(20.0 / ratio), 128, 8192);
}

// Chi-square p-value; bins the density gives almost no samples must stay nearly empty.
double chiSquarePValue(const std::vector<double>& observed, const std::vector<double>& expected)
{
  const aniso_test::ChiSquareResult r = aniso_test::chiSquare(observed, expected);
  if (r.pooledExpected < 5.0)
  {
    EXPECT_LE(r.pooledObserved, 20.0) << "samples where the density says there are almost none";
  }
  return r.pValue;
}

// Independent GGX f(v, l)(n.l), written out: D G2 F / (4 n.v), with
// D = 1 / (pi ax ay ((h.x/ax)^2 + (h.y/ay)^2 + h.z^2)^2) and
// Lambda(w) = (sqrt(1 + (ax^2 w.x^2 + ay^2 w.y^2) / w.z^2) - 1) / 2.
glm::dvec3 ggxBrdfCos(double ax, double ay, const glm::dvec3& f0, const glm::dvec3& v,
                      const glm::dvec3& l)
{
  if (l.z <= 0.0 || v.z <= 0.0)
    return glm::dvec3(0.0);
  const glm::dvec3 h = glm::normalize(v + l);
  const double x = h.x / ax;
  const double y = h.y / ay;
  const double s = x * x + y * y + h.z * h.z;
  const double d = 1.0 / (kPi * ax * ay * s * s);
  auto lambda = [&](const glm::dvec3& w)
  {
    return 0.5 * (std::sqrt(1.0 + (ax * ax * w.x * w.x + ay * ay * w.y * w.y) / (w.z * w.z)) - 1.0);
  };
  const double g2 = 1.0 / (1.0 + lambda(v) + lambda(l));
  const double m = 1.0 - glm::dot(v, h);
  const glm::dvec3 fresnel = f0 + (glm::dvec3(1.0) - f0) * std::pow(m, 5.0);
  return d * g2 / (4.0 * v.z) * fresnel;
}

// Brute force over the light direction: midpoint rule in (mu = n.l, phi) for lobes wide
// enough for the grid.
glm::dvec3 bruteForceOverLight(double ax, double ay, const glm::dvec3& f0,
                               const aniso::Frame& frame, const glm::dvec3& v,
                               const aniso::Environment& env, int muNodes, int phiNodes)
{
  glm::dvec3 total(0.0);
  const double dMu = 1.0 / muNodes;
  const double dPhi = 2.0 * kPi / phiNodes;
  for (int i = 0; i < muNodes; ++i)
    for (int j = 0; j < phiNodes; ++j)
    {
      const glm::dvec3 l = direction((i + 0.5) * dMu, (j + 0.5) * dPhi);
      total += (dMu * dPhi) * ggxBrdfCos(ax, ay, f0, v, l) * env.radiance(frame.toWorld(l));
    }
  return total;
}
} // namespace

// D(h)(n.h) integrates to 1 over the hemisphere for round, elongated, nearly mirror and very
// rough lobes; D(n) = 1 / (pi ax ay) and D is even in h.x and h.y.
TEST(GgxDistribution, ProjectedAreaIsOne)
{
  for (const aniso::GgxLobe& lobe : testLobes())
  {
    const double area = hemisphereIntegral(
        lobe, [&](const glm::dvec3& h) { return aniso::ggxDistribution(lobe, h) * h.z; },
        azimuthsFor(lobe));
    EXPECT_NEAR(area, 1.0, 1e-6) << lobe.alphaX << ',' << lobe.alphaY;
    EXPECT_DOUBLE_EQ(aniso::ggxDistribution(lobe, {0, 0, 1}),
                     1.0 / (kPi * lobe.alphaX * lobe.alphaY));
    const glm::dvec3 h = glm::normalize(glm::dvec3(0.2, -0.1, 0.9));
    EXPECT_DOUBLE_EQ(aniso::ggxDistribution(lobe, h),
                     aniso::ggxDistribution(lobe, {-h.x, h.y, h.z}));
    EXPECT_DOUBLE_EQ(aniso::ggxDistribution(lobe, h),
                     aniso::ggxDistribution(lobe, {h.x, -h.y, h.z}));
    EXPECT_EQ(aniso::ggxDistribution(lobe, {1, 0, 0}), 0.0);
  }
}

// Smith's masking is defined by D: the visible projected area of the microfacets, the integral
// of G1(v) max(0, v.h) D(h) dw_h, equals the projected area v.z of the surface. Checked by
// quadrature for every test lobe and views from normal to grazing, which pins Lambda to D.
TEST(GgxMasking, VisibleProjectedAreaMatchesSurface)
{
  for (const aniso::GgxLobe& lobe : testLobes())
    for (const glm::dvec3& v :
         {direction(1.0, 0.0), direction(0.7, 0.3), direction(0.2, 1.3), direction(0.02, -2.0)})
    {
      const double visible = hemisphereIntegral(
          lobe,
          [&](const glm::dvec3& h)
          { return std::max(0.0, glm::dot(v, h)) * aniso::ggxDistribution(lobe, h); },
          azimuthsFor(lobe));
      // The kink of max(0, v.h) limits the quadrature to about 1e-6.
      EXPECT_NEAR(aniso::ggxMasking(lobe, v) * visible, v.z, 1e-5 * (v.z + 1.0))
          << lobe.alphaX << ',' << lobe.alphaY << " v.z " << v.z;
    }
}

// The height-correlated G2 lies between the uncorrelated product G1(v) G1(l) and min(G1(v),
// G1(l)) (1 / (1 + a + b) against 1 / ((1 + a)(1 + b)) and 1 / (1 + max(a, b))); masking is 1
// at the normal, 0 at and below the horizon. Random pairs over the test lobes.
TEST(GgxMasking, G2BetweenProductAndMinimum)
{
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const aniso::GgxLobe& lobe : testLobes())
  {
    EXPECT_EQ(aniso::ggxMasking(lobe, {0, 0, 1}), 1.0);
    EXPECT_EQ(aniso::ggxMasking(lobe, {1, 0, 0}), 0.0);
    EXPECT_EQ(aniso::ggxMaskingShadowing(lobe, {0, 0, 1}, direction(-0.1, 0.0)), 0.0);
    for (int i = 0; i < 2000; ++i)
    {
      const glm::dvec3 v = direction(uniform(random), 2.0 * kPi * uniform(random));
      const glm::dvec3 l = direction(uniform(random), 2.0 * kPi * uniform(random));
      const double g1v = aniso::ggxMasking(lobe, v);
      const double g1l = aniso::ggxMasking(lobe, l);
      const double g2 = aniso::ggxMaskingShadowing(lobe, v, l);
      EXPECT_LE(g2, std::min(g1v, g1l) * (1.0 + 1e-12));
      EXPECT_GE(g2, g1v * g1l * (1.0 - 1e-12));
      EXPECT_LE(g2, 1.0);
    }
  }
}

// f(v, l) = f(l, v), and it agrees with the formula written out in this test.
TEST(GgxSpecular, ReciprocalAndMatchesFormula)
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const glm::dvec3 f0(0.9, 0.5, 0.04);
  for (const aniso::GgxLobe& lobe : testLobes())
    for (int i = 0; i < 500; ++i)
    {
      const glm::dvec3 v = direction(uniform(random), 2.0 * kPi * uniform(random));
      const glm::dvec3 l = direction(uniform(random), 2.0 * kPi * uniform(random));
      const glm::dvec3 a = aniso::evalSpecular(lobe, f0, v, l);
      const glm::dvec3 b = aniso::evalSpecular(lobe, f0, l, v);
      const glm::dvec3 expected = ggxBrdfCos(lobe.alphaX, lobe.alphaY, f0, v, l) / l.z;
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_NEAR(a[k], b[k], 1e-12 * std::abs(a[k]) + 1e-300);
        EXPECT_NEAR(a[k], expected[k], 1e-10 * std::abs(expected[k]) + 1e-300);
      }
    }
}

// VTK 9.1's mapping worked by hand: roughness 0.5, anisotropy 0.8 gives aspect sqrt(0.28),
// alpha_t = 0.25 / aspect, alpha_b = 0.25 aspect; anisotropy 0 is isotropic r^2; roughness 0 is
// clamped to 0.001; values outside [0, 1] are refused naming the parameter.
TEST(GgxVtkMapping, WorkedValuesAndErrors)
{
  const aniso::GgxLobe a = aniso::ggxLobeFromVtk(0.5, 0.8);
  EXPECT_NEAR(a.alphaX, 0.25 / std::sqrt(0.28), 1e-15);
  EXPECT_NEAR(a.alphaY, 0.25 * std::sqrt(0.28), 1e-15);
  const aniso::GgxLobe b = aniso::ggxLobeFromVtk(0.7, 0.0);
  EXPECT_NEAR(b.alphaX, 0.49, 1e-15);
  EXPECT_NEAR(b.alphaY, 0.49, 1e-15);
  const aniso::GgxLobe c = aniso::ggxLobeFromVtk(0.0, 1.0);
  EXPECT_EQ(c.alphaX, 0.001);
  EXPECT_EQ(c.alphaY, 0.001);
  const aniso::GgxLobe d = aniso::ggxLobeFromVtk(1.0, 1.0);
  EXPECT_NEAR(d.alphaX, 1.0 / std::sqrt(0.1), 1e-14);
  EXPECT_NO_THROW(aniso::validateGgxLobe(d));
  auto messageOf = [](double r, double an) -> std::string
  {
    try
    {
      aniso::ggxLobeFromVtk(r, an);
    }
    catch (const aniso::Error& e)
    {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(messageOf(-0.1, 0.5).rfind("roughness: ", 0), 0u);
  EXPECT_EQ(messageOf(std::numeric_limits<double>::quiet_NaN(), 0.5).rfind("roughness: ", 0), 0u);
  EXPECT_EQ(messageOf(0.5, 1.5).rfind("anisotropy: ", 0), 0u);
  EXPECT_THROW(aniso::validateGgxLobe({0.0, 0.5}), aniso::Error);
  EXPECT_THROW(aniso::validateGgxLobe({0.5, 11.0}), aniso::Error);
}

// Visible normals against their density: 400k samples binned over the stretched slope plane
// (u = 1 / sqrt(1 + r^2), the cosine of the stretched polar angle, and its azimuth psi), the
// expected count of each bin integrated from pdfVisibleNormal with the Jacobian of that map
// (dw_h = cos^3(theta) ax ay du dpsi / u^3) by 6 x 6 Gauss-Legendre nodes. A Pearson test at
// p > 1e-4 for each lobe and view (a fixed seed, so the outcome is reproducible). Samples are
// unit, above the horizon and facing the view.
TEST(GgxSampling, VisibleNormalsMatchDensityChiSquare)
{
  const int uBins = 16;
  const int psiBins = 32;
  const int samples = 400000;
  const aniso::QuadratureRule unit = aniso::gaussLegendre(6);
  std::mt19937_64 random(2024);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const aniso::GgxLobe& lobe : {aniso::GgxLobe{0.3, 0.3}, aniso::GgxLobe{0.05, 0.5},
                                     aniso::GgxLobe{1.0, 0.2}, aniso::GgxLobe{1e-3, 1e-3}})
    for (const glm::dvec3& v : {direction(1.0, 0.0), direction(0.6, 0.4), direction(0.05, 2.0)})
    {
      auto binOf = [&](const glm::dvec3& h)
      {
        const double sx = h.x / h.z / lobe.alphaX;
        const double sy = h.y / h.z / lobe.alphaY;
        const double u = 1.0 / std::sqrt(1.0 + sx * sx + sy * sy);
        double psi = std::atan2(sy, sx);
        if (psi < 0.0)
          psi += 2.0 * kPi;
        const int i = std::min(uBins - 1, int(u * uBins));
        const int j = std::min(psiBins - 1, int(psi / (2.0 * kPi) * psiBins));
        return i * psiBins + j;
      };
      std::vector<double> observed(std::size_t(uBins * psiBins), 0.0);
      for (int s = 0; s < samples; ++s)
      {
        const glm::dvec3 h =
            aniso::sampleVisibleNormal(lobe, v, {uniform(random), uniform(random)});
        ASSERT_NEAR(glm::length(h), 1.0, 1e-12);
        ASSERT_GE(h.z, 0.0);
        ASSERT_GE(glm::dot(h, v), -1e-12);
        if (h.z > 0.0)
          observed[std::size_t(binOf(h))] += 1.0;
      }
      std::vector<double> expected(observed.size(), 0.0);
      double totalProbability = 0.0;
      for (int i = 0; i < uBins; ++i)
        for (int j = 0; j < psiBins; ++j)
        {
          double mass = 0.0;
          for (std::size_t a = 0; a < unit.nodes.size(); ++a)
            for (std::size_t b = 0; b < unit.nodes.size(); ++b)
            {
              const double u = (i + unit.nodes[a]) / uBins;
              const double psi = (j + unit.nodes[b]) * 2.0 * kPi / psiBins;
              const double r = std::sqrt(1.0 - u * u) / u;
              const glm::dvec3 h = glm::normalize(glm::dvec3(lobe.alphaX * r * std::cos(psi),
                                                             lobe.alphaY * r * std::sin(psi), 1.0));
              const double jacobian = h.z * h.z * h.z * lobe.alphaX * lobe.alphaY / (u * u * u);
              mass += unit.weights[a] * unit.weights[b] * jacobian *
                      aniso::pdfVisibleNormal(lobe, v, h);
            }
          mass *= (1.0 / uBins) * (2.0 * kPi / psiBins);
          expected[std::size_t(i * psiBins + j)] = mass * samples;
          totalProbability += mass;
        }
      EXPECT_NEAR(totalProbability, 1.0, 2e-3) << lobe.alphaX << ',' << lobe.alphaY;
      const double p = chiSquarePValue(observed, expected);
      EXPECT_GT(p, 1e-4) << lobe.alphaX << ',' << lobe.alphaY << " v.z " << v.z;
    }
}

// pdfLight is the density of l = reflect(v, h) for visible-normal h: it integrates to the
// fraction of such l that exists (all of them, including those below the horizon), i.e. 1,
// by quadrature over the whole sphere of l.
TEST(GgxSampling, LightDensityIntegratesToOne)
{
  for (const aniso::GgxLobe& lobe : {aniso::GgxLobe{0.3, 0.3}, aniso::GgxLobe{1.0, 0.2}})
    for (const glm::dvec3& v : {direction(0.9, 0.0), direction(0.3, 1.0)})
    {
      // Midpoint rule in (cos theta, phi) over the sphere; these lobes are wide.
      const int mu = 2000;
      const int phi = 2000;
      double total = 0.0;
      for (int i = 0; i < mu; ++i)
        for (int j = 0; j < phi; ++j)
        {
          const glm::dvec3 l = direction(-1.0 + 2.0 * (i + 0.5) / mu, (j + 0.5) * 2.0 * kPi / phi);
          total += aniso::pdfLight(lobe, v, l);
        }
      total *= (2.0 / mu) * (2.0 * kPi / phi);
      EXPECT_NEAR(total, 1.0, 2e-3) << lobe.alphaX << ',' << lobe.alphaY << " v.z " << v.z;
    }
}

// The reference integral of GGX against brute force over the light direction, under a uniform
// sky (white furnace, F0 = 1 and 0.04) and under the studio, for lobes wide enough for a
// 1024 x 2048 grid: agreement within 2e-4 of the luminance. The albedo never exceeds 1.
TEST(GgxReference, MatchesBruteForceOverLight)
{
  aniso::UniformEnvironment one(glm::dvec3(1.0));
  aniso::StudioEnvironment studio;
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-5;
  const aniso::Frame tilted = aniso::Frame::fromNormalTangent({0.3, -0.5, 0.8}, {1, 1, 0});
  struct Case
  {
    double ax, ay, cosTheta;
    glm::dvec3 f0;
    bool useStudio;
  };
  for (const Case& c :
       {Case{0.5, 0.5, 0.9, glm::dvec3(1.0), false}, Case{0.5, 0.5, 0.1, glm::dvec3(1.0), false},
        Case{0.3, 0.8, 0.5, glm::dvec3(0.04), false}, Case{1.0, 1.0, 0.3, glm::dvec3(1.0), false},
        Case{0.4, 0.4, 0.7, glm::dvec3(0.9, 0.6, 0.3), true},
        Case{0.2, 0.6, 0.3, glm::dvec3(0.9, 0.6, 0.3), true}})
  {
    const aniso::Environment& env = c.useStudio ? static_cast<const aniso::Environment&>(studio)
                                                : static_cast<const aniso::Environment&>(one);
    const glm::dvec3 v = direction(c.cosTheta, 0.7);
    const aniso::ReferenceResult r =
        aniso::integrateSpecularGgx({c.ax, c.ay}, c.f0, tilted, tilted.toWorld(v), env, options);
    const glm::dvec3 expected = bruteForceOverLight(c.ax, c.ay, c.f0, tilted, v, env, 1024, 2048);
    EXPECT_TRUE(r.converged);
    const double scale = 0.2126 * expected.x + 0.7152 * expected.y + 0.0722 * expected.z;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(r.value[k], expected[k], 2e-4 * scale)
          << c.ax << ',' << c.ay << " n.v " << c.cosTheta;
    if (!c.useStudio)
    {
      EXPECT_LE(r.value.x, 1.0);
    }
  }
}

// White furnace over the whole range (F0 = 1, L = 1): the albedo is at most 1 for alphas from
// 1e-4 to 10 and views down to n.v = 1e-6, and tends to 1 for a nearly smooth lobe at normal
// incidence (masking vanishes there: the loss is below 1e-5 for alpha = 1e-3).
TEST(GgxReference, WhiteFurnaceAtMostOne)
{
  aniso::UniformEnvironment one(glm::dvec3(1.0));
  const aniso::Frame frame;
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-4;
  const double alphas[] = {1e-4, 1e-2, 0.3, 1.0, 10.0};
  for (double ax : alphas)
    for (double ay : alphas)
      for (double cosTheta : {1.0, 0.5, 1e-3, 1e-6})
      {
        const aniso::ReferenceResult r = aniso::integrateSpecularGgx(
            {ax, ay}, glm::dvec3(1.0), frame, direction(cosTheta, 0.4), one, options);
        ASSERT_TRUE(std::isfinite(r.value.x)) << ax << ',' << ay << ' ' << cosTheta;
        EXPECT_TRUE(r.converged) << ax << ',' << ay << ' ' << cosTheta;
        EXPECT_GE(r.value.x, 0.0);
        EXPECT_LE(r.value.x, 1.0 + 1e-4) << ax << ',' << ay << ' ' << cosTheta;
      }
  options.relativeTolerance = 1e-7;
  const aniso::ReferenceResult smooth =
      aniso::integrateSpecularGgx({1e-3, 1e-3}, glm::dvec3(1.0), frame, {0, 0, 1}, one, options);
  EXPECT_NEAR(smooth.value.x, 1.0, 1e-5);
}

// The lobes VTK's PBR anisotropy produces (roughness 0.05 to 1, anisotropy 0 to 1) under the
// studio, views from normal to n.v = 0.05: the reference reaches the default tolerance
// (errorEstimate <= 1e-3 of the luminance) within the default evaluation budget.
TEST(GgxReference, ConvergesForVtkLobes)
{
  aniso::StudioEnvironment studio;
  const aniso::Frame frame = aniso::Frame::fromNormalTangent({-0.7, 0.2, 0.1}, {0, 0, 1});
  const glm::dvec3 f0(0.95, 0.64, 0.54);
  uint64_t most = 0;
  for (double roughness : {0.05, 0.3, 0.7, 1.0})
    for (double anisotropy : {0.0, 0.5, 1.0})
      for (double cosTheta : {1.0, 0.5, 0.05})
      {
        const aniso::GgxLobe lobe = aniso::ggxLobeFromVtk(roughness, anisotropy);
        const aniso::ReferenceResult r = aniso::integrateSpecularGgx(
            lobe, f0, frame, frame.toWorld(direction(cosTheta, 2.1)), studio);
        const double luminance = 0.2126 * r.value.x + 0.7152 * r.value.y + 0.0722 * r.value.z;
        EXPECT_TRUE(r.converged) << roughness << ',' << anisotropy << " n.v " << cosTheta;
        EXPECT_LE(r.errorEstimate, 1e-3 * luminance)
            << roughness << ',' << anisotropy << " n.v " << cosTheta;
        most = std::max(most, r.evaluations);
      }
  std::printf("most evaluations for 1e-3: %llu\n", static_cast<unsigned long long>(most));
}

// Stress: alphas over the whole range, views to n.v = 1e-6, random light directions: f, the
// masking terms, the densities and the samples are finite (and samples unit).
TEST(GgxStress, FiniteEverywhere)
{
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double alphas[] = {1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0};
  for (double ax : alphas)
    for (double ay : alphas)
      for (double cosTheta : {1.0, 0.3, 1e-3, 1e-6})
      {
        const aniso::GgxLobe lobe{ax, ay};
        const glm::dvec3 v = direction(cosTheta, 2.0 * kPi * uniform(random));
        for (int i = 0; i < 200; ++i)
        {
          const glm::dvec2 xi(uniform(random), uniform(random));
          const glm::dvec3 h = aniso::sampleVisibleNormal(lobe, v, xi);
          const glm::dvec3 l = aniso::reflectAbout(v, h);
          const glm::dvec3 f = aniso::evalSpecular(lobe, glm::dvec3(1.0), v, l);
          const glm::dvec3 other = direction(uniform(random) * 2.0 - 1.0, 7.0 * uniform(random));
          const glm::dvec3 g = aniso::evalSpecular(lobe, glm::dvec3(1.0), v, other);
          const double values[] = {h.x,
                                   h.y,
                                   h.z,
                                   f.x,
                                   g.x,
                                   aniso::pdfVisibleNormal(lobe, v, h),
                                   aniso::pdfLight(lobe, v, l),
                                   aniso::pdfLight(lobe, v, other),
                                   aniso::ggxMaskingShadowing(lobe, v, l),
                                   aniso::ggxMasking(lobe, v)};
          for (double value : values)
            ASSERT_TRUE(std::isfinite(value)) << ax << ',' << ay << " n.v " << cosTheta;
          ASSERT_NEAR(glm::length(h), 1.0, 1e-12);
        }
      }
  // The corner values themselves.
  const aniso::GgxLobe sharp{1e-4, 1e-4};
  EXPECT_GE(aniso::ggxMasking(sharp, direction(1e-300, 0.0)), 0.0);
  EXPECT_EQ(aniso::ggxLambda(sharp, {1, 0, 0}), std::numeric_limits<double>::infinity());
  EXPECT_EQ(aniso::sampleVisibleNormal(sharp, {0, 0, -1}, {0.5, 0.5}), glm::dvec3(0, 0, 1));
}
