#include "core/sampling/hammersley.h"

#include "core/error.h"

#include <cmath>
#include <limits>
#include <string>

namespace aniso
{
namespace
{
constexpr double kBelowOne = 1.0 - std::numeric_limits<double>::epsilon() / 2.0;

// 1/g and 1/g^2 for the plastic constant g (the real root of x^3 = x + 1), as 64-bit binary
// fractions: frame shifts are then exact modular sums, with no loss of precision at large k.
constexpr uint64_t kR2Alpha1 = 0xC13FA9A902A6328FULL;
constexpr uint64_t kR2Alpha2 = 0x91E10DA5C79E7B1DULL;

// Top 53 bits of a 64-bit binary fraction, as a double in [0, 1).
double fractionToDouble(uint64_t f)
{
  return static_cast<double>(f >> 11) * 0x1.0p-53;
}

double wrapUnit(double x)
{
  const double f = x - std::floor(x);
  // x just below an integer rounds up to 1 here; keep the largest value below 1 instead.
  return f < 1.0 ? f : kBelowOne;
}

uint32_t reverseBits(uint32_t i)
{
  uint32_t bits = i;
  bits = (bits << 16) | (bits >> 16);
  bits = ((bits & 0x00FF00FFu) << 8) | ((bits & 0xFF00FF00u) >> 8);
  bits = ((bits & 0x0F0F0F0Fu) << 4) | ((bits & 0xF0F0F0F0u) >> 4);
  bits = ((bits & 0x33333333u) << 2) | ((bits & 0xCCCCCCCCu) >> 2);
  bits = ((bits & 0x55555555u) << 1) | ((bits & 0xAAAAAAAAu) >> 1);
  return bits;
}
} // namespace

double radicalInverse2(uint32_t i)
{
  return static_cast<double>(reverseBits(i)) * 0x1.0p-32;
}

glm::dvec2 hammersley(uint32_t i, uint32_t n)
{
  if (n == 0)
  {
    throw errorAbout("hammersley", "the point count must be positive");
  }
  if (i >= n)
  {
    throw errorAbout("hammersley", "index " + std::to_string(i) + " is not below the point count " +
                                       std::to_string(n));
  }
  return {static_cast<double>(i) / static_cast<double>(n), radicalInverse2(i)};
}

glm::dvec2 cranleyPatterson(const glm::dvec2& p, const glm::dvec2& shift)
{
  return {wrapUnit(p.x + shift.x), wrapUnit(p.y + shift.y)};
}

uint32_t sobol2Bits(uint32_t i)
{
  uint32_t result = 0;
  for (uint32_t v = 0x80000000u; i != 0; i >>= 1, v ^= v >> 1)
  {
    if (i & 1u)
    {
      result ^= v;
    }
  }
  return result;
}

namespace
{
uint32_t log2Block(uint32_t count)
{
  uint32_t log2 = 0;
  while (log2 < 31 && (1u << log2) < count)
  {
    ++log2;
  }
  return log2;
}
} // namespace

SequenceBlock sequenceBlock(uint32_t frame, uint32_t count)
{
  const uint32_t index = frame << log2Block(count);
  return {sobol2Bits(index), reverseBits(index)};
}

bool takesSequence(uint32_t frame, uint32_t count)
{
  return frame >= 2 && count >= 2 && count <= kMaxSequenceCount;
}

glm::dvec2 progressivePoint(uint32_t frame, uint32_t i, uint32_t count)
{
  if (!takesSequence(frame, count))
  {
    return cranleyPatterson(hammersley(i, count), frameShift(frame));
  }
  if (i >= count)
  {
    throw errorAbout("progressive point", "index " + std::to_string(i) +
                                              " is not below the point count " +
                                              std::to_string(count));
  }
  const uint32_t index = (frame << log2Block(count)) | i;
  return {static_cast<double>(sobol2Bits(index)) * 0x1.0p-32, radicalInverse2(index)};
}

glm::dvec2 frameShift(uint32_t frame)
{
  const uint64_t k = frame;
  return {fractionToDouble(k * kR2Alpha1), fractionToDouble(k * kR2Alpha2)};
}
} // namespace aniso
