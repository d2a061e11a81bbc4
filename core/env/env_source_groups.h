#pragma once
// The source part of an analysed environment (core/env/env_sources.h, the excess above T) as a
// few groups the renderer chooses between per pixel, so that a pixel's source samples go to the
// sources its lobe sees: the seven most powerful sources each a group of its own, every other
// source together the last (kMaxGroups in all). A source sample picks group g with probability
// q_g (the pixel's selection, lobeAwareSelection), then a texel of the group with probability
// proportional to its excess luminance power (a row of the group's texels by its power, then a
// texel of the row, so that the group's samples stratify in both directions as the whole
// environment's tables do), then a point of the texel's tent in (u, v) (the weight its centre
// has in the bilinear interpolation the excess is read with: one texel either side, wrapping
// in u, reflected at the poles). The samples' density is then the texels' probabilities
// interpolated as the excess is: per solid angle q_g x (bilinear excess luminance) / P_g up to
// the ratio of sin theta at the texels' centres and at the point (P_g the group's luminance
// power), so the excess over the density stays near P_g / q_g across a source of one colour,
// and the estimate integrates the image the reference does (bilinear), not its texels as
// constants. docs/METHOD.md, "The sources split off".
//
// Layout (shader tables): the rows, group after group, each group's from the top: rowY the grid
// row, rowCdf the cumulative probability within its group at the row's end (the group's last is
// 1), rowFirst and rowCount its entries; the entries, row after row in x order: entryTexel the
// texel index y W + x, entryCdf the cumulative probability within its row at the entry's end
// (the row's last is 1). Per texel of the grid: density (its probability within its group
// times W H / (2 pi^2), the density per solid angle of the tent's mass where sin theta = 1)
// and group (-1 outside the source part). The density at direction d is
// sum_k w_k q_{g_k} density_k / sin theta(d) over the four texels of d's bilinear
// interpolation (weights w_k).
#include "core/env/env_sources.h"
#include "core/env/environment.h"

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
struct SourceGroup
{
  glm::dvec3 direction{0.0, 0.0, 1.0}; // excess-power-weighted mean direction (unit, env coords)
  double angularRadius = 0.0;          // largest angle from direction to where its samples reach
  double solidAngle = 0.0;             // of its texels
  double power = 0.0;                  // integral of the excess luminance over its texels
  double squaredPower = 0.0;           // integral of the excess luminance squared (L^2 sr)
  int firstRow = 0;                    // its rows: [firstRow, firstRow + rowCount)
  int rowCount = 0;
  int texels = 0;
};

struct SourceGroupSample
{
  glm::dvec3 direction{0.0, 0.0, 1.0}; // env coords, unit
  double pdf = 0.0;                    // per solid angle, the selection's
  int group = -1;
};

struct SourceGroups
{
  static constexpr int kMaxGroups = 8;

  int width = 0; // the analysis grid
  int height = 0;
  double power = 0.0;        // of the whole source part (luminance)
  double residualMean = 0.0; // mean luminance of the residual: (total - power) / (4 pi)
  std::vector<SourceGroup> groups;
  std::vector<int> rowY;
  std::vector<float> rowCdf;
  std::vector<int> rowFirst;
  std::vector<int> rowCount;
  std::vector<std::uint32_t> entryTexel;
  std::vector<float> entryCdf;
  // Guides (guidedSearch), one a row and one an entry: rowGuide[firstRow + k] the first row of
  // the group's run whose rowCdf exceeds k / rowCount, entryGuide[rowFirst + k] likewise within
  // the row's entries (absolute indices).
  std::vector<std::uint32_t> rowGuide;
  std::vector<std::uint32_t> entryGuide;
  std::vector<float> density;     // width x height
  std::vector<std::int8_t> group; // width x height

  // The CPU twin of the shader's source samples: a direction from xi in [0, 1)^2 (xi.x picks the
  // group by the selection's cumulative sum, then, rescaled, the texel of the row and the
  // column inside it; xi.y the row and the height inside the texel),
  // and its density under the selection (one weight per group, summing to 1). Density zero and
  // group -1 when the selected group is empty of power.
  SourceGroupSample sample(const std::vector<double>& selection, const glm::dvec2& xi) const;
  // Density per solid angle of sample() under the selection at direction d (env coords).
  double pdf(const std::vector<double>& selection, const glm::dvec3& d) const;
  // The selection in proportion to the groups' power alone.
  std::vector<double> powerSelection() const;
};

// The source technique shared by a frame's pixels (env-sampling sources, docs/METHOD.md "The
// sources split off"): COUNT points drawn by SourceGroups::sample under pointSelection, the
// same for every pixel of the frame, each with the excess radiance there (EXCESS: the analysis'
// excess as an equirectangular environment, read as the image interpolates it) and COUNT times
// its density. A pixel adds f (n.l) L / (N p_lobe(l) + density) for each, and its N lobe
// samples read the excess at weight N p_lobe / (N p_lobe + COUNT pdf) (multi-sample MIS,
// balance heuristic); what a point costs a pixel is one evaluation of its lobe, no texel read
// and no search. Point i of frame k is point k COUNT + i of Sobol's (0, 2)-sequence
// (sequenceColumns(1) and the radical inverse), its digits shifted by fixed constants: frames
// [0, 2^a) together stratify as one net when COUNT is a power of two, and no point lands on
// the edge of a tent (where the density is 0). The points come in the order they were drawn,
// each with its group (the material orders them by group: a pixel takes a group's run of
// points or leaves the group to its lobe samples).
struct SourcePoint
{
  glm::dvec3 direction{0.0, 0.0, 1.0}; // env coords, unit
  glm::dvec3 radiance{0.0};            // the excess there (RGB)
  double density = 0.0;                // COUNT x the selection's pdf; 0: the point adds nothing
  int group = -1;                      // the group it was drawn from
};
std::vector<SourcePoint> sourcePoints(const SourceGroups& groups,
                                      const std::vector<double>& selection,
                                      const Environment& excess, std::uint32_t frame, int count);

// The selection the shared points are drawn under: by power, with kPointUniformShare of it
// spread evenly over the groups (a lamp of 2% of the power keeps points where its lobe needs
// them; docs/BENCHMARKS.md, "Source points shared by a frame's pixels").
std::vector<double> pointSelection(const SourceGroups& groups);
constexpr double kPointUniformShare = 0.25;

// How many shared points a frame of N lobe samples draws: 8 N within [16, kMaxSourcePoints]
// (16 at one lobe sample, as while moving; 128 at the default 16).
constexpr int kMaxSourcePoints = 128;
int sourcePointCount(int lobeSamples);

// The first index i of the run [first, first + count) of cdf (cumulative ends, the last 1)
// with cdf[i] > u (the last when none), found from the run's guide: start at the guide of u's
// bin, k = floor(u count), one step back while the cell before already exceeds u (u count
// rounded up into the next bin), then forward. What a bisection finds, in one or two reads on
// average where a bisection takes log2(count) (the shader's anisoSourcePick).
std::size_t guidedSearch(const std::vector<float>& cdf, const std::vector<std::uint32_t>& guide,
                         int first, int count, float u);

// The groups of an analysis (its sourceRank and excess); none when it has no source part.
// Throws aniso::Error naming the analysis' key when its sourceRank does not cover its grid.
SourceGroups buildSourceGroups(const EnvAnalysis& analysis);

// A pixel's selection: group g weighs w_g = P_g min(p(l_g), 1 / solidAngle_g), where p is the
// lobe's density per solid angle (what the pixel's lobe samples draw) and l_g the direction of
// the group's cap (direction, angularRadius) nearest to the mirror direction (env coords): an
// upper bound of the share of the group's power the lobe's samples see, up to its colour. Then
// q_g = (1 - defensive) w_g / sum w + defensive P_g / sum P (all by power when sum w is 0), so
// that no group a lobe might see is left to the lobe samples alone.
std::vector<double> lobeAwareSelection(const SourceGroups& groups, const glm::dvec3& mirror,
                                       const std::function<double(const glm::dvec3&)>& lobePdf,
                                       double defensive);

// How much of what a pixel's lobe sees comes from groups smaller than the lobe: group g seen
// as w_g = P_g min(p(l_g), 1 / solidAngle_g) (lobeAwareSelection's weight), r_g = p(l_g)
// solidAngle_g (the group's solid angle against the lobe's, where the lobe reaches it), and
// share = sum_g w_g min(1 / r_g, 1) / (sum_g w_g + residualMean): a group the lobe fits inside
// (r > 1) is found by the lobe's own samples, a smaller one by the source samples. In [0, 1].
// (Also leaving out groups across which the lobe is flat, r below 0.01, was measured: no better
// at equal time, docs/BENCHMARKS.md.)
double smallSourceShare(const SourceGroups& groups, const glm::dvec3& mirror,
                        const std::function<double(const glm::dvec3&)>& lobePdf);

// Where a pixel's N lobe samples alone integrate the sources well enough to take no source
// samples (their MIS weight 1; the shader then also skips the lobe samples' MIS share): a lobe
// sample's estimate of the sources' light is L_s(l) times its AS weight (at most 1, up to
// colour), so its second moment is at most sum_g max_{cap g} p(l) integral_g L^2:
// lobeSourceSecondMoment, with boundPdf read at each cap's point nearest to the mirror
// direction. The shader reads the lobe's own density there, not the largest over the cap; the
// moment measured stays below 0.66 of that in every configuration test_env_source_groups
// draws (sharp, broad and anisotropic lobes 0-0.3 rad from lamps and a window). The lobe
// samples suffice where it is below noise^2 N (seen + residualMean)^2: the sources then add
// at most `noise` to the relative standard deviation of the pixel's N-sample estimate of its
// light (seen: lobeAwareSelection's sum of w_g).
double lobeSourceSecondMoment(const SourceGroups& groups, const glm::dvec3& mirror,
                              const std::function<double(const glm::dvec3&)>& boundPdf);
bool lobeSamplesSuffice(const SourceGroups& groups, const glm::dvec3& mirror,
                        const std::function<double(const glm::dvec3&)>& lobePdf,
                        const std::function<double(const glm::dvec3&)>& boundPdf, int lobeSamples,
                        double noise);

// The noise the renderer allows the sources where a pixel takes them by its lobe samples alone
// (lobeSamplesSuffice): 3% of its light at one frame's N samples (docs/BENCHMARKS.md, "Lobe
// samples alone where they suffice").
constexpr double kLobeOnlySourceNoise = 0.03;

// How many doublings of the base count a pixel may take: at most 2, and no more source samples
// than the lobe's own (one lobe sample, as while moving, takes one source sample).
int sourceSampleSteps(int base, int lobeSamples);

// A pixel's source samples per frame from its share: base x 2^k, k = round(log2(1 + 3 share))
// clamped to [0, maxSteps] (sourceSampleSteps), so 4 base when all it sees is such groups and
// two steps are allowed, base when it sees none. The shader's anisoSourceSelection.
int sourceSampleCount(double smallShare, int base, int maxSteps);
} // namespace aniso
