#pragma once
// Lookup tables of the AS method (DESIGN.md, source 1), float, baked on all cores,
// deterministic (same inputs, same bits), cached by their inputs.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "brdf/ashikhmin_shirley.h"

namespace aniso
{
// Half-vector LUT: size x size RGBA32F. Texel (i, j) (column i, row j, row 0 first in memory)
// holds the sample at xi = ((i + 0.5) / size, (j + 0.5) / size):
// RGB = h in tangent space, A = log2 p_h(h) (survives half floats for exponents up to 1e6;
// the shader recovers p_h = exp2(A) only where it needs it, e.g. for a filtered lookup).
struct HalfVectorLut
{
  int size = 0;
  AsLobe lobe;
  std::vector<float> rgba; // size * size * 4
};

// BRDF LUT: size x size RG32F, R = s ("size"), G = b ("bias"), F0 * s + b the directional
// albedo for F0. Texel (i, j) is at (u, v) = ((i + 0.5) / size, (j + 0.5) / size) with
// u = (2/pi) atan(|b.v| / |t.v|), v = sqrt(n.v).
struct BrdfLut
{
  int size = 0;
  int samples = 0;
  AsLobe lobe;
  std::vector<float> rg; // size * size * 2
};

// (u, v) of a tangent-space view direction, and the view direction of (u, v) (t.v, b.v >= 0).
glm::dvec2 brdfLutCoords(const glm::dvec3& view);
glm::dvec3 brdfLutView(const glm::dvec2& uv);

// s and b for one view by N importance samples (Hammersley): the definition the LUT bakes.
glm::dvec2 sizeBiasAt(const AsLobe& lobe, const glm::dvec3& view, int samples);

HalfVectorLut bakeHalfVectorLut(const AsLobe& lobe, int size);
BrdfLut bakeBrdfLut(const AsLobe& lobe, int size, int samples);

// Limits checked by the bakers (aniso::Error otherwise).
constexpr int kMinLutSize = 2;
constexpr int kMaxLutSize = 4096;
constexpr int kMaxLutSamples = 1 << 20;
constexpr double kMaxExponent = 1e6;
} // namespace aniso
