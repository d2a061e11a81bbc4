#include "core/env/environment.h"
#include "core/env/sun_sky.h"

#include "core/env/parallel.h"
#include "core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <sstream>
#include <system_error>
#include <utility>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

// Keeps RGB (grey expanded), zeroes texels with a non-finite channel and clamps negative
// channels, counting every texel it had to change.
Image sanitizedRgb(const Image& source, std::size_t* invalid)
{
  Image rgb(source.width, source.height, 3);
  std::size_t count = 0;
  const std::size_t texels = std::size_t(source.width) * std::size_t(source.height);
  const std::size_t stride = std::size_t(source.channels);
  for (std::size_t i = 0; i < texels; ++i)
  {
    const float* in = source.data.data() + i * stride;
    float c[3];
    for (int k = 0; k < 3; ++k)
      c[k] = source.channels >= 3 ? in[k] : in[0];
    bool finite = std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]);
    bool negative = false;
    for (int k = 0; k < 3; ++k)
    {
      if (!finite)
        c[k] = 0.0f;
      else if (c[k] < 0.0f)
      {
        c[k] = 0.0f;
        negative = true;
      }
      rgb.data[i * 3 + std::size_t(k)] = c[k];
    }
    if (!finite || negative)
      ++count;
  }
  *invalid = count;
  return rgb;
}

// Path, size and modification time: a file edited in place gets a new key.
std::string fileKey(const std::string& path, int width, int height)
{
  std::ostringstream key;
  key << path << '|' << width << 'x' << height;
  std::error_code error;
  const auto bytes = std::filesystem::file_size(path, error);
  if (!error)
    key << '|' << bytes;
  const auto time = std::filesystem::last_write_time(path, error);
  if (!error)
    key << '|' << time.time_since_epoch().count();
  return key.str();
}

// A rectangular light seen from the origin: radiance * exp(-(x/w)^6 - (y/h)^6) in gnomonic
// coordinates (x, y) of its plane. The 6th-power super-Gaussian has a flat top and a soft but
// visible edge, and is infinitely differentiable, so quadratures converge quickly over it.
struct SoftBox
{
  glm::dvec3 centre;
  glm::dvec3 across; // horizontal axis of the box
  glm::dvec3 up;     // second axis
  double halfWidth;  // in units of the gnomonic plane (tangent of the angle)
  double halfHeight;
  glm::dvec3 radiance;
  double minCos; // beyond this angle from the centre the box contributes below exp(-64)
};

SoftBox makeBox(double azimuthDeg, double elevationDeg, double halfWidth, double halfHeight,
                const glm::dvec3& radiance)
{
  const double az = azimuthDeg * kPi / 180.0;
  const double el = elevationDeg * kPi / 180.0;
  SoftBox box;
  box.centre = {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  const glm::dvec3 horizontal{-box.centre.y, box.centre.x, 0.0};
  box.across = glm::length(horizontal) > 1e-9 ? glm::normalize(horizontal) : glm::dvec3(1, 0, 0);
  box.up = glm::cross(box.centre, box.across);
  box.halfWidth = halfWidth;
  box.halfHeight = halfHeight;
  box.radiance = radiance;
  // |x| > 2 w or |y| > 2 h gives exp(-64) at most; both hold outside this cone.
  box.minCos = std::cos(std::atan(2.0 * std::hypot(halfWidth, halfHeight)));
  return box;
}

const std::array<SoftBox, 4>& studioBoxes()
{
  static const std::array<SoftBox, 4> boxes = {
      makeBox(30.0, 30.0, 0.35, 0.25, 14.0 * glm::dvec3(1.0, 0.96, 0.90)), // key
      makeBox(150.0, 15.0, 0.60, 0.35, 3.5 * glm::dvec3(0.92, 0.96, 1.0)), // fill
      makeBox(-120.0, 20.0, 0.12, 0.60, 9.0 * glm::dvec3(1.0, 1.0, 1.0)),  // rim strip
      makeBox(0.0, 90.0, 0.45, 0.45, 6.0 * glm::dvec3(1.0, 0.98, 0.95)),   // top
  };
  return boxes;
}
} // namespace

glm::dvec2 directionToEquirect(const glm::dvec3& d)
{
  double u = 0.5 - std::atan2(d.y, d.x) / kTwoPi;
  u -= std::floor(u);
  if (u >= 1.0)
    u = 0.0; // -1e-17 wraps to 1 in floating point
  const double theta = std::atan2(std::hypot(d.x, d.y), d.z);
  return {u, 1.0 - theta / kPi};
}

glm::dvec3 equirectToDirection(const glm::dvec2& uv)
{
  const double phi = kPi - kTwoPi * uv.x; // atan2(d.y, d.x)
  const double theta = kPi * (1.0 - uv.y);
  const double s = std::sin(theta);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

EquirectEnvironment::EquirectEnvironment(Image image, std::string key) : key_(std::move(key))
{
  if (image.width < 1 || image.height < 1 || image.channels < 1 ||
      image.data.size() !=
          std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
    throw errorAbout(key_, "empty or inconsistent image");
  image_ = sanitizedRgb(image, &invalidTexels_);
}

glm::dvec3 EquirectEnvironment::radiance(const glm::dvec3& d) const
{
  const glm::dvec2 uv = directionToEquirect(d);
  // Texel centres sit at half-integer coordinates; row 0 is the top (v = 1).
  const double x = uv.x * image_.width - 0.5;
  const double y = (1.0 - uv.y) * image_.height - 0.5;
  if (!std::isfinite(x) || !std::isfinite(y))
    return glm::dvec3(0.0);
  const double fx0 = std::floor(x);
  const double fy0 = std::floor(y);
  const double ax = x - fx0;
  const double ay = y - fy0;
  const int w = image_.width;
  const int h = image_.height;
  int x0 = int(fx0) % w;
  if (x0 < 0)
    x0 += w;
  const int x1 = (x0 + 1) % w;
  const int y0 = std::clamp(int(fy0), 0, h - 1);
  const int y1 = std::clamp(int(fy0) + 1, 0, h - 1);
  auto texel = [&](int tx, int ty)
  { return glm::dvec3(image_.at(tx, ty, 0), image_.at(tx, ty, 1), image_.at(tx, ty, 2)); };
  const glm::dvec3 top = (1.0 - ax) * texel(x0, y0) + ax * texel(x1, y0);
  const glm::dvec3 bottom = (1.0 - ax) * texel(x0, y1) + ax * texel(x1, y1);
  return (1.0 - ay) * top + ay * bottom;
}

std::shared_ptr<EquirectEnvironment> loadEquirect(const std::string& path)
{
  Image image = readImage(path);
  const int w = image.width;
  const int h = image.height;
  if (w < 2 || h < 1 || std::abs(w - 2 * h) > std::max(1, w / 100))
  {
    std::ostringstream reason;
    reason << "not an equirectangular image: " << w << 'x' << h << ", expected width = 2 x height";
    throw errorAbout(path, reason.str());
  }
  auto env = std::make_shared<EquirectEnvironment>(std::move(image), fileKey(path, w, h));
  const std::size_t texels = std::size_t(w) * std::size_t(h);
  if (env->invalidTexels() == texels)
    throw errorAbout(path, "no valid texel: all " + std::to_string(texels) +
                               " are NaN, infinite or negative");
  return env;
}

glm::dvec3 StudioEnvironment::radiance(const glm::dvec3& d) const
{
  // Dim warm floor to brighter cool sky, blended smoothly across the horizon.
  const glm::dvec3 floorColour(0.10, 0.085, 0.07);
  const glm::dvec3 skyColour(0.35, 0.40, 0.48);
  const double blend = 0.5 + 0.5 * std::tanh(d.z / 0.2);
  glm::dvec3 result = floorColour + blend * (skyColour - floorColour);
  for (const SoftBox& box : studioBoxes())
  {
    const double c = glm::dot(d, box.centre);
    if (c <= box.minCos)
      continue;
    const double x = glm::dot(d, box.across) / (c * box.halfWidth);
    const double y = glm::dot(d, box.up) / (c * box.halfHeight);
    const double x2 = x * x;
    const double y2 = y * y;
    const double exponent = x2 * x2 * x2 + y2 * y2 * y2;
    if (exponent < 64.0)
      result += std::exp(-exponent) * box.radiance;
  }
  return result;
}

std::string UniformEnvironment::key() const
{
  std::ostringstream key;
  key.precision(17);
  key << "builtin:uniform:" << radiance_.x << ',' << radiance_.y << ',' << radiance_.z;
  return key.str();
}

std::shared_ptr<Environment> openEnvironment(const std::string& spec)
{
  if (spec == "builtin:studio")
    return std::make_shared<StudioEnvironment>();
  if (spec == "builtin:white")
    return std::make_shared<UniformEnvironment>(glm::dvec3(1.0));
  if (spec == "builtin:sunsky")
    // A stress environment: the sun (radius 0.27 degrees, radiance 1e5) over a sky of 1, as in
    // the variance benchmark (docs/BENCHMARKS.md).
    return std::make_shared<SunSkyEnvironment>(glm::dvec3(0.3, -0.6, 0.74),
                                               SunSkyEnvironment::kSunAngularRadius,
                                               glm::dvec3(1e5), glm::dvec3(1.0));
  if (spec.rfind("builtin:", 0) == 0)
    throw errorAbout(spec, "unknown built-in environment (known: builtin:studio, builtin:white, "
                           "builtin:sunsky)");
  if (spec.empty())
    throw errorAbout("environment", "empty path");
  return loadEquirect(spec);
}

Image renderEquirect(const Environment& env, int width, int height, int supersample)
{
  if (width < 1 || width > 32768)
    throw errorAbout("width", "must be in [1, 32768], got " + std::to_string(width));
  if (height < 1 || height > 16384)
    throw errorAbout("height", "must be in [1, 16384], got " + std::to_string(height));
  if (supersample < 1 || supersample > 16)
    throw errorAbout("supersample", "must be in [1, 16], got " + std::to_string(supersample));
  Image image(width, height, 3);
  const int n = supersample;
  parallelFor(height,
              [&](int y)
              {
                for (int x = 0; x < width; ++x)
                {
                  glm::dvec3 sum(0.0);
                  double weightSum = 0.0;
                  for (int j = 0; j < n; ++j)
                  {
                    const double v = 1.0 - (y + (j + 0.5) / n) / height;
                    // Solid angle per unit (u, v) is proportional to sin(theta).
                    const double weight = std::sin(kPi * (1.0 - v));
                    for (int i = 0; i < n; ++i)
                    {
                      const double u = (x + (i + 0.5) / n) / width;
                      sum += weight * env.radiance(equirectToDirection({u, v}));
                      weightSum += weight;
                    }
                  }
                  const glm::dvec3 value = sum / weightSum;
                  for (int c = 0; c < 3; ++c)
                    image.at(x, y, c) = float(value[c]);
                }
              });
  return image;
}
} // namespace aniso
