// The aniso command line: help texts list every option, and every kind of bad input gives
// exactly one error line naming the culprit, the documented exit code and no output at all.
#include "cli_runner.h"
#include "image/image.h"
#include "material/parameters.h"

#include <fstream>
#include <gtest/gtest.h>
#include <set>
#include <string>
#include <vector>

namespace
{
using aniso_test::Outcome;
using CliErrors = aniso_test::CliTest;

// Every help exits 0 and names every option of its command, with the declared defaults.
TEST_F(CliErrors, HelpListsEveryOption)
{
  struct Help
  {
    std::vector<std::string> args;
    std::vector<std::string> mentions;
  };
  const std::string nuDefault = aniso::formatNumber(aniso::parameterSpec("nu").defaultValue[0]);
  const std::vector<Help> helps = {
      {{"--help"},
       {"bake", "--version", "--help", "halfvector", "brdf", "quaternion", "tpr", "cubemap",
        "irradiance"}},
      {{"bake", "--help"}, {"halfvector", "brdf", "quaternion", "tpr", "cubemap", "irradiance"}},
      {{"bake", "halfvector", "--help"},
       {"--nu", "--nv", "--size", "--cache", "-o", "--output", "--help", "default " + nuDefault,
        "1e6"}},
      {{"bake", "brdf", "-h"},
       {"--nu", "--nv", "--size", "--samples", "--cache", "-o", "--output", "--help", "1024"}},
      {{"bake", "quaternion", "--help"}, {"NORMALMAP", "--encoding", "auto|unorm|snorm", "-o"}},
      {{"bake", "tpr", "--help"}, {"--pattern", "--angle-image", "--size", "-o", "circular"}},
      {{"bake", "cubemap", "--help"},
       {"--env", "--size", "--supersample", "-o", "builtin:studio", "_px_m0"}},
      {{"bake", "irradiance", "--help"}, {"--env", "--size", "-o", "l m R G B"}},
  };
  for (const Help& h : helps)
  {
    const Outcome r = run(h.args);
    EXPECT_EQ(r.exitCode, 0) << h.args.back();
    EXPECT_EQ(r.err, "");
    for (const auto& word : h.mentions)
    {
      EXPECT_NE(r.out.find(word), std::string::npos)
          << "help of " << h.args[0] << " " << (h.args.size() > 1 ? h.args[1] : "") << " lacks "
          << word;
    }
  }
  const Outcome version = run({"--version"});
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_EQ(version.out.rfind("aniso ", 0), 0u) << version.out;
}

// Bad command lines (exit 2) and run-time failures (exit 1): exactly one stderr line
// "aniso: ..." naming the offending argument or file, and nothing written.
TEST_F(CliErrors, BadInputGivesOneLineNamingTheCulpritAndNoOutput)
{
  {
    std::ofstream(path("not-an-image.png")) << "this is text, not a PNG\n";
    aniso::Image one(2, 2, 1);
    aniso::writeImage(path("grey.exr").string(), one);
  }
  const std::string out = path("out.exr").string();
  const std::string missingDir = path("no-such-dir/out.exr").string();
  const std::string missingFile = path("missing.exr").string();
  struct Case
  {
    std::vector<std::string> args;
    int exitCode;
    std::string culprit;
  };
  const std::vector<Case> cases = {
      {{}, 2, "COMMAND"},
      {{"frobnicate"}, 2, "frobnicate"},
      {{"--frobnicate"}, 2, "--frobnicate"},
      {{"bake"}, 2, "KIND"},
      {{"bake", "sphere", "-o", out}, 2, "sphere"},
      {{"bake", "brdf", "--frobnicate", "3", "-o", out}, 2, "--frobnicate"},
      {{"bake", "brdf", "-o", out, "--nu"}, 2, "--nu"},
      {{"bake", "brdf", "--nu", "--nv", "5", "-o", out}, 2, "--nu"},
      {{"bake", "brdf", "--nu", "abc", "-o", out}, 2, "abc"},
      {{"bake", "brdf", "--nu", "2e6", "-o", out}, 2, "--nu"},
      {{"bake", "brdf", "--nv", "-1", "-o", out}, 2, "--nv"},
      {{"bake", "brdf", "--size", "-4", "-o", out}, 2, "--size"},
      {{"bake", "brdf", "--size", "6.5", "-o", out}, 2, "--size"},
      {{"bake", "brdf", "--samples", "0", "-o", out}, 2, "--samples"},
      {{"bake", "brdf", "--nu", "5", "--nu", "6", "-o", out}, 2, "--nu"},
      {{"bake", "brdf"}, 2, "-o"},
      {{"bake", "brdf", "-o", path("out.png").string()}, 2, "out.png"},
      {{"bake", "brdf", "extra", "-o", out}, 2, "extra"},
      {{"bake", "halfvector", "--size", "5000", "-o", out}, 2, "--size"},
      {{"bake", "quaternion", "-o", out}, 2, "NORMALMAP"},
      {{"bake", "quaternion", path("grey.exr").string(), "--encoding", "raw", "-o", out},
       2,
       "--encoding"},
      {{"bake", "tpr", "--pattern", "zigzag", "-o", out}, 2, "zigzag"},
      {{"bake", "tpr", "--size", "0x5", "-o", out}, 2, "--size"},
      {{"bake", "tpr", "--size", "-3", "-o", out}, 2, "--size"},
      {{"bake", "tpr", "--size", "axb", "-o", out}, 2, "--size"},
      {{"bake", "tpr", "--angle-image", path("grey.exr").string(), "--pattern", "wave", "-o", out},
       2,
       "--angle-image"},
      {{"bake", "cubemap", "--size", "100", "-o", path("cube").string()}, 2, "--size"},
      {{"bake", "cubemap", "--supersample", "0", "-o", path("cube").string()}, 2, "--supersample"},
      {{"bake", "irradiance", "--size", "8x4", "-o", path("sh.txt").string()}, 2, "--size"},
      {{"bake", "irradiance", "-o", path("sh.dat").string()}, 2, "sh.dat"},
      // Outcome-time failures: unreadable inputs, missing output directories.
      {{"bake", "quaternion", missingFile, "-o", out}, 1, missingFile},
      {{"bake", "quaternion", path("not-an-image.png").string(), "-o", out}, 1, "not-an-image.png"},
      {{"bake", "quaternion", path("grey.exr").string(), "-o", out}, 1, "grey.exr"},
      {{"bake", "tpr", "--angle-image", missingFile, "-o", out}, 1, missingFile},
      {{"bake", "cubemap", "--env", missingFile, "-o", path("cube").string()}, 1, missingFile},
      {{"bake", "irradiance", "--env", path("not-an-image.png").string(), "-o",
        path("sh.txt").string()},
       1,
       "not-an-image.png"},
      {{"bake", "brdf", "--size", "4", "--samples", "4", "--cache", "none", "-o", missingDir},
       1,
       missingDir},
      {{"bake", "cubemap", "--size", "2", "-o", path("no-such-dir/cube").string()},
       1,
       "no-such-dir"},
      {{"bake", "irradiance", "-o", path("no-such-dir/sh.txt").string()}, 1, "no-such-dir"},
  };
  const std::set<std::string> before = files();
  for (const Case& c : cases)
  {
    std::string shown;
    for (const auto& a : c.args)
    {
      shown += a + " ";
    }
    const Outcome r = run(c.args);
    EXPECT_EQ(r.exitCode, c.exitCode) << shown << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("aniso: ", 0), 0u) << shown << "\n" << r.err;
    ASSERT_FALSE(r.err.empty()) << shown;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << shown << ": not one line:\n" << r.err;
    EXPECT_NE(r.err.find(c.culprit), std::string::npos) << shown << "\n" << r.err;
    EXPECT_EQ(files(), before) << shown << ": left files behind";
  }
}
} // namespace
