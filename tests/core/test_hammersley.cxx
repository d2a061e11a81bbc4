// Hammersley points, Cranley-Patterson rotation and the R2 frame shifts, checked against
// digit-by-digit definitions, exact binary values and stratification properties.
#include "core/error.h"
#include "core/sampling/hammersley.h"

#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace
{
// Reference radical inverse: the binary digits of i, least significant first, written after the
// binary point (the definition, one digit at a time).
double referenceRadicalInverse(uint32_t i)
{
  double value = 0.0;
  double digitWeight = 0.5;
  for (uint32_t rest = i; rest != 0; rest >>= 1)
  {
    if (rest & 1u)
    {
      value += digitWeight;
    }
    digitWeight *= 0.5;
  }
  return value;
}

// Distance on the unit circle (coordinates live on the torus after the rotation).
double circleDistance(double a, double b)
{
  const double d = std::abs(a - b);
  return std::min(d, 1.0 - d);
}
} // namespace

// Exact binary values of the van der Corput sequence, and the definition for many indices.
TEST(Hammersley, RadicalInverseExactValues)
{
  EXPECT_EQ(aniso::radicalInverse2(0), 0.0);
  EXPECT_EQ(aniso::radicalInverse2(1), 0.5);
  EXPECT_EQ(aniso::radicalInverse2(2), 0.25);
  EXPECT_EQ(aniso::radicalInverse2(3), 0.75);
  EXPECT_EQ(aniso::radicalInverse2(4), 0.125);
  EXPECT_EQ(aniso::radicalInverse2(5), 0.625);
  EXPECT_EQ(aniso::radicalInverse2(6), 0.375);
  EXPECT_EQ(aniso::radicalInverse2(0x80000000u), std::ldexp(1.0, -32));
  EXPECT_EQ(aniso::radicalInverse2(0xFFFFFFFFu), 1.0 - std::ldexp(1.0, -32));
  for (uint32_t i = 0; i < 100000; i += 7)
  {
    ASSERT_EQ(aniso::radicalInverse2(i), referenceRadicalInverse(i)) << "i = " << i;
  }
  for (uint32_t i = 0xFFFFFFFFu; i > 0xFFFFFFFFu - 1000u; --i)
  {
    const double r = aniso::radicalInverse2(i);
    ASSERT_EQ(r, referenceRadicalInverse(i)) << "i = " << i;
    ASSERT_LT(r, 1.0);
  }
}

// Points lie in [0, 1)^2 and equal (i/n, radical inverse); with n divisible by 4 the first
// coordinate hits 1/4, 1/2, 3/4 exactly (the sampler's quadrant boundaries).
TEST(Hammersley, PointsAndQuarterValues)
{
  for (uint32_t n : {1u, 3u, 4u, 64u, 200u, 1024u, 1000u})
  {
    for (uint32_t i = 0; i < n; ++i)
    {
      const glm::dvec2 p = aniso::hammersley(i, n);
      ASSERT_GE(p.x, 0.0);
      ASSERT_LT(p.x, 1.0);
      ASSERT_GE(p.y, 0.0);
      ASSERT_LT(p.y, 1.0);
      ASSERT_EQ(p.x, static_cast<double>(i) / static_cast<double>(n));
      ASSERT_EQ(p.y, referenceRadicalInverse(i));
    }
    if (n % 4 == 0)
    {
      EXPECT_EQ(aniso::hammersley(n / 4, n).x, 0.25);
      EXPECT_EQ(aniso::hammersley(n / 2, n).x, 0.5);
      EXPECT_EQ(aniso::hammersley(3 * n / 4, n).x, 0.75);
    }
  }
}

// Invalid arguments are reported as aniso::Error naming the function.
TEST(Hammersley, RejectsInvalidArguments)
{
  EXPECT_THROW(aniso::hammersley(0, 0), aniso::Error);
  EXPECT_THROW(aniso::hammersley(4, 4), aniso::Error);
  try
  {
    aniso::hammersley(5, 4);
    FAIL() << "no error for i >= n";
  }
  catch (const aniso::Error& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("hammersley: ", 0), 0u) << e.what();
  }
}

// For n = 2^m the set is a (0, m, 2)-net: every elementary box of area 1/n (2^j columns by
// 2^(m-j) rows) holds exactly one point. This is the defining property of the construction.
TEST(Hammersley, IsZeroMTwoNet)
{
  const int m = 8;
  const uint32_t n = 1u << m;
  for (int j = 0; j <= m; ++j)
  {
    const double columns = std::ldexp(1.0, j);
    const double rows = std::ldexp(1.0, m - j);
    std::set<std::pair<int, int>> boxes;
    for (uint32_t i = 0; i < n; ++i)
    {
      const glm::dvec2 p = aniso::hammersley(i, n);
      boxes.emplace(static_cast<int>(std::floor(p.x * columns)),
                    static_cast<int>(std::floor(p.y * rows)));
    }
    EXPECT_EQ(boxes.size(), n) << "j = " << j;
  }
}

// The rotation is fract(p + shift) on the torus and never returns 1, including shifts that put
// the sum a hair below an integer (where x - floor(x) rounds to 1) and large or negative shifts.
TEST(Hammersley, CranleyPattersonStaysBelowOne)
{
  const double belowOne = std::nextafter(1.0, 0.0);
  const double tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<std::pair<glm::dvec2, glm::dvec2>> cases = {
      {{0.5, 0.5}, {0.5 - 0x1.0p-60, 0.5 - 0x1.0p-54}},
      {{belowOne, belowOne}, {0x1.0p-54, 0x1.0p-53}},
      {{0.0, 0.0}, {-1e-20, -tiny}},
      {{0.0, 0.25}, {-1.0, -3.0 - 1e-17}},
      {{0.75, 0.3}, {1e9 + 0.3, -1e9 + 0.25}},
      {{0.2, 0.9}, {0.3, 0.2}},
  };
  for (const auto& [p, shift] : cases)
  {
    const glm::dvec2 r = aniso::cranleyPatterson(p, shift);
    for (int c = 0; c < 2; ++c)
    {
      ASSERT_GE(r[c], 0.0);
      ASSERT_LT(r[c], 1.0);
      // Reference: the fractional part computed in long double, compared on the circle.
      const long double sum = static_cast<long double>(p[c]) + static_cast<long double>(shift[c]);
      const double expected = static_cast<double>(sum - std::floor(sum));
      EXPECT_LT(circleDistance(r[c], expected), 1e-6) << "component " << c;
    }
  }
}

// Frame 0 is the unrotated set; frame k is (fract(k/g), fract(k/g^2)) for the plastic constant g,
// the real root of g^3 = g + 1 (solved here by Newton's method in long double).
TEST(Hammersley, FrameShiftFollowsR2)
{
  EXPECT_EQ(aniso::frameShift(0), glm::dvec2(0.0, 0.0));
  long double g = 1.3L;
  for (int it = 0; it < 60; ++it)
  {
    g -= (g * g * g - g - 1.0L) / (3.0L * g * g - 1.0L);
  }
  const long double a1 = 1.0L / g;
  const long double a2 = 1.0L / (g * g);
  std::set<std::pair<double, double>> seen;
  for (uint32_t k = 0; k < 5000; ++k)
  {
    const glm::dvec2 s = aniso::frameShift(k);
    ASSERT_GE(s.x, 0.0);
    ASSERT_LT(s.x, 1.0);
    ASSERT_GE(s.y, 0.0);
    ASSERT_LT(s.y, 1.0);
    const long double x = k * a1;
    const long double y = k * a2;
    ASSERT_LT(circleDistance(s.x, static_cast<double>(x - std::floor(x))), 1e-12) << k;
    ASSERT_LT(circleDistance(s.y, static_cast<double>(y - std::floor(y))), 1e-12) << k;
    seen.emplace(s.x, s.y);
  }
  EXPECT_EQ(seen.size(), 5000u); // no frame repeats another
  // Large frame numbers stay in range (exact modular arithmetic, no growth of rounding).
  const glm::dvec2 last = aniso::frameShift(0xFFFFFFFFu);
  EXPECT_LT(last.x, 1.0);
  EXPECT_LT(last.y, 1.0);
}

// Every rotated frame is still stratified: a shift modulo 1 moves the n columns i/n and the n
// rows (radical inverses of 0..n-1, a permutation of j/n for n = 2^m) by the same amount, so each
// column [i/n, (i+1)/n) and each row holds exactly one point.
TEST(Hammersley, RotatedFramesStayStratified)
{
  const uint32_t n = 256;
  for (uint32_t frame = 0; frame < 64; ++frame)
  {
    const glm::dvec2 shift = aniso::frameShift(frame);
    std::vector<int> columns(n, 0);
    std::vector<int> rows(n, 0);
    for (uint32_t i = 0; i < n; ++i)
    {
      const glm::dvec2 p = aniso::cranleyPatterson(aniso::hammersley(i, n), shift);
      ++columns[static_cast<size_t>(std::floor(p.x * n))];
      ++rows[static_cast<size_t>(std::floor(p.y * n))];
    }
    for (uint32_t c = 0; c < n; ++c)
    {
      ASSERT_EQ(columns[c], 1) << "frame " << frame << ", column " << c;
      ASSERT_EQ(rows[c], 1) << "frame " << frame << ", row " << c;
    }
  }
}

namespace
{
// Whether POINTS (2^t of them) form a (0, t, 2)-net in base 2: every elementary interval
// [x / 2^p, (x + 1) / 2^p) x [y / 2^q, (y + 1) / 2^q) with p + q = t holds exactly one point.
bool isZeroNet(const std::vector<glm::dvec2>& points, int t)
{
  if (points.size() != (std::size_t(1) << t))
  {
    return false;
  }
  for (int p = 0; p <= t; ++p)
  {
    const int q = t - p;
    std::vector<int> count(points.size(), 0);
    for (const glm::dvec2& point : points)
    {
      const auto x = static_cast<std::size_t>(std::floor(point.x * double(1u << p)));
      const auto y = static_cast<std::size_t>(std::floor(point.y * double(1u << q)));
      ++count[(x << q) | y];
    }
    for (int c : count)
    {
      if (c != 1)
      {
        return false;
      }
    }
  }
  return true;
}
} // namespace

// Sobol's second dimension, restated from its definition: direction number v_j is the binary
// fraction of the j-th row of Pascal's triangle modulo 2 (v_1 = 0.1, v_2 = 0.11, v_3 = 0.101,
// v_4 = 0.1111, v_{j+1} = v_j XOR v_j / 2), and point i XORs the v_j of i's set bits.
static uint32_t referenceSobol2Bits(uint32_t i)
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

// The sequence of two points a frame is Sobol's (the construction from a one-bit corner gives
// Pascal's triangle): its exact first values, and its first 2^m values a permutation of j / 2^m.
TEST(ProgressivePoints, SobolSecondDimension)
{
  const aniso::SequenceColumns& sobol = aniso::sequenceColumns(2);
  EXPECT_EQ(aniso::sequenceBits(0, sobol), 0u);
  EXPECT_EQ(aniso::sequenceBits(1, sobol), 0x80000000u); // 0.1
  EXPECT_EQ(aniso::sequenceBits(2, sobol), 0xC0000000u); // 0.11
  EXPECT_EQ(aniso::sequenceBits(3, sobol), 0x40000000u); // 0.1 xor 0.11 = 0.01
  EXPECT_EQ(aniso::sequenceBits(4, sobol), 0xA0000000u); // 0.101
  EXPECT_EQ(aniso::sequenceBits(8, sobol), 0xF0000000u); // 0.1111
  for (uint32_t m = 1; m <= 10; ++m)
  {
    std::set<uint32_t> values;
    for (uint32_t i = 0; i < (1u << m); ++i)
    {
      const uint32_t bits = aniso::sequenceBits(i, sobol);
      EXPECT_EQ(bits, referenceSobol2Bits(i));
      EXPECT_EQ(bits & ((1u << (32 - m)) - 1u), 0u);
      values.insert(bits >> (32 - m));
    }
    EXPECT_EQ(values.size(), std::size_t(1) << m);
  }
}

// The sequences' generators: Sobol's second dimension for counts that are not a power of two
// and for 2 (its corner is the Hammersley set's already); for 4, 8 and 16 points a frame the
// first 2^m points are a (0, m, 2)-net for every m from log2(count) on (up to 2^13 points
// checked), and the first block of count points is the Hammersley set exactly.
TEST(ProgressivePoints, SequencesStartWithTheHammersleySetAndStayNets)
{
  for (uint32_t count : {1u, 2u, 3u, 12u, 24u})
  {
    const aniso::SequenceColumns& columns = aniso::sequenceColumns(count);
    for (uint32_t c = 0; c < 32; ++c)
    {
      EXPECT_EQ(columns[c], referenceSobol2Bits(1u << c)) << count << " points, column " << c;
    }
  }
  for (uint32_t count : {4u, 8u, 16u})
  {
    const aniso::SequenceColumns& columns = aniso::sequenceColumns(count);
    const int m0 = static_cast<int>(std::lround(std::log2(count)));
    for (uint32_t i = 0; i < count; ++i)
    {
      EXPECT_EQ(double(aniso::sequenceBits(i, columns)) * 0x1.0p-32, aniso::hammersley(i, count).x);
    }
    for (int m = m0; m <= 13; ++m)
    {
      std::vector<glm::dvec2> points;
      for (uint32_t j = 0; j < (1u << m); ++j)
      {
        points.push_back(
            {double(aniso::sequenceBits(j, columns)) * 0x1.0p-32, aniso::radicalInverse2(j)});
      }
      EXPECT_TRUE(isZeroNet(points, m)) << count << " points a frame, the first 2^" << m;
    }
    // Below the corner the first points are no net (the Hammersley set's x = i / count).
    EXPECT_FALSE(isZeroNet(
        {{0.0, 0.0},
         {double(aniso::sequenceBits(1, columns)) * 0x1.0p-32, aniso::radicalInverse2(1)}},
        1));
  }
}

// Each frame of 2^m points, from 2 to 16, is a (0, m, 2)-net from frame 0 on, frame 0 the
// Hammersley set, and the frames [0, 2^a) and [2^a, 2^(a+1)) together are each one
// (0, m + a, 2)-net: the frames stratify as one set (frames of one point or of more than 16:
// all rotated by frameShift). Rotating one set anew each frame (frameShift) does not: eight
// rotated copies of a 16-point set are not a 128-point net.
TEST(ProgressivePoints, FramesFormNets)
{
  for (uint32_t frame = 0; frame < 100; ++frame)
  {
    EXPECT_EQ(aniso::progressivePoint(frame, 0, 1), aniso::frameShift(frame));
    for (uint32_t i = 0; i < 32; ++i)
    {
      EXPECT_EQ(aniso::progressivePoint(frame, i, 32),
                aniso::cranleyPatterson(aniso::hammersley(i, 32), aniso::frameShift(frame)));
    }
  }
  for (uint32_t count : {2u, 4u, 8u, 16u})
  {
    for (uint32_t i = 0; i < count; ++i)
    {
      EXPECT_EQ(aniso::progressivePoint(0, i, count), aniso::hammersley(i, count));
    }
    const int m = static_cast<int>(std::lround(std::log2(count)));
    for (uint32_t frame = 0; frame < 40; ++frame)
    {
      std::vector<glm::dvec2> points;
      for (uint32_t i = 0; i < count; ++i)
      {
        points.push_back(aniso::progressivePoint(frame, i, count));
      }
      EXPECT_TRUE(isZeroNet(points, m)) << count << " points, frame " << frame;
    }
    for (int a = 0; a <= 5; ++a)
    {
      for (const uint32_t first : {0u, 1u << a})
      {
        std::vector<glm::dvec2> points;
        for (uint32_t frame = first; frame < first + (1u << a); ++frame)
        {
          for (uint32_t i = 0; i < count; ++i)
          {
            points.push_back(aniso::progressivePoint(frame, i, count));
          }
        }
        EXPECT_TRUE(isZeroNet(points, m + a))
            << count << " points, " << (1 << a) << " frames from " << first;
      }
    }
  }
  std::vector<glm::dvec2> shifted;
  for (uint32_t frame = 8; frame < 16; ++frame)
  {
    for (uint32_t i = 0; i < 16; ++i)
    {
      shifted.push_back(
          aniso::cranleyPatterson(aniso::hammersley(i, 16), aniso::frameShift(frame)));
    }
  }
  EXPECT_FALSE(isZeroNet(shifted, 7));
  // Frame 2's 16 points are the sequence's indices 32 to 47.
  const aniso::SequenceColumns& columns = aniso::sequenceColumns(16);
  for (uint32_t i = 0; i < 16; ++i)
  {
    EXPECT_EQ(aniso::progressivePoint(2, i, 16),
              glm::dvec2(double(aniso::sequenceBits(32 + i, columns)) * 0x1.0p-32,
                         aniso::radicalInverse2(32 + i)));
  }
}

// A count that is not a power of two takes the first COUNT points of each block of the next
// power of two: points stay in [0, 1)^2, no two frames from frame 2 on share
// a point, and an index past the count is refused.
TEST(ProgressivePoints, AnyCount)
{
  std::set<std::pair<double, double>> seen;
  for (uint32_t frame = 0; frame < 32; ++frame)
  {
    for (uint32_t i = 0; i < 24; ++i)
    {
      const glm::dvec2 p = aniso::progressivePoint(frame, i, 24);
      ASSERT_GE(p.x, 0.0);
      ASSERT_LT(p.x, 1.0);
      ASSERT_GE(p.y, 0.0);
      ASSERT_LT(p.y, 1.0);
      if (frame > 1)
      {
        EXPECT_TRUE(seen.emplace(p.x, p.y).second) << "frame " << frame << " point " << i;
      }
    }
  }
  EXPECT_THROW(aniso::progressivePoint(3, 24, 24), aniso::Error);
  EXPECT_THROW(aniso::progressivePoint(0, 5, 5), aniso::Error);
}

// The shader's way to the sequence's points: point k B + i is point i XOR the block's first
// point, in both coordinates, for every count and frame the shader takes the sequence for
// (every frame for a power of two, from frame 2 on for the other counts).
TEST(ProgressivePoints, BlockXorPointGivesThePoint)
{
  for (uint32_t count = 2; count <= aniso::kMaxSequenceCount; ++count)
  {
    for (uint32_t frame = 0; frame < 70; ++frame)
    {
      if (!aniso::takesSequence(frame, count))
      {
        EXPECT_LT(frame, 2u) << count << " points";
        continue;
      }
      const aniso::SequenceBlock block = aniso::sequenceBlock(frame, count);
      for (uint32_t i = 0; i < count; ++i)
      {
        const uint32_t x = block.x ^ aniso::sequenceBits(i, aniso::sequenceColumns(count));
        const uint32_t y = block.y ^ static_cast<uint32_t>(aniso::radicalInverse2(i) * 0x1.0p32);
        EXPECT_EQ(aniso::progressivePoint(frame, i, count),
                  glm::dvec2(double(x) * 0x1.0p-32, double(y) * 0x1.0p-32))
            << count << " points, frame " << frame << ", point " << i;
      }
    }
  }
}
