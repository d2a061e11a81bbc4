#include "materials/height_field.h"

#include "error.h"

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
} // namespace aniso
