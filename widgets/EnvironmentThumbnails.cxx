#include "widgets/EnvironmentThumbnails.h"

#include "core/env/environment.h"
#include "core/error.h"
#include "widgets/ParameterControls.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace aniso
{
namespace
{
float channel(const Image& image, int x, int y, int c)
{
  // Grey images spread to RGB; a missing channel of a two-channel (grey + alpha) image too.
  const int source = image.channels >= 3 ? c : 0;
  const float v = image.at(x, y, source);
  return std::isfinite(v) && v > 0.0f ? v : 0.0f;
}

double aces(double x)
{
  return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
} // namespace

Image toneMappedThumbnail(const Image& hdr, int width)
{
  if (hdr.empty() || hdr.width < 1 || hdr.height < 1 || hdr.channels < 1)
  {
    throw errorAbout("thumbnail", "empty image");
  }
  const int w = std::clamp(width, 1, hdr.width);
  const int h = std::clamp(w / 2, 1, hdr.height);
  Image small(w, h, 3);
  for (int y = 0; y < h; ++y)
  {
    const int y0 = y * hdr.height / h;
    const int y1 = std::max(y0 + 1, (y + 1) * hdr.height / h);
    for (int x = 0; x < w; ++x)
    {
      const int x0 = x * hdr.width / w;
      const int x1 = std::max(x0 + 1, (x + 1) * hdr.width / w);
      double sum[3] = {0.0, 0.0, 0.0};
      for (int sy = y0; sy < y1; ++sy)
      {
        for (int sx = x0; sx < x1; ++sx)
        {
          for (int c = 0; c < 3; ++c)
          {
            sum[c] += channel(hdr, sx, sy, c);
          }
        }
      }
      const double n = double(x1 - x0) * double(y1 - y0);
      for (int c = 0; c < 3; ++c)
      {
        small.at(x, y, c) = static_cast<float>(sum[c] / n);
      }
    }
  }
  // Reinhard's log-average luminance; the small offset keeps black texels finite.
  double logSum = 0.0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const double luminance =
          0.2126 * small.at(x, y, 0) + 0.7152 * small.at(x, y, 1) + 0.0722 * small.at(x, y, 2);
      logSum += std::log(1e-4 + luminance);
    }
  }
  const double average = std::exp(logSum / (double(w) * h));
  const double exposure = 0.18 / average;
  for (float& v : small.data)
  {
    v = static_cast<float>(linearToSrgb(aces(exposure * v)));
  }
  return small;
}

QImage toQImage(const Image& rgb)
{
  QImage image(rgb.width, rgb.height, QImage::Format_RGB888);
  for (int y = 0; y < rgb.height; ++y)
  {
    uchar* line = image.scanLine(y);
    for (int x = 0; x < rgb.width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const float v = rgb.channels >= 3 ? rgb.at(x, y, c) : rgb.at(x, y, 0);
        line[3 * x + c] = static_cast<uchar>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
      }
    }
  }
  return image;
}

QImage environmentThumbnail(const std::string& spec, int width)
{
  if (spec.rfind("builtin:", 0) == 0)
  {
    const std::shared_ptr<Environment> env = openEnvironment(spec);
    const int w = std::max(width, 2);
    return toQImage(toneMappedThumbnail(renderEquirect(*env, w, w / 2, 1), w));
  }
  return toQImage(toneMappedThumbnail(readImage(spec), width));
}
} // namespace aniso
