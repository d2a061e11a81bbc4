#pragma once
// Height maps as surfaces: one tile covers [0, 1)^2 of texture space and repeats; image row 0 is
// the top (v = 1), so texel (x, y) sits at u = (x + 0.5) / W, v = 1 - (y + 0.5) / H. Heights are
// in texture units once multiplied by `scale`. Slopes are dimensionless: (dh/du, dh/dv), and the
// normal of a slope (x, y) is normalize(-x, -y, 1), so slope = (-n.x / n.z, -n.y / n.z).
#include "core/image/image.h"

#include <cstdint>
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

// A size x size tiling height map (texture units) of `waves` random-phase plane waves with
// integer frequencies of up to maxFrequency per tile along each axis (the zero wave left out),
// amplitudes 1 / frequency so that each wave adds the same slope variance, scaled so that each
// slope axis has deviation slopeDeviation: a sum of many independent waves, so its slopes are
// close to Gaussian (the relief LEADR assumes). The same map for the same seed on every machine.
// Throws aniso::Error "wave relief: reason" unless size >= 4, waves >= 1, maxFrequency >= 1 and
// slopeDeviation is finite and >= 0.
Image randomWaveHeight(int size, double slopeDeviation, int waves = 96, int maxFrequency = 6,
                       std::uint32_t seed = 7);
} // namespace aniso
