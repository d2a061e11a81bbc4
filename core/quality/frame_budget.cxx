#include "core/quality/frame_budget.h"

#include <algorithm>
#include <cmath>

namespace aniso
{
namespace
{
// Least squares of seconds = perRender + pixels (fixed + perSample samples) over MEASURED; false
// when the three columns are not independent (too few distinct pairs) or a part is negative.
bool fitThreeParts(const std::vector<FrameCostSample>& measured, FrameCostModel& model)
{
  // Normal equations in scaled units (megapixels), solved by Cramer's rule.
  double m[3][3] = {};
  double r[3] = {};
  for (const FrameCostSample& f : measured)
  {
    const double q = f.pixels * 1e-6;
    const double x[3] = {1.0, q, q * f.samples};
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        m[i][j] += x[i] * x[j];
      }
      r[i] += x[i] * f.seconds;
    }
  }
  const auto det = [](const double a[3][3])
  {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double d = det(m);
  // Relative to the diagonal's product: near 0 means a column is (almost) a mix of the others.
  if (!(std::fabs(d) > 1e-9 * m[0][0] * m[1][1] * m[2][2]))
  {
    return false;
  }
  double parts[3];
  for (int k = 0; k < 3; ++k)
  {
    double a[3][3];
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        a[i][j] = j == k ? r[i] : m[i][j];
      }
    }
    parts[k] = det(a) / d;
  }
  if (!(parts[0] >= 0.0 && parts[1] >= 0.0 && parts[2] >= 0.0))
  {
    return false;
  }
  model.perRender = parts[0];
  model.fixedPerPixel = parts[1] * 1e-6;
  model.perSamplePerPixel = parts[2] * 1e-6;
  return true;
}
} // namespace

FrameCostModel fitFrameCost(const std::vector<FrameCostSample>& all)
{
  std::vector<FrameCostSample> measured;
  for (const FrameCostSample& m : all)
  {
    if (m.pixels > 0.0 && m.seconds >= 0.0 && m.samples >= 1)
    {
      measured.push_back(m);
    }
  }
  bool twoSizes = false;
  bool twoCounts = false;
  for (const FrameCostSample& m : measured)
  {
    twoSizes = twoSizes || m.pixels != measured.front().pixels;
    twoCounts = twoCounts || m.samples != measured.front().samples;
  }
  if (twoSizes && twoCounts)
  {
    FrameCostModel model;
    if (fitThreeParts(measured, model))
    {
      model.known = true;
      model.separated = true;
      return model;
    }
  }
  // Sums for the fit of y = a + b x, x the sample count, y the seconds per pixel.
  double n = 0.0;
  double sx = 0.0;
  double sy = 0.0;
  double sxx = 0.0;
  double sxy = 0.0;
  for (const FrameCostSample& m : measured)
  {
    const double x = m.samples;
    const double y = m.seconds / m.pixels;
    n += 1.0;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  FrameCostModel model;
  if (n == 0.0)
  {
    return model;
  }
  model.known = true;
  if (!twoCounts)
  {
    // One count x: y = a + b x with a = b, so b = y / (1 + x).
    const double b = (sy / n) / (1.0 + measured.front().samples);
    model.fixedPerPixel = b;
    model.perSamplePerPixel = b;
    return model;
  }
  model.separated = true;
  const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double a = (sy - b * sx) / n;
  if (b < 0.0)
  {
    // More samples measured cheaper (noise, or one-off costs in a cheap frame): nothing to tell
    // the parts apart by, so the split assumed with one count, at the mean count: it
    // overestimates the cost of more samples, where "all of it fixed" would let a plan take
    // any number of samples for the price of one.
    const double b1 = (sy / n) / (1.0 + sx / n);
    model.fixedPerPixel = b1;
    model.perSamplePerPixel = b1;
  }
  else if (a < 0.0)
  {
    // All of it per sample: y = b x through the origin.
    model.perSamplePerPixel = sxy / sxx;
  }
  else
  {
    model.fixedPerPixel = a;
    model.perSamplePerPixel = b;
  }
  return model;
}

int runTotalSamples(int targetSamples, int samplesPerFrame)
{
  const int s = std::max(samplesPerFrame, 1);
  const int frames = (std::max(targetSamples, 1) + s - 1) / s;
  return frames * s;
}

int chooseFrameBands(const FrameCostModel& model, int samples, double pixels, double budgetSeconds,
                     int maxBands)
{
  const int most = std::max(maxBands, 1);
  if (!model.known || !(budgetSeconds > 0.0) || !(pixels > 0.0))
  {
    return 1;
  }
  for (int bands = 1; bands < most; ++bands)
  {
    if (model.predictSeconds(std::max(samples, 1), pixels / bands) <= budgetSeconds)
    {
      return bands;
    }
  }
  return most;
}

FramePlan chooseFramePlan(const FrameCostModel& model, double pixels, double budgetSeconds,
                          int maxSamples, int runTotal, int maxBands)
{
  const int most = std::max(maxSamples, 1);
  if (!model.known || !(budgetSeconds > 0.0) || !(pixels > 0.0))
  {
    return {most, 1};
  }
  FramePlan best{1, std::max(maxBands, 1)};
  double bestRate = 0.0;
  for (int samples = 1; samples <= most; ++samples)
  {
    if (samples != most && std::max(runTotal, 1) % samples != 0)
    {
      continue;
    }
    const int bands = chooseFrameBands(model, samples, pixels, budgetSeconds, maxBands);
    if (model.predictSeconds(samples, pixels / bands) > budgetSeconds)
    {
      continue; // not even in the most bands
    }
    const double frameSeconds = bands * model.perRender +
                                pixels * (model.fixedPerPixel + model.perSamplePerPixel * samples);
    const double rate = frameSeconds > 0.0 ? samples / frameSeconds : double(samples);
    if (rate > bestRate)
    {
      best = {samples, bands};
      bestRate = rate;
    }
  }
  return best;
}

double loadMargin(const std::vector<double>& measuredOverPredicted, double maxMargin)
{
  double margin = 1.0;
  for (const double r : measuredOverPredicted)
  {
    if (std::isfinite(r) && r > 0.0)
    {
      margin = std::max(margin, r);
    }
  }
  return std::min(margin, std::max(maxMargin, 1.0));
}

bool frameOverran(double measuredSeconds, double budgetSeconds, double tolerance)
{
  return budgetSeconds > 0.0 && measuredSeconds > budgetSeconds * (1.0 + std::max(tolerance, 0.0));
}

int largestDivisorAtMost(int total, int limit)
{
  const int t = std::max(total, 1);
  for (int s = std::min(limit, t); s > 1; --s)
  {
    if (t % s == 0)
    {
      return s;
    }
  }
  return 1;
}
} // namespace aniso
