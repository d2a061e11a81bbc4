#pragma once
// The bilinear, wrapping lookup every tiling map in the core uses (material maps, LEADR moments,
// microstructures), mirroring GL_REPEAT + GL_LINEAR: texel (x, y) is centred at
// u = (x + 0.5) / W, v = 1 - (y + 0.5) / H (image row 0 is the top, v = 1).
#include <cmath>
#include <cstdint>
#include <glm/vec2.hpp>

namespace aniso
{
// The four texels around (u, v) and their weights (wx[i] wy[j] for texel (x[i], y[j])).
struct BilinearTaps
{
  int x[2] = {0, 0};
  int y[2] = {0, 0};
  double wx[2] = {1.0, 0.0};
  double wy[2] = {1.0, 0.0};
};

// i modulo n in [0, n), for integral i of any size.
inline int wrapIndex(double i, int n)
{
  const int k = int(i - n * std::floor(i / n));
  return k >= n ? 0 : k; // i / n rounding up to an integer
}

// Taps for a width x height map at uv; non-finite or huge coordinates are reduced to one tile
// first (non-finite ones to 0). width, height >= 1.
inline BilinearTaps bilinearTaps(int width, int height, const glm::dvec2& uvIn)
{
  glm::dvec2 uv = uvIn;
  for (int k = 0; k < 2; ++k)
    uv[k] = std::isfinite(uv[k]) ? uv[k] - std::floor(uv[k]) : 0.0;
  const double fx = uv.x * width - 0.5;
  const double fy = (1.0 - uv.y) * height - 0.5;
  const double x0 = std::floor(fx);
  const double y0 = std::floor(fy);
  BilinearTaps taps;
  taps.x[0] = wrapIndex(x0, width);
  taps.x[1] = wrapIndex(x0 + 1.0, width);
  taps.y[0] = wrapIndex(y0, height);
  taps.y[1] = wrapIndex(y0 + 1.0, height);
  taps.wx[1] = fx - x0;
  taps.wx[0] = 1.0 - taps.wx[1];
  taps.wy[1] = fy - y0;
  taps.wy[0] = 1.0 - taps.wy[1];
  return taps;
}

// Integer hash (lowbias32) for procedural content and jitter: the same values on every machine,
// unlike the standard library's distributions.
inline std::uint32_t hash32(std::uint32_t x)
{
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// A uniform number in [0, 1) from a seed and two indices.
inline double hashedUniform(std::uint32_t seed, std::uint32_t a, std::uint32_t b = 0)
{
  return hash32(seed ^ hash32(a ^ hash32(b + 0x9e3779b9U))) * (1.0 / 4294967296.0);
}
} // namespace aniso
