// Error against cost of the GPU specular methods: one frame of the built-in sphere under the
// studio (64 x 64, F0 = 1, no jitter), for each method, filtering and half-vector source and
// N samples, against the CPU reference integrator at every other pixel (relative L2 over RGB,
// as in tests/vtkpasses/render/test_render_reference.cxx). Prints a Markdown table per lobe with the
// error and the frame time. Needs an X display (xvfb-run).
#include "core/env/environment.h"
#include "core/frame.h"
#include "core/reference/reference_integrator.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <memory>
#include <vector>
#include <vtkPolyData.h>

namespace
{
using namespace aniso;

struct Pixel
{
  int x;
  int y;
  glm::dvec3 reference;
};

std::vector<Pixel> referencePixels(const RenderSettings& s, const AsLobe& lobe)
{
  const CameraPlacement camera = placeCamera(s.view, glm::dvec3(0.0), 1.0);
  const glm::dvec3 forward = glm::normalize(camera.focalPoint - camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.viewUp));
  const glm::dvec3 up = glm::cross(right, forward);
  const double t = std::tan(0.5 * camera.viewAngleDegrees * M_PI / 180.0);
  const StudioEnvironment env;
  std::vector<Pixel> pixels;
  for (int y = 0; y < s.height; y += 2)
  {
    for (int x = 0; x < s.width; x += 2)
    {
      const double sx = (x + 0.5) / s.width * 2.0 - 1.0;
      const double sy = 1.0 - (y + 0.5) / s.height * 2.0;
      const glm::dvec3 d = glm::normalize(forward + sx * t * right + sy * t * up);
      const double b = glm::dot(camera.position, d);
      const double disc = b * b - (glm::dot(camera.position, camera.position) - 1.0);
      if (disc < 0.0)
      {
        continue;
      }
      const glm::dvec3 n = camera.position + (-b - std::sqrt(disc)) * d;
      if (glm::dot(n, -d) < 0.2 || std::abs(n.z) > 0.95)
      {
        continue;
      }
      const Frame frame = Frame::fromNormalTangent(n, {-n.y, n.x, 0.0});
      pixels.push_back({x, y, integrateSpecular(lobe, glm::dvec3(1.0), frame, -d, env).value});
    }
  }
  return pixels;
}

double relativeL2(const Image& image, const std::vector<Pixel>& pixels)
{
  double error = 0.0;
  double norm = 0.0;
  for (const Pixel& p : pixels)
  {
    for (int c = 0; c < 3; ++c)
    {
      error += std::pow(image.at(p.x, p.y, c) - p.reference[c], 2);
      norm += p.reference[c] * p.reference[c];
    }
  }
  return std::sqrt(error / norm);
}
} // namespace

int main()
{
  RenderSettings s;
  s.surface = makeSphere(256, 128);
  s.environment = std::make_shared<StudioEnvironment>();
  s.cubeSize = 512;
  s.material.f0 = glm::dvec3(1.0);
  s.display.background = BackgroundMode::Transparent;
  s.width = 64;
  s.height = 64;
  s.frames = 1;
  s.jitter = false;
  for (const AsLobe lobe : {AsLobe{1000.0, 100.0}, AsLobe{20000.0, 70.0}})
  {
    s.material.lobe = lobe;
    const std::vector<Pixel> pixels = referencePixels(s, lobe);
    std::printf("\nLobe (%g, %g), one frame, %zu pixels: relative L2 against the reference "
                "\n\n",
                lobe.nu, lobe.nv, pixels.size());
    std::printf("| Method | Filtered | Half vectors | N = 1 | N = 4 | N = 16 | N = 64 | N = 256 |\n"
                "| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (const SpecularMethod method : {SpecularMethod::Exact, SpecularMethod::SplitSum})
    {
      for (const bool filtered : {true, false})
      {
        for (const HalfVectorSource source : {HalfVectorSource::Lut, HalfVectorSource::Shader})
        {
          std::printf("| %s | %s | %s |", method == SpecularMethod::Exact ? "exact" : "split-sum",
                      filtered ? "on" : "off", source == HalfVectorSource::Lut ? "LUT" : "shader");
          for (const int n : {1, 4, 16, 64, 256})
          {
            s.material.method = method;
            s.material.filtered = filtered;
            s.material.halfVectors = source;
            s.material.samples = n;
            const RenderResult r = renderOffscreen(s);
            std::printf(" %.3f |", relativeL2(r.linear, pixels));
          }
          std::printf("\n");
          std::fflush(stdout);
        }
      }
    }
  }
  return 0;
}
