#include "core/maps/quaternion_map.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

namespace aniso
{
glm::dvec3 quaternionFromNormal(const glm::dvec3& n)
{
  const double len = glm::length(n);
  if (!std::isfinite(len) || !(len > 0.0))
  {
    return {1.0, 0.0, 0.0};
  }
  const glm::dvec3 u = n / len;
  const double r = std::hypot(u.x, u.y);
  if (!(r > 0.0))
  {
    // On the axis: identity at +z, the half turn about t at -z.
    return u.z > 0.0 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  }
  // 1 + z and 1 - z with no cancellation: the small one from (1 + z)(1 - z) = r^2. Near
  // z = -1 this keeps a (and the tilt it carries) even where z itself has rounded to -1.
  const double z = std::clamp(u.z, -1.0, 1.0);
  const double onePlusZ = z >= 0.0 ? 1.0 + z : r * r / (1.0 - z);
  const double oneMinusZ = z >= 0.0 ? r * r / (1.0 + z) : 1.0 - z;
  const double a = std::sqrt(0.5 * onePlusZ);
  // |(b, c)| = sqrt((1 - z)/2) directly, rather than dividing by 2a, which loses all
  // precision as a -> 0; the direction (y, -x)/r is that of (y, -x)/(2a).
  const double s = std::sqrt(0.5 * oneMinusZ);
  return {a, s * u.y / r, -s * u.x / r};
}

Frame frameFromQuaternion(const glm::dvec3& abc)
{
  const double a = abc.x;
  const double b = abc.y;
  const double c = abc.z;
  Frame f;
  f.t = {a * a + b * b - c * c, 2.0 * b * c, 2.0 * a * c};
  f.b = {2.0 * b * c, a * a - b * b + c * c, -2.0 * a * b};
  f.n = {-2.0 * a * c, 2.0 * a * b, a * a - b * b - c * c};
  return f;
}

Image bakeQuaternionMap(const Image& normalMap, bool integerEncoded, QuaternionBakeStats* stats)
{
  const int channels = normalMap.channels;
  if (normalMap.width <= 0 || normalMap.height <= 0)
  {
    throw errorAbout("normal map", "image is " + std::to_string(normalMap.width) + "x" +
                                       std::to_string(normalMap.height));
  }
  if (channels < 2)
  {
    throw errorAbout("normal map",
                     std::to_string(channels) + " channel(s); a normal map needs 2 (x, y), 3 or 4");
  }
  const std::size_t texels = std::size_t(normalMap.width) * normalMap.height;
  if (normalMap.data.size() != texels * channels)
  {
    throw errorAbout("normal map", "data holds " + std::to_string(normalMap.data.size()) +
                                       " values, not width x height x channels");
  }

  const double tolerance = integerEncoded ? kNonUnitToleranceInteger : kNonUnitToleranceFloat;
  QuaternionBakeStats counts;
  counts.texels = texels;
  Image out(normalMap.width, normalMap.height, 4);
  for (std::size_t i = 0; i < texels; ++i)
  {
    const float* src = &normalMap.data[i * channels];
    auto decode = [&](int c) { return integerEncoded ? 2.0 * src[c] - 1.0 : double(src[c]); };
    glm::dvec3 n{decode(0), decode(1), 0.0};
    if (channels >= 3)
    {
      n.z = decode(2);
    }
    else
    {
      n.z = std::sqrt(std::max(0.0, 1.0 - n.x * n.x - n.y * n.y));
    }

    const double len = glm::length(n);
    if (!std::isfinite(len) || !(len >= kMinNormalLength))
    {
      ++counts.invalid;
      n = {0.0, 0.0, 1.0};
    }
    else
    {
      if (std::abs(len - 1.0) > tolerance)
      {
        ++counts.nonUnit;
      }
      n /= len;
    }
    if (1.0 + n.z <= kAntipodalOnePlusZ)
    {
      ++counts.antipodal;
    }

    const glm::dvec3 q = quaternionFromNormal(n);
    float* dst = &out.data[i * 4];
    dst[0] = float(q.x);
    dst[1] = float(q.y);
    dst[2] = float(q.z);
    dst[3] = 1.0f;
  }
  if (stats)
  {
    *stats = counts;
  }
  return out;
}
} // namespace aniso
