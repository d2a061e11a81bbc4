#pragma once
// Per-pixel shading frames (docs/METHOD.md, sources 1 and 2). Interpolated vertex normals and tangents
// are not unit length (nor orthogonal) inside a triangle, so they are renormalised and made
// orthogonal here; a normal map then tilts the frame by the minimal rotation (the quaternion
// construction of source 1), and a tangent map turns t within the tilted tangent plane.
#include "core/frame.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace aniso
{
// World-space frame at a pixel:
//  1. n0 = normalize(interpolatedNormal); t0 = interpolatedTangent made orthogonal to n0 and
//     normalised (Frame::fromNormalTangent), b0 = n0 x t0;
//  2. mapNormal (tangent space of the base frame, any length) rotates (t0, b0, n0) by the
//     smallest rotation taking n0 to it: (t', b', n');
//  3. mapTangent (x, y) (any length) gives t = normalize(x t' + y b'), b = n' x t.
// A zero or non-finite interpolated normal gives the default frame (+X, +Y, +Z); a zero or
// non-finite map normal leaves the frame untilted; a zero map tangent keeps t'.
Frame perturbedFrame(const glm::dvec3& interpolatedNormal, const glm::dvec3& interpolatedTangent,
                     const glm::dvec3& mapNormal = {0.0, 0.0, 1.0},
                     const glm::dvec2& mapTangent = {1.0, 0.0});

// The vectors source 2 stores in its material textures for a frame and roughnesses:
// t / alpha_x and b / alpha_y. For a unit h, (h . tScaled)^2 + (h . bScaled)^2 is the
// roughness-weighted tangential part of h that Ward and Blinn-Phong exponentiate.
struct ScaledTangents
{
  glm::dvec3 tScaled{1.0, 0.0, 0.0};
  glm::dvec3 bScaled{0.0, 1.0, 0.0};
};
ScaledTangents scaledTangents(const Frame& frame, double alphaX, double alphaY);
} // namespace aniso
