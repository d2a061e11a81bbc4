#pragma once
// Low-discrepancy points for the per-fragment sample loops and the LUT bakers.
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

// Sobol's second dimension of index i (primitive polynomial x + 1: direction numbers
// v_1 = 1/2, v_j = v_{j-1} XOR v_{j-1} / 2), as the bits of a 32-bit binary fraction.
uint32_t sobol2Bits(uint32_t i);

// Point i of progressive frame k's set of COUNT points, what the environment material's
// shader samples with (docs/METHOD.md, "Progressive frames"). Frames 0 and 1 are the Hammersley
// set, frame 1 rotated by frameShift(1) (the best single frame, and the best pair measured).
// Frames of one point, and of more than kMaxSequenceCount, are all rotated so, frame k by
// frameShift(k): measured, the rotation converged to a lower error than the sequence below at
// one and at 32 samples a frame. From COUNT 2 to kMaxSequenceCount, frame k >= 2 is the block
// [k B, k B + COUNT) of the (0,2)-sequence (sobol2(j), radicalInverse2(j)), B = COUNT rounded
// up to a power of two, point i its index k B + i. For a COUNT of 2^m each frame k >= 2 is a
// (0, m, 2)-net and frames [2^a, 2^(a+1)), a >= 1, together one (0, m + a, 2)-net: the frames
// fill the square as one stratified set, where rotating one set anew each frame only averages
// copies of it. Requires i < COUNT; k B counts modulo 2^32.
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
