#pragma once
// Quaternion maps from normal maps (docs/METHOD.md, source 1): n' = (x, y, z) gives
// a = sqrt((z+1)/2), b = y/(2a), c = -x/(2a); the frame t', b', n' follows from (a, b, c).
#include "core/frame.h"
#include "core/image/image.h"

#include <cstddef>
#include <glm/vec3.hpp>

namespace aniso
{
// |n| further than this from 1 counts as non-unit: 1e-3 for float maps, 1e-2 for integer maps,
// whose 8-bit quantisation alone moves the length by up to sqrt(3)/255 = 0.0068.
constexpr double kNonUnitToleranceFloat = 1e-3;
constexpr double kNonUnitToleranceInteger = 1e-2;
// Shorter than this, a decoded normal has no usable direction (8-bit noise is 0.0068).
constexpr double kMinNormalLength = 1e-2;
// Within 1 degree of (0, 0, -1) (1 + z <= 1 - cos 1deg) counts as antipodal: the rotation is
// close to 180 degrees, so its axis is ill-conditioned and may flip between neighbouring texels.
constexpr double kAntipodalOnePlusZ = 1.5230484360873e-4;

struct QuaternionBakeStats
{
  std::size_t texels = 0;
  std::size_t nonUnit = 0;   // |n| off 1 by more than the tolerance above: normalised
  std::size_t invalid = 0;   // NaN/Inf or length below kMinNormalLength: replaced by (0, 0, 1)
  std::size_t antipodal = 0; // within 1 degree of (0, 0, -1): a -> 0, axis from (y, -x)
};

// (a, b, c) of a normal; a >= 0 and a^2 + b^2 + c^2 = 1. The normal is normalised first; zero
// or non-finite normals give the identity (1, 0, 0). (b, c) is computed as (y, -x)/|(x, y)|
// scaled by sqrt((1-z)/2), equal to (y, -x)/(2a) for unit normals but exact as z -> -1;
// exactly (0, 0, -1) gives (0, 1, 0), the half turn about t.
glm::dvec3 quaternionFromNormal(const glm::dvec3& n);
// The rotated frame of (a, b, c): t', b', n' per docs/METHOD.md.
Frame frameFromQuaternion(const glm::dvec3& abc);

// Normal map: integer formats are decoded n = 2 c - 1, float formats are taken as stored.
// 3 or 4 channels (a fourth is ignored); 2 channels (x, y) reconstruct z = sqrt(max(0,
// 1 - x^2 - y^2)) as two-channel (BC5-style) normal maps do; 0 or 1 channel, or an image
// whose data does not match its size, throws aniso::Error. Any size.
// Output: RGBA float, RGB = (a, b, c) as stored (signed), A = 1. stats may be null.
Image bakeQuaternionMap(const Image& normalMap, bool integerEncoded, QuaternionBakeStats* stats);
} // namespace aniso
