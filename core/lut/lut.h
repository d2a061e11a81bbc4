#pragma once
// Lookup tables of the AS method (docs/METHOD.md, source 1), float, baked on all cores,
// deterministic (same inputs, same bits, whatever the thread count), cached by their inputs.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/error.h"

#include <atomic>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
// Half-vector LUT: size x size RGBA32F. Texel (i, j) (column i, row j, row 0 first in memory)
// holds the sample at xi = ((i + 0.5) / size, (j + 0.5) / size):
// RGB = h = sampleHalfVector(lobe, xi) in tangent space (unit, h.z >= 0),
// A = log2 p_h(h) = log2PdfHalfVector(lobe, h).
// Why log2: p_h peaks at sqrt((n_u+1)(n_v+1))/(2 pi), ~1.6e5 for exponents of 1e6, beyond the
// half-float maximum 65504, while log2 p_h stays in [-17, 18] for every texel and exponent in
// [0, 1e6] and keeps 11 significant bits in a half float (|error in A| <= |A| 2^-11). The
// shader recovers p_h = exp2(A) where it needs the density itself; a mip level from the
// sample's solid angle uses A directly.
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
// s = sum (n.l)(1 - chi) / max(n.v, n.l) / N, b = sum (n.l) chi / max(n.v, n.l) / N with
// chi = (1 - v.h)^5, l = 2 (v.h) h - v; samples with n.l <= 0 or v.h <= 0 contribute 0.
// A view below the horizon (n.v < 0) gives (0, 0).
glm::dvec2 sizeBiasAt(const AsLobe& lobe, const glm::dvec3& view, int samples);

// Thrown by a bake whose cancel flag was set: it stopped early and made nothing.
class BakeCancelled : public Error
{
public:
  using Error::Error;
};

// threads: 0 uses every hardware thread; the result does not depend on it (every texel is
// computed alone, in the same order). Invalid inputs throw aniso::Error "name: reason".
// cancel: when another thread sets it, the bake stops after the rows in progress and throws
// BakeCancelled (an interactive caller drops a bake that newer inputs made stale).
HalfVectorLut bakeHalfVectorLut(const AsLobe& lobe, int size, int threads = 0,
                                const std::atomic<bool>* cancel = nullptr);
BrdfLut bakeBrdfLut(const AsLobe& lobe, int size, int samples, int threads = 0,
                    const std::atomic<bool>* cancel = nullptr);

// Limits checked by the bakers (aniso::Error otherwise).
constexpr int kMinLutSize = 2;
constexpr int kMaxLutSize = 4096;
constexpr int kMaxLutSamples = 1 << 20;

// Throws aniso::Error naming the parameter ("n_u", "n_v" as validateLobe does, "size",
// "samples") and the reason unless exponents are finite in [0, kMaxExponent], size in
// [kMinLutSize, kMaxLutSize] and samples in [1, kMaxLutSamples].
void checkLutInputs(const AsLobe& lobe, int size, int samples = 1);
} // namespace aniso
