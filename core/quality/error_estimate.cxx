#include "core/quality/error_estimate.h"

#include "core/error.h"

#include <cmath>
#include <string>

namespace aniso
{
bool isErrorSnapshot(int frames)
{
  if (frames < 2)
  {
    return false;
  }
  const int odd = frames % 3 == 0 ? frames / 3 : frames;
  return (odd & (odd - 1)) == 0; // a power of two
}

bool isErrorCheckpoint(int frames)
{
  return frames >= 4 && isErrorSnapshot(frames);
}

int minimumErrorStopFrames(int samplesPerFrame)
{
  const int s = samplesPerFrame > 0 ? samplesPerFrame : 1;
  return (kMinimumErrorStopSamples + s - 1) / s;
}

bool errorTargetReached(double estimate, double target)
{
  return estimate >= 0.0 && target > 0.0 && estimate <= kErrorStopShare * target;
}

double estimatedRelativeError(const Image& mean, const Image& half)
{
  if (mean.channels != 4 || half.channels != 4)
  {
    throw errorAbout("error estimate", "the means need four channels (RGBA)");
  }
  if (mean.width != half.width || mean.height != half.height)
  {
    throw errorAbout("error estimate",
                     "the mean is " + std::to_string(mean.width) + "x" +
                         std::to_string(mean.height) + " and the mean of its first half " +
                         std::to_string(half.width) + "x" + std::to_string(half.height));
  }
  double error = 0.0;
  double signal = 0.0;
  for (std::size_t p = 0; p + 3 < mean.data.size(); p += 4)
  {
    const double coverage = mean.data[p + 3];
    if (!(coverage > 0.0))
    {
      continue;
    }
    for (std::size_t c = 0; c < 3; ++c)
    {
      const double m = mean.data[p + c];
      const double d = m - half.data[p + c];
      signal += coverage * m * m;
      error += coverage * d * d;
    }
  }
  if (!(signal > 0.0) || !std::isfinite(signal) || !std::isfinite(error))
  {
    return -1.0;
  }
  return std::sqrt(error / signal);
}
} // namespace aniso
