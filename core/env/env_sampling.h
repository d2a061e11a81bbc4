#pragma once
// Environment importance sampling: a piecewise-constant density over the sphere proportional to
// the environment's luminance (plus a small uniform part), on the texel grid of an
// equirectangular image (Blender's convention, see environment.h).
//
// Layout and why: texel (x, y) covers u in [x/W, (x+1)/W] and the polar band
// theta in [pi y/H, pi (y+1)/H] (row 0 at the zenith). A sample picks a row from the marginal
// CDF, a column from that row's conditional CDF, then a point uniform in (phi, cos theta) inside
// the texel, so the density per solid angle is constant on each texel (no 1/sin(theta) spike at
// the poles) and pdf(d) is a single table read. The same tables suit a shader: the CDFs as one
// R32F texture searched by bisection (about log2 W + log2 H texel fetches per sample) and the
// pdf as a W x H R32F texture (one fetch per direction). Sizes are whatever the caller bakes;
// 512 x 256 costs 0.5 MB per table.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/env/environment.h"
#include "core/image/image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

namespace aniso
{
struct EnvSamplingOptions
{
  int width = 512;               // grid columns; rows = width / 2. Even, in [2, 8192]
  int supersample = 4;           // radiance samples per texel side when baking from an environment
  double uniformFraction = 0.02; // share of samples spread uniformly over the sphere, in [0, 1]
};

// Texels of similar density grouped: their mean density and their total solid angle.
struct DensityLevel
{
  double density = 0.0;    // per unit solid angle
  double solidAngle = 0.0; // steradians
};

struct EnvSample
{
  glm::dvec3 direction{0.0, 0.0, 1.0}; // world, unit
  double pdf = 0.0;                    // per unit solid angle
};

class EnvironmentDistribution
{
public:
  // From an equirectangular RGB image (or grey: channel 0) of texel-mean radiance; luminance is
  // 0.2126 R + 0.7152 G + 0.0722 B, negative values count as 0. density = (1 - f) L / (mean of L
  // over the sphere) / (4 pi) + f / (4 pi) with f = uniformFraction; an image with no positive
  // texel gives the uniform density. Throws aniso::Error naming the argument for an empty or
  // inconsistent image, a non-finite texel or f outside [0, 1]. key identifies the content
  // (see distributionKey).
  EnvironmentDistribution(const Image& equirect, double uniformFraction, std::string key);

  // Bakes env at options.width x options.width / 2 with renderEquirect (options.supersample^2
  // solid-angle-weighted samples per texel). Where the luminance within a 3 x 3 neighbourhood
  // spans more than a factor 2 (the edge of a small bright source, which the supersamples may
  // have only grazed, or a source smaller than a texel), texels are sampled again, up to 32 times
  // more densely per side (within 4 times the cost of the first pass). The sample spacing,
  // pi / height / supersample radians, must be below the radius of the smallest bright source
  // for the density to see it at all (the uniform part keeps the estimators unbiased either way,
  // but not efficient). Grids whose texels are about the size of the source (1024 x 512 for the
  // sun, 0.27 degrees) send most of the sun's samples onto it. Throws aniso::Error naming the
  // option out of range.
  static EnvironmentDistribution bake(const Environment& env, const EnvSamplingOptions& options);

  // Direction with density pdf(direction) from xi in [0, 1)^2 (clamped into it).
  EnvSample sample(const glm::dvec2& xi) const;
  // Density per unit solid angle of sample() at a direction (need not be unit; zero gives the
  // zenith's texel).
  double pdf(const glm::dvec3& direction) const;

  int width() const { return width_; }
  int height() const { return height_; }
  const std::string& key() const { return key_; }
  // The values the density takes over the sphere, in levels half an octave wide (ascending):
  // what the choice of the MIS split needs to know of the environment (misLobeFraction).
  const std::vector<DensityLevel>& densityLevels() const { return levels_; }

  // Shader tables. cdfTable(): (max(W, H) + 1) x (H + 1), one channel; image row y < H holds
  // the conditional CDF of grid row y (columns 0..W, from 0 to 1), row H the marginal CDF over
  // rows (columns 0..H, from 0 to 1); entries past either end are 1. pdfTable(): W x H, one
  // channel, the density per unit solid angle of each texel.
  Image cdfTable() const;
  Image pdfTable() const;

private:
  int width_ = 0;
  int height_ = 0;
  std::string key_;
  std::vector<double> marginal_;    // height + 1
  std::vector<double> conditional_; // height * (width + 1)
  std::vector<double> density_;     // width * height, per solid angle
  std::vector<DensityLevel> levels_;
};

// Share c of the lobe technique in one-sample MIS (each sample from the lobe with probability c,
// from the environment otherwise, weighted by f (n.l) / (c p_lobe + (1 - c) p_env)), chosen to
// minimise the second moment of that estimate summed over every orientation of the lobe against
// the environment, i.e. over the pixels of an image, with the integrand modelled as
// p_lobe p_env (a radiance proportional to the environment's density). Over uniformly random
// orientations the pair (p_lobe(x), p_env(y)) is independent, so the sum is the double integral
// of p_lobe(x)^2 p_env(y)^2 / (c p_lobe(x) + (1 - c) p_env(y)) over x and y: it needs only the
// values the two densities take (the lobe's from 64 of its own samples at normal view, the
// environment's from densityLevels), not where. A sun next to a broad lobe gets a small c (the
// pixels that reflect it dominate the error), soft light next to a sharp lobe a large one.
// Of the shares within 10% of the modelled minimum the largest is taken (the lobe's Hammersley
// points are stratified, which the model of independent samples does not credit), within
// [1/16, 15/16] so neither technique loses its density (a defensive mixture); any c in (0, 1)
// keeps the estimate unbiased.
double misLobeFraction(const AsLobe& lobe, const EnvironmentDistribution& distribution);

// Samples env into a width x height equirectangular image as bake does: renderEquirect with
// supersample^2 solid-angle-weighted samples per texel, then every texel whose 3 x 3
// neighbourhood spans more than a factor 2 in luminance sampled again, up to 32 times more
// densely per side, within 4 times the samples of the first pass. A source smaller than a texel
// keeps its power (the built-in sun-sky's within 1% at 1024 x 512). Throws as renderEquirect.
Image renderEquirectRefined(const Environment& env, int width, int height, int supersample);

// Cache key of a bake: the environment's key and every option that changes the tables.
std::string distributionKey(const std::string& environmentKey, const EnvSamplingOptions& options);

// Bakes once per distributionKey and process: later calls with the same key share the result
// while anyone holds it. Thread-safe.
std::shared_ptr<const EnvironmentDistribution>
sharedDistribution(const Environment& env, const EnvSamplingOptions& options);
} // namespace aniso
