#pragma once
// LEADR mapping (Dupuy et al. 2013; docs/METHOD.md, source 3). A height or normal map is turned into
// the five moments of its slopes, E[x], E[y], E[x^2], E[y^2], E[xy], which average linearly: a
// box-filtered mip level (or a trilinear lookup) holds exactly the moments of all the fine
// texels it covers. Each texel's moments define a Gaussian distribution of slopes (mean slope and
// covariance, plus a base roughness), i.e. an anisotropic Beckmann microfacet distribution that
// need not be centred on the normal, so a distant, minified bumpy surface is shaded with the
// spread of normals it really has instead of their (flattened) average.
//
// Conventions: slopes are relative to the geometric shading frame (t = +X along +u, b = +Y,
// n = +Z), slope (x, y) <-> microfacet normal normalize(-x, -y, 1) (core/models/height_field.h).
// Masking is Smith's for the shifted Gaussian: along the azimuth of a direction w, the slopes
// are Gaussian with mean mu_w and deviation sigma_w, and
//   Lambda(w) = Lambda_Beckmann(a),  a = (cot(theta_w) - mu_w) / (sqrt(2) sigma_w),
// G1 = 1 / (1 + Lambda) for a > 0 and 0 when w is below the mean microsurface (a <= 0). This
// satisfies integral G1(v) (v.m)+ D(m) dm = v . (-mu_x, -mu_y, 1) exactly (the projected area of
// the mean surface). Lambda_Beckmann uses Walter's rational approximation unless stated.
// Specular: f = F(v.h) D(h) G1(v) G1(l) / (4 (n.v)(n.l)) with the geometric n, so that the
// average of f over fine texels is f with the averaged distribution (up to the masking terms).
#include "core/env/cubemap.h"
#include "core/env/environment.h"
#include "core/frame.h"
#include "core/image/image.h"
#include "core/lights/light.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
// E[x], E[y], E[x^2], E[y^2], E[xy] of the slopes under a texel.
struct SlopeMoments
{
  double x = 0.0;
  double y = 0.0;
  double xx = 0.0;
  double yy = 0.0;
  double xy = 0.0;
};

SlopeMoments momentsOfSlope(const glm::dvec2& slope);

// Mip chain of moments: levels[k] is a 5-channel float image (E[x], E[y], E[x^2], E[y^2],
// E[xy]; a renderer uploads it as an RGBA and an R texture). Level k+1 has max(1, W_k / 2) x
// max(1, H_k / 2) texels; its texel i covers the level-k texels [i W_k / W_k+1, (i+1) W_k /
// W_k+1) (three of them next to odd sizes) and holds the exact mean of all the level-0 texels
// under them, each with the same weight, down to 1 x 1.
struct LeadrMips
{
  std::vector<Image> levels;
};

// From a slope image (channels 0, 1 = dh/du, dh/dv). Throws aniso::Error "slope map: reason"
// for an empty image, fewer than 2 channels or a non-finite texel.
LeadrMips bakeLeadrFromSlopes(const Image& slopes);
// From a height map (slopesFromHeight, central differences with wrapping, times scale).
LeadrMips bakeLeadrFromHeight(const Image& height, double scale);
// From a tangent-space normal map (3 or 4 channels; integer formats decoded as 2 c - 1): slopes
// (-n.x / n.z, -n.y / n.z), n.z floored at 1e-6; zero or non-finite normals count as flat.
// Throws aniso::Error "normal map: reason".
LeadrMips bakeLeadrFromNormals(const Image& normals, bool integerEncoded);

// One texel of a level (no filtering); level, x and y must be in range.
SlopeMoments leadrTexel(const LeadrMips& mips, int level, int x, int y);
// Trilinear lookup with wrapping at (u, v) (row 0 at v = 1), lod clamped to the chain.
SlopeMoments sampleLeadr(const LeadrMips& mips, const glm::dvec2& uv, double lod);

// Gaussian slope statistics of a texel.
struct SlopeStatistics
{
  glm::dvec2 mean{0.0};
  double varX = 0.005; // slope variances (a Beckmann roughness alpha has variance alpha^2 / 2)
  double varY = 0.005;
  double covXY = 0.0;
};

// Roughness floor of the base distribution (a smaller one would make the covariance singular
// on flat texels).
constexpr double kLeadrMinAlpha = 1e-3;
constexpr double kLeadrMaxAlpha = 2.0;

// Mean = (E[x], E[y]); covariance = moments' covariance (variances floored at 0, correlation
// clamped to |rho| <= 0.999) plus the base Beckmann roughness alpha^2 / 2 on the diagonal.
// Throws aniso::Error "base roughness: reason" outside [kLeadrMinAlpha, kLeadrMaxAlpha].
SlopeStatistics slopeStatistics(const SlopeMoments& moments, double baseAlphaX, double baseAlphaY);

// What plain normal-map filtering gives: the slope of the renormalised average normal with the
// base roughness only (the baseline LEADR improves on).
SlopeStatistics statisticsFromAveragedNormal(const glm::dvec3& averagedNormal, double baseAlphaX,
                                             double baseAlphaY);

// Gaussian slope density P22(slope), integrating to 1 over the plane.
double slopeDensity(const SlopeStatistics& stats, const glm::dvec2& slope);
// D(m) = P22(slope of m) / (m.z)^4; integral D(m) (m.z) dm = 1 over the hemisphere. 0 for
// m.z <= 0.
double beckmannDistribution(const SlopeStatistics& stats, const glm::dvec3& m);

// Beckmann Lambda(a) for a > 0: exact (erfc) and Walter's rational approximation
// (1 - 1.259 a + 0.396 a^2) / (3.535 a + 2.181 a^2) for a < 1.6, 0 beyond.
double beckmannLambdaExact(double a);
double beckmannLambdaWalter(double a);
// a of direction w (unit) for the distribution (see the header comment); +infinity at normal
// incidence (|w.xy| = 0), <= 0 at or below the mean microsurface's horizon.
double maskingParameter(const SlopeStatistics& stats, const glm::dvec3& w);
// G1(w); 0 for w.z <= 0 or a <= 0.
double leadrMasking(const SlopeStatistics& stats, const glm::dvec3& w, bool exactLambda = false);

// Specular f(v, l) (Schlick Fresnel per channel); zero below either geometric horizon.
glm::dvec3 evalLeadrSpecular(const SlopeStatistics& stats, const glm::dvec3& f0,
                             const glm::dvec3& v, const glm::dvec3& l);

// Silhouettes. Where the view grazes the mean microsurface (or falls below it), G1(v) -> 0, and
// where the mean microfacet mirrors the view into the surface, every reflected direction lies
// below the horizon: the pixel turns black although the geometry is visible. The artificial
// micronormal moves the mean slope along the view's azimuth, towards the viewer, just enough
// that (1) the view stays kSilhouetteMinA deviations above the mean microsurface's horizon and
// (2) the mirror direction of the view about the mean normal stays above the geometric horizon
// (theta_v + 2 beta <= 90 degrees for a mean tilt beta away from the viewer; mean slopes across
// the view plane count up to 1). Otherwise the statistics are unchanged, so the result is
// continuous; away from silhouettes filtered levels (whose mean slopes are small) are untouched.
// A view at or below the geometric horizon (interpolated normals facing away) is first lifted
// to kSilhouetteMinViewCosine above it, keeping its azimuth.
constexpr double kSilhouetteMinA = 0.25;
constexpr double kSilhouetteMinViewCosine = 1e-3;
glm::dvec3 liftedView(const glm::dvec3& v);
SlopeStatistics withSilhouetteMicronormal(const SlopeStatistics& stats, const glm::dvec3& v);

// The slope-space grid: n x n points of equal probability 1/n^2, at the standard-normal
// quantiles z_i = Phi^-1((i + 0.5) / n) on each axis, mapped to slopes by mean + L z with L the
// Cholesky factor of the covariance. n in [1, 64]; otherwise aniso::Error "slope grid: reason".
struct SlopeGrid
{
  int n = 0;
  std::vector<double> quantiles; // z_i, ascending
};
SlopeGrid makeSlopeGrid(int n);
// The grid of the still view's progressive frame k: quantiles Phi^-1((i + s)/n) on each axis,
// s = slopeGridShift(k) per axis (u = (i + s)/n kept in [2^-24, 1 - 2^-24]). Frame 0 is the
// centred grid above (s = 0.5); frame k > 0 is it moved by the R2 sequence's point k
// (core/sampling/hammersley.h frameShift, mod 1), so that the frames' points fill each of the
// n x n cells evenly and their mean converges to the integral over the slope distribution,
// where the one grid under a jittered camera only averages its own quadrature (docs/METHOD.md,
// "LEADR's frames"). (The dyadic points of a (0,2)-sequence would put one frame's first point
// at u = 0, the distribution's far tail, and every point at its stratum's lower end.)
glm::dvec2 slopeGridShift(uint32_t frame);
SlopeGrid makeShiftedSlopeGrid(int n, double shift);
// Phi^-1(p) for p in (0, 1) (Acklam's approximation refined by one Halley step, ~1e-15).
double inverseNormalCdf(double p);
glm::dvec2 gridSlope(const SlopeStatistics& stats, double z1, double z2);

struct LeadrMaterial
{
  glm::dvec3 diffuse{0.0}; // rho_d in [0, 1]
  glm::dvec3 f0{0.04};     // in [0, 1]
  double baseAlphaX = 0.1; // base Beckmann roughness added to every texel's statistics
  double baseAlphaY = 0.1;
};

// Point and directional lights: per light, (f_spec(v, l) (n.l) + rho_d / pi mean over the grid
// of (m.l)+) E, i.e. the rough diffuse is the average Lambert term over the texel's normals.
// View lifted and micronormal applied first; lights below the geometric horizon are skipped.
glm::dvec3 shadeLeadr(const LeadrMaterial& material, const SlopeStatistics& stats,
                      const Frame& frame, const glm::dvec3& position, const glm::dvec3& viewWorld,
                      const std::vector<Light>& lights, const SlopeGrid& grid);

// Environment specular on the slope grid: each grid slope gives a microfacet normal m and
// l = reflect(v, m); with equal probabilities the reflected radiance is
//   (1/n^2) sum F(v.m) G1(v) G1(l) L(l) (v.m) / ((n.v)(n.m))   over (v.m) > 0, l.z > 0.
// This version reads the environment directly (the CPU reference).
glm::dvec3 leadrEnvironmentSpecular(const SlopeStatistics& stats, const glm::dvec3& f0,
                                    const Frame& frame, const glm::dvec3& viewWorld,
                                    const Environment& env, const SlopeGrid& grid);

// The same sum with each sample read from a prefiltered cubemap at the level whose texels cover
// the solid angle the sample stands for, Omega = 4 (v.m) / (n^2 D(m) (m.z)):
//   lod = 0.5 log2(Omega / Omega_0),  Omega_0 = 4 pi / (6 size^2),  clamped to the chain.
glm::dvec3 leadrEnvironmentSpecular(const SlopeStatistics& stats, const glm::dvec3& f0,
                                    const Frame& frame, const glm::dvec3& viewWorld,
                                    const Cubemap& cube, const SlopeGrid& grid);
double leadrSampleLod(const SlopeStatistics& stats, const glm::dvec3& v, const glm::dvec3& m,
                      int gridN, int cubeSize);

// Rough diffuse under the environment: rho_d / pi times the SH9 irradiance averaged over the
// grid's normals (world space), negative irradiance (ringing) clamped to 0.
glm::dvec3 leadrEnvironmentDiffuse(const SlopeStatistics& stats, const glm::dvec3& diffuse,
                                   const Frame& frame, const Sh9& sh, const SlopeGrid& grid);

// textureLod on a Cubemap: bilinear inside the face (clamped to its edge texels; no filtering
// across faces), linear between the two nearest levels; lod clamped to [0, levels - 1].
glm::dvec3 sampleCubemap(const Cubemap& cube, const glm::dvec3& d, double lod);
} // namespace aniso
