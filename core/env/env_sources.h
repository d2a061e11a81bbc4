#pragma once
// Environment analysis: how concentrated an environment's power is, and where. Bright, small
// regions (suns, lamps, windows) are found as connected sets of texels of an equirectangular
// image whose luminance exceeds a threshold T; their light above T is split off as the
// environment's *source part*, the rest is the *residual*, whose luminance never exceeds T:
//
//   L(d) = residual(d) + excess(d),   excess = L (1 - T / Y) where Y > T, 0 elsewhere
//
// (Y the luminance 0.2126 R + 0.7152 G + 0.0722 B; the residual keeps each texel's colour at
// luminance T). The split is exact on the image, so a renderer that integrates the residual by
// lobe sampling (smooth now, safe to filter) and the excess by sampling the sources adds up to
// the whole environment: no bias, whatever T is. Texel layout as environment.h (row 0 at the
// zenith, texel (x, y) covers u in [x/W, (x+1)/W] and theta in [pi y/H, pi (y+1)/H]).
#include "core/env/environment.h"
#include "core/image/image.h"

#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

namespace aniso
{
struct EnvAnalysisOptions
{
  // Grid of the analysis when the environment is not an image (analytic environments are
  // sampled into one, more densely next to bright texels); images are analysed at their own
  // resolution when at most maxWidth wide, box-filtered down otherwise. Even, in [16, 8192].
  int width = 1024;
  int maxWidth = 4096;
  // A texel is part of a source when its luminance exceeds T = max(relativeThreshold x the
  // solid-angle-weighted median luminance, meanThreshold x the mean luminance). > 0.
  double relativeThreshold = 16.0;
  double meanThreshold = 2.0;
  // Sources listed (by power, the largest first); every texel above T is in the source part
  // whether listed or not. In [0, 64].
  int maxSources = 8;
};

// The rule (docs/METHOD.md, "Environment analysis"): a window covers 2e-3 sr or more; a smaller
// source is a lamp, but for the sun: the most powerful small source above the horizon
// (z > -0.05), when its peak exceeds 100 T and it carries 4 times the power of any other small
// source. A large region around a core above 400 T (a sun in a bright sky) is listed as its
// core (the texels above 16 T) and the rest.
enum class EnvSourceKind
{
  Sun,    // a small disc far brighter than the rest, above the horizon
  Lamp,   // a small bright region that is not the sun
  Window, // a large bright region (windows, panels, soft boxes)
};
const char* spelling(EnvSourceKind kind); // "sun", "lamp", "window"

struct EnvSource
{
  EnvSourceKind kind = EnvSourceKind::Lamp;
  glm::dvec3 direction{0.0, 0.0, 1.0}; // excess-power-weighted mean direction, unit, env coords
  double solidAngle = 0.0;             // steradians, of its texels
  double angularRadius = 0.0; // radians: largest angle from direction to a texel's corner
  glm::dvec3 radiance{0.0};   // mean excess radiance over its texels (RGB)
  glm::dvec3 power{0.0};      // integral of the excess over its texels (RGB), W / m^2 per sr*sr
  double powerShare = 0.0;    // its excess luminance power / the whole environment's
  double peakLuminance = 0.0; // of its brightest texel (the whole radiance, not the excess)
  int texels = 0;
};

struct EnvAnalysis
{
  std::string key; // the environment's key and the options (cache identity)
  int width = 0;   // of the analysed grid (height = width / 2)
  int height = 0;
  double totalPower = 0.0;    // integral of the luminance over the sphere
  double meanLuminance = 0.0; // totalPower / (4 pi)
  double medianLuminance = 0.0; // solid-angle weighted
  double threshold = 0.0;       // T
  // Share of the total power arriving from the brightest 1% of the sphere's solid angle: about
  // 0.01 for a uniform environment, near 1 under a sun.
  double concentration = 0.0;
  double sourcePowerShare = 0.0; // the source part's share of the total power (listed or not)
  std::vector<EnvSource> sources; // listed ones, by power, largest first
  // The split, on the analysed grid: excess + residual = the analysed image (RGB float).
  Image excess;
  Image residual;
  // Per texel of the grid (row-major): the rank by power of the connected set of texels above T
  // holding it (0 the most powerful, as `sources`; sets beyond maxSources keep their ranks),
  // -1 outside the source part. What the renderer's source groups are made of
  // (core/env/env_source_groups.h).
  std::vector<int> sourceRank;

  // True when a source is bright enough against the rest that lobe samples alone miss it: a
  // listed one whose peak reaches kConcentratedPeak x T and which carries at least
  // kConcentratedShare of the power. Two runs of `aniso bench --models hdri` set the bar
  // (docs/BENCHMARKS.md, "Real HDRIs right by default"): under Blender's courtyard (sunlit
  // windows of at most 35 T) lobe samples did better at every lobe, under its studio (soft
  // boxes of 164 T on black) the sources did at three of four; suns and lamps reach 449 T
  // (sunset) to thousands; the built-in studio's soft boxes 3 T. What `env-sampling auto` reads.
  static constexpr double kConcentratedPeak = 64.0;
  static constexpr double kConcentratedShare = 0.005;
  bool concentrated() const
  {
    for (const EnvSource& s : sources)
    {
      if (s.peakLuminance >= kConcentratedPeak * threshold && s.powerShare >= kConcentratedShare)
      {
        return true;
      }
    }
    return false;
  }
};

// Analyses an equirectangular RGB image of texel-mean radiance (1 or 2 channels: grey, beyond
// 3 only RGB), halved (solid-angle weighted) while wider than options.maxWidth. key names its
// content. Throws aniso::Error "key: reason" for an empty or inconsistent image
// (width != 2 height, or one that cannot be halved to maxWidth), a non-finite or negative
// texel, or options out of range (naming the option).
EnvAnalysis analyzeEquirect(const Image& equirect, const std::string& key,
                            const EnvAnalysisOptions& options = {});

// Analyses an environment: an EquirectEnvironment's image as it is (or box-filtered to
// maxWidth), any other (and an image that is not exactly 2:1) sampled at options.width x
// options.width / 2, texels next to a steep change of luminance sampled again more densely
// (renderEquirectRefined), so a sun smaller than a texel keeps its power (within 1% for the
// built-in sun-sky's; 0.02% measured).
EnvAnalysis analyzeEnvironment(const Environment& env, const EnvAnalysisOptions& options = {});

// Once per environment key and options per process: later calls share the result while anyone
// holds it (the dock's thumbnails, the view's bake and `aniso render` ask for the same).
// Thread-safe.
std::shared_ptr<const EnvAnalysis> sharedEnvironmentAnalysis(const Environment& env,
                                                             const EnvAnalysisOptions& options = {});

// The residual as an environment: env(d) - bilinear excess(d) (with the equirect
// environment's interpolation), which is the bilinear residual image itself for an
// EquirectEnvironment analysed at its own resolution, and may dip below zero right at the edge
// of an analytic source (the split stays exact in the integral). Key: env's + ":residual:" +
// the analysis key.
std::shared_ptr<Environment> residualEnvironment(std::shared_ptr<const Environment> env,
                                                 std::shared_ptr<const EnvAnalysis> analysis);
} // namespace aniso
