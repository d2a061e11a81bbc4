#pragma once
// Tangent-plane rotation (TPR) maps (DESIGN.md, source 1): two channels (x, y), the rotated
// tangent in the tangent plane of the (quaternion) frame; b = J t (90 degree rotation).
#include <string>

#include <glm/vec2.hpp>

#include "image/image.h"

namespace aniso
{
enum class TprPattern
{
  Linear,   // straight brushing at angleDegrees from +u
  Circular, // concentric circles around centre (vinyl, CD, turned face)
  Radial,   // rays from centre
  Spiral,   // circles opened by pitchDegrees towards the rays
  Wave      // x = cos(pi v), y = sin(pi v)
};

struct TprParams
{
  TprPattern pattern = TprPattern::Linear;
  double angleDegrees = 0.0;         // Linear
  glm::dvec2 centre{0.5, 0.5};       // Circular, Radial, Spiral, in (u, v)
  double pitchDegrees = 15.0;        // Spiral
};

// Parses "linear[:ANGLE]", "circular[:U,V]", "radial[:U,V]", "spiral[:U,V[:PITCH]]", "wave".
// Throws aniso::Error naming the text and the reason.
TprParams parseTprPattern(const std::string& text);

// Unit tangent (x, y) at texture coordinate (u, v) (v = 0 at the bottom row).
glm::dvec2 tprTangentAt(const TprParams& params, const glm::dvec2& uv);

// RG float map (x, y) of width x height; row 0 is the top row (v = 1 - (row + 0.5) / height).
Image bakeTprMap(const TprParams& params, int width, int height);

// From an angle image: channel 0 in [0, 1] maps to an angle in [0, pi] from +u.
Image tprFromAngleImage(const Image& angles);
} // namespace aniso
