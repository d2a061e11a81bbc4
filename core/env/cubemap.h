#pragma once
// Float cubemaps with full mip chains, and 9-coefficient spherical-harmonic irradiance.
#include "core/env/environment.h"
#include "core/image/image.h"

#include <array>
#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
// Faces in OpenGL order +X, -X, +Y, -Y, +Z, -Z with OpenGL's (sc, tc, ma) table, so that
// texture(cube, d) returns radiance(d) for world directions d. Row j of a face image is at
// tc = (j + 0.5) / size (row 0 is uploaded first, i.e. OpenGL t = 0).
struct Cubemap
{
  int size = 0; // of level 0
  // mips[level][face]: RGB float, size >> level squared, down to 1x1.
  std::vector<std::array<Image, 6>> mips;
};

// Direction (unit) through the centre of texel (x, y) of face f at resolution size.
glm::dvec3 cubeTexelDirection(int face, int x, int y, int size);
// Face and (s, t) in [0, 1]^2 for a direction. Ties between axes go to X, then Y; the zero
// vector gives +Z at (0.5, 0.5).
int cubeFaceOf(const glm::dvec3& d, double* s, double* t);
// Solid angle of a texel (exact, from the area-element integral); the same on every face.
double cubeTexelSolidAngle(int x, int y, int size);

// Level 0 sampled from env (supersample^2 samples per texel, weighted by solid angle), then
// 2x2 box-filtered down to 1x1, so every level has the same mean texel value. size is a power
// of two in [1, 8192], supersample in [1, 16]; otherwise aniso::Error naming the argument.
Cubemap buildCubemap(const Environment& env, int size, int supersample = 2);

// Spherical harmonics up to l = 2 of the radiance (real basis, standard ordering
// Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22 in world coordinates).
using Sh9 = std::array<glm::dvec3, 9>;
// From level 0, each texel weighted by its exact solid angle.
Sh9 projectSh9(const Cubemap& cube);
// By a product rule: samplesPerAxis Gauss-Legendre nodes in cos(theta) times 2 * samplesPerAxis
// equally spaced azimuths (exact when the radiance is a polynomial in the direction of degree
// <= 2 samplesPerAxis - 3). samplesPerAxis >= 2.
Sh9 projectSh9(const Environment& env, int samplesPerAxis = 256);
// Irradiance E(n) = integral of L (n.l)+ over the sphere, from the coefficients
// (cosine-lobe convolution); diffuse radiance is albedo / pi * E.
glm::dvec3 irradianceSh9(const Sh9& sh, const glm::dvec3& n);
} // namespace aniso
