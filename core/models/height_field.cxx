#include "core/models/height_field.h"

#include "core/error.h"
#include "core/models/texture_sampling.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace aniso
{
Image slopesFromHeight(const Image& height, double scale)
{
  if (height.width <= 0 || height.height <= 0 || height.channels <= 0 ||
      height.data.size() != std::size_t(height.width) * height.height * height.channels)
    throw errorAbout("height map", "empty or inconsistent image");
  if (!std::isfinite(scale))
    throw errorAbout("height map", "the height scale must be finite");
  for (int y = 0; y < height.height; ++y)
    for (int x = 0; x < height.width; ++x)
      if (!std::isfinite(height.at(x, y, 0)))
        throw errorAbout("height map", "texel (" + std::to_string(x) + ", " + std::to_string(y) +
                                           ") is not a finite number");
  const int w = height.width;
  const int h = height.height;
  Image slopes(w, h, 2);
  for (int y = 0; y < h; ++y)
  {
    const int up = (y + h - 1) % h;
    const int down = (y + 1) % h;
    for (int x = 0; x < w; ++x)
    {
      const int left = (x + w - 1) % w;
      const int right = (x + 1) % w;
      const double du = (double(height.at(right, y, 0)) - height.at(left, y, 0)) * 0.5 * w;
      const double dv = (double(height.at(x, up, 0)) - height.at(x, down, 0)) * 0.5 * h;
      slopes.at(x, y, 0) = float(scale * du);
      slopes.at(x, y, 1) = float(scale * dv);
    }
  }
  return slopes;
}

Image normalsFromSlopes(const Image& slopes)
{
  Image normals(slopes.width, slopes.height, 3);
  for (int y = 0; y < slopes.height; ++y)
  {
    for (int x = 0; x < slopes.width; ++x)
    {
      const glm::dvec3 n = normalOfSlope({slopes.at(x, y, 0), slopes.at(x, y, 1)});
      for (int c = 0; c < 3; ++c)
        normals.at(x, y, c) = float(n[c]);
    }
  }
  return normals;
}

glm::dvec2 slopeOfNormal(const glm::dvec3& n)
{
  const double z = std::max(n.z, 1e-6);
  return {-n.x / z, -n.y / z};
}

glm::dvec3 normalOfSlope(const glm::dvec2& slope)
{
  return glm::normalize(glm::dvec3(-slope.x, -slope.y, 1.0));
}
Image randomWaveHeight(int size, double slopeDeviation, int waves, int maxFrequency,
                       std::uint32_t seed)
{
  if (size < 4 || waves < 1 || maxFrequency < 1)
    throw errorAbout("wave relief", "needs a size of at least 4, one wave and a frequency");
  if (!std::isfinite(slopeDeviation) || slopeDeviation < 0.0)
    throw errorAbout("wave relief", "the slope deviation must be finite and >= 0");
  constexpr double kTwoPi = 6.283185307179586;
  struct Wave
  {
    double fx, fy, amplitude, phase;
  };
  std::vector<Wave> relief;
  const int choices = 2 * maxFrequency + 1;
  for (std::uint32_t k = 0; relief.size() < std::size_t(waves); ++k)
  {
    const double fx = std::floor(hashedUniform(seed, k, 0) * choices) - maxFrequency;
    const double fy = std::floor(hashedUniform(seed, k, 1) * choices) - maxFrequency;
    const double f = std::hypot(fx, fy);
    if (f >= 1.0)
      relief.push_back({fx, fy, 1.0 / f, kTwoPi * hashedUniform(seed, k, 2)});
  }
  // A wave of amplitude 1 / f has a gradient of length 2 pi and mean square (2 pi)^2 / 2, half
  // of it on each axis on average over directions.
  const double scale = slopeDeviation / std::sqrt(waves * kTwoPi * kTwoPi / 4.0);
  Image height(size, size, 1);
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      const double u = (x + 0.5) / size;
      const double v = 1.0 - (y + 0.5) / size;
      double h = 0.0;
      for (const Wave& w : relief)
        h += w.amplitude * std::sin(kTwoPi * (w.fx * u + w.fy * v) + w.phase);
      height.at(x, y, 0) = float(scale * h);
    }
  }
  return height;
}
} // namespace aniso
