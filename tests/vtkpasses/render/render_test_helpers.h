#pragma once
// Shared by the render tests: the analytic view rays of a rendered image (from the camera
// placement, not from VTK's matrices or the shaders), error metrics over covered pixels, checks
// for non-finite values, and diff images kept when a comparison fails.
#include "core/env/environment.h"
#include "core/env/sun_sky.h"
#include "core/frame.h"
#include "core/image/image.h"
#include "core/reference/reference_integrator.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "vtkpasses/render/ViewSettings.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <vtkPolyData.h>

namespace aniso::test
{
// The environment `--env builtin:sunsky` opens (a sun of 1e5 over a sky of 1).
inline std::shared_ptr<SunSkyEnvironment> sunSkyEnvironment()
{
  return std::dynamic_pointer_cast<SunSkyEnvironment>(openEnvironment("builtin:sunsky"));
}

// The sampling tests' scene: the built-in sphere (256 x 128, fine enough that facets and
// interpolated normals stay far below the lobes compared) under ENV, seen from the front at
// SIZE x SIZE, F0 = 1, no diffuse, the exact method, one frame, no jitter, no background. Each
// test sets its cube size, filtering, half vectors, samples and frames.
inline RenderSettings sphereScene(std::shared_ptr<const Environment> env, const AsLobe& lobe,
                                  int size)
{
  RenderSettings s;
  s.surface = makeSphere(256, 128);
  s.environment = std::move(env);
  s.material.lobe = lobe;
  s.material.f0 = glm::dvec3(1.0);
  s.material.albedo = glm::dvec3(0.0);
  s.material.method = SpecularMethod::Exact;
  s.display.background = BackgroundMode::Transparent;
  s.width = size;
  s.height = size;
  s.frames = 1;
  s.jitter = false;
  return s;
}

// Render tests need an X server (./test runs the suite under xvfb-run).
inline bool haveDisplay()
{
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}

#define ANISO_REQUIRE_DISPLAY()                                                                    \
  if (!::aniso::test::haveDisplay())                                                               \
  {                                                                                                \
    GTEST_SKIP() << "no X display: run under xvfb-run (./test does)";                              \
  }

// Where the ray through the centre of pixel (x, y) of a SIZE x SIZE parallel projection meets
// the plane z = 0, the direction back to the camera, and the built-in plate's and disk's texture
// coordinates there: u = (x + 1) / 2, v = (y + 1) / 2.
struct PlaneHit
{
  glm::dvec3 position;
  glm::dvec3 view;
  glm::dvec2 uv;
};

inline PlaneHit planeHit(const CameraPlacement& camera, int size, double x, double y)
{
  const glm::dvec3 forward = glm::normalize(camera.focalPoint - camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.viewUp));
  const glm::dvec3 up = glm::cross(right, forward);
  const glm::dvec3 origin = camera.position +
                            ((x + 0.5) / size * 2.0 - 1.0) * camera.parallelScale * right +
                            (1.0 - (y + 0.5) / size * 2.0) * camera.parallelScale * up;
  const glm::dvec3 p = origin + (-origin.z / forward.z) * forward;
  return {p, -forward, glm::dvec2((p.x + 1.0) / 2.0, (p.y + 1.0) / 2.0)};
}

struct Ray
{
  glm::dvec3 origin;
  glm::dvec3 direction; // unit
};

// The ray through the centre of pixel (x, y) (row 0 at the top) of a width x height image seen
// by the camera placeCamera() gives: vertical field of view, square pixels.
inline Ray pixelRay(const CameraPlacement& camera, int x, int y, int width, int height)
{
  const glm::dvec3 forward = glm::normalize(camera.focalPoint - camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.viewUp));
  const glm::dvec3 up = glm::cross(right, forward);
  const double aspect = double(width) / height;
  const double sx = (x + 0.5) / width * 2.0 - 1.0;
  const double sy = 1.0 - (y + 0.5) / height * 2.0;
  if (camera.parallel)
  {
    const glm::dvec3 origin = camera.position + sx * camera.parallelScale * aspect * right +
                              sy * camera.parallelScale * up;
    return {origin, forward};
  }
  const double t = std::tan(0.5 * camera.viewAngleDegrees * M_PI / 180.0);
  return {camera.position, glm::normalize(forward + sx * t * aspect * right + sy * t * up)};
}

// First intersection with the unit sphere at the origin.
inline std::optional<glm::dvec3> hitUnitSphere(const Ray& ray)
{
  const double b = glm::dot(ray.origin, ray.direction);
  const double c = glm::dot(ray.origin, ray.origin) - 1.0;
  const double discriminant = b * b - c;
  if (discriminant < 0.0)
  {
    return std::nullopt;
  }
  const double t = -b - std::sqrt(discriminant);
  if (t <= 0.0)
  {
    return std::nullopt;
  }
  return ray.origin + t * ray.direction;
}

// Counts NaN and infinite values in an image.
inline int nonFiniteValues(const Image& image)
{
  int count = 0;
  for (float value : image.data)
  {
    count += std::isfinite(value) ? 0 : 1;
  }
  return count;
}

// Where failing tests keep their images: $ANISO_TEST_OUTPUT, else the working directory.
inline std::filesystem::path outputDirectory()
{
  const char* dir = std::getenv("ANISO_TEST_OUTPUT");
  return dir && *dir ? std::filesystem::path(dir) : std::filesystem::current_path();
}

// |a - b| per channel (RGB, alpha 1), scaled so the largest difference is white.
inline Image differenceImage(const Image& a, const Image& b)
{
  Image diff(a.width, a.height, 4);
  float largest = 0.0f;
  for (int y = 0; y < a.height; ++y)
  {
    for (int x = 0; x < a.width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const float d = std::abs(a.at(x, y, c) - b.at(x, y, c));
        diff.at(x, y, c) = std::isfinite(d) ? d : 1e30f;
        largest = std::max(largest, diff.at(x, y, c));
      }
      diff.at(x, y, 3) = 1.0f;
    }
  }
  for (int y = 0; y < a.height; ++y)
  {
    for (int x = 0; x < a.width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        diff.at(x, y, c) = largest > 0.0f ? diff.at(x, y, c) / largest : 0.0f;
      }
    }
  }
  return diff;
}

// Writes NAME_rendered.exr, NAME_expected.exr and NAME_diff.png for a failed comparison.
inline void keepImages(const std::string& name, const Image& rendered, const Image& expected)
{
  const std::filesystem::path dir = outputDirectory();
  writeImage((dir / (name + "_rendered.exr")).string(), rendered);
  writeImage((dir / (name + "_expected.exr")).string(), expected);
  writeImage((dir / (name + "_diff.png")).string(), differenceImage(rendered, expected));
  std::cout << name << ": images kept in " << dir.string() << "\n";
}
// A rendered pixel and the CPU reference radiance it is compared with.
struct Compared
{
  int x = 0;
  int y = 0;
  glm::dvec3 reference{0.0};
};

using Integrator = std::function<ReferenceResult(const Frame& frame, const glm::dvec3& viewWorld)>;

// Every other pixel in each direction (the reference is the expensive part) whose centre ray hits
// the unit sphere away from its silhouette (n.v >= 0.2, where the faceted mesh and the analytic
// sphere disagree on what the ray hits) and from the poles (|n.z| <= 0.95, where the tangent field
// of the parallels is singular); `integrate` gives the reference for the pixel's frame and view.
inline std::vector<Compared> referencePixels(const RenderSettings& s, const Integrator& integrate)
{
  const CameraPlacement camera = placeCamera(s.view, glm::dvec3(0.0), 1.0);
  std::vector<Compared> pixels;
  for (int y = 0; y < s.height; y += 2)
  {
    for (int x = 0; x < s.width; x += 2)
    {
      const Ray ray = pixelRay(camera, x, y, s.width, s.height);
      const auto hit = hitUnitSphere(ray);
      if (!hit)
      {
        continue;
      }
      const glm::dvec3 n = *hit;
      const glm::dvec3 v = -ray.direction;
      if (glm::dot(n, v) < 0.2 || std::abs(n.z) > 0.95)
      {
        continue;
      }
      const Frame frame = Frame::fromNormalTangent(n, glm::dvec3(-n.y, n.x, 0.0));
      pixels.push_back({x, y, integrate(frame, v).value});
    }
  }
  return pixels;
}

// Relative L2 error of the rendered RGB against the reference over the compared pixels.
inline double relativeL2(const Image& rendered, const std::vector<Compared>& pixels)
{
  double error = 0.0;
  double norm = 0.0;
  for (const Compared& p : pixels)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double d = rendered.at(p.x, p.y, c) - p.reference[c];
      error += d * d;
      norm += p.reference[c] * p.reference[c];
    }
  }
  return std::sqrt(error / norm);
}
} // namespace aniso::test
