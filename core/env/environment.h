#pragma once
// Environments: radiance as a function of a world direction (Z up), the Blender-compatible
// equirectangular mapping, and the built-in procedural studio.
#include "core/image/image.h"

#include <cstddef>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string>

namespace aniso
{
// d -> (u, v): u = 0.5 - atan2(d.y, d.x) / (2 pi) wrapped to [0, 1), v = 1 - acos(d.z) / pi
// (v = 1 is the top row, the zenith; +X looks at the image centre, +Y at u = 0.25).
// d need not be unit length.
glm::dvec2 directionToEquirect(const glm::dvec3& d);
glm::dvec3 equirectToDirection(const glm::dvec2& uv);

class Environment
{
public:
  virtual ~Environment() = default;
  // Linear RGB radiance arriving from direction d (unit, world space, Z up). Called
  // concurrently from several threads by the bakers and the reference integrator.
  virtual glm::dvec3 radiance(const glm::dvec3& d) const = 0;
  // Stable identity of the content, for caches ("builtin:studio", or path + size + mtime).
  virtual std::string key() const = 0;
};

// Equirectangular image, bilinear, wrapping in u, clamped in v. Image row 0 is the top row
// (v = 1), so texel row y covers v in [1 - (y + 1) / H, 1 - y / H].
class EquirectEnvironment : public Environment
{
public:
  // The image is kept as RGB: 1 or 2 channels are grey (+ alpha), beyond 3 only RGB is kept.
  // Texels with a NaN or infinite channel become black, negative channels become 0; their count
  // is invalidTexels(). Throws aniso::Error "KEY: reason" for an empty or inconsistent image.
  explicit EquirectEnvironment(Image image, std::string key);
  glm::dvec3 radiance(const glm::dvec3& d) const override;
  std::string key() const override { return key_; }
  const Image& image() const { return image_; }
  std::size_t invalidTexels() const { return invalidTexels_; }

private:
  Image image_;
  std::string key_;
  std::size_t invalidTexels_ = 0;
};

// Loads an equirectangular HDR/EXR (anything readImage reads). Accepted: width = 2 * height
// within 1% (at least 2 texels; files exported with an odd extra column still load), any channel
// count (see EquirectEnvironment). A few invalid texels (NaN, infinite, negative) are repaired
// and counted; a file with no valid texel at all is refused. Throws aniso::Error "PATH: reason".
std::shared_ptr<EquirectEnvironment> loadEquirect(const std::string& path);

// The built-in studio: soft boxes (key, fill, rim, top; peak radiance about 14) over a vertical
// gradient from a dim warm floor to a brighter cool sky. Analytic and smooth (no hard edge
// anywhere), so it can be evaluated exactly by the reference integrator and baked at any
// resolution.
class StudioEnvironment : public Environment
{
public:
  glm::dvec3 radiance(const glm::dvec3& d) const override;
  std::string key() const override { return "builtin:studio"; }
};

// The same radiance from every direction (white furnace tests, a neutral viewing mode).
class UniformEnvironment : public Environment
{
public:
  explicit UniformEnvironment(const glm::dvec3& radiance) : radiance_(radiance) {}
  glm::dvec3 radiance(const glm::dvec3&) const override { return radiance_; }
  std::string key() const override;

private:
  glm::dvec3 radiance_;
};

// "builtin:studio", "builtin:white" (uniform radiance 1), "builtin:sunsky" (a sun of 1e5 over a
// sky of 1, see sun_sky.h) or a file path (loadEquirect).
std::shared_ptr<Environment> openEnvironment(const std::string& spec);

// Samples an environment into an equirectangular RGB image (supersample^2 samples per texel,
// weighted by their solid angle). width, height >= 1, supersample in [1, 16].
Image renderEquirect(const Environment& env, int width, int height, int supersample = 2);
} // namespace aniso
