#include "core/lights/env_lights.h"

#include "core/env/environment.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

double luminance(double r, double g, double b)
{
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}
} // namespace

double sourceMeanCosine(const EnvAnalysis& analysis, const EnvSource& source)
{
  const Image& excess = analysis.excess;
  const int w = excess.width;
  const int h = excess.height;
  if (w < 1 || h < 1 || excess.channels < 3 || w != 2 * h)
    return 1.0;
  const glm::dvec3 c = glm::normalize(source.direction);
  const double radius = std::clamp(source.angularRadius, 0.0, kPi);
  // The texels whose centres lie within the radius (which reaches the farthest corner of the
  // source's texels, so every one of them is in): the rows the cap spans, every column.
  const double theta = std::acos(std::clamp(c.z, -1.0, 1.0));
  const int y0 = std::clamp(int(std::floor((theta - radius) / kPi * h)) - 1, 0, h - 1);
  const int y1 = std::clamp(int(std::ceil((theta + radius) / kPi * h)) + 1, 0, h - 1);
  const double minCos = std::cos(radius) - 1e-12;
  double weight = 0.0;
  double weightedCos = 0.0;
  for (int y = y0; y <= y1; ++y)
  {
    const double omega = 2.0 * kPi / w * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
    for (int x = 0; x < w; ++x)
    {
      const double lum = luminance(excess.at(x, y, 0), excess.at(x, y, 1), excess.at(x, y, 2));
      if (!(lum > 0.0))
        continue;
      const glm::dvec3 d = equirectToDirection({(x + 0.5) / w, 1.0 - (y + 0.5) / h});
      const double cosine = glm::dot(d, c);
      if (cosine < minCos)
        continue;
      weight += lum * omega;
      weightedCos += lum * omega * cosine;
    }
  }
  return weight > 0.0 ? std::clamp(weightedCos / weight, 0.0, 1.0) : 1.0;
}

std::vector<Light> environmentSourceLights(const EnvAnalysis& analysis, double rotationDegrees,
                                           const EnvLightOptions& options)
{
  if (options.maxLights < 0)
    throw errorAbout("env-lights",
                     "maxLights must be >= 0, got " + std::to_string(options.maxLights));
  if (!(options.minPowerShare >= 0.0 && options.minPowerShare <= 1.0))
  {
    std::ostringstream reason;
    reason << "minPowerShare must be in [0, 1], got " << options.minPowerShare;
    throw errorAbout("env-lights", reason.str());
  }
  if (!std::isfinite(rotationDegrees))
    throw errorAbout("env-lights", "the environment's rotation is not finite");
  const double a = rotationDegrees * kPi / 180.0;
  const double ca = std::cos(a);
  const double sa = std::sin(a);
  // The analysis lists its sources by power, the largest first; kept in that order.
  std::vector<const EnvSource*> order;
  for (const EnvSource& s : analysis.sources)
    order.push_back(&s);
  std::stable_sort(order.begin(), order.end(),
                   [](const EnvSource* p, const EnvSource* q)
                   {
                     return luminance(p->power.x, p->power.y, p->power.z) >
                            luminance(q->power.x, q->power.y, q->power.z);
                   });
  std::vector<Light> lights;
  for (const EnvSource* s : order)
  {
    if (int(lights.size()) >= options.maxLights)
      break;
    if (s->powerShare < options.minPowerShare)
      continue;
    const glm::dvec3 power = glm::max(s->power, glm::dvec3(0.0));
    if (!(power.x + power.y + power.z > 0.0) || !std::isfinite(power.x + power.y + power.z) ||
        !(glm::length(s->direction) > 0.0))
      continue;
    const glm::dvec3 e = glm::normalize(s->direction);
    Light light;
    light.type = LightType::Directional;
    light.vector = glm::dvec3(ca * e.x - sa * e.y, sa * e.x + ca * e.y, e.z); // R_z(+angle) e
    light.intensity = power * sourceMeanCosine(analysis, *s);
    lights.push_back(light);
  }
  return lights;
}
} // namespace aniso
