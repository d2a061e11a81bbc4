#include "core/env/cubemap.h"

#include "core/env/parallel.h"
#include "core/env/quadrature.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

// Unnormalised direction for face coordinates (sc, tc) in [-1, 1]: the inverse of OpenGL's
// major-axis table (+X: sc = -z, tc = -y; -X: sc = z, tc = -y; +Y: sc = x, tc = z;
// -Y: sc = x, tc = -z; +Z: sc = x, tc = -y; -Z: sc = -x, tc = -y).
glm::dvec3 faceDirection(int face, double sc, double tc)
{
  switch (face)
  {
  case 0:
    return {1.0, -tc, -sc};
  case 1:
    return {-1.0, -tc, sc};
  case 2:
    return {sc, 1.0, tc};
  case 3:
    return {sc, -1.0, -tc};
  case 4:
    return {sc, -tc, 1.0};
  default:
    return {-sc, -tc, -1.0};
  }
}

// Real SH basis up to l = 2 at a unit direction.
std::array<double, 9> shBasis(const glm::dvec3& d)
{
  const double c0 = 0.5 / std::sqrt(kPi); // 1 / (2 sqrt(pi))
  const double c1 = std::sqrt(3.0) / (2.0 * std::sqrt(kPi));
  const double c2 = std::sqrt(15.0) / (2.0 * std::sqrt(kPi));
  const double c20 = std::sqrt(5.0) / (4.0 * std::sqrt(kPi));
  const double c22 = std::sqrt(15.0) / (4.0 * std::sqrt(kPi));
  return {c0,
          c1 * d.y,
          c1 * d.z,
          c1 * d.x,
          c2 * d.x * d.y,
          c2 * d.y * d.z,
          c20 * (3.0 * d.z * d.z - 1.0),
          c2 * d.x * d.z,
          c22 * (d.x * d.x - d.y * d.y)};
}

void accumulateSh(Sh9& sh, const glm::dvec3& d, const glm::dvec3& value, double weight)
{
  const std::array<double, 9> y = shBasis(d);
  for (std::size_t i = 0; i < 9; ++i)
    sh[i] += (weight * y[i]) * value;
}

bool isPowerOfTwo(int n)
{
  return n > 0 && (n & (n - 1)) == 0;
}
} // namespace

glm::dvec3 cubeTexelDirection(int face, int x, int y, int size)
{
  const double sc = 2.0 * (x + 0.5) / size - 1.0;
  const double tc = 2.0 * (y + 0.5) / size - 1.0;
  return glm::normalize(faceDirection(face, sc, tc));
}

int cubeFaceOf(const glm::dvec3& d, double* s, double* t)
{
  const double ax = std::abs(d.x);
  const double ay = std::abs(d.y);
  const double az = std::abs(d.z);
  int face;
  double sc;
  double tc;
  double ma;
  if (ax >= ay && ax >= az && ax > 0.0)
  {
    face = d.x > 0.0 ? 0 : 1;
    sc = d.x > 0.0 ? -d.z : d.z;
    tc = -d.y;
    ma = ax;
  }
  else if (ay >= az && ay > 0.0)
  {
    face = d.y > 0.0 ? 2 : 3;
    sc = d.x;
    tc = d.y > 0.0 ? d.z : -d.z;
    ma = ay;
  }
  else if (az > 0.0)
  {
    face = d.z > 0.0 ? 4 : 5;
    sc = d.z > 0.0 ? d.x : -d.x;
    tc = -d.y;
    ma = az;
  }
  else
  {
    *s = 0.5;
    *t = 0.5;
    return 4;
  }
  *s = 0.5 * (sc / ma + 1.0);
  *t = 0.5 * (tc / ma + 1.0);
  return face;
}

double cubeTexelSolidAngle(int x, int y, int size)
{
  // Solid angle of [0, a] x [0, b] on the plane at distance 1, by the area element
  // dA / (1 + s^2 + t^2)^(3/2): atan(a b / sqrt(a^2 + b^2 + 1)); inclusion-exclusion for a texel.
  auto corner = [](double a, double b)
  { return std::atan2(a * b, std::sqrt(a * a + b * b + 1.0)); };
  const double x0 = 2.0 * x / size - 1.0;
  const double x1 = 2.0 * (x + 1) / size - 1.0;
  const double y0 = 2.0 * y / size - 1.0;
  const double y1 = 2.0 * (y + 1) / size - 1.0;
  return corner(x0, y0) - corner(x0, y1) - corner(x1, y0) + corner(x1, y1);
}

Cubemap buildCubemap(const Environment& env, int size, int supersample)
{
  if (!isPowerOfTwo(size) || size > 8192)
    throw errorAbout("size", "must be a power of two in [1, 8192], got " + std::to_string(size));
  if (supersample < 1 || supersample > 16)
    throw errorAbout("supersample", "must be in [1, 16], got " + std::to_string(supersample));

  Cubemap cube;
  cube.size = size;
  int levels = 1;
  while ((size >> (levels - 1)) > 1)
    ++levels;
  cube.mips.resize(std::size_t(levels));
  for (int level = 0; level < levels; ++level)
    for (Image& face : cube.mips[std::size_t(level)])
      face = Image(size >> level, size >> level, 3);

  const int n = supersample;
  std::array<Image, 6>& base = cube.mips[0];
  parallelFor(
      6 * size,
      [&](int row)
      {
        const int face = row / size;
        const int y = row % size;
        for (int x = 0; x < size; ++x)
        {
          glm::dvec3 sum(0.0);
          double weightSum = 0.0;
          for (int j = 0; j < n; ++j)
          {
            const double tc = 2.0 * (y + (j + 0.5) / n) / size - 1.0;
            for (int i = 0; i < n; ++i)
            {
              const double sc = 2.0 * (x + (i + 0.5) / n) / size - 1.0;
              // Solid angle per unit face area: (1 + sc^2 + tc^2)^(-3/2).
              const double r2 = 1.0 + sc * sc + tc * tc;
              const double weight = 1.0 / (r2 * std::sqrt(r2));
              sum += weight * env.radiance(glm::normalize(faceDirection(face, sc, tc)));
              weightSum += weight;
            }
          }
          const glm::dvec3 value = sum / weightSum;
          for (int c = 0; c < 3; ++c)
            base[std::size_t(face)].at(x, y, c) = float(value[c]);
        }
      },
      8);

  for (std::size_t level = 1; level < cube.mips.size(); ++level)
  {
    for (std::size_t face = 0; face < 6; ++face)
    {
      const Image& fine = cube.mips[level - 1][face];
      Image& coarse = cube.mips[level][face];
      for (int y = 0; y < coarse.height; ++y)
        for (int x = 0; x < coarse.width; ++x)
          for (int c = 0; c < 3; ++c)
          {
            const double sum = double(fine.at(2 * x, 2 * y, c)) + fine.at(2 * x + 1, 2 * y, c) +
                               fine.at(2 * x, 2 * y + 1, c) + fine.at(2 * x + 1, 2 * y + 1, c);
            coarse.at(x, y, c) = float(0.25 * sum);
          }
    }
  }
  return cube;
}

Sh9 projectSh9(const Cubemap& cube)
{
  if (cube.mips.empty() || cube.size < 1 || cube.mips[0][0].width != cube.size)
    throw errorAbout("cubemap", "empty or inconsistent");
  const int size = cube.size;
  std::vector<Sh9> rows(std::size_t(6 * size));
  parallelFor(
      6 * size,
      [&](int row)
      {
        const int face = row / size;
        const int y = row % size;
        const Image& image = cube.mips[0][std::size_t(face)];
        Sh9 sh{};
        for (int x = 0; x < size; ++x)
        {
          const glm::dvec3 value(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
          accumulateSh(sh, cubeTexelDirection(face, x, y, size), value,
                       cubeTexelSolidAngle(x, y, size));
        }
        rows[std::size_t(row)] = sh;
      },
      32);
  Sh9 total{};
  for (const Sh9& sh : rows)
    for (std::size_t i = 0; i < 9; ++i)
      total[i] += sh[i];
  return total;
}

Sh9 projectSh9(const Environment& env, int samplesPerAxis)
{
  if (samplesPerAxis < 2 || samplesPerAxis > 8192)
    throw errorAbout("samplesPerAxis",
                     "must be in [2, 8192], got " + std::to_string(samplesPerAxis));
  const QuadratureRule cosTheta = gaussLegendre(samplesPerAxis, -1.0, 1.0);
  const int azimuths = 2 * samplesPerAxis;
  const double dPhi = 2.0 * kPi / azimuths;
  std::vector<Sh9> rows(static_cast<std::size_t>(samplesPerAxis));
  parallelFor(samplesPerAxis,
              [&](int i)
              {
                const double z = cosTheta.nodes[std::size_t(i)];
                const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                const double weight = cosTheta.weights[std::size_t(i)] * dPhi;
                Sh9 sh{};
                for (int k = 0; k < azimuths; ++k)
                {
                  const double phi = (k + 0.5) * dPhi;
                  const glm::dvec3 d(r * std::cos(phi), r * std::sin(phi), z);
                  accumulateSh(sh, d, env.radiance(d), weight);
                }
                rows[std::size_t(i)] = sh;
              });
  Sh9 total{};
  for (const Sh9& sh : rows)
    for (std::size_t i = 0; i < 9; ++i)
      total[i] += sh[i];
  return total;
}

glm::dvec3 irradianceSh9(const Sh9& sh, const glm::dvec3& n)
{
  // Clamped-cosine convolution per band: A0 = pi, A1 = 2 pi / 3, A2 = pi / 4.
  constexpr double a0 = kPi;
  constexpr double a1 = 2.0 * kPi / 3.0;
  constexpr double a2 = kPi / 4.0;
  const std::array<double, 9> band = {a0, a1, a1, a1, a2, a2, a2, a2, a2};
  const std::array<double, 9> y = shBasis(glm::normalize(n));
  glm::dvec3 e(0.0);
  for (std::size_t i = 0; i < 9; ++i)
    e += (band[i] * y[i]) * sh[i];
  return e;
}
} // namespace aniso
