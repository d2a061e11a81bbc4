#pragma once
// Quaternion maps from normal maps (DESIGN.md, source 1): n' = (x, y, z) gives
// a = sqrt((z+1)/2), b = y/(2a), c = -x/(2a); the frame t', b', n' follows from (a, b, c).
#include <cstddef>

#include <glm/vec3.hpp>

#include "frame.h"
#include "image/image.h"

namespace aniso
{
struct QuaternionBakeStats
{
  std::size_t texels = 0;
  std::size_t nonUnit = 0;   // |n| off 1 by more than 1e-3: normalised
  std::size_t invalid = 0;   // NaN/Inf or zero length: replaced by (0, 0, 1)
  std::size_t antipodal = 0; // z close to -1: a -> 0, axis taken from (x, y) (or +t if none)
};

// (a, b, c) of a unit normal; a >= 0 and a^2 + b^2 + c^2 = 1.
glm::dvec3 quaternionFromNormal(const glm::dvec3& n);
// The rotated frame of (a, b, c): t', b', n' per DESIGN.md.
Frame frameFromQuaternion(const glm::dvec3& abc);

// Normal map: integer formats are decoded n = 2 c - 1, float formats are taken as stored.
// Output: RGBA float, RGB = (a, b, c) as stored (signed), A = 1.
Image bakeQuaternionMap(const Image& normalMap, bool integerEncoded, QuaternionBakeStats* stats);
} // namespace aniso
