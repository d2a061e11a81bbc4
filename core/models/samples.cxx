#include "core/models/samples.h"

#include "core/error.h"
#include "core/models/height_field.h"
#include "core/models/texture_sampling.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

double smooth5(double t)
{
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

// Value noise on a period x period lattice over the unit tile (so it tiles), in [0, 1].
double valueNoise(double u, double v, int period, std::uint32_t seed)
{
  const double x = u * period;
  const double y = v * period;
  const double x0 = std::floor(x);
  const double y0 = std::floor(y);
  const double ax = smooth5(x - x0);
  const double ay = smooth5(y - y0);
  auto lattice = [&](double i, double j)
  {
    const auto wi = std::uint32_t(((long long)(i) % period + period) % period);
    const auto wj = std::uint32_t(((long long)(j) % period + period) % period);
    return hashedUniform(seed, wi, wj);
  };
  const double a = lattice(x0, y0) + ax * (lattice(x0 + 1, y0) - lattice(x0, y0));
  const double b = lattice(x0, y0 + 1) + ax * (lattice(x0 + 1, y0 + 1) - lattice(x0, y0 + 1));
  return a + ay * (b - a);
}

// Fractal sum of value noise, octaves doubling in frequency and halving in weight; in [0, 1].
double fbm(double u, double v, int basePeriod, int octaves, std::uint32_t seed)
{
  double sum = 0.0;
  double weight = 0.5;
  double total = 0.0;
  for (int o = 0; o < octaves; ++o)
  {
    sum += weight * valueNoise(u, v, basePeriod << o, seed + std::uint32_t(o) * 7919U);
    total += weight;
    weight *= 0.5;
  }
  return sum / total;
}

void checkSize(const char* what, int size)
{
  if (!(size >= 16 && size <= 4096))
    throw errorAbout(what, "size must be in [16, 4096] (got " + std::to_string(size) + ")");
}

void setTexel(SvMaps& maps, int x, int y, const glm::dvec2& tangent, double ax, double ay,
              const glm::dvec3& diffuse, double specular)
{
  maps.tangentAlpha.at(x, y, 0) = float(tangent.x);
  maps.tangentAlpha.at(x, y, 1) = float(tangent.y);
  maps.tangentAlpha.at(x, y, 2) = float(ax);
  maps.tangentAlpha.at(x, y, 3) = float(ay);
  for (int c = 0; c < 3; ++c)
    maps.albedoSpecular.at(x, y, c) = float(diffuse[c]);
  maps.albedoSpecular.at(x, y, 3) = float(specular);
}

SvMaps allocate(int size)
{
  SvMaps maps;
  maps.tangentAlpha = Image(size, size, 4);
  maps.albedoSpecular = Image(size, size, 4);
  maps.height = Image(size, size, 1);
  return maps;
}
} // namespace

SvTexel brushedMetal(BrushDirection direction)
{
  SvTexel texel;
  texel.tangent =
      direction == BrushDirection::Latitudinal ? glm::dvec2(1.0, 0.0) : glm::dvec2(0.0, 1.0);
  texel.alphaX = 0.05;
  texel.alphaY = 0.35;
  texel.diffuse = glm::dvec3(0.02);
  texel.specular = 0.9;
  return texel;
}

SvMaps scratchedPlate(int size, std::uint32_t seed)
{
  checkSize("scratched plate", size);
  constexpr int kScratchesPerAxis = 50;
  constexpr double kBaseAlpha = 0.08;
  constexpr double kAlongAlpha = 0.03;
  constexpr double kAcrossAlpha = 0.4;
  // Strongest scratch profile at each texel (0 outside scratches) and its axis.
  std::vector<double> strength(std::size_t(size) * size, 0.0);
  std::vector<double> depth(std::size_t(size) * size, 0.0);
  std::vector<unsigned char> alongV(std::size_t(size) * size, 0);
  for (int s = 0; s < 2 * kScratchesPerAxis; ++s)
  {
    const bool vertical = s >= kScratchesPerAxis;
    const auto id = std::uint32_t(s);
    const double start = hashedUniform(seed, id, 1);                          // along the scratch
    const double length = 0.1 + 0.4 * hashedUniform(seed, id, 2);             // tile fraction
    const double offset = hashedUniform(seed, id, 3);                         // across the scratch
    const double halfWidth = (1.0 + 1.5 * hashedUniform(seed, id, 4)) / size; // 1 to 2.5 texels
    const double groove = (0.2 + 0.8 * hashedUniform(seed, id, 5)) * 0.5 / size;
    const int steps = int(std::ceil(length * size));
    const int across = int(std::ceil(halfWidth * size)) + 1;
    for (int i = 0; i <= steps; ++i)
    {
      const double along = start + length * i / std::max(steps, 1);
      // Tapered ends: the scratch fades in over its first and last tenth.
      const double taper = std::min(1.0, std::min(i, steps - i) / (0.1 * steps + 1.0));
      const int centre = int(std::floor(offset * size));
      for (int k = -across; k <= across; ++k)
      {
        const int c = ((centre + k) % size + size) % size;
        const double dist = std::abs((centre + k + 0.5) / size - offset) / halfWidth;
        const double profile = std::max(0.0, 1.0 - dist * dist) * taper;
        if (profile <= 0.0)
          continue;
        const int a = (int(std::floor(along * size)) % size + size) % size;
        const int x = vertical ? c : a;
        const int y = vertical ? a : c;
        const std::size_t index = std::size_t(y) * size + x;
        if (profile > strength[index])
        {
          strength[index] = profile;
          alongV[index] = vertical ? 1 : 0;
        }
        depth[index] = std::max(depth[index], profile * groove);
      }
    }
  }

  SvMaps maps = allocate(size);
  const glm::dvec3 steel(0.02);
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      const std::size_t index = std::size_t(y) * size + x;
      const double s = strength[index];
      const glm::dvec2 tangent = alongV[index] ? glm::dvec2(0.0, 1.0) : glm::dvec2(1.0, 0.0);
      setTexel(maps, x, y, tangent, kBaseAlpha + s * (kAlongAlpha - kBaseAlpha),
               kBaseAlpha + s * (kAcrossAlpha - kBaseAlpha), steel, 0.9);
      maps.height.at(x, y, 0) = float(-depth[index]);
    }
  }
  maps.normal = normalsFromSlopes(slopesFromHeight(maps.height, 1.0));
  return maps;
}

SvMaps veinedMarble(int size, double veinHeight, std::uint32_t seed)
{
  checkSize("marble", size);
  if (!(veinHeight >= 0.0 && veinHeight <= 0.1))
    throw errorAbout("marble",
                     "vein height must be in [0, 0.1] (got " + std::to_string(veinHeight) + ")");
  const glm::dvec3 base(0.88, 0.86, 0.82);
  const glm::dvec3 vein(0.28, 0.32, 0.30);
  SvMaps maps = allocate(size);
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      const double u = (x + 0.5) / size;
      const double v = 1.0 - (y + 0.5) / size;
      // Integer wave numbers and a tiling turbulence keep the veins continuous across tiles.
      const double turbulence = fbm(u, v, 4, 5, seed);
      const double phase = 2.0 * kPi * (2.0 * u + 1.0 * v) + 7.0 * turbulence;
      const double mask = std::pow(1.0 - std::abs(std::sin(phase)), 10.0);
      const double cloud = 0.94 + 0.06 * fbm(u, v, 8, 4, seed + 101U);
      const glm::dvec3 colour = base * cloud * (1.0 - mask) + vein * mask;
      setTexel(maps, x, y, {1.0, 0.0}, 0.06 + 0.09 * mask, 0.06 + 0.09 * mask, colour, 0.04);
      maps.height.at(x, y, 0) = float(veinHeight * mask);
    }
  }
  maps.normal = normalsFromSlopes(slopesFromHeight(maps.height, 1.0));
  return maps;
}
} // namespace aniso
