// `aniso render --turntable N` end to end (GL renders, serial). Checks: N images named
// OUT_0000.png ... of the requested size; image K is the plain render from azimuth
// A + 360 K / N at the same elevation (an independent run of `aniso render --azimuth
// --elevation`, compared pixel by pixel); consecutive images differ; --turntable with --compare
// is a usage error naming the option.
#include "core/image/image.h"
#include "tests/app/cli_runner.h"

#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace
{
using aniso_test::Outcome;
using RenderTurntableCli = aniso_test::CliTest;

double maxDifference(const aniso::Image& a, const aniso::Image& b)
{
  double most = 0.0;
  for (std::size_t i = 0; i < a.data.size(); ++i)
  {
    most = std::max(most, double(std::abs(a.data[i] - b.data[i])));
  }
  return most;
}

double meanDifference(const aniso::Image& a, const aniso::Image& b)
{
  double sum = 0.0;
  for (std::size_t i = 0; i < a.data.size(); ++i)
  {
    sum += std::abs(a.data[i] - b.data[i]);
  }
  return sum / double(a.data.size());
}

const std::vector<std::string> kScene = {"render", "--builtin", "torus", "--size",
                                         "48x32",  "--frames",  "1",     "--samples",
                                         "4",      "--jitter",  "off"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more)
{
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST_F(RenderTurntableCli, WritesNumberedImagesOfTheTurnedViews)
{
  const Outcome r = run(with(kScene, {"--azimuth", "30", "--elevation", "20", "--turntable", "3",
                                      "-o", path("spin.png").string()}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::vector<aniso::Image> images;
  for (int k = 0; k < 3; ++k)
  {
    const std::string name = "spin_000" + std::to_string(k) + ".png";
    ASSERT_TRUE(aniso_test::fs::exists(path(name))) << name << "\n" << r.out;
    images.push_back(aniso::readImage(path(name).string()));
    EXPECT_EQ(images.back().width, 48);
    EXPECT_EQ(images.back().height, 32);
  }
  EXPECT_FALSE(aniso_test::fs::exists(path("spin.png")));
  // Image 1 is the view from 30 + 120 degrees, rendered on its own.
  const Outcome plain = run(
      with(kScene, {"--azimuth", "150", "--elevation", "20", "-o", path("plain.png").string()}));
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  const aniso::Image reference = aniso::readImage(path("plain.png").string());
  EXPECT_LE(maxDifference(images[1], reference), 1.5 / 255.0);
  EXPECT_GT(meanDifference(images[0], images[1]), 0.01);
  EXPECT_GT(meanDifference(images[1], images[2]), 0.01);
}

TEST_F(RenderTurntableCli, NotWithCompare)
{
  const Outcome r = run(
      with(kScene, {"--turntable", "3", "--compare", "as,ward", "-o", path("spin.png").string()}));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--turntable"), std::string::npos) << r.err;
  EXPECT_TRUE(files().empty());
}
} // namespace
