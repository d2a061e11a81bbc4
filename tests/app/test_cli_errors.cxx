// The aniso command line: help texts list every option, and every kind of bad input gives
// exactly one error line naming the culprit, the documented exit code and no output at all.
// Most cases call the bake command in-process through the same error reporting main() uses
// (each launch of the executable costs the dynamic loading of OpenImageIO's dependencies); the
// executable itself is run for the top-level command line and one case of each exit code.
#include "app/bake_command.h"
#include "app/cli.h"
#include "core/image/image.h"
#include "core/parameters/parameters.h"
#include "tests/app/cli_runner.h"

#include <fstream>
#include <gtest/gtest.h>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using aniso_test::Outcome;

class CliErrors : public aniso_test::CliTest
{
protected:
  // `aniso bake ARGS` in-process: runBake under runReportingErrors, as main() runs it.
  static Outcome bake(const std::vector<std::string>& args)
  {
    std::ostringstream out;
    std::ostringstream err;
    Outcome r;
    r.exitCode =
        aniso::cli::runReportingErrors([&] { return aniso::cli::runBake(args, out); }, err);
    r.out = out.str();
    r.err = err.str();
    return r;
  }

  void makeInputs() const
  {
    std::ofstream(path("not-an-image.png")) << "this is text, not a PNG\n";
    aniso::Image one(2, 2, 1);
    aniso::writeImage(path("grey.exr").string(), one);
  }
};

struct Case
{
  std::vector<std::string> args;
  int exitCode;
  std::string culprit;
};

std::string shown(const std::vector<std::string>& args)
{
  std::string s;
  for (const auto& a : args)
  {
    s += a + " ";
  }
  return s;
}

// One line "aniso: ..." on stderr naming the culprit, the expected exit code.
void expectOneLineError(const Outcome& r, const Case& c)
{
  const std::string what = shown(c.args) + "\n" + r.err;
  EXPECT_EQ(r.exitCode, c.exitCode) << what;
  ASSERT_FALSE(r.err.empty()) << what;
  EXPECT_EQ(r.err.rfind("aniso: ", 0), 0u) << what;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << what;
  EXPECT_NE(r.err.find(c.culprit), std::string::npos) << what;
  EXPECT_EQ(r.out, "") << what;
}

// TEXT with every run of white space (help lines wrap) turned into one space.
std::string squeezed(const std::string& text)
{
  std::istringstream words(text);
  std::string word;
  std::string s;
  while (words >> word)
  {
    s += (s.empty() ? "" : " ") + word;
  }
  return s;
}

// Every help exits 0 and names every option of its command, with the declared defaults.
TEST_F(CliErrors, HelpListsEveryOption)
{
  struct Help
  {
    std::vector<std::string> args; // after "bake"
    std::vector<std::string> mentions;
  };
  const std::string nuDefault = aniso::formatNumber(aniso::parameterSpec("nu").defaultValue[0]);
  const std::vector<Help> helps = {
      {{"--help"}, {"halfvector", "brdf", "quaternion", "tpr", "cubemap", "irradiance"}},
      {{"halfvector", "--help"},
       {"--nu", "--nv", "--size", "--cache", "-o", "--output", "--help", "default " + nuDefault,
        "1e6"}},
      {{"brdf", "-h"},
       {"--nu", "--nv", "--size", "--samples", "--cache", "-o", "--output", "--help", "1024"}},
      {{"quaternion", "--help"}, {"NORMALMAP", "--encoding", "auto|unorm|snorm", "-o"}},
      {{"tpr", "--help"}, {"--pattern", "--angle-image", "--size", "-o", "circular"}},
      {{"cubemap", "--help"},
       {"--env", "--size", "--supersample", "-o", "builtin:studio", "_px_m0", "power of two"}},
      {{"irradiance", "--help"}, {"--env", "--size", "-o", "l m R G B"}},
  };
  for (const Help& h : helps)
  {
    const Outcome r = bake(h.args);
    EXPECT_EQ(r.exitCode, 0) << shown(h.args);
    EXPECT_EQ(r.err, "");
    const std::string text = squeezed(r.out);
    for (const auto& word : h.mentions)
    {
      EXPECT_NE(text.find(word), std::string::npos) << "bake " << shown(h.args) << "lacks " << word;
    }
  }
}

// The executable's own --help and --version.
TEST_F(CliErrors, ExecutableHelpAndVersion)
{
  const Outcome help = run({"--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_EQ(help.err, "");
  for (const char* word : {"bake", "--version", "--help", "halfvector", "irradiance"})
  {
    EXPECT_NE(help.out.find(word), std::string::npos) << "aniso --help lacks " << word;
  }
  const Outcome version = run({"--version"});
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_EQ(version.out.rfind("aniso ", 0), 0u) << version.out;
}

// Bad command lines (exit 2) and run-time failures (exit 1) of the bake command: exactly one
// stderr line "aniso: ..." naming the offending argument or file, and nothing written.
TEST_F(CliErrors, BadBakeInputGivesOneLineNamingTheCulpritAndNoOutput)
{
  makeInputs();
  const std::string out = path("out.exr").string();
  const std::string missingDir = path("no-such-dir/out.exr").string();
  const std::string missingFile = path("missing.exr").string();
  const std::vector<Case> cases = {
      {{}, 2, "KIND"},
      {{"sphere", "-o", out}, 2, "sphere"},
      {{"--nu", "5"}, 2, "--nu"},
      {{"brdf", "--frobnicate", "3", "-o", out}, 2, "--frobnicate"},
      {{"brdf", "-o", out, "--nu"}, 2, "--nu"},
      {{"brdf", "--nu", "--nv", "5", "-o", out}, 2, "--nu"},
      {{"brdf", "--nu", "abc", "-o", out}, 2, "abc"},
      {{"brdf", "--nu", "2e6", "-o", out}, 2, "--nu"},
      {{"brdf", "--nv", "-1", "-o", out}, 2, "--nv"},
      {{"brdf", "--size", "-4", "-o", out}, 2, "--size"},
      {{"brdf", "--size", "6.5", "-o", out}, 2, "--size"},
      {{"brdf", "--samples", "0", "-o", out}, 2, "--samples"},
      {{"brdf", "--nu", "5", "--nu", "6", "-o", out}, 2, "--nu"},
      {{"brdf"}, 2, "-o"},
      {{"brdf", "-o", path("out.png").string()}, 2, "out.png"},
      {{"brdf", "extra", "-o", out}, 2, "extra"},
      {{"halfvector", "--size", "5000", "-o", out}, 2, "--size"},
      {{"quaternion", "-o", out}, 2, "NORMALMAP"},
      {{"quaternion", path("grey.exr").string(), "--encoding", "raw", "-o", out}, 2, "--encoding"},
      {{"tpr", "--pattern", "zigzag", "-o", out}, 2, "zigzag"},
      {{"tpr", "--size", "0x5", "-o", out}, 2, "--size"},
      {{"tpr", "--size", "-3", "-o", out}, 2, "--size"},
      {{"tpr", "--size", "axb", "-o", out}, 2, "--size"},
      {{"tpr", "--angle-image", path("grey.exr").string(), "--pattern", "wave", "-o", out},
       2,
       "--angle-image"},
      {{"cubemap", "--size", "100", "-o", path("cube").string()}, 2, "--size"},
      {{"cubemap", "--supersample", "0", "-o", path("cube").string()}, 2, "--supersample"},
      {{"irradiance", "--size", "8x4", "-o", path("sh.txt").string()}, 2, "--size"},
      {{"irradiance", "-o", path("sh.dat").string()}, 2, "sh.dat"},
      // Run-time failures: unreadable or unusable inputs, missing output directories.
      {{"quaternion", missingFile, "-o", out}, 1, missingFile},
      {{"quaternion", path("not-an-image.png").string(), "-o", out}, 1, "not-an-image.png"},
      {{"quaternion", path("grey.exr").string(), "-o", out}, 1, "grey.exr"},
      {{"tpr", "--angle-image", missingFile, "-o", out}, 1, missingFile},
      {{"cubemap", "--env", missingFile, "-o", path("cube").string()}, 1, missingFile},
      {{"irradiance", "--env", path("not-an-image.png").string(), "-o", path("sh.txt").string()},
       1,
       "not-an-image.png"},
      {{"brdf", "--size", "4", "--samples", "4", "--cache", "none", "-o", missingDir},
       1,
       missingDir},
      {{"cubemap", "--size", "2", "-o", path("no-such-dir/cube").string()}, 1, "no-such-dir"},
      {{"irradiance", "-o", path("no-such-dir/sh.txt").string()}, 1, "no-such-dir"},
  };
  const std::set<std::string> before = files();
  for (const Case& c : cases)
  {
    expectOneLineError(bake(c.args), c);
    EXPECT_EQ(files(), before) << shown(c.args) << ": left files behind";
  }
}

// The executable turns the same failures into its exit code and one stderr line.
TEST_F(CliErrors, ExecutableReportsOneLineAndTheExitCode)
{
  makeInputs();
  const std::string out = path("out.exr").string();
  const std::vector<Case> cases = {
      {{"--session"}, 2, "--session"}, // the window's options are checked before it opens
      {{"frobnicate"}, 2, "frobnicate"},
      {{"--frobnicate"}, 2, "--frobnicate"},
      {{"bake"}, 2, "KIND"},
      {{"bake", "brdf", "--nu", "abc", "-o", out}, 2, "abc"},
      {{"bake", "quaternion", path("not-an-image.png").string(), "-o", out}, 1, "not-an-image.png"},
      {{"bake", "irradiance", "-o", path("no-such-dir/sh.txt").string()}, 1, "no-such-dir"},
  };
  const std::set<std::string> before = files();
  for (const Case& c : cases)
  {
    expectOneLineError(run(c.args), c);
    EXPECT_EQ(files(), before) << shown(c.args) << ": left files behind";
  }
}
} // namespace
