#pragma once
// Float cubemaps with full mip chains, and 9-coefficient spherical-harmonic irradiance.
#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "env/environment.h"
#include "image/image.h"

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

// Direction through the centre of texel (x, y) of face f at resolution size.
glm::dvec3 cubeTexelDirection(int face, int x, int y, int size);
// Face and (s, t) in [0, 1]^2 for a direction.
int cubeFaceOf(const glm::dvec3& d, double* s, double* t);
// Solid angle of a texel (exact, from the area-element integral).
double cubeTexelSolidAngle(int x, int y, int size);

// Level 0 sampled from env (supersampled per texel), then 2x2 box-filtered down to 1x1.
Cubemap buildCubemap(const Environment& env, int size, int supersample = 2);

// Spherical harmonics up to l = 2 of the radiance (real basis, standard ordering
// Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22 in world coordinates).
using Sh9 = std::array<glm::dvec3, 9>;
Sh9 projectSh9(const Cubemap& cube);
Sh9 projectSh9(const Environment& env, int samplesPerAxis = 256);
// Irradiance E(n) = integral of L (n.l)+ over the sphere, from the coefficients
// (cosine-lobe convolution); diffuse radiance is albedo / pi * E.
glm::dvec3 irradianceSh9(const Sh9& sh, const glm::dvec3& n);
} // namespace aniso
