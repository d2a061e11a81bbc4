// The help of every subcommand reads well on a terminal:
//  - at 80 columns (COLUMNS=80) no line of `aniso --help`, `aniso bake --help`, each
//    `aniso bake KIND --help`, `aniso render --help` and `aniso bench --help` is longer than 80,
//    and every option description starts at column 40 or before, so none is narrower than 40;
//  - at 120 columns the render help uses the width (lines longer than 80, none longer than 120);
//  - render's options come under their headings (Scene, View, Material, Maps, Lighting,
//    Sampling, Models, Output), in that order, each option once; a choice's values are on a line
//    of their own ("one of: ...");
//  - helpText alone: an option whose own text is longer than the description column (the
//    case of an option with eight choices) puts its description on the next line at column 30
//    instead of pushing every description right; a terminal narrower than 70 still gets 40
//    columns of description.
#include "app/cli.h"
#include "tests/app/cli_runner.h"

#include <algorithm>
#include <cstdlib>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using aniso_test::Outcome;

std::vector<std::string> linesOf(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
  {
    lines.push_back(line);
  }
  return lines;
}

std::size_t leadingBlanks(const std::string& line)
{
  const std::size_t first = line.find_first_not_of(' ');
  return first == std::string::npos ? line.size() : first;
}

// Checks TEXT against WIDTH: no line longer, and in the option sections (a heading "Name:" up to
// the next blank line) every description starting at WIDTH - 40 or before. An option line is
// "  -x, --name VALUE   description"; its description starts after the first run of two or more
// blanks past the option; any other line of a section is a description (or choices) line.
void expectFits(const std::string& what, const std::string& text, std::size_t width,
                bool listsOptions = true)
{
  bool inOptions = false;
  int optionLines = 0;
  for (const std::string& line : linesOf(text))
  {
    EXPECT_LE(line.size(), width) << what << ": " << line;
    if (line.empty())
    {
      inOptions = false;
      continue;
    }
    if (line.back() == ':' && line.front() != ' ')
    {
      inOptions = true;
      continue;
    }
    if (!inOptions)
    {
      continue;
    }
    std::size_t description = leadingBlanks(line);
    if (line.compare(description, 1, "-") == 0)
    {
      ++optionLines;
      const std::size_t gap = line.find("  ", description);
      if (gap == std::string::npos)
      {
        continue; // the description is on the next line
      }
      description = line.find_first_not_of(' ', gap);
    }
    EXPECT_LE(description, width - 40) << what << ": " << line;
  }
  if (listsOptions)
  {
    EXPECT_GT(optionLines, 0) << what << " lists no options";
  }
}

class CliHelp : public aniso_test::CliTest
{
protected:
  Outcome help(const std::vector<std::string>& args, const char* columns) const
  {
    ::setenv("COLUMNS", columns, 1);
    Outcome r = run(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r;
  }
};

TEST_F(CliHelp, EverySubcommandFitsEightyColumns)
{
  const std::vector<std::vector<std::string>> commands = {{"--help"},
                                                          {"bake", "--help"},
                                                          {"bake", "halfvector", "--help"},
                                                          {"bake", "brdf", "--help"},
                                                          {"bake", "quaternion", "--help"},
                                                          {"bake", "tpr", "--help"},
                                                          {"bake", "cubemap", "--help"},
                                                          {"bake", "irradiance", "--help"},
                                                          {"render", "--help"},
                                                          {"bench", "--help"},
                                                          {"thumbnail", "--help"}};
  for (const auto& args : commands)
  {
    std::string what = "aniso";
    for (const auto& a : args)
    {
      what += " " + a;
    }
    // `aniso bake --help` lists the kinds, not options.
    expectFits(what, help(args, "80").out, 80, args != std::vector<std::string>{"bake", "--help"});
  }
}

TEST_F(CliHelp, RenderUsesAWideTerminal)
{
  const std::string text = help({"render", "--help"}, "120").out;
  expectFits("aniso render --help at 120", text, 120);
  std::size_t longest = 0;
  for (const std::string& line : linesOf(text))
  {
    longest = std::max(longest, line.size());
  }
  EXPECT_GT(longest, 80u);
  // Fewer lines than at 80 columns: the descriptions are wider.
  EXPECT_LT(linesOf(text).size(), linesOf(help({"render", "--help"}, "80").out).size());
}

TEST_F(CliHelp, RenderOptionsAreGrouped)
{
  const std::string text = help({"render", "--help"}, "80").out;
  std::size_t previous = 0;
  for (const char* heading :
       {"\nScene:\n", "\nView:\n", "\nMaterial:\n", "\nMaps:\n", "\nLighting:\n", "\nSampling:\n",
        "\nModels:\n", "\nOutput:\n", "\nOptions:\n"})
  {
    const std::size_t at = text.find(heading);
    ASSERT_NE(at, std::string::npos) << heading;
    EXPECT_GT(at, previous) << heading;
    previous = at;
  }
  // Each option under the heading its declaration or its command gives it.
  const auto headingOf = [&](const std::string& option)
  {
    const std::size_t at = text.find("\n  " + option + " ");
    EXPECT_NE(at, std::string::npos) << option;
    const std::size_t heading = text.rfind(":\n", at);
    return text.substr(text.rfind('\n', heading - 1) + 1,
                       heading - text.rfind('\n', heading - 1) - 1);
  };
  EXPECT_EQ(headingOf("--builtin"), "Scene");
  EXPECT_EQ(headingOf("--cad-angle"), "Scene");
  EXPECT_EQ(headingOf("--view"), "View");
  EXPECT_EQ(headingOf("--nu"), "Material");
  EXPECT_EQ(headingOf("--f0"), "Material");
  EXPECT_EQ(headingOf("--tpr"), "Maps");
  EXPECT_EQ(headingOf("--env"), "Lighting");
  EXPECT_EQ(headingOf("--light"), "Lighting");
  EXPECT_EQ(headingOf("--samples"), "Sampling");
  EXPECT_EQ(headingOf("--method"), "Sampling");
  EXPECT_EQ(headingOf("--leadr-tiles"), "Models");
  EXPECT_EQ(headingOf("--exposure"), "Output");
  EXPECT_EQ(headingOf("-o, --output"), "Output");
  EXPECT_NE(text.find("one of: exact|split-sum\n"), std::string::npos);
  EXPECT_NE(text.find("one of: three-quarter|-y|+y|-x|+x|+z|-z\n"), std::string::npos);
}

TEST(HelpText, ALongOptionDoesNotNarrowTheOthers)
{
  aniso::cli::Command c;
  c.usage = "aniso try [options]";
  c.summary = "A summary long enough to be wrapped at the width of the terminal the help is "
              "printed to, word by word.";
  aniso::cli::Option choice = aniso::cli::textOption("--a-rather-long-option-name", "WORD",
                                                     "picks one of eight words", "one");
  choice.choices = {"one", "two", "three", "four", "five", "six", "seven", "eight"};
  c.options.push_back(choice);
  c.options.push_back(aniso::cli::textOption(
      "--short", "X",
      "a description long enough to need three lines at eighty columns, since it goes on and "
      "on about nothing in particular for a while"));
  const std::string text = aniso::cli::helpText(c, 80);
  EXPECT_NE(text.find("\n  --a-rather-long-option-name WORD\n" + std::string(30, ' ') +
                      "picks one of eight words (default one)\n" + std::string(30, ' ') +
                      "one of: one|two|three|four|five|six|seven|eight\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\n  --short X" + std::string(30 - 11, ' ') + "a description long"),
            std::string::npos)
      << text;
  expectFits("helpText at 80", text, 80);
  // A 50-column terminal: descriptions keep 40 columns (lines up to 70).
  const std::string narrow = aniso::cli::helpText(c, 50);
  for (const std::string& line : linesOf(narrow))
  {
    EXPECT_LE(line.size(), 70u) << line;
  }
  EXPECT_NE(narrow.find("\n  --short X" + std::string(30 - 11, ' ') +
                        "a description long enough to need three\n"),
            std::string::npos)
      << narrow;
}
} // namespace
