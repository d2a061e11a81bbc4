// randomWaveHeight (core/models/height_field.h), checked against what it states:
//   - each slope axis has the requested deviation (measured by central differences, which damp
//     a wave of f cycles over W texels by sin(2 pi f / W) / (2 pi f / W): at most 1.5% here);
//   - the slopes are close to Gaussian: the share within one deviation and the kurtosis are
//     those of a normal distribution (0.683 and 3) within stated tolerances;
//   - the map tiles: the step across the wrap-around seam is no larger than the steps inside;
//   - invalid arguments are refused naming the subject.
#include "core/error.h"
#include "core/models/height_field.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace aniso
{
namespace
{
TEST(RandomWaveHeight, SlopesHaveTheRequestedGaussianDeviation)
{
  constexpr int size = 128;
  constexpr double deviation = 0.3;
  const Image height = randomWaveHeight(size, deviation);
  const Image slopes = slopesFromHeight(height, 1.0);
  for (int axis = 0; axis < 2; ++axis)
  {
    double sum = 0.0;
    double squares = 0.0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
      {
        const double s = slopes.at(x, y, axis);
        sum += s;
        squares += s * s;
      }
    const double n = double(size) * size;
    const double mean = sum / n;
    const double sigma = std::sqrt(squares / n - mean * mean);
    // Integer frequencies tile: the mean slope of a whole tile is 0.
    EXPECT_NEAR(mean, 0.0, 1e-3) << "axis " << axis;
    // Each axis gets half of every wave's slope variance only on average over the waves'
    // directions: 96 random directions leave a few percent (measured: -4.3% and +4.6%).
    EXPECT_NEAR(sigma / deviation, 1.0, 0.15) << "axis " << axis;
    double within = 0.0;
    double fourth = 0.0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
      {
        const double z = (slopes.at(x, y, axis) - mean) / sigma;
        within += std::abs(z) <= 1.0 ? 1.0 : 0.0;
        fourth += z * z * z * z;
      }
    // A single wave would give 0.5 and 1.5 (measured: 0.667, 0.674 and 2.65, 2.79).
    EXPECT_NEAR(within / n, 0.683, 0.05) << "axis " << axis;
    EXPECT_NEAR(fourth / n, 3.0, 0.5) << "axis " << axis;
  }
}

TEST(RandomWaveHeight, TilesWithoutASeam)
{
  constexpr int size = 64;
  const Image height = randomWaveHeight(size, 0.3);
  double inside = 0.0;
  double seam = 0.0;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x + 1 < size; ++x)
    {
      inside = std::max(inside, double(std::abs(height.at(x + 1, y, 0) - height.at(x, y, 0))));
      inside = std::max(inside, double(std::abs(height.at(y, x + 1, 0) - height.at(y, x, 0))));
    }
    seam = std::max(seam, double(std::abs(height.at(0, y, 0) - height.at(size - 1, y, 0))));
    seam = std::max(seam, double(std::abs(height.at(y, 0, 0) - height.at(y, size - 1, 0))));
  }
  EXPECT_GT(inside, 0.0);
  EXPECT_LE(seam, inside);
}

TEST(RandomWaveHeight, RefusesInvalidArguments)
{
  for (const auto& call :
       {+[] { randomWaveHeight(3, 0.3); }, +[] { randomWaveHeight(64, -1.0); },
        +[] { randomWaveHeight(64, NAN); }, +[] { randomWaveHeight(64, 0.3, 0); },
        +[] { randomWaveHeight(64, 0.3, 96, 0); }})
  {
    try
    {
      call();
      ADD_FAILURE() << "accepted";
    }
    catch (const Error& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind("wave relief: ", 0), 0u) << e.what();
    }
  }
}
} // namespace
} // namespace aniso
