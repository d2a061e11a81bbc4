#include "core/env/env_source_groups.h"

#include "core/env/environment.h"
#include "core/error.h"
#include "core/sampling/hammersley.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

double luminance(const Image& image, std::size_t i)
{
  return 0.2126 * image.data[i * 3] + 0.7152 * image.data[i * 3 + 1] +
         0.0722 * image.data[i * 3 + 2];
}

// Texel corner (x, y) of the grid, y = 0 at the zenith.
glm::dvec3 cornerDirection(double x, double y, int w, int h)
{
  return equirectToDirection({x / w, 1.0 - y / h});
}

// The guide of the run [first, first + count) of cdf, appended: cell k the first index whose
// cumulative end exceeds k / count.
void appendGuide(const std::vector<float>& cdf, int first, int count,
                 std::vector<std::uint32_t>& guide)
{
  int i = first;
  for (int k = 0; k < count; ++k)
  {
    const double bin = double(k) / double(count);
    while (i < first + count - 1 && !(double(cdf[std::size_t(i)]) > bin))
      ++i;
    guide.push_back(std::uint32_t(i));
  }
}

// The inverse of the tent's cumulative distribution on [-1, 1] at s in [0, 1].
double tentOffset(double s)
{
  return s < 0.5 ? std::sqrt(2.0 * s) - 1.0 : 1.0 - std::sqrt(2.0 * (1.0 - s));
}
} // namespace

SourceGroups buildSourceGroups(const EnvAnalysis& analysis)
{
  SourceGroups out;
  const int w = analysis.width;
  const int h = analysis.height;
  const std::size_t texels = std::size_t(w) * std::size_t(h);
  if (analysis.sourceRank.size() != texels || analysis.excess.data.size() != texels * 3)
    throw errorAbout(analysis.key, "the analysis' source ranks or excess do not cover its " +
                                       std::to_string(w) + "x" + std::to_string(h) + " grid");
  out.width = w;
  out.height = h;
  out.density.assign(texels, 0.0f);
  out.group.assign(texels, std::int8_t(-1));

  // A texel's probability as a density per solid angle where sin theta = 1 (docs above).
  const double texelsPerEquatorSr = double(w) * double(h) / (2.0 * kPi * kPi);
  std::vector<double> omega(std::size_t(std::max(h, 0)));
  for (int y = 0; y < h; ++y)
    omega[std::size_t(y)] = 2.0 * kPi / w * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));

  // Each texel's group: its source's rank, the ranks from kMaxGroups - 1 on together. Groups
  // with no excess power (a source of zero excess cannot exist, but guard) are dropped.
  int groupCount = 0;
  for (std::size_t i = 0; i < texels; ++i)
    if (analysis.sourceRank[i] >= 0 && luminance(analysis.excess, i) > 0.0)
      groupCount =
          std::max(groupCount, std::min(analysis.sourceRank[i], SourceGroups::kMaxGroups - 1) + 1);
  std::vector<SourceGroup> groups(static_cast<std::size_t>(groupCount));
  std::vector<glm::dvec3> weighted(groups.size(), glm::dvec3(0.0));
  std::vector<std::vector<std::uint32_t>> members(groups.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
    {
      const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
      const double lum = luminance(analysis.excess, i);
      if (analysis.sourceRank[i] < 0 || !(lum > 0.0))
        continue;
      const int g = std::min(analysis.sourceRank[i], SourceGroups::kMaxGroups - 1);
      const double power = lum * omega[std::size_t(y)];
      SourceGroup& group = groups[std::size_t(g)];
      group.power += power;
      group.squaredPower += lum * power;
      group.solidAngle += omega[std::size_t(y)];
      weighted[std::size_t(g)] += power * cornerDirection(x + 0.5, y + 0.5, w, h);
      members[std::size_t(g)].push_back(std::uint32_t(i));
      out.group[i] = std::int8_t(g);
    }

  // Keep the groups that hold texels (ranks are dense, but a rank's texels may all be zero).
  std::vector<int> renumber(groups.size(), -1);
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    if (members[g].empty())
      continue;
    SourceGroup group = groups[g];
    group.direction =
        glm::length(weighted[g]) > 0.0 ? glm::normalize(weighted[g]) : glm::dvec3(0.0, 0.0, 1.0);
    // Over the square its samples reach: one texel beyond each texel's centre.
    double minCos = 1.0;
    for (const std::uint32_t i : members[g])
    {
      const int x = int(i % std::uint32_t(w));
      const int y = int(i / std::uint32_t(w));
      for (int cy = 0; cy <= 1; ++cy)
        for (int cx = 0; cx <= 1; ++cx)
          minCos = std::min(
              minCos,
              glm::dot(group.direction,
                       cornerDirection(x - 0.5 + 2 * cx,
                                       std::clamp(y - 0.5 + 2 * cy, 0.0, double(h)), w, h)));
    }
    group.angularRadius = std::acos(std::clamp(minCos, -1.0, 1.0));
    group.firstRow = int(out.rowY.size());
    group.texels = int(members[g].size());
    double groupCumulative = 0.0;
    for (std::size_t m = 0; m < members[g].size();)
    {
      // One row: the members of grid row y, in x order (members are row-major).
      const int y = int(members[g][m] / std::uint32_t(w));
      std::size_t end = m;
      double rowPower = 0.0;
      while (end < members[g].size() && int(members[g][end] / std::uint32_t(w)) == y)
      {
        rowPower += luminance(analysis.excess, members[g][end]) * omega[std::size_t(y)];
        ++end;
      }
      out.rowY.push_back(y);
      out.rowFirst.push_back(int(out.entryTexel.size()));
      out.rowCount.push_back(int(end - m));
      double rowCumulative = 0.0;
      for (; m < end; ++m)
      {
        const std::uint32_t i = members[g][m];
        const double lum = luminance(analysis.excess, i);
        rowCumulative += lum * omega[std::size_t(y)];
        out.entryTexel.push_back(i);
        out.entryCdf.push_back(float(rowCumulative / rowPower));
        out.density[i] = float(lum * omega[std::size_t(y)] / group.power * texelsPerEquatorSr);
      }
      out.entryCdf.back() = 1.0f;
      appendGuide(out.entryCdf, out.rowFirst.back(), out.rowCount.back(), out.entryGuide);
      groupCumulative += rowPower;
      out.rowCdf.push_back(float(groupCumulative / group.power));
    }
    out.rowCdf.back() = 1.0f;
    group.rowCount = int(out.rowY.size()) - group.firstRow;
    appendGuide(out.rowCdf, group.firstRow, group.rowCount, out.rowGuide);
    renumber[g] = int(out.groups.size());
    out.power += group.power;
    out.groups.push_back(group);
  }
  out.residualMean = std::max(analysis.totalPower - out.power, 0.0) / (4.0 * kPi);
  for (std::size_t i = 0; i < texels; ++i)
    if (out.group[i] >= 0)
      out.group[i] = std::int8_t(renumber[std::size_t(out.group[i])]);
  return out;
}

std::vector<double> SourceGroups::powerSelection() const
{
  std::vector<double> selection(groups.size(), 0.0);
  for (std::size_t g = 0; g < groups.size(); ++g)
    selection[g] = power > 0.0 ? groups[g].power / power : 0.0;
  return selection;
}

SourceGroupSample SourceGroups::sample(const std::vector<double>& selection,
                                       const glm::dvec2& xi) const
{
  SourceGroupSample out;
  if (groups.empty())
    return out;
  const double u = std::clamp(xi.x, 0.0, 1.0);
  // The group whose share of [0, 1) holds u (the last non-empty one for rounding at the end).
  int g = -1;
  double start = 0.0;
  double cumulative = 0.0;
  for (int k = 0; k < int(groups.size()); ++k)
  {
    const double q = selection[std::size_t(k)];
    if (q > 0.0)
    {
      g = k;
      start = cumulative;
      if (u < cumulative + q)
        break;
    }
    cumulative += q;
  }
  const double q = selection[std::size_t(g)];
  const double within = std::clamp((u - start) / q, 0.0, 1.0);
  const SourceGroup& chosen = groups[std::size_t(g)];
  // The first row, then the first entry of the row, whose cumulative end exceeds the number.
  auto pick = [](const std::vector<float>& cdf, const std::vector<std::uint32_t>& guide, int first,
                 int count, double number, double* rest)
  {
    const std::size_t k = guidedSearch(cdf, guide, first, count, float(number));
    const double c0 = k == std::size_t(first) ? 0.0 : double(cdf[k - 1]);
    *rest = std::clamp((number - c0) / std::max(double(cdf[k]) - c0, 1e-30), 0.0, 1.0);
    return k;
  };
  double t = 0.0;
  const std::size_t row =
      pick(rowCdf, rowGuide, chosen.firstRow, chosen.rowCount, std::clamp(xi.y, 0.0, 1.0), &t);
  double s = 0.0;
  const std::size_t e = pick(entryCdf, entryGuide, rowFirst[row], rowCount[row], within, &s);
  const std::uint32_t texel = entryTexel[e];
  const int x = int(texel % std::uint32_t(width));
  const int y = int(texel / std::uint32_t(width));
  // A point of the texel's tent (the bilinear weight of its centre), wrapped in u, reflected
  // at the poles (where the clamped interpolation gives the edge row the weight of both).
  double gx = x + 0.5 + tentOffset(s);
  double gy = y + 0.5 + tentOffset(t);
  gx -= width * std::floor(gx / width);
  gy = gy < 0.0 ? -gy : gy > height ? 2.0 * height - gy : gy;
  out.direction = equirectToDirection({gx / width, 1.0 - gy / height});
  out.pdf = pdf(selection, out.direction);
  out.group = g;
  return out;
}

double SourceGroups::pdf(const std::vector<double>& selection, const glm::dvec3& d) const
{
  if (groups.empty() || !(glm::length(d) > 0.0))
    return 0.0;
  const glm::dvec3 unit = glm::normalize(d);
  const glm::dvec2 uv = directionToEquirect(unit);
  // The texels' densities interpolated as the excess is (bilinear, wrapping in u, clamped in
  // v), per unit of (u, v) area, then per solid angle.
  const double fx = uv.x * width - 0.5;
  const double fy = (1.0 - uv.y) * height - 0.5;
  const double x0 = std::floor(fx);
  const double y0 = std::floor(fy);
  const double a = fx - x0;
  const double b = fy - y0;
  double sum = 0.0;
  for (int j = 0; j <= 1; ++j)
    for (int k = 0; k <= 1; ++k)
    {
      const int x = int(x0 + k - width * std::floor((x0 + k) / width));
      const int y = std::clamp(int(y0) + j, 0, height - 1);
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      const int g = group[i];
      if (g >= 0)
        sum +=
            (k ? a : 1.0 - a) * (j ? b : 1.0 - b) * selection[std::size_t(g)] * double(density[i]);
    }
  const double sinTheta = std::sqrt(std::max(1.0 - unit.z * unit.z, 0.0));
  return sum > 0.0 ? sum / std::max(sinTheta, 1e-300) : 0.0;
}

namespace
{
// The lobe's density at the direction of the group's cap nearest to the mirror direction r.
double lobePdfAtCap(const SourceGroup& group, const glm::dvec3& r,
                    const std::function<double(const glm::dvec3&)>& lobePdf)
{
  const double cosAngle = std::clamp(glm::dot(group.direction, r), -1.0, 1.0);
  glm::dvec3 nearest = r;
  if (std::acos(cosAngle) > group.angularRadius)
  {
    const glm::dvec3 across = r - cosAngle * group.direction;
    const double length = glm::length(across);
    const glm::dvec3 side = length > 0.0 ? across / length : glm::dvec3(0.0);
    nearest =
        std::cos(group.angularRadius) * group.direction + std::sin(group.angularRadius) * side;
  }
  return lobePdf(nearest);
}
} // namespace

std::vector<SourcePoint> sourcePoints(const SourceGroups& groups,
                                      const std::vector<double>& selection,
                                      const Environment& excess, std::uint32_t frame, int count)
{
  std::vector<SourcePoint> points;
  if (groups.groups.empty() || count <= 0)
    return points;
  // Digital shifts of the two coordinates (XOR keeps every block a net).
  constexpr std::uint32_t kShiftX = 0x9E3779B9u;
  constexpr std::uint32_t kShiftY = 0x7F4A7C15u;
  const SequenceColumns& columns = sequenceColumns(1);
  points.reserve(std::size_t(count));
  for (int i = 0; i < count; ++i)
  {
    const std::uint32_t index = frame * std::uint32_t(count) + std::uint32_t(i);
    const std::uint32_t x = sequenceBits(index, columns) ^ kShiftX;
    const auto y = std::uint32_t(radicalInverse2(index) * 0x1.0p32) ^ kShiftY;
    const SourceGroupSample s = groups.sample(selection, {x * 0x1.0p-32, y * 0x1.0p-32});
    SourcePoint p;
    p.direction = s.direction;
    p.group = s.group;
    if (s.pdf > 0.0)
    {
      p.radiance = excess.radiance(s.direction);
      p.density = count * s.pdf;
    }
    points.push_back(p);
  }
  return points;
}

std::vector<double> pointSelection(const SourceGroups& groups)
{
  std::vector<double> selection = groups.powerSelection();
  const double n = double(selection.size());
  for (double& q : selection)
    q = (1.0 - kPointUniformShare) * q + kPointUniformShare / n;
  return selection;
}

int sourcePointCount(int lobeSamples)
{
  return std::clamp(8 * lobeSamples, 16, kMaxSourcePoints);
}

std::vector<double> lobeAwareSelection(const SourceGroups& groups, const glm::dvec3& mirror,
                                       const std::function<double(const glm::dvec3&)>& lobePdf,
                                       double defensive)
{
  const std::size_t n = groups.groups.size();
  std::vector<double> weight(n, 0.0);
  double sum = 0.0;
  const glm::dvec3 r = glm::normalize(mirror);
  for (std::size_t g = 0; g < n; ++g)
  {
    const SourceGroup& group = groups.groups[g];
    weight[g] = group.power * std::min(lobePdfAtCap(group, r, lobePdf), 1.0 / group.solidAngle);
    sum += weight[g];
  }
  std::vector<double> selection = groups.powerSelection();
  if (sum > 0.0)
    for (std::size_t g = 0; g < n; ++g)
      selection[g] = (1.0 - defensive) * weight[g] / sum + defensive * selection[g];
  return selection;
}

double smallSourceShare(const SourceGroups& groups, const glm::dvec3& mirror,
                        const std::function<double(const glm::dvec3&)>& lobePdf)
{
  double seen = 0.0;
  double small = 0.0;
  const glm::dvec3 r = glm::normalize(mirror);
  for (const SourceGroup& group : groups.groups)
  {
    const double pdf = lobePdfAtCap(group, r, lobePdf);
    if (!(pdf > 0.0))
      continue;
    const double w = group.power * std::min(pdf, 1.0 / group.solidAngle);
    seen += w;
    small += w * std::min(1.0 / (pdf * group.solidAngle), 1.0);
  }
  const double whole = seen + groups.residualMean;
  return whole > 0.0 ? small / whole : 0.0;
}

double lobeSourceSecondMoment(const SourceGroups& groups, const glm::dvec3& mirror,
                              const std::function<double(const glm::dvec3&)>& boundPdf)
{
  double secondMoment = 0.0;
  const glm::dvec3 r = glm::normalize(mirror);
  for (const SourceGroup& group : groups.groups)
    secondMoment += lobePdfAtCap(group, r, boundPdf) * group.squaredPower;
  return secondMoment;
}

bool lobeSamplesSuffice(const SourceGroups& groups, const glm::dvec3& mirror,
                        const std::function<double(const glm::dvec3&)>& lobePdf,
                        const std::function<double(const glm::dvec3&)>& boundPdf, int lobeSamples,
                        double noise)
{
  double seen = 0.0;
  const glm::dvec3 r = glm::normalize(mirror);
  for (const SourceGroup& group : groups.groups)
    seen += group.power * std::min(lobePdfAtCap(group, r, lobePdf), 1.0 / group.solidAngle);
  const double whole = seen + groups.residualMean;
  return lobeSourceSecondMoment(groups, r, boundPdf) <
         noise * noise * double(std::max(lobeSamples, 1)) * whole * whole;
}

int sourceSampleSteps(int base, int lobeSamples)
{
  int steps = 0;
  while (steps < 2 && (std::max(base, 1) << (steps + 1)) <= lobeSamples)
    ++steps;
  return steps;
}

int sourceSampleCount(double smallShare, int base, int maxSteps)
{
  const double share = std::clamp(smallShare, 0.0, 1.0);
  const int k = std::clamp(int(std::lround(std::log2(1.0 + 3.0 * share))), 0, maxSteps);
  return std::max(base, 1) << k;
}

std::size_t guidedSearch(const std::vector<float>& cdf, const std::vector<std::uint32_t>& guide,
                         int first, int count, float u)
{
  const int last = first + count - 1;
  const int k = std::clamp(int(u * float(count)), 0, count - 1);
  int i = int(guide[std::size_t(first + k)]);
  while (i > first && cdf[std::size_t(i - 1)] > u)
    --i;
  while (i < last && !(cdf[std::size_t(i)] > u))
    ++i;
  return std::size_t(i);
}
} // namespace aniso
