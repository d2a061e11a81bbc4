#pragma once
// Tangent-plane rotation (TPR) maps (docs/METHOD.md, source 1): two channels (x, y), the rotated
// tangent in the tangent plane of the (quaternion) frame; b = J t (90 degree rotation).
#include "core/image/image.h"

#include <glm/vec2.hpp>
#include <string>

namespace aniso
{
enum class TprPattern
{
  Linear,   // straight brushing at angleDegrees from +u
  Circular, // concentric circles around centre (vinyl, CD, turned face), counter-clockwise
  Radial,   // rays from centre, pointing outwards
  Spiral,   // circles opened by pitchDegrees towards the rays
  Wave      // x = cos(pi v), y = sin(pi v)
};

struct TprParams
{
  TprPattern pattern = TprPattern::Linear;
  double angleDegrees = 0.0;   // Linear
  glm::dvec2 centre{0.5, 0.5}; // Circular, Radial, Spiral, in (u, v)
  double pitchDegrees = 15.0;  // Spiral, in [-90, 90]: 0 is Circular, 90 is Radial
};

// Parses "linear[:ANGLE]", "circular[:U,V]", "radial[:U,V]", "spiral[:U,V[:PITCH]]", "wave"
// (names case-insensitive, numbers finite, angles in degrees). Omitted values keep the
// TprParams defaults. Throws aniso::Error naming the text and the reason.
TprParams parseTprPattern(const std::string& text);

// Unit tangent (x, y) at texture coordinate (u, v) (v = 0 at the bottom row). With r = uv -
// centre: Circular (-r.y, r.x)/|r|, Radial r/|r|, Spiral cos(p) circular + sin(p) radial.
// At the centre itself (r = 0) the direction is undefined; +u, (1, 0), is returned there.
glm::dvec2 tprTangentAt(const TprParams& params, const glm::dvec2& uv);

// RG float map (x, y) of width x height, each in 1..32768 (else aniso::Error); row 0 is the
// top row: texel (col, row) is sampled at u = (col + 0.5) / width, v = 1 - (row + 0.5) / height.
Image bakeTprMap(const TprParams& params, int width, int height);

// From an angle image: channel 0 in [0, 1] maps to an angle in [0, pi] from +u, (x, y) =
// (cos(pi a), sin(pi a)); values outside [0, 1] continue the same mapping (a tangent line
// repeats every pi). A non-finite texel or an empty image throws aniso::Error.
Image tprFromAngleImage(const Image& angles);
} // namespace aniso
