#include "core/sampling/hammersley.h"

#include "core/error.h"

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

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

bool powerOfTwo(uint32_t count)
{
  return count != 0 && (count & (count - 1)) == 0;
}

// Whether the d x d submatrix of the generator (rows [0, d): the fraction's digits 1 to d;
// columns [m - d, m): bits m - d to m - 1 of the index) is invertible over GF(2). Its rows as
// bit masks, eliminated.
bool invertible(const SequenceColumns& columns, uint32_t m, uint32_t d)
{
  std::array<uint32_t, 32> rows{};
  for (uint32_t r = 0; r < d; ++r)
  {
    for (uint32_t c = m - d; c < m; ++c)
    {
      if (columns[c] & (0x80000000u >> r))
      {
        rows[r] |= 1u << (c - (m - d));
      }
    }
  }
  for (uint32_t r = 0; r < d; ++r)
  {
    // A pivot for the lowest bit left in row r's place: a later row that has it comes up.
    uint32_t pivot = r;
    while (pivot < d && rows[pivot] == 0)
    {
      ++pivot;
    }
    if (pivot == d)
    {
      return false;
    }
    std::swap(rows[r], rows[pivot]);
    const uint32_t low = rows[r] & (~rows[r] + 1u);
    for (uint32_t k = 0; k < d; ++k)
    {
      if (k != r && (rows[k] & low))
      {
        rows[k] ^= rows[r];
      }
    }
  }
  return true;
}

SequenceColumns buildSequenceColumns(uint32_t m0)
{
  SequenceColumns columns{};
  // The corner: index bit c to digit m0 - c, so that point i < 2^m0 has x = i / 2^m0.
  for (uint32_t c = 0; c < m0; ++c)
  {
    columns[c] = 0x80000000u >> (m0 - 1 - c);
  }
  // Column m - 1 enters the nets of 2^m points: its digits 1 to m one by one, each making the
  // submatrix of the rows so far and the last columns invertible (its cofactor is the submatrix
  // of the net before, invertible, so exactly one choice does); deeper digits 0.
  for (uint32_t m = m0 + 1; m <= 32; ++m)
  {
    for (uint32_t d = 1; d <= m; ++d)
    {
      if (!invertible(columns, m, d))
      {
        columns[m - 1] ^= 0x80000000u >> (d - 1);
      }
    }
  }
  return columns;
}
} // namespace

const SequenceColumns& sequenceColumns(uint32_t count)
{
  // Corners of 1 to 4 bits; the first is Sobol's own, for every count without a corner.
  static const std::array<SequenceColumns, 4> tables{
      buildSequenceColumns(1), buildSequenceColumns(2), buildSequenceColumns(3),
      buildSequenceColumns(4)};
  static_assert(kMaxSequenceCount == 16, "a table per power of two up to the largest count");
  const bool corner = powerOfTwo(count) && count >= 2 && count <= kMaxSequenceCount;
  return tables[corner ? log2Block(count) - 1 : 0];
}

uint32_t sequenceBits(uint32_t index, const SequenceColumns& columns)
{
  uint32_t bits = 0;
  for (uint32_t c = 0; index != 0; ++c, index >>= 1)
  {
    if (index & 1u)
    {
      bits ^= columns[c];
    }
  }
  return bits;
}

SequenceBlock sequenceBlock(uint32_t frame, uint32_t count)
{
  const uint32_t index = frame << log2Block(count);
  return {sequenceBits(index, sequenceColumns(count)), reverseBits(index)};
}

bool takesSequence(uint32_t frame, uint32_t count)
{
  return count >= 2 && count <= kMaxSequenceCount && (frame >= 2 || powerOfTwo(count));
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
  return {static_cast<double>(sequenceBits(index, sequenceColumns(count))) * 0x1.0p-32,
          radicalInverse2(index)};
}

glm::dvec2 frameShift(uint32_t frame)
{
  const uint64_t k = frame;
  return {fractionToDouble(k * kR2Alpha1), fractionToDouble(k * kR2Alpha2)};
}
} // namespace aniso
