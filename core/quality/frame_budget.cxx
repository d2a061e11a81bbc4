#include "quality/frame_budget.h"

#include <algorithm>
#include <cmath>

namespace aniso
{
FrameCostModel fitFrameCost(const std::vector<FrameCostSample>& measured)
{
  // Sums for the fit of y = a + b x, x the sample count, y the seconds per pixel.
  double n = 0.0;
  double sx = 0.0;
  double sy = 0.0;
  double sxx = 0.0;
  double sxy = 0.0;
  int firstSamples = 0;
  bool twoCounts = false;
  for (const FrameCostSample& m : measured)
  {
    if (!(m.pixels > 0.0) || !(m.seconds >= 0.0) || m.samples < 1)
    {
      continue;
    }
    const double x = m.samples;
    const double y = m.seconds / m.pixels;
    n += 1.0;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    if (firstSamples == 0)
    {
      firstSamples = m.samples;
    }
    twoCounts = twoCounts || m.samples != firstSamples;
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
    const double b = (sy / n) / (1.0 + firstSamples);
    model.fixedPerPixel = b;
    model.perSamplePerPixel = b;
    return model;
  }
  model.separated = true;
  const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double a = (sy - b * sx) / n;
  if (b < 0.0)
  {
    // More samples measured cheaper (noise): all of it fixed.
    model.fixedPerPixel = sy / n;
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

int chooseFrameSamples(const FrameCostModel& model, double pixels, double budgetSeconds,
                       int maxSamples, int runTotal)
{
  const int most = std::max(maxSamples, 1);
  if (!model.known || !(budgetSeconds > 0.0) || !(pixels > 0.0) ||
      model.predictSeconds(most, pixels) <= budgetSeconds)
  {
    return most;
  }
  int affordable = 1;
  if (model.perSamplePerPixel > 0.0)
  {
    const double room = budgetSeconds / pixels - model.fixedPerPixel;
    const double count = std::floor(room / model.perSamplePerPixel);
    affordable = static_cast<int>(std::clamp(count, 1.0, static_cast<double>(most)));
  }
  // The largest divisor of the run's total within reach: the run keeps its sample count.
  return largestDivisorAtMost(runTotal, affordable);
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
