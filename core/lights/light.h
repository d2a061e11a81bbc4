#pragma once
// Point and directional lights (docs/METHOD.md, source 2) and the sum every lit model evaluates:
// radiance = sum over lights of term(v, l) * E_light, where E_light is the irradiance the light
// delivers on a surface facing it and term(v, l) is the model's reflected radiance per unit of
// that irradiance (for a BRDF: f(v, l) (n.l)+).
#include "core/frame.h"

#include <algorithm>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace aniso
{
enum class LightType
{
  Directional, // from direction `vector` (unit, pointing towards the light), infinitely far
  Point        // at position `vector`, intensity falling off as 1 / distance^2
};

struct Light
{
  LightType type = LightType::Directional;
  // Directional: unit direction towards the light (dir:0,0,1 shines straight down, from the
  // zenith of the Z-up world). Point: position in world space.
  glm::dvec3 vector{0.0, 0.0, 1.0};
  // Linear RGB, >= 0. Directional: irradiance on a surface facing the light (W m^-2 per
  // channel). Point: radiant intensity (W sr^-1), so irradiance is intensity / distance^2.
  glm::dvec3 intensity{1.0};
};

// What a light delivers at a surface point.
struct LightArrival
{
  glm::dvec3 direction{0.0, 0.0, 1.0}; // unit, from the point towards the light (world space)
  glm::dvec3 irradiance{0.0};          // on a surface facing the light, before any cosine
  double distance = 0.0;               // to a point light; infinity for a directional light
};

// Closer than this to a point light, the point receives nothing: the falloff would diverge and
// the direction is undefined.
constexpr double kMinPointLightDistance = 1e-9;

// Direction and irradiance of `light` at `position` (world space).
LightArrival arriveAt(const Light& light, const glm::dvec3& position);

// Parses "dir:X,Y,Z:INTENSITY" or "point:X,Y,Z:INTENSITY" (type names case-insensitive, blanks
// around numbers allowed). INTENSITY is either one number (white) or R,G,B. Directions are
// normalised and must not be zero; every number must be finite and intensities >= 0.
// Throws aniso::Error "light "TEXT": reason".
Light parseLight(const std::string& text);

// The text parseLight reads back to the same light (numbers printed to full precision).
std::string formatLight(const Light& light);

// Throws aniso::Error "light: reason" for a zero or non-finite direction, a non-finite position
// or a negative or non-finite intensity. Lights built in code (not parsed) are checked with it.
void validateLight(const Light& light);

// Sum over lights of term(vLocal, lLocal) * irradiance. term receives the view and light
// directions in the tangent space of `frame` (t = +X, b = +Y, n = +Z) and returns RGB radiance
// per unit irradiance, including whatever cosine the model applies. Lights below the geometric
// horizon of the frame (l.z <= 0) or a view below it contribute nothing.
template <class Term>
glm::dvec3 sumOverLights(const std::vector<Light>& lights, const Frame& frame,
                         const glm::dvec3& position, const glm::dvec3& viewWorld, const Term& term)
{
  glm::dvec3 sum(0.0);
  const glm::dvec3 v = frame.toLocal(viewWorld);
  if (!(v.z > 0.0))
    return sum;
  for (const Light& light : lights)
  {
    const LightArrival arrival = arriveAt(light, position);
    const glm::dvec3 l = frame.toLocal(arrival.direction);
    if (!(l.z > 0.0))
      continue;
    sum += term(v, l) * arrival.irradiance;
  }
  return sum;
}

// The usual case of sumOverLights: term = brdf(v, l) * (n.l).
template <class Brdf>
glm::dvec3 shadeBrdfWithLights(const std::vector<Light>& lights, const Frame& frame,
                               const glm::dvec3& position, const glm::dvec3& viewWorld,
                               const Brdf& brdf)
{
  return sumOverLights(lights, frame, position, viewWorld,
                       [&](const glm::dvec3& v, const glm::dvec3& l)
                       { return brdf(v, l) * std::max(l.z, 0.0); });
}
} // namespace aniso
