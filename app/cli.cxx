#include "app/cli.h"

#include <algorithm>
#include <new>
#include <ostream>
#include <sstream>

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

constexpr std::size_t kHelpWidth = 100;

// TEXT broken at spaces into lines of at most WIDTH columns, continuation lines indented to
// INDENT (the first line starts there already).
std::string wrapped(const std::string& text, std::size_t indent, std::size_t width)
{
  const std::size_t room = width > indent + 20 ? width - indent : 20;
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

} // namespace

Option parameterOption(std::string_view parameter, std::string name, std::string_view help)
{
  Option option;
  option.spec = parameterSpec(parameter);
  option.name = name.empty() ? "--" + std::string(parameter) : std::move(name);
  option.valueName = valueNameOf(option.spec.type);
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

std::string helpText(const Command& command)
{
  std::ostringstream s;
  s << "Usage: " << command.usage << "\n\n" << command.summary << "\n";
  std::vector<std::pair<std::string, std::string>> rows;
  for (const auto& option : command.options)
  {
    std::string left = (option.alias.empty() ? "" : option.alias + ", ") + option.name;
    if (!option.valueName.empty() || !option.choices.empty())
    {
      left += " " + (option.choices.empty() ? option.valueName : joined(option.choices, "|"));
    }
    rows.emplace_back(left, std::string(option.spec.help) + rangeAndDefault(option));
  }
  rows.emplace_back("-h, --help", "show this help and exit");
  std::size_t width = 0;
  for (const auto& row : rows)
  {
    width = std::max(width, row.first.size());
  }
  s << "\nOptions:\n";
  const std::size_t indent = 2 + width + 2;
  for (const auto& row : rows)
  {
    s << "  " << row.first << std::string(width - row.first.size() + 2, ' ')
      << wrapped(row.second, indent, kHelpWidth) << "\n";
  }
  if (!command.details.empty())
  {
    s << "\n" << command.details;
    if (command.details.back() != '\n')
    {
      s << "\n";
    }
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
