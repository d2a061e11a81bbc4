#include "core/quality/error_estimate.h"

#include "core/error.h"

#include <cmath>
#include <limits>
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

namespace
{
void checkMeans(const Image& mean, const Image& half)
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
}

double estimate(const Image& mean, const Image& half, const FrozenPixels* frozen)
{
  checkMeans(mean, half);
  const bool withFrozen = frozen && frozen->width == mean.width && frozen->height == mean.height &&
                          !frozen->mask.empty();
  double error = 0.0;
  double signal = 0.0;
  for (std::size_t p = 0; p + 3 < mean.data.size(); p += 4)
  {
    const double coverage = mean.data[p + 3];
    if (!(coverage > 0.0))
    {
      continue;
    }
    const bool still = withFrozen && frozen->mask[p / 4] != 0;
    for (std::size_t c = 0; c < 3; ++c)
    {
      const double m = mean.data[p + c];
      const double d = m - half.data[p + c];
      signal += coverage * m * m;
      error += still ? 0.0 : coverage * d * d;
    }
    if (still)
    {
      error += frozen->error[p / 4];
    }
  }
  if (!(signal > 0.0) || !std::isfinite(signal) || !std::isfinite(error))
  {
    return -1.0;
  }
  return std::sqrt(error / signal);
}
} // namespace

double estimatedRelativeError(const Image& mean, const Image& half)
{
  return estimate(mean, half, nullptr);
}

double estimatedRelativeError(const Image& mean, const Image& half, const FrozenPixels& frozen)
{
  return estimate(mean, half, &frozen);
}

int freezeConvergedPixels(const Image& mean, const Image& half, double target, FrozenPixels& frozen)
{
  checkMeans(mean, half);
  const int w = mean.width;
  const int h = mean.height;
  const std::size_t pixels = std::size_t(w) * h;
  if (frozen.width != w || frozen.height != h || frozen.mask.size() != pixels)
  {
    frozen = FrozenPixels{w, h, std::vector<unsigned char>(pixels, 0),
                          std::vector<float>(pixels, 0.0f), 0};
  }
  if (!(target > 0.0) || w < 3 || h < 3)
  {
    return 0;
  }
  // Each pixel's squared difference (coverage-weighed, as the estimate counts it), or its error
  // at freezing; and the mean signal of the covered pixels.
  std::vector<double> squared(pixels, 0.0);
  std::vector<unsigned char> full(pixels, 0);
  double signal = 0.0;
  int covered = 0;
  for (std::size_t i = 0; i < pixels; ++i)
  {
    const float* m = &mean.data[4 * i];
    const float* a = &half.data[4 * i];
    const double coverage = m[3];
    if (!(coverage > 0.0))
    {
      continue;
    }
    ++covered;
    full[i] = coverage >= 1.0 ? 1 : 0;
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      signal += coverage * double(m[c]) * m[c];
      d2 += coverage * (double(m[c]) - a[c]) * (double(m[c]) - a[c]);
    }
    squared[i] = frozen.mask[i] ? double(frozen.error[i]) : d2;
  }
  if (covered == 0 || !(signal > 0.0) || !std::isfinite(signal))
  {
    return 0;
  }
  const double level = kErrorStopShare * target;
  const double threshold = kFreezeShare * level * level * signal / covered;
  // A pixel's squared difference averaged over its 3 x 3 neighbourhood, where every pixel of it
  // is fully covered (else infinite: not to freeze).
  const auto windowed = [&](int x, int y)
  {
    if (x < 1 || y < 1 || x + 1 >= w || y + 1 >= h)
    {
      return std::numeric_limits<double>::infinity();
    }
    double sum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        const std::size_t j = std::size_t(y + dy) * w + (x + dx);
        if (!full[j])
        {
          return std::numeric_limits<double>::infinity();
        }
        sum += squared[j];
      }
    }
    return sum / 9.0;
  };
  // Tiles of kFreezeTile x kFreezeTile pixels aligned in GL's rows (from the bottom), frozen
  // whole: a software rasteriser shades blocks of pixels together and skips a block only when
  // every pixel of it is discarded. Tiles are disjoint and decided on SQUARED, which freezing
  // does not change: each is applied at once.
  int now = 0;
  std::vector<std::pair<std::size_t, double>> tile;
  for (int ty = 0; ty * kFreezeTile < h; ++ty)
  {
    for (int tx = 0; tx * kFreezeTile < w; ++tx)
    {
      bool all = true;
      tile.clear();
      for (int gy = ty * kFreezeTile; gy < std::min(h, (ty + 1) * kFreezeTile) && all; ++gy)
      {
        const int y = h - 1 - gy; // the image's row of GL row gy
        for (int x = tx * kFreezeTile; x < std::min(w, (tx + 1) * kFreezeTile); ++x)
        {
          const std::size_t i = std::size_t(y) * w + x;
          if (frozen.mask[i])
          {
            continue;
          }
          const double average = windowed(x, y);
          if (!(std::isfinite(average) && average < threshold))
          {
            all = false;
            break;
          }
          tile.emplace_back(i, average);
        }
      }
      if (!all)
      {
        continue;
      }
      for (const auto& [i, average] : tile)
      {
        frozen.mask[i] = 1;
        frozen.error[i] = static_cast<float>(average);
        ++now;
      }
    }
  }
  frozen.count += now;
  return now;
}
} // namespace aniso
