// The Ashikhmin-Shirley model: normalisation, sampling, inversion, reciprocity, energy and
// robustness. References are deterministic quadrature of the densities (never the sampler),
// the closed forms of docs/METHOD.md, and analytic albedos.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/error.h"
#include "tests/core/chi_square.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <iomanip>
#include <limits>
#include <queue>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using aniso::AsLobe;

constexpr double kPi = 3.14159265358979323846;
const double kBelowOne = std::nextafter(1.0, 0.0);

// ---- Adaptive Gauss-Kronrod (7/15) quadrature -------------------------------------------------

constexpr std::array<double, 8> kKronrodNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kKronrodWeights = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Gauss weights of the embedded 7-point rule (at Kronrod nodes 1, 3, 5, 7).
constexpr std::array<double, 4> kGaussWeights = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Panel
{
  double a = 0.0;
  double b = 0.0;
  double value = 0.0;
  double error = 0.0;
  bool operator<(const Panel& other) const { return error < other.error; }
};

// One 15-point Kronrod rule on [a, b]; the error estimate is its distance to the embedded
// 7-point Gauss rule (conservative).
template <class F>
Panel gaussKronrod(const F& f, double a, double b)
{
  const double centre = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  const double fc = f(centre);
  double kronrod = kKronrodWeights[7] * fc;
  double gauss = kGaussWeights[3] * fc;
  for (size_t k = 0; k < 7; ++k)
  {
    const double sum = f(centre - half * kKronrodNodes[k]) + f(centre + half * kKronrodNodes[k]);
    kronrod += kKronrodWeights[k] * sum;
    if (k % 2 == 1)
    {
      gauss += kGaussWeights[k / 2] * sum;
    }
  }
  return {a, b, kronrod * half, std::abs(kronrod - gauss) * half};
}

// Globally adaptive quadrature over [a, b] (QUADPACK's QAG strategy): start from `pieces` equal
// panels so that no feature hides between the nodes of a single rule, then keep bisecting the
// panel with the largest error estimate until the total is below `tolerance` or the panel budget
// is spent. The budget bounds the cost even where rounding or a kink stalls the estimate.
template <class F>
double integrate(const F& f, double a, double b, double tolerance, int pieces,
                 size_t maxPanels = 400)
{
  std::priority_queue<Panel> panels;
  double totalError = 0.0;
  for (int i = 0; i < pieces; ++i)
  {
    const double lo = a + (b - a) * i / pieces;
    const double hi = i + 1 == pieces ? b : a + (b - a) * (i + 1) / pieces;
    const Panel panel = gaussKronrod(f, lo, hi);
    totalError += panel.error;
    panels.push(panel);
  }
  while (totalError > tolerance && panels.size() < maxPanels)
  {
    const Panel worst = panels.top();
    panels.pop();
    const double centre = 0.5 * (worst.a + worst.b);
    const Panel left = gaussKronrod(f, worst.a, centre);
    const Panel right = gaussKronrod(f, centre, worst.b);
    totalError += left.error + right.error - worst.error;
    panels.push(left);
    panels.push(right);
  }
  double sum = 0.0;
  for (; !panels.empty(); panels.pop())
  {
    sum += panels.top().value;
  }
  return sum;
}

// ---- Hemisphere coordinates that resolve any lobe ---------------------------------------------
// A half vector is written with azimuth phi and t = -ln(1 - cos theta). Then dw = sin(theta)
// dtheta dphi = e^-t dt dphi, and a lobe (cos theta)^e of any exponent becomes a smooth bump of
// width ~1 around t = ln(e): the same panels resolve e = 0 and e = 1e6. t = 40 leaves out a
// cap of solid angle 2 pi e^-40 (below 1e-11 of probability even at p_h = 1.6e5).
constexpr double kTMax = 40.0;

glm::dvec3 halfVectorAt(double phi, double t)
{
  const double w = std::exp(-t); // 1 - cos(theta), exact to rounding even when tiny
  const double sinTheta = std::sqrt(w * (2.0 - w));
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), 1.0 - w};
}

// Integral of g(h) over the part of the upper hemisphere with phi in [phi0, phi1] and
// t in [t0, t1].
template <class G>
double integrateHemisphere(const G& g, double phi0, double phi1, double t0, double t1,
                           double tolerance, int phiPieces)
{
  const auto overT = [&](double phi)
  {
    const auto integrand = [&](double t) { return g(halfVectorAt(phi, t)) * std::exp(-t); };
    const int tPieces = std::max(1, static_cast<int>(std::ceil(0.25 * (t1 - t0))));
    return integrate(integrand, t0, t1, 1e-3 * tolerance, tPieces);
  };
  return integrate(overT, phi0, phi1, tolerance, phiPieces);
}

// Whole upper hemisphere, quadrant by quadrant.
template <class G>
double integrateUpperHemisphere(const G& g, double tolerance)
{
  double sum = 0.0;
  for (int q = 0; q < 4; ++q)
  {
    sum += integrateHemisphere(g, 0.5 * kPi * q, 0.5 * kPi * (q + 1), 0.0, kTMax, 0.25 * tolerance,
                               16);
  }
  return sum;
}

// ---- Independent forms of the design formulas -------------------------------------------------

// e(phi) = n_u cos^2 phi + n_v sin^2 phi (docs/METHOD.md, with t.h = sin(theta) cos(phi), etc.).
double exponentAt(const AsLobe& lobe, double phi)
{
  const double c = std::cos(phi);
  const double s = std::sin(phi);
  return lobe.nu * c * c + lobe.nv * s * s;
}

double azimuth(const glm::dvec3& h)
{
  const double phi = std::atan2(h.y, h.x);
  return phi < 0.0 ? phi + 2.0 * kPi : phi;
}

glm::dvec3 viewWithCosine(double cosTheta, double azimuthAngle)
{
  const double sinTheta = std::sqrt((1.0 - cosTheta) * (1.0 + cosTheta));
  return {sinTheta * std::cos(azimuthAngle), sinTheta * std::sin(azimuthAngle), cosTheta};
}

std::string str(double x)
{
  std::ostringstream out;
  out << std::setprecision(17) << x;
  return out.str();
}

std::string describe(const AsLobe& lobe)
{
  return "lobe (" + str(lobe.nu) + ", " + str(lobe.nv) + ")";
}

const std::vector<AsLobe> kStressLobes = []
{
  const std::array<double, 8> exponents = {0.0, 1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6};
  std::vector<AsLobe> lobes;
  for (double nu : exponents)
  {
    for (double nv : exponents)
    {
      lobes.push_back({nu, nv});
    }
  }
  return lobes;
}();
} // namespace

// 1. p_h integrates to 1 over the hemisphere (reference: the normalisation stated in docs/METHOD.md),
// by adaptive Gauss-Kronrod quadrature in (phi, -ln(1 - cos theta)); no sampling involved.
TEST(AshikhminShirley, HalfVectorPdfIntegratesToOne)
{
  const std::vector<AsLobe> lobes = {{0, 0},      {1, 1},      {10, 10},   {100, 10},
                                     {1000, 100}, {20000, 70}, {1e5, 1e5}, {1e6, 10}};
  for (const AsLobe& lobe : lobes)
  {
    const double total = integrateUpperHemisphere(
        [&](const glm::dvec3& h) { return aniso::pdfHalfVector(lobe, h); }, 1e-8);
    EXPECT_NEAR(total, 1.0, 1e-6) << describe(lobe);
    RecordProperty("deviation " + describe(lobe), str(total - 1.0));
  }
}

// 2. Chi-square goodness of fit of sampleHalfVector against pdfHalfVector. Bins: columns in phi
// whose edges follow tan(phi) = sqrt((n_u+1)/(n_v+1)) tan(psi) for equally spaced psi
// (lobe-adapted, from the design formula), rows equally spaced in y = 1 - cos(theta)^(e_c+1) with
// e_c the exponent at the column centre. Expected counts: quadrature of the pdf over each bin. Bins
// expecting fewer than 5 samples are pooled. Pseudo-random xi from a fixed seed; significance 1e-3,
// Bonferroni corrected over the lobes.
TEST(AshikhminShirley, SamplerMatchesPdfChiSquare)
{
  // The survival function used below, checked on closed forms: Q(1, x) = e^-x and
  // Q(1/2, x) = erfc(sqrt(x)).
  ASSERT_NEAR(aniso_test::gammaQ(1.0, 3.0), std::exp(-3.0), 1e-14);
  ASSERT_NEAR(aniso_test::gammaQ(0.5, 0.3), std::erfc(std::sqrt(0.3)), 1e-14);
  ASSERT_NEAR(aniso_test::gammaQ(0.5, 7.0), std::erfc(std::sqrt(7.0)), 1e-14);

  const std::vector<AsLobe> lobes = {{1, 1}, {100, 10}, {10, 100}, {20000, 70}, {1e6, 1e3}};
  const int quadrantColumns = 8;
  const int columns = 4 * quadrantColumns;
  const int rows = 16;
  const int samples = 200000;
  const double significance = 1e-3 / static_cast<double>(lobes.size());

  for (const AsLobe& lobe : lobes)
  {
    // Column edges: one quadrant from psi, mirrored into the others like the quadrant symmetry
    // of p_h (phi -> pi - phi, phi -> -phi).
    const double ratio = std::sqrt((lobe.nu + 1.0) / (lobe.nv + 1.0));
    std::vector<double> quadrantEdges(quadrantColumns + 1);
    for (int j = 0; j <= quadrantColumns; ++j)
    {
      const double psi = 0.5 * kPi * j / quadrantColumns;
      quadrantEdges[j] =
          j == quadrantColumns ? 0.5 * kPi : std::atan2(ratio * std::sin(psi), std::cos(psi));
    }
    std::vector<double> edges;
    for (int q = 0; q < 4; ++q)
    {
      for (int j = 0; j < quadrantColumns; ++j)
      {
        const double local =
            q % 2 == 0 ? quadrantEdges[j] : 0.5 * kPi - quadrantEdges[quadrantColumns - j];
        edges.push_back(0.5 * kPi * q + local);
      }
    }
    edges.push_back(2.0 * kPi);
    std::vector<double> rowPower(columns); // e_c + 1 per column
    for (int j = 0; j < columns; ++j)
    {
      rowPower[j] = exponentAt(lobe, 0.5 * (edges[j] + edges[j + 1])) + 1.0;
    }

    // Expected probabilities by quadrature; row edges in y map to t = -ln(1 - cos theta).
    std::vector<double> expected(static_cast<size_t>(columns * rows));
    double totalProbability = 0.0;
    for (int j = 0; j < columns; ++j)
    {
      for (int r = 0; r < rows; ++r)
      {
        const auto tOfY = [&](double y)
        {
          if (y <= 0.0)
          {
            return kTMax;
          }
          const double w = -std::expm1(std::log1p(-y) / rowPower[j]); // 1 - cos theta
          return std::min(-std::log(w), kTMax);
        };
        const double tHigh = tOfY(static_cast<double>(r) / rows);
        const double tLow = r + 1 == rows ? 0.0 : tOfY(static_cast<double>(r + 1) / rows);
        const double p =
            integrateHemisphere([&](const glm::dvec3& h) { return aniso::pdfHalfVector(lobe, h); },
                                edges[j], edges[j + 1], tLow, tHigh, 1e-9, 4);
        expected[static_cast<size_t>(j * rows + r)] = p;
        totalProbability += p;
      }
    }
    EXPECT_NEAR(totalProbability, 1.0, 1e-6) << describe(lobe);

    std::vector<double> observed(expected.size(), 0.0);
    std::mt19937_64 rng(20240229);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    int misplaced = 0;
    for (int i = 0; i < samples; ++i)
    {
      const double xi1 = uniform(rng);
      const double xi2 = uniform(rng);
      const glm::dvec3 h = aniso::sampleHalfVector(lobe, {xi1, xi2});
      if (!(h.z >= 0.0))
      {
        ++misplaced;
        continue;
      }
      const double phi = azimuth(h);
      const int j = std::min(
          columns - 1,
          static_cast<int>(std::upper_bound(edges.begin(), edges.end(), phi) - edges.begin()) - 1);
      const double logCos = 0.5 * std::log1p(-(h.x * h.x + h.y * h.y));
      const double y = -std::expm1(rowPower[j] * logCos);
      const int r = std::min(rows - 1, static_cast<int>(y * rows));
      observed[static_cast<size_t>(j * rows + std::max(r, 0))] += 1.0;
    }
    EXPECT_EQ(misplaced, 0) << describe(lobe);

    double chi2 = 0.0;
    int cells = 0;
    double pooledExpected = 0.0;
    double pooledObserved = 0.0;
    for (size_t k = 0; k < expected.size(); ++k)
    {
      const double e = expected[k] * samples;
      if (e < 5.0)
      {
        pooledExpected += e;
        pooledObserved += observed[k];
        continue;
      }
      chi2 += (observed[k] - e) * (observed[k] - e) / e;
      ++cells;
    }
    if (pooledExpected >= 5.0)
    {
      chi2 +=
          (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
      ++cells;
    }
    else
    {
      // Too few expected to form a cell of its own: the pooled rest must stay small too.
      EXPECT_LT(pooledObserved, 20.0) << describe(lobe);
    }
    ASSERT_GT(cells, 100) << describe(lobe);
    const double pValue = aniso_test::gammaQ(0.5 * (cells - 1), 0.5 * chi2);
    RecordProperty("p-value " + describe(lobe), str(pValue));
    EXPECT_GT(pValue, significance)
        << describe(lobe) << ": chi2 = " << chi2 << " over " << cells << " cells";
  }
}

// 3a. The sampler is the construction of docs/METHOD.md: phi = atan(A tan(pi u / 2)) mirrored into the
// quadrants, cos theta = (1 - xi2)^(1/(e+1)), here evaluated directly with tan and pow away from
// the edges where those forms are exact enough.
TEST(AshikhminShirley, SamplerFollowsTheDesignFormulas)
{
  const std::vector<AsLobe> lobes = {{0, 0}, {10, 10}, {100, 10}, {10, 100}, {20000, 70}};
  for (const AsLobe& lobe : lobes)
  {
    const double ratio = std::sqrt((lobe.nu + 1.0) / (lobe.nv + 1.0));
    for (int i = 1; i < 400; ++i)
    {
      const double xi1 = (i + 0.37) / 400.0;
      const double scaled = 4.0 * xi1;
      const int q = static_cast<int>(scaled);
      const double u = scaled - q;
      if (u < 1e-3 || u > 1.0 - 1e-3)
      {
        continue;
      }
      double phi = 0.0;
      switch (q)
      {
      case 0:
        phi = std::atan(ratio * std::tan(0.5 * kPi * u));
        break;
      case 1:
        phi = kPi - std::atan(ratio * std::tan(0.5 * kPi * (1.0 - u)));
        break;
      case 2:
        phi = kPi + std::atan(ratio * std::tan(0.5 * kPi * u));
        break;
      default:
        phi = 2.0 * kPi - std::atan(ratio * std::tan(0.5 * kPi * (1.0 - u)));
        break;
      }
      for (double xi2 : {0.1, 0.5, 0.9})
      {
        const glm::dvec3 h = aniso::sampleHalfVector(lobe, {xi1, xi2});
        const double cosTheta = std::pow(1.0 - xi2, 1.0 / (exponentAt(lobe, phi) + 1.0));
        ASSERT_NEAR(azimuth(h), phi, 1e-10) << describe(lobe) << " xi1 = " << xi1;
        ASSERT_NEAR(h.z, cosTheta, 1e-12) << describe(lobe) << " xi2 = " << xi2;
      }
    }
  }
}

// 3b. Quadrants: xi1 in [k/4, (k+1)/4) lands in quadrant k of phi (half-open like [0, pi/2)),
// the quarter values land exactly on the axes, and phi grows continuously with xi1 (no jump
// larger than the bound 2 pi max(A, 1/A) dxi1 from the derivative of the design formula).
TEST(AshikhminShirley, QuadrantsAxesAndContinuity)
{
  const double xi2 = 0.5;
  for (const AsLobe& lobe : kStressLobes)
  {
    // Axes at the exact quarter values.
    const glm::dvec3 h0 = aniso::sampleHalfVector(lobe, {0.0, xi2});
    const glm::dvec3 h1 = aniso::sampleHalfVector(lobe, {0.25, xi2});
    const glm::dvec3 h2 = aniso::sampleHalfVector(lobe, {0.5, xi2});
    const glm::dvec3 h3 = aniso::sampleHalfVector(lobe, {0.75, xi2});
    EXPECT_TRUE(h0.x > 0.0 && h0.y == 0.0) << describe(lobe);
    EXPECT_TRUE(h1.x == 0.0 && h1.y > 0.0) << describe(lobe);
    EXPECT_TRUE(h2.x < 0.0 && h2.y == 0.0) << describe(lobe);
    EXPECT_TRUE(h3.x == 0.0 && h3.y < 0.0) << describe(lobe);

    // Quadrant membership, including the values just below each quarter.
    std::vector<double> xis;
    for (int k = 0; k < 4; ++k)
    {
      const double start = 0.25 * k;
      const double end = 0.25 * (k + 1);
      for (double xi1 : {start, start + 1e-12, start + 0.1, std::nextafter(end, 0.0), end - 1e-12})
      {
        xis.push_back(xi1);
      }
    }
    for (double xi1 : xis)
    {
      const glm::dvec3 h = aniso::sampleHalfVector(lobe, {xi1, xi2});
      const int k = static_cast<int>(4.0 * xi1);
      const bool inQuadrant =
          (k == 0 && h.x > 0.0 && h.y >= 0.0) || (k == 1 && h.x <= 0.0 && h.y > 0.0) ||
          (k == 2 && h.x < 0.0 && h.y <= 0.0) || (k == 3 && h.x >= 0.0 && h.y < 0.0);
      EXPECT_TRUE(inQuadrant) << describe(lobe) << " xi1 = " << xi1 << " h = (" << h.x << ", "
                              << h.y << ", " << h.z << ")";
    }

    // Monotone and continuous over [0, 1), up to the wrap at 2 pi.
    const double ratio = std::sqrt((lobe.nu + 1.0) / (lobe.nv + 1.0));
    const int steps = 4096;
    const double bound = 2.0 * kPi * std::max(ratio, 1.0 / ratio) / steps * (1.0 + 1e-9);
    double previous = 0.0;
    for (int i = 1; i <= steps; ++i)
    {
      const double xi1 = i == steps ? kBelowOne : static_cast<double>(i) / steps;
      const double phi = azimuth(aniso::sampleHalfVector(lobe, {xi1, xi2}));
      ASSERT_GE(phi, previous) << describe(lobe) << " xi1 = " << xi1;
      ASSERT_LE(phi - previous, bound + 1e-12) << describe(lobe) << " xi1 = " << xi1;
      previous = phi;
    }
    EXPECT_GT(previous, 2.0 * kPi - bound - 1e-12) << describe(lobe);
  }
}

// 3c. invertHalfVector is the exact inverse: xi -> h -> xi returns xi (xi1 compared on the
// circle, where 0 and 1 meet), and an arbitrary unit h -> xi -> h returns h.
TEST(AshikhminShirley, InverseRoundTrips)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> xi1s = {0.0, 0.25, 0.5, 0.75, kBelowOne, 0.25 - 1e-12, 0.5 + 1e-12};
  std::vector<double> xi2s = {1e-12, 1e-6, 0.5, 1.0 - 1e-10, kBelowOne};
  for (int i = 0; i < 40; ++i)
  {
    xi1s.push_back(uniform(rng));
    xi2s.push_back(uniform(rng));
  }
  for (const AsLobe& lobe : kStressLobes)
  {
    for (double xi1 : xi1s)
    {
      for (double xi2 : xi2s)
      {
        const glm::dvec3 h = aniso::sampleHalfVector(lobe, {xi1, xi2});
        const glm::dvec2 back = aniso::invertHalfVector(lobe, h);
        ASSERT_GE(back.x, 0.0);
        ASSERT_LT(back.x, 1.0);
        ASSERT_GE(back.y, 0.0);
        ASSERT_LT(back.y, 1.0);
        const double d1 = std::abs(back.x - xi1);
        ASSERT_LT(std::min(d1, 1.0 - d1), 1e-10)
            << describe(lobe) << " xi = (" << xi1 << ", " << xi2 << ")";
        ASSERT_NEAR(back.y, xi2, 1e-10) << describe(lobe) << " xi = (" << xi1 << ", " << xi2 << ")";
      }
    }
    for (int i = 0; i < 200; ++i)
    {
      // Directions where xi2 = 1 - (n.h)^(e+1) is still resolved in double (at least 1e-6 from
      // 1): closer to the horizon every h rounds to xi2 = 1 - 2^-53 and cannot come back.
      const double logCos =
          std::log(1e-6 + (1.0 - 1e-6) * uniform(rng)) / (std::max(lobe.nu, lobe.nv) + 1.0);
      const double sinTheta = std::sqrt(-std::expm1(2.0 * logCos));
      const double phi = 2.0 * kPi * uniform(rng);
      const glm::dvec3 h(sinTheta * std::cos(phi), sinTheta * std::sin(phi), std::exp(logCos));
      const glm::dvec3 again = aniso::sampleHalfVector(lobe, aniso::invertHalfVector(lobe, h));
      ASSERT_LT(glm::length(again - h), 1e-9) << describe(lobe);
    }
  }
  // The pole has no azimuth: it maps to xi = (0, 0).
  EXPECT_EQ(aniso::invertHalfVector({100, 10}, {0.0, 0.0, 1.0}), glm::dvec2(0.0, 0.0));
}

// 4a. Reciprocity f_s(v, l) = f_s(l, v), and p_l = p_h(h) / (4 v.h) with h = (v + l)/|v + l|
// (the Jacobian of the reflection, docs/METHOD.md).
TEST(AshikhminShirley, ReciprocityAndLightPdf)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const glm::dvec3 f0(0.9, 0.5, 0.04);
  for (const AsLobe& lobe : kStressLobes)
  {
    for (int i = 0; i < 200; ++i)
    {
      const glm::dvec3 v = viewWithCosine(uniform(rng), 2.0 * kPi * uniform(rng));
      const glm::dvec3 l = viewWithCosine(uniform(rng), 2.0 * kPi * uniform(rng));
      const glm::dvec3 a = aniso::evalSpecular(lobe, f0, v, l);
      const glm::dvec3 b = aniso::evalSpecular(lobe, f0, l, v);
      for (int c = 0; c < 3; ++c)
      {
        ASSERT_NEAR(a[c], b[c], 1e-12 * std::max(1.0, std::abs(a[c]))) << describe(lobe);
      }
      const glm::dvec3 h = glm::normalize(v + l);
      const double expectedPdf = aniso::pdfHalfVector(lobe, h) / (4.0 * glm::dot(v, h));
      const double pdf = aniso::pdfLight(lobe, v, l);
      ASSERT_NEAR(pdf, expectedPdf, 1e-12 * std::max(1.0, expectedPdf)) << describe(lobe);

      // f_s itself from the formula of docs/METHOD.md, with Schlick's Fresnel written out.
      const double vh = glm::dot(v, h);
      const double fresnelWeight = std::pow(1.0 - vh, 5.0);
      const double ph = aniso::pdfHalfVector(lobe, h);
      for (int c = 0; c < 3; ++c)
      {
        const double expected =
            ph * (f0[c] + (1.0 - f0[c]) * fresnelWeight) / (4.0 * vh * std::max(v.z, l.z));
        ASSERT_NEAR(a[c], expected, 1e-10 * std::max(1.0, expected)) << describe(lobe);
      }
    }
  }
  // Below either horizon there is no reflection.
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const glm::dvec3 below = glm::normalize(glm::dvec3(0.3, 0.0, -0.2));
  EXPECT_EQ(aniso::evalSpecular({10, 10}, f0, up, below), glm::dvec3(0.0));
  EXPECT_EQ(aniso::evalSpecular({10, 10}, f0, below, up), glm::dvec3(0.0));
  // Schlick end points: F(1) = F0, F(0) = 1.
  EXPECT_EQ(aniso::schlickFresnel(f0, 1.0), f0);
  EXPECT_EQ(aniso::schlickFresnel(f0, 0.0), glm::dvec3(1.0));
}

// 4b. p_l is a density of l: its integral over the sphere of l, computed in coordinates centred on
// the mirror direction (so independent of the half-vector parametrisation), equals the mass of
// p_h over the half vectors with v.h > 0, computed over h. This checks the 1/(4 v.h) Jacobian.
TEST(AshikhminShirley, LightPdfIsADensity)
{
  int checkedViews = 0;
  const std::vector<AsLobe> lobes = {{10, 10}, {100, 10}, {1000, 1000}, {20000, 70}, {1e5, 1e5}};
  for (const AsLobe& lobe : lobes)
  {
    for (double cosView : {1.0, 0.99, 0.9, 0.75, 0.5, 0.1})
    {
      // p_l has an integrable 1/|v + l| singularity at l = -v, where h runs over the great circle
      // orthogonal to v. Views are kept where p_h on that circle, at most
      // C (sin theta_v)^min(n_u, n_v), is negligible, so that the quadrature needs no special
      // treatment there.
      const double scale = std::sqrt((lobe.nu + 1.0) * (lobe.nv + 1.0)) / (2.0 * kPi);
      const double sinView = std::sqrt(1.0 - cosView * cosView);
      if (cosView < 1.0 && scale * std::pow(sinView, std::min(lobe.nu, lobe.nv)) > 1e-10)
      {
        continue;
      }
      const glm::dvec3 v = viewWithCosine(cosView, 0.7);
      const glm::dvec3 mirror(-v.x, -v.y, v.z);
      const glm::dvec3 axisA = glm::normalize(glm::cross(mirror, glm::dvec3(0.6, 0.8, 0.0)));
      const glm::dvec3 axisB = glm::cross(mirror, axisA);
      // l = cos(beta) m + sin(beta)(cos(alpha) a + sin(alpha) b), 1 - cos(beta) = 2 e^-s over the
      // full sphere: dw = 2 e^-s ds dalpha.
      const auto overS = [&](double alpha)
      {
        const auto integrand = [&](double s)
        {
          const double w = 2.0 * std::exp(-s);
          const double sinBeta = std::sqrt(w * (2.0 - w));
          const glm::dvec3 l =
              (1.0 - w) * mirror + sinBeta * (std::cos(alpha) * axisA + std::sin(alpha) * axisB);
          return aniso::pdfLight(lobe, v, l) * w;
        };
        return integrate(integrand, 0.0, kTMax, 1e-12, 10);
      };
      const double overLight = integrate(overS, 0.0, 2.0 * kPi, 1e-9, 32);
      const double overHalf = integrateUpperHemisphere(
          [&](const glm::dvec3& h)
          { return glm::dot(v, h) > 0.0 ? aniso::pdfHalfVector(lobe, h) : 0.0; },
          1e-9);
      EXPECT_NEAR(overLight, overHalf, 1e-6) << describe(lobe) << " n.v = " << cosView;
      ++checkedViews;
      // Half vectors with v.h < 0 reflect nothing, so the mass can only be below 1 (equal at v =
      // n).
      EXPECT_LE(overHalf, 1.0 + 1e-6) << describe(lobe);
      if (cosView == 1.0)
      {
        EXPECT_NEAR(overHalf, 1.0, 1e-6) << describe(lobe);
      }
    }
  }
  EXPECT_EQ(checkedViews, 17); // the normal for every lobe, oblique views for the sharper ones
}

// 4c. White furnace: with F0 = 1 the directional albedo int f_s (n.l) dw_l, written over half
// vectors with dw_l = 4 (v.h) dw_h, stays at or below 1 for every view down to grazing; at normal
// incidence on an isotropic lobe it equals the closed form
// (n+1) [2 (1 - 2^-(n+3)/2)/(n+3) - (1 - 2^-(n+1)/2)/(n+1)] (from l.z = 2 (n.h)^2 - 1).
TEST(AshikhminShirley, WhiteFurnace)
{
  const glm::dvec3 white(1.0);
  const auto albedo = [&](const AsLobe& lobe, const glm::dvec3& v)
  {
    return integrateUpperHemisphere(
        [&](const glm::dvec3& h)
        {
          const double vh = glm::dot(v, h);
          if (!(vh > 0.0))
          {
            return 0.0;
          }
          const glm::dvec3 l = aniso::reflectAbout(v, h);
          return aniso::evalSpecular(lobe, white, v, l).x * std::max(l.z, 0.0) * 4.0 * vh;
        },
        1e-7);
  };
  for (double n : {0.0, 1.0, 10.0, 1000.0, 1e6})
  {
    const double expected = (n + 1.0) * (2.0 * (1.0 - std::pow(2.0, -(n + 3.0) / 2.0)) / (n + 3.0) -
                                         (1.0 - std::pow(2.0, -(n + 1.0) / 2.0)) / (n + 1.0));
    EXPECT_NEAR(albedo({n, n}, {0.0, 0.0, 1.0}), expected, 1e-6) << "n = " << n;
  }
  for (const AsLobe& lobe :
       std::vector<AsLobe>{{0, 0}, {10, 10}, {100, 10}, {20000, 70}, {1e6, 10}})
  {
    for (double cosView : {1.0, 0.5, 0.1, 1e-3, 1e-6})
    {
      // Views along t and along b: the extremes of an anisotropic lobe.
      for (double azimuthAngle : {0.0, 0.5 * kPi})
      {
        const double a = albedo(lobe, viewWithCosine(cosView, azimuthAngle));
        EXPECT_LE(a, 1.0 + 1e-6) << describe(lobe) << " n.v = " << cosView;
        EXPECT_GE(a, 0.0) << describe(lobe) << " n.v = " << cosView;
      }
    }
  }
}

// 5. Stress grid: every exponent pair in {0, 1, 10, ..., 1e6}^2, views down to n.v = 1e-6 and xi
// on the edges of [0, 1)^2: sampled h is unit (to 1e-12) with h.z >= 0, and every density and
// BRDF value is finite and non-negative; log2 p_h is finite and agrees with log2 of p_h.
TEST(AshikhminShirley, StressGridStaysFinite)
{
  const std::vector<double> xi1s = {0.0, 1e-300, 0.125, std::nextafter(0.25, 0.0), 0.25,
                                    0.3, 0.5,    0.75,  std::nextafter(0.75, 1.0), kBelowOne};
  const std::vector<double> xi2s = {0.0,
                                    std::numeric_limits<double>::denorm_min(),
                                    1e-300,
                                    1e-16,
                                    0.5,
                                    1.0 - 1e-10,
                                    1.0 - 0x1.0p-53,
                                    kBelowOne};
  const glm::dvec3 f0(1.0, 0.5, 0.0);
  for (const AsLobe& lobe : kStressLobes)
  {
    for (double cosView : {1.0, 0.5, 0.1, 1e-2, 1e-3, 1e-6})
    {
      for (double azimuthAngle : {0.0, 0.25 * kPi, 0.5 * kPi})
      {
        const glm::dvec3 v = viewWithCosine(cosView, azimuthAngle);
        for (double xi1 : xi1s)
        {
          for (double xi2 : xi2s)
          {
            const glm::dvec3 h = aniso::sampleHalfVector(lobe, {xi1, xi2});
            const std::string where = describe(lobe) + " n.v = " + str(cosView) + " xi = (" +
                                      str(xi1) + ", " + str(xi2) + ")";
            ASSERT_TRUE(std::isfinite(h.x) && std::isfinite(h.y) && std::isfinite(h.z)) << where;
            ASSERT_LT(std::abs(glm::length(h) - 1.0), 1e-12) << where;
            ASSERT_GE(h.z, 0.0) << where;
            const double ph = aniso::pdfHalfVector(lobe, h);
            ASSERT_TRUE(std::isfinite(ph) && ph >= 0.0) << where;
            const double log2Ph = aniso::log2PdfHalfVector(lobe, h);
            ASSERT_TRUE(std::isfinite(log2Ph) && log2Ph >= aniso::kLog2PdfFloor) << where;
            if (ph > 1e-30)
            {
              ASSERT_NEAR(log2Ph, std::log2(ph), 1e-9 * std::max(1.0, std::abs(log2Ph))) << where;
            }
            const glm::dvec3 l = aniso::reflectAbout(v, h);
            const glm::dvec3 f = aniso::evalSpecular(lobe, f0, v, l);
            for (int c = 0; c < 3; ++c)
            {
              ASSERT_TRUE(std::isfinite(f[c]) && f[c] >= 0.0) << where;
            }
            const double pl = aniso::pdfLight(lobe, v, l);
            ASSERT_TRUE(std::isfinite(pl) && pl >= 0.0) << where;
          }
        }
      }
    }
  }
}

// Edge cases with known values: the exponent at the pole (0/0) is the mean of n_u and n_v, and
// just off the pole it is n_u cos^2 phi + n_v sin^2 phi even for subnormal tangent components;
// p_h at the pole is the normalisation constant; p_h vanishes below the horizon and log2 p_h
// floors there; at e = 0 the lobe is uniform up to the horizon (no pow(0, 0)).
TEST(AshikhminShirley, PoleHorizonAndExponentEdges)
{
  const AsLobe lobe{1e6, 10};
  EXPECT_EQ(aniso::asExponent(lobe, {0.0, 0.0, 1.0}), 0.5 * (1e6 + 10));
  const double phi = 0.3;
  for (double tiny : {1e-8, 1e-200, 1e-310})
  {
    const glm::dvec3 h(tiny * std::cos(phi), tiny * std::sin(phi), 1.0);
    EXPECT_NEAR(aniso::asExponent(lobe, h), exponentAt(lobe, phi), 1e-9 * 1e6) << tiny;
  }
  const double scale = std::sqrt((1e6 + 1.0) * 11.0) / (2.0 * kPi);
  EXPECT_NEAR(aniso::pdfHalfVector(lobe, {0.0, 0.0, 1.0}), scale, 1e-12 * scale);
  EXPECT_NEAR(aniso::log2PdfHalfVector(lobe, {0.0, 0.0, 1.0}), std::log2(scale), 1e-12);
  EXPECT_EQ(aniso::pdfHalfVector(lobe, {1.0, 0.0, 0.0}), 0.0);
  EXPECT_EQ(aniso::pdfHalfVector(lobe, {0.6, 0.0, -0.8}), 0.0);
  EXPECT_EQ(aniso::log2PdfHalfVector(lobe, {1.0, 0.0, 0.0}), aniso::kLog2PdfFloor);
  EXPECT_EQ(aniso::log2PdfHalfVector(lobe, {0.6, 0.0, -0.8}), aniso::kLog2PdfFloor);
  // Far from the pole a sharp lobe's density underflows; its log stays finite, floored.
  const glm::dvec3 wide = viewWithCosine(0.5, 0.0);
  EXPECT_EQ(aniso::pdfHalfVector(lobe, wide), 0.0);
  EXPECT_EQ(aniso::log2PdfHalfVector(lobe, wide), aniso::kLog2PdfFloor);
  // Moderately sharp: log2 p_h = log2 C + e log2(n.h), exactly representable where p_h underflows
  // only in float.
  const glm::dvec3 near = viewWithCosine(std::cos(0.01), 0.0);
  EXPECT_NEAR(aniso::log2PdfHalfVector(lobe, near),
              std::log2(scale) + 1e6 * std::log2(std::cos(0.01)), 1e-6);

  const AsLobe flat{0, 0};
  const glm::dvec3 grazing = viewWithCosine(1e-300, 1.0);
  EXPECT_DOUBLE_EQ(aniso::pdfHalfVector(flat, grazing), 1.0 / (2.0 * kPi));
  EXPECT_DOUBLE_EQ(aniso::pdfHalfVector(flat, {0.0, 0.0, 1.0}), 1.0 / (2.0 * kPi));
}

// Lobe validation reports the offending exponent by name.
TEST(AshikhminShirley, ValidateLobe)
{
  EXPECT_NO_THROW(aniso::validateLobe({0, 0}));
  EXPECT_NO_THROW(aniso::validateLobe({1e6, 1e6}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const AsLobe& bad : std::vector<AsLobe>{{-1, 10}, {1e6 + 1, 10}, {nan, 10}, {inf, 10}})
  {
    try
    {
      aniso::validateLobe(bad);
      FAIL() << "accepted n_u = " << bad.nu;
    }
    catch (const aniso::Error& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind("n_u: ", 0), 0u) << e.what();
    }
  }
  try
  {
    aniso::validateLobe({10, -0.5});
    FAIL() << "accepted n_v = -0.5";
  }
  catch (const aniso::Error& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("n_v: ", 0), 0u) << e.what();
  }
}
