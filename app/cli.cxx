#include "app/cli.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <new>
#include <ostream>
#include <sstream>
#include <sys/ioctl.h>
#include <unistd.h>

namespace aniso::cli
{
namespace
{
std::string valueNameOf(ParameterType type)
{
  switch (type)
  {
  case ParameterType::Integer:
    return "N";
  case ParameterType::Real:
    return "X";
  case ParameterType::Color:
    return "R,G,B";
  case ParameterType::Text:
    break;
  }
  return "TEXT";
}

const Option* findOption(const Command& command, const std::string& name)
{
  for (const auto& option : command.options)
  {
    if (option.name == name || (!option.alias.empty() && option.alias == name))
    {
      return &option;
    }
  }
  return nullptr;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator)
{
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i)
  {
    s += (i ? separator : "") + items[i];
  }
  return s;
}

// "(0 to 1e6, default 1000)", "(deg, -180 to 180, default 0)", "(default builtin:studio)".
std::string rangeAndDefault(const Option& option)
{
  const ParameterSpec& spec = option.spec;
  std::vector<std::string> parts;
  if (spec.type != ParameterType::Text)
  {
    if (!spec.unit.empty())
    {
      parts.push_back(std::string(spec.unit));
    }
    parts.push_back(formatNumber(spec.minimum) + " to " + formatNumber(spec.maximum));
    if (spec.powerOfTwo)
    {
      parts.push_back("a power of two");
    }
  }
  if (option.required)
  {
    parts.push_back("required");
  }
  else
  {
    const std::string shown = formatParameterValue(spec, defaultParameterValue(spec));
    if (!shown.empty())
    {
      parts.push_back("default " + shown);
    }
  }
  return parts.empty() ? std::string() : " (" + joined(parts, ", ") + ")";
}

// The column option descriptions start at, and the narrowest they may be.
constexpr std::size_t kDescriptionColumn = 30;
constexpr std::size_t kMinDescription = 40;

bool startsWith(std::string_view text, std::string_view prefix)
{
  return text.substr(0, prefix.size()) == prefix;
}

// One option's rows: "  -o, --output FILE" and its description (range and default included),
// then its choices, each wrapped at COLUMN to WIDTH.
// "one of: a|b|c" from COLUMN, broken after a '|' where a line would pass WIDTH.
std::string choiceRows(const std::vector<std::string>& choices, std::size_t column,
                       std::size_t width)
{
  std::string out = std::string(column, ' ') + "one of: ";
  std::size_t length = out.size();
  for (std::size_t i = 0; i < choices.size(); ++i)
  {
    const std::string piece = choices[i] + (i + 1 < choices.size() ? "|" : "");
    if (length + piece.size() > width && length > column + 8)
    {
      out += "\n" + std::string(column + 8, ' ');
      length = column + 8;
    }
    out += piece;
    length += piece.size();
  }
  return out + "\n";
}

std::string optionRows(const std::string& left, const std::string& description,
                       const std::vector<std::string>& choices, std::size_t column,
                       std::size_t width)
{
  std::string out = "  " + left;
  if (2 + left.size() + 2 <= column)
  {
    out += std::string(column - 2 - left.size(), ' ');
  }
  else
  {
    out += "\n" + std::string(column, ' ');
  }
  out += wrapText(description, column, width) + "\n";
  if (!choices.empty())
  {
    out += choiceRows(choices, column, width);
  }
  return out;
}

// A line of a help's details that is a command (indented): broken where it would pass WIDTH
// into lines continued with " \\", each after the first indented by four more blanks.
std::string wrappedCommandLine(const std::string& line, std::size_t width)
{
  const std::size_t indent = line.find_first_not_of(' ');
  if (line.size() <= width || indent == std::string::npos)
  {
    return line + "\n";
  }
  std::string out = line.substr(0, indent);
  std::size_t column = indent;
  std::istringstream words(line.substr(indent));
  std::string word;
  bool first = true;
  while (words >> word)
  {
    if (!first && column + 1 + word.size() + 2 > width)
    {
      out += " \\\n" + std::string(indent + 4, ' ');
      column = indent + 4;
    }
    else if (!first)
    {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    first = false;
  }
  return out + "\n";
}

// A help's details wrapped to WIDTH: indented lines (commands) stay lines of their own
// (wrappedCommandLine); other lines are rewrapped as paragraphs, a paragraph ending at a blank
// or indented line, or where a line ending in '.' or ':' is followed by one starting with a
// capital ("Output: ...", "Example: ...").
std::string wrappedDetails(const std::string& text, std::size_t width)
{
  std::string out;
  std::string paragraph;
  const auto flush = [&]
  {
    if (!paragraph.empty())
    {
      out += wrapText(paragraph, 0, width) + "\n";
      paragraph.clear();
    }
  };
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
  {
    if (line.empty() || line.front() == ' ')
    {
      flush();
      out += line.empty() ? "\n" : wrappedCommandLine(line, width);
      continue;
    }
    const char last = paragraph.empty() ? ' ' : paragraph.back();
    if ((last == '.' || last == ':') && std::isupper(static_cast<unsigned char>(line.front())))
    {
      flush();
    }
    paragraph += (paragraph.empty() ? "" : " ") + line;
  }
  flush();
  return out;
}

// The summary's paragraphs (separated by a blank line; single line breaks are blanks) wrapped.
std::string wrappedParagraphs(const std::string& text, std::size_t width)
{
  std::string out;
  std::size_t begin = 0;
  while (begin <= text.size())
  {
    std::size_t end = text.find("\n\n", begin);
    if (end == std::string::npos)
    {
      end = text.size();
    }
    std::string paragraph = text.substr(begin, end - begin);
    std::replace(paragraph.begin(), paragraph.end(), '\n', ' ');
    if (paragraph.find_first_not_of(' ') != std::string::npos)
    {
      out += (out.empty() ? "" : "\n") + wrapText(paragraph, 0, width) + "\n";
    }
    begin = end + 2;
  }
  return out;
}
} // namespace

Option parameterOption(std::string_view parameter, std::string name, std::string_view help)
{
  Option option;
  option.spec = parameterSpec(parameter);
  option.name = name.empty() ? "--" + std::string(parameter) : std::move(name);
  option.valueName = valueNameOf(option.spec.type);
  option.group = groupOf(option.spec);
  if (!help.empty())
  {
    option.spec.help = help;
  }
  return option;
}

Option textOption(std::string name, std::string valueName, std::string_view help,
                  std::string_view defaultText)
{
  Option option;
  option.name = std::move(name);
  option.valueName = std::move(valueName);
  option.spec.type = ParameterType::Text;
  option.spec.help = help;
  option.spec.defaultText = defaultText;
  return option;
}

bool Arguments::has(const std::string& name) const
{
  return given_.count(name) != 0;
}

const ParameterValue& Arguments::value(const std::string& name) const
{
  const auto given = given_.find(name);
  if (given != given_.end())
  {
    return given->second;
  }
  const auto fallback = defaults_.find(name);
  if (fallback == defaults_.end())
  {
    throw errorAbout(name, "not an option of this command");
  }
  return fallback->second;
}

double Arguments::real(const std::string& name) const
{
  return value(name).number[0];
}

int Arguments::integer(const std::string& name) const
{
  return static_cast<int>(value(name).number[0]);
}

glm::dvec3 Arguments::color(const std::string& name) const
{
  const auto& n = value(name).number;
  return {n[0], n[1], n[2]};
}

const std::string& Arguments::text(const std::string& name) const
{
  return value(name).text;
}

std::vector<std::string> Arguments::texts(const std::string& name) const
{
  const auto found = repeated_.find(name);
  return found != repeated_.end() ? found->second : std::vector<std::string>{};
}

Arguments parseArguments(const Command& command, const std::vector<std::string>& args)
{
  Arguments parsed;
  for (const auto& option : command.options)
  {
    parsed.defaults_[option.name] = defaultParameterValue(option.spec);
  }
  const std::string seeHelp =
      " (see " + command.usage.substr(0, command.usage.find(" [")) + " --help)";

  bool optionsEnded = false;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& arg = args[i];
    if (optionsEnded || arg.size() < 2 || arg[0] != '-')
    {
      parsed.positionals.push_back(arg);
      continue;
    }
    if (arg == "--")
    {
      optionsEnded = true;
      continue;
    }
    if (arg == "-h" || arg == "--help")
    {
      parsed.helpRequested = true;
      continue;
    }
    std::string name = arg;
    std::string text;
    bool inlineValue = false;
    const std::size_t equals = arg.find('=');
    if (arg.compare(0, 2, "--") == 0 && equals != std::string::npos)
    {
      name = arg.substr(0, equals);
      text = arg.substr(equals + 1);
      inlineValue = true;
    }
    const Option* option = findOption(command, name);
    if (!option)
    {
      throw usageError(name, "unknown option" + seeHelp);
    }
    if (parsed.given_.count(option->name) && !option->repeatable)
    {
      throw usageError(name, "given more than once");
    }
    if (option->valueName.empty())
    {
      // A flag: present or not.
      if (inlineValue)
      {
        throw usageError(name, "takes no value");
      }
      parsed.given_[option->name] = ParameterValue{};
      continue;
    }
    if (!inlineValue)
    {
      // A following "--option" is a forgotten value, not a value; "-30" is a value.
      if (i + 1 >= args.size() || args[i + 1].compare(0, 2, "--") == 0)
      {
        throw usageError(name, "missing value " + option->valueName);
      }
      text = args[++i];
    }
    try
    {
      ParameterValue value = parseParameterValue(option->spec, text, name);
      if (!option->choices.empty() && std::find(option->choices.begin(), option->choices.end(),
                                                value.text) == option->choices.end())
      {
        throw usageError(name, "'" + text + "' is not one of " + joined(option->choices, ", "));
      }
      if (option->repeatable)
      {
        parsed.repeated_[option->name].push_back(value.text);
      }
      parsed.given_[option->name] = std::move(value);
    }
    catch (const UsageError&)
    {
      throw;
    }
    catch (const Error& e)
    {
      throw UsageError(e.what());
    }
  }
  if (parsed.helpRequested)
  {
    return parsed;
  }
  for (const auto& option : command.options)
  {
    if (option.required && !parsed.has(option.name))
    {
      throw usageError(option.alias.empty() ? option.name : option.alias,
                       "missing " + option.valueName + " (required)");
    }
  }
  if (parsed.positionals.size() < command.positionals.size())
  {
    throw usageError(command.positionals[parsed.positionals.size()], "missing argument");
  }
  if (parsed.positionals.size() > command.positionals.size() &&
      !(command.lastPositionalRepeats && !command.positionals.empty()))
  {
    throw usageError(parsed.positionals[command.positionals.size()], "unexpected argument");
  }
  return parsed;
}

std::string groupOf(const ParameterSpec& spec)
{
  if (spec.affects(Affects::Meshes))
  {
    return kGroupScene;
  }
  if (spec.scope == ParameterScope::Material)
  {
    return spec.affects(Affects::Variant) ? kGroupMaps : kGroupMaterial;
  }
  if (spec.affects(Affects::Display))
  {
    return kGroupOutput;
  }
  if (spec.affects(Affects::Variant | Affects::Luts | Affects::Uniforms))
  {
    return kGroupSampling;
  }
  if (spec.affects(Affects::LitModels) || startsWith(spec.name, "env"))
  {
    return kGroupLighting;
  }
  return kGroupModels;
}

std::string wrapText(const std::string& text, std::size_t indent, std::size_t width)
{
  const std::size_t room = width > indent ? width - indent : 1;
  std::string out;
  std::size_t column = 0;
  std::istringstream words(text);
  std::string word;
  while (words >> word)
  {
    if (column > 0 && column + 1 + word.size() > room)
    {
      out += "\n" + std::string(indent, ' ');
      column = 0;
    }
    else if (column > 0)
    {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
  }
  return out;
}

std::size_t terminalWidth()
{
  if (const char* columns = std::getenv("COLUMNS"))
  {
    char* end = nullptr;
    const long n = std::strtol(columns, &end, 10);
    if (end != columns && *end == '\0' && n > 0 && n < 10000)
    {
      return static_cast<std::size_t>(n);
    }
  }
  winsize size{};
  if (isatty(STDOUT_FILENO) && ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0)
  {
    return size.ws_col;
  }
  return 80;
}

std::string helpText(const Command& command)
{
  return helpText(command, terminalWidth());
}

std::string helpText(const Command& command, std::size_t terminal)
{
  // Room for the description column and 40 columns of description, however narrow the terminal.
  const std::size_t width = std::max(terminal, kDescriptionColumn + kMinDescription);
  std::ostringstream s;
  s << "Usage: " << command.usage << "\n\n" << wrappedParagraphs(command.summary, width);

  // Groups in their fixed order, then any other heading in the order of its first option, then
  // the options of no group with --help.
  std::vector<std::string> order = {kGroupScene,    kGroupView,     kGroupMaterial, kGroupMaps,
                                    kGroupLighting, kGroupSampling, kGroupModels,   kGroupOutput};
  std::map<std::string, std::string> rows;
  for (const auto& option : command.options)
  {
    const std::string group = command.grouped ? option.group : std::string();
    std::string left = (option.alias.empty() ? "" : option.alias + ", ") + option.name;
    if (!option.valueName.empty())
    {
      const bool chosen = !option.choices.empty();
      left += " " + (chosen && option.valueName == "TEXT" ? std::string("WORD") : option.valueName);
    }
    if (!group.empty() && std::find(order.begin(), order.end(), group) == order.end())
    {
      order.push_back(group);
    }
    rows[group] += optionRows(left, std::string(option.spec.help) + rangeAndDefault(option),
                              option.choices, kDescriptionColumn, width);
  }
  rows[""] += optionRows("-h, --help", "show this help and exit", {}, kDescriptionColumn, width);
  order.push_back("");
  for (const std::string& group : order)
  {
    const auto found = rows.find(group);
    if (found != rows.end())
    {
      s << "\n" << (group.empty() ? std::string("Options") : group) << ":\n" << found->second;
    }
  }
  if (!command.details.empty())
  {
    s << "\n" << wrappedDetails(command.details, width);
  }
  return s.str();
}

std::pair<int, int> parseImageSize(const std::string& text, const std::string& subject, int maxSide)
{
  ParameterSpec side;
  side.type = ParameterType::Integer;
  side.minimum = 1.0;
  side.maximum = maxSide;
  const std::size_t x = text.find('x');
  const std::string w = text.substr(0, x);
  const std::string h = x == std::string::npos ? w : text.substr(x + 1);
  try
  {
    return {static_cast<int>(parseParameterValue(side, w, subject).number[0]),
            static_cast<int>(parseParameterValue(side, h, subject).number[0])};
  }
  catch (const Error& e)
  {
    throw UsageError(e.what());
  }
}

std::string oneLine(std::string text)
{
  std::replace(text.begin(), text.end(), '\r', ' ');
  std::string out;
  for (char c : text)
  {
    if (c == '\n')
    {
      if (!out.empty() && out.back() != ' ')
      {
        out += "; ";
      }
    }
    else
    {
      out += c;
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';'))
  {
    out.pop_back();
  }
  return out;
}

int runReportingErrors(const std::function<int()>& body, std::ostream& err)
{
  try
  {
    return body();
  }
  catch (const UsageError& e)
  {
    err << "aniso: " << oneLine(e.what()) << std::endl;
    return 2;
  }
  catch (const Error& e)
  {
    err << "aniso: " << oneLine(e.what()) << std::endl;
    return 1;
  }
  catch (const std::bad_alloc&)
  {
    err << "aniso: out of memory" << std::endl;
    return 1;
  }
  catch (const std::exception& e)
  {
    err << "aniso: " << oneLine(e.what()) << std::endl;
    return 1;
  }
}
} // namespace aniso::cli
