#pragma once
// A small command-line parser for the aniso subcommands. Options that set a tunable
// parameter are derived from its declaration (core/parameters/parameters.h), so their type,
// default, range and help text are stated once for the CLI, the docks and the sessions.
#include "core/error.h"
#include "core/parameters/parameters.h"

#include <cstddef>
#include <functional>
#include <glm/vec3.hpp>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace aniso::cli
{
// A bad command line (exit code 2); any other aniso::Error is a run-time failure (exit code 1).
class UsageError : public Error
{
public:
  using Error::Error;
};

inline UsageError usageError(const std::string& subject, const std::string& reason)
{
  return UsageError(subject + ": " + reason);
}

struct Option
{
  std::string name;                 // "--nu"
  std::string alias;                // "-o", or empty
  std::string valueName;            // "N", "FILE"; empty for a flag
  ParameterSpec spec;               // type, default, range, unit and help (spec.name is not used)
  std::vector<std::string> choices; // allowed values of a text option, if restricted
  bool required = false;
  bool repeatable = false; // may be given more than once (Arguments::texts lists every value)
  // The heading the option is listed under in a grouped help (Command::grouped): one of the
  // kGroup names below. parameterOption derives it from the declaration (groupOf); an option
  // the declaration does not cover states it where it is made.
  std::string group;
};

// The headings of a grouped help, in the order it lists them (options of no group come last,
// under "Options", with --help).
inline constexpr const char* kGroupScene = "Scene";
inline constexpr const char* kGroupView = "View";
inline constexpr const char* kGroupMaterial = "Material";
inline constexpr const char* kGroupMaps = "Maps";
inline constexpr const char* kGroupLighting = "Lighting";
inline constexpr const char* kGroupSampling = "Sampling";
inline constexpr const char* kGroupModels = "Models";
inline constexpr const char* kGroupOutput = "Output";

// The group of a declared parameter, from what it is and what a change of it affects: a mesh
// reading setting is the scene's; a material's value is the material's, or of its maps when it
// changes the shader variant (bump); the display transform is the output's; the shader variant,
// the lookup tables and the sample uniforms are sampling; the environment and what lights the lit
// models is lighting; the rest (settings of the LEADR and microstructure models) the models'.
std::string groupOf(const ParameterSpec& spec);

// The option of declared parameter PARAMETER, named "--" + PARAMETER unless NAME is given
// (the bake commands call lut-size just --size); HELP replaces the declared help if given.
Option parameterOption(std::string_view parameter, std::string name = {},
                       std::string_view help = {});
// A text option that no declared parameter covers (paths, patterns, choices).
Option textOption(std::string name, std::string valueName, std::string_view help,
                  std::string_view defaultText = {});

struct Command
{
  std::string usage;                    // "aniso bake brdf [options] -o FILE"
  std::string summary;                  // what it does, one or two sentences
  std::vector<std::string> positionals; // required positional arguments, in order
  std::vector<Option> options;
  std::string details; // output format and examples, printed after the options
  // The last positional may be given more than once ("MESH..."): Arguments::positionals holds
  // every one given.
  bool lastPositionalRepeats = false;
  // Lists the options under their groups' headings (Option::group) rather than all together.
  bool grouped = false;
};

class Arguments
{
public:
  bool helpRequested = false;
  std::vector<std::string> positionals;

  bool has(const std::string& name) const; // given on the command line
  // The given value (already parsed and range-checked), or the option's default.
  const ParameterValue& value(const std::string& name) const;
  double real(const std::string& name) const;
  int integer(const std::string& name) const;
  glm::dvec3 color(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  // Every value given for a repeatable option, in command-line order (empty when not given).
  std::vector<std::string> texts(const std::string& name) const;

private:
  friend Arguments parseArguments(const Command&, const std::vector<std::string>&);
  std::map<std::string, ParameterValue> given_;
  std::map<std::string, ParameterValue> defaults_;
  std::map<std::string, std::vector<std::string>> repeated_;
};

// "--name VALUE", "--name=VALUE", aliases ("-o FILE"), "-h"/"--help", "--" ending the options.
// Every value is parsed and range-checked here, so a bad one is reported before any work.
// Throws UsageError naming the argument.
Arguments parseArguments(const Command& command, const std::vector<std::string>& args);

// The help of COMMAND laid out for a terminal of WIDTH columns: the summary wrapped, each option
// with its description beside it from column 30 (under it when the option's own text is longer),
// wrapped, its choices on a line of their own; descriptions are never narrower than 40 columns
// (a terminal narrower than 70 gets lines longer than itself rather than a slim column).
std::string helpText(const Command& command, std::size_t width);
// The same for the terminal the help is printed to (terminalWidth).
std::string helpText(const Command& command);

// Columns of the terminal standard output is: $COLUMNS when set to a number, else the
// terminal's own width when standard output is one, else 80.
std::size_t terminalWidth();

// TEXT broken at blanks into lines that fit WIDTH columns, each line after the first starting
// with INDENT spaces (the first starts at column INDENT already); no trailing newline. A word
// longer than the room keeps its own line.
std::string wrapText(const std::string& text, std::size_t indent, std::size_t width);

// An image size "N" (square) or "WxH", each side in [1, maxSide]; throws UsageError
// "SUBJECT: reason".
std::pair<int, int> parseImageSize(const std::string& text, const std::string& subject,
                                   int maxSide);

// TEXT as one line: core errors may quote a library's multi-line message ("a\nb" becomes
// "a; b"), the user gets one line.
std::string oneLine(std::string text);

// Runs BODY and turns what it throws into exactly one line "aniso: subject: reason" on ERR
// and an exit code: 2 for usage errors, 1 for run-time failures.
int runReportingErrors(const std::function<int()>& body, std::ostream& err);
} // namespace aniso::cli
