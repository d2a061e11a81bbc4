#pragma once
// Height maps as surfaces: one tile covers [0, 1)^2 of texture space and repeats; image row 0 is
// the top (v = 1), so texel (x, y) sits at u = (x + 0.5) / W, v = 1 - (y + 0.5) / H. Heights are
// in texture units once multiplied by `scale`. Slopes are dimensionless: (dh/du, dh/dv), and the
// normal of a slope (x, y) is normalize(-x, -y, 1), so slope = (-n.x / n.z, -n.y / n.z).
#include "image/image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace aniso
{
// Central differences with wrapping: dh/du = scale (h[x+1] - h[x-1]) W / 2, dh/dv = scale
// (h[y-1] - h[y+1]) H / 2 (rows run downwards in v). Channel 0 of `height` is used. Output: RG
// float. Throws aniso::Error "height map: reason" for an empty image, a non-finite texel or a
// non-finite scale.
Image slopesFromHeight(const Image& height, double scale);

// RGB unit normals from an RG slope image.
Image normalsFromSlopes(const Image& slopes);

// (-n.x / n.z, -n.y / n.z); n.z is floored at 1e-6 so that normals at or below the horizon give
// large finite slopes rather than infinities.
glm::dvec2 slopeOfNormal(const glm::dvec3& n);
glm::dvec3 normalOfSlope(const glm::dvec2& slope);
} // namespace aniso
