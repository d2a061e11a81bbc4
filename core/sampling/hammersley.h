#pragma once
// Low-discrepancy points for the per-fragment sample loops and the LUT bakers.
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>

namespace aniso
{
// Base-2 radical inverse (van der Corput) of i, in [0, 1).
double radicalInverse2(uint32_t i);

// Point i of an n-point Hammersley set: (i / n, radicalInverse2(i)). Requires n > 0, i < n.
glm::dvec2 hammersley(uint32_t i, uint32_t n);

// Cranley-Patterson rotation: fract(p + shift), kept strictly below 1.
glm::dvec2 cranleyPatterson(const glm::dvec2& p, const glm::dvec2& shift);

// Shift of progressive frame k: frame 0 is (0, 0) (the unrotated set); later frames follow
// the R2 low-discrepancy sequence. The microstructure's frames draw their seeds from it.
glm::dvec2 frameShift(uint32_t frame);

// The sequences the progressive frames take their points from: (x_j, radicalInverse2(j)), x_j
// the XOR of the columns of the set bits of j (a digital sequence, linear over GF(2) in j's
// bits: column c is the x of j = 2^c, as a 32-bit binary fraction). For COUNT = 2^m0 points a
// frame, m0 >= 2, the columns of the first m0 bits put digit m0 - c of x at bit c, so that the
// first block of COUNT points is the Hammersley set (i / COUNT, radicalInverse2(i)); each later
// column is chosen digit by digit so that the first 2^m points are a (0, m, 2)-net for every
// m >= m0 (one choice at each digit: docs/METHOD.md, "Progressive frames"); deeper digits 0.
// For any other COUNT (and for 1 and 2 points, where that corner is Sobol's own), Sobol's second
// dimension (direction numbers v_1 = 1/2, v_j = v_{j-1} XOR v_{j-1} / 2: Pascal's triangle
// modulo 2, which the construction gives from a corner of one bit).
using SequenceColumns = std::array<uint32_t, 32>;
const SequenceColumns& sequenceColumns(uint32_t count);
uint32_t sequenceBits(uint32_t index, const SequenceColumns& columns);

// Point i of progressive frame k's set of COUNT points, what the environment material's
// shader samples with (docs/METHOD.md, "Progressive frames"). From COUNT 2 to
// kMaxSequenceCount, frame k is the block [k B, k B + COUNT) of COUNT's sequence above, B =
// COUNT rounded up to a power of two, point i its index k B + i: for a COUNT of 2^m, from frame 0
// on (frame 0 is then the Hammersley set, the best single frame measured), so that each frame
// is a (0, m, 2)-net and frames [0, 2^a) together, and [2^a, 2^(a+1)), one (0, m + a, 2)-net: the
// frames fill the square as one stratified set, where rotating one set anew each frame only
// averages copies of it. For other COUNTs, from frame 2 on; frames 0 and 1 are the Hammersley
// set, frame 1 rotated by frameShift(1). Frames of one point, and of more than
// kMaxSequenceCount, are all rotated so, frame k by frameShift(k): measured, the rotation
// converged to a lower error than the sequence at one and at 32 samples a frame. Requires
// i < COUNT; k B counts modulo 2^32.
constexpr uint32_t kMaxSequenceCount = 16;
glm::dvec2 progressivePoint(uint32_t frame, uint32_t i, uint32_t count);
// Whether frame k's set of COUNT points is a block of the sequence (else the rotated set).
bool takesSequence(uint32_t frame, uint32_t count);

// The bits (32-bit binary fractions) of point k B of the sequence, the first of frame k's block
// for sets of COUNT points: point k B + i is point i XOR it in each coordinate (the sequence is
// linear over GF(2) in its index's bits, and k B has none of i's). The shader takes the block's
// points so, for the material's sample count and, with a block of their own, for the sources'
// samples (env-sampling sources).
struct SequenceBlock
{
  uint32_t x = 0;
  uint32_t y = 0;
};
SequenceBlock sequenceBlock(uint32_t frame, uint32_t count);
} // namespace aniso
