#pragma once
// Environments: radiance as a function of a world direction (Z up), the Blender-compatible
// equirectangular mapping, and the built-in procedural studio.
#include <memory>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "image/image.h"

namespace aniso
{
// d -> (u, v): u = 0.5 - atan2(d.y, d.x) / (2 pi) wrapped to [0, 1), v = 1 - acos(d.z) / pi
// (v = 1 is the top row, the zenith; +X looks at the image centre).
glm::dvec2 directionToEquirect(const glm::dvec3& d);
glm::dvec3 equirectToDirection(const glm::dvec2& uv);

class Environment
{
public:
  virtual ~Environment() = default;
  // Linear RGB radiance arriving from direction d (unit, world space, Z up).
  virtual glm::dvec3 radiance(const glm::dvec3& d) const = 0;
  // Stable identity of the content, for caches ("builtin:studio", or path + size + mtime).
  virtual std::string key() const = 0;
};

// Equirectangular image, bilinear, wrapping in u, clamped in v.
class EquirectEnvironment : public Environment
{
public:
  explicit EquirectEnvironment(Image image, std::string key);
  glm::dvec3 radiance(const glm::dvec3& d) const override;
  std::string key() const override { return key_; }
  const Image& image() const { return image_; }

private:
  Image image_;
  std::string key_;
};

// Loads an equirectangular HDR/EXR (anything OpenImageIO reads; 2:1 aspect expected, RGB or
// RGBA, finite non-negative values). Throws aniso::Error "PATH: reason".
std::shared_ptr<EquirectEnvironment> loadEquirect(const std::string& path);

// The built-in studio: soft boxes over a vertical gradient, analytic and smooth, so it can be
// evaluated exactly by the reference integrator and baked at any resolution.
class StudioEnvironment : public Environment
{
public:
  glm::dvec3 radiance(const glm::dvec3& d) const override;
  std::string key() const override { return "builtin:studio"; }
};

// "builtin:studio" or a file path.
std::shared_ptr<Environment> openEnvironment(const std::string& spec);

// Samples an environment into an equirectangular RGB image (supersampled per texel).
Image renderEquirect(const Environment& env, int width, int height, int supersample = 2);
} // namespace aniso
