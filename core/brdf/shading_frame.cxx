#include "core/brdf/shading_frame.h"

#include "core/maps/quaternion_map.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
bool usable(const glm::dvec3& x)
{
  const double len = glm::length(x);
  return std::isfinite(len) && len > 0.0;
}
} // namespace

Frame perturbedFrame(const glm::dvec3& interpolatedNormal, const glm::dvec3& interpolatedTangent,
                     const glm::dvec3& mapNormal, const glm::dvec2& mapTangent)
{
  if (!usable(interpolatedNormal))
    return Frame{};
  const glm::dvec3 tangentHint =
      usable(interpolatedTangent) ? interpolatedTangent : glm::dvec3(1.0, 0.0, 0.0);
  const Frame base = Frame::fromNormalTangent(interpolatedNormal, tangentHint);

  // The tilted frame in the base frame's tangent space, then in world space. Renormalised
  // because the quaternion products carry a few ulps of error.
  const Frame local = frameFromQuaternion(quaternionFromNormal(mapNormal));
  const glm::dvec3 n = glm::normalize(base.toWorld(local.n));
  glm::dvec3 t = glm::normalize(base.toWorld(local.t));
  const glm::dvec3 b = glm::normalize(base.toWorld(local.b));

  const double x = mapTangent.x;
  const double y = mapTangent.y;
  if (std::isfinite(x) && std::isfinite(y) && (x != 0.0 || y != 0.0))
    t = x * t + y * b;
  return Frame::fromNormalTangent(n, t);
}

ScaledTangents scaledTangents(const Frame& frame, double alphaX, double alphaY)
{
  return {frame.t / alphaX, frame.b / alphaY};
}
} // namespace aniso
