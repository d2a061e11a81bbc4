#include "core/formats/mtl.h"

#include "core/error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <system_error>

namespace aniso
{
namespace
{
bool isBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string lower(std::string_view s)
{
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](char c)
                 { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; });
  return out;
}

// Whether TEXT is well-formed UTF-8 (no overlong forms, surrogates or code points past
// U+10FFFF): names and file names go into JSON documents, which hold nothing else.
bool isUtf8(std::string_view text)
{
  size_t i = 0;
  while (i < text.size())
  {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char c = byte(i);
    size_t length = 0;
    unsigned lowest = 0;
    if (c < 0x80)
    {
      ++i;
      continue;
    }
    if (c >= 0xC2 && c <= 0xDF)
    {
      length = 2;
      lowest = 0x80;
    }
    else if (c >= 0xE0 && c <= 0xEF)
    {
      length = 3;
      lowest = 0x800;
    }
    else if (c >= 0xF0 && c <= 0xF4)
    {
      length = 4;
      lowest = 0x10000;
    }
    else
    {
      return false;
    }
    if (i + length > text.size())
    {
      return false;
    }
    unsigned code = c & (0x7Fu >> length);
    for (size_t k = 1; k < length; ++k)
    {
      if ((byte(i + k) & 0xC0) != 0x80)
      {
        return false;
      }
      code = (code << 6) | (byte(i + k) & 0x3Fu);
    }
    if (code < lowest || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
    {
      return false;
    }
    i += length;
  }
  return true;
}

// A line's words, and where each begins (a texture's file name is the rest of the line from a
// word on).
struct Words
{
  std::string_view line;
  std::vector<std::string_view> words;
  std::vector<size_t> starts;

  explicit Words(std::string_view text) : line(text)
  {
    size_t at = 0;
    while (at < line.size())
    {
      while (at < line.size() && isBlank(line[at]))
      {
        ++at;
      }
      const size_t start = at;
      while (at < line.size() && !isBlank(line[at]))
      {
        ++at;
      }
      if (at > start)
      {
        words.push_back(line.substr(start, at - start));
        starts.push_back(start);
      }
    }
  }

  // The text from word I to the end of the line, trailing blanks dropped.
  std::string_view restFrom(size_t i) const
  {
    std::string_view rest = line.substr(starts[i]);
    while (!rest.empty() && isBlank(rest.back()))
    {
      rest.remove_suffix(1);
    }
    return rest;
  }
};

// A finite number spelt as the whole of WORD (std::from_chars: no locale, no "nan", no "inf").
std::optional<double> numberOf(std::string_view word)
{
  if (!word.empty() && word.front() == '+')
  {
    word.remove_prefix(1);
  }
  double value = 0.0;
  const char* end = word.data() + word.size();
  const auto [ptr, ec] = std::from_chars(word.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value))
  {
    return std::nullopt;
  }
  return value;
}

std::string spelt(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Thrown inside the parser only, for the line at hand; caught and made a warning.
struct Malformed
{
  std::string reason;
};

double numberIn(std::string_view word, const std::string& key, double low, double high)
{
  const std::optional<double> value = numberOf(word);
  if (!value)
  {
    throw Malformed{key + ": '" + std::string(word) + "' is not a finite number"};
  }
  if (*value < low || *value > high)
  {
    throw Malformed{key + ": " + std::string(word) + " is outside [" + spelt(low) + ", " +
                    spelt(high) + "]"};
  }
  return *value;
}

double scalarOf(const Words& w, const std::string& key, double low, double high)
{
  if (w.words.size() != 2)
  {
    throw Malformed{key + ": one value expected, " + std::to_string(w.words.size() - 1) + " given"};
  }
  return numberIn(w.words[1], key, low, high);
}

MtlColor colorOf(const Words& w, const std::string& key)
{
  if (w.words.size() >= 2)
  {
    const std::string form = lower(w.words[1]);
    if (form == "spectral" || form == "xyz")
    {
      throw Malformed{key + " " + form + ": only r g b colours are read"};
    }
  }
  constexpr double kHuge = 1e6;
  if (w.words.size() == 2)
  {
    const double grey = numberIn(w.words[1], key, 0.0, kHuge);
    return {grey, grey, grey};
  }
  if (w.words.size() != 4)
  {
    throw Malformed{key + ": 1 or 3 values expected, " + std::to_string(w.words.size() - 1) +
                    " given"};
  }
  return {numberIn(w.words[1], key, 0.0, kHuge), numberIn(w.words[2], key, 0.0, kHuge),
          numberIn(w.words[3], key, 0.0, kHuge)};
}

// "on" or "off".
void onOffAt(const Words& w, size_t at, const std::string& option)
{
  if (at >= w.words.size() || (lower(w.words[at]) != "on" && lower(w.words[at]) != "off"))
  {
    throw Malformed{option + ": on or off expected"};
  }
}

MtlTexture textureOf(const Words& w, const std::string& key, int line)
{
  MtlTexture texture;
  texture.line = line;
  size_t at = 1;
  auto needs = [&](size_t count, const std::string& option)
  {
    if (at + count > w.words.size())
    {
      throw Malformed{key + " " + option + ": a value is missing"};
    }
  };
  while (at < w.words.size() && w.words[at].size() > 1 && w.words[at].front() == '-')
  {
    const std::string option = lower(w.words[at]);
    ++at;
    if (option == "-blendu" || option == "-blendv" || option == "-cc" || option == "-clamp")
    {
      onOffAt(w, at, key + " " + option);
      ++at;
    }
    else if (option == "-bm")
    {
      needs(1, option);
      texture.bumpMultiplier = numberIn(w.words[at++], key + " -bm", -1e6, 1e6);
    }
    else if (option == "-boost" || option == "-texres")
    {
      needs(1, option);
      numberIn(w.words[at++], key + " " + option, -1e9, 1e9);
    }
    else if (option == "-mm")
    {
      needs(2, option);
      numberIn(w.words[at++], key + " -mm", -1e9, 1e9);
      numberIn(w.words[at++], key + " -mm", -1e9, 1e9);
    }
    else if (option == "-imfchan" || option == "-type")
    {
      needs(1, option);
      ++at;
    }
    else if (option == "-o" || option == "-s" || option == "-t")
    {
      // One to three numbers; the identity is 0 for -o and -t, 1 for -s.
      const double identity = option == "-s" ? 1.0 : 0.0;
      needs(1, option);
      size_t taken = 0;
      while (taken < 3 && at < w.words.size() && numberOf(w.words[at]))
      {
        texture.transformed = texture.transformed || *numberOf(w.words[at]) != identity;
        ++at;
        ++taken;
      }
      if (taken == 0)
      {
        throw Malformed{key + " " + option + ": '" + std::string(w.words[at]) +
                        "' is not a finite number"};
      }
    }
    else
    {
      throw Malformed{key + ": unknown option " + std::string(w.words[at - 1])};
    }
  }
  if (at >= w.words.size())
  {
    throw Malformed{key + ": no file name"};
  }
  std::string file(w.restFrom(at));
  std::replace(file.begin(), file.end(), '\\', '/');
  if (file.size() > kMaxMtlNameLength)
  {
    throw Malformed{key + ": a file name longer than " + std::to_string(kMaxMtlNameLength) +
                    " characters"};
  }
  if (!isUtf8(file))
  {
    throw Malformed{key + ": a file name that is not UTF-8"};
  }
  texture.file = std::move(file);
  return texture;
}

// The statements that are read, by their lower-case keyword; the others of the format that
// this project has no use for are passed over.
bool isPassedOver(const std::string& key)
{
  static const char* const kUnused[] = {
      "ka",    "ke",   "ni", "illum", "tf",     "map_ka",    "map_ke",  "map_d", "disp",
      "decal", "refl", "pc", "pcr",   "map_ps", "sharpness", "map_aat", "tr_map"};
  return std::find(std::begin(kUnused), std::end(kUnused), key) != std::end(kUnused);
}

class Parser
{
public:
  explicit Parser(const std::string& path) : path_(path) {}

  void warn(int line, const std::string& reason)
  {
    ++warnings_;
    if (library_.warnings.size() < kMaxMtlWarnings)
    {
      library_.warnings.push_back(path_ + ":" + std::to_string(line) + ": " + reason);
    }
  }

  void statement(std::string_view text, int line)
  {
    const Words w(text);
    if (w.words.empty())
    {
      return;
    }
    const std::string key = lower(w.words[0]);
    if (key == "newmtl")
    {
      newMaterial(w, line);
      return;
    }
    if (isPassedOver(key))
    {
      return;
    }
    if (skipping_)
    {
      return; // the statements of a material refused at its newmtl (told there)
    }
    if (!current())
    {
      warn(line, std::string(w.words[0]) + ": a statement before any newmtl");
      return;
    }
    MtlMaterial& m = *current();
    if (key == "kd")
    {
      m.kd = colorOf(w, "Kd");
    }
    else if (key == "ks")
    {
      m.ks = colorOf(w, "Ks");
    }
    else if (key == "ns")
    {
      m.ns = scalarOf(w, "Ns", 0.0, 1e9);
    }
    else if (key == "d")
    {
      if (w.words.size() == 3 && lower(w.words[1]) == "-halo")
      {
        m.opacity = numberIn(w.words[2], "d -halo", 0.0, 1.0);
      }
      else
      {
        m.opacity = scalarOf(w, "d", 0.0, 1.0);
      }
    }
    else if (key == "tr")
    {
      m.opacity = 1.0 - scalarOf(w, "Tr", 0.0, 1.0);
    }
    else if (key == "pr")
    {
      m.pr = scalarOf(w, "Pr", 0.0, 1.0);
    }
    else if (key == "pm")
    {
      m.pm = scalarOf(w, "Pm", 0.0, 1.0);
    }
    else if (key == "ps")
    {
      m.ps = scalarOf(w, "Ps", 0.0, 1.0);
    }
    else if (key == "aniso")
    {
      m.aniso = scalarOf(w, "aniso", 0.0, 1.0);
    }
    else if (key == "anisor")
    {
      m.anisor = scalarOf(w, "anisor", -1e9, 1e9);
      m.anisorLine = line;
    }
    else if (key == "map_kd")
    {
      m.mapKd = textureOf(w, "map_Kd", line);
    }
    else if (key == "map_ks")
    {
      m.mapKs = textureOf(w, "map_Ks", line);
    }
    else if (key == "map_ns")
    {
      m.mapNs = textureOf(w, "map_Ns", line);
    }
    else if (key == "map_bump" || key == "bump")
    {
      m.bump = textureOf(w, std::string(w.words[0]), line);
    }
    else if (key == "norm" || key == "map_norm")
    {
      m.norm = textureOf(w, std::string(w.words[0]), line);
    }
    else if (key == "map_pr")
    {
      m.mapPr = textureOf(w, "map_Pr", line);
    }
    else if (key == "map_pm")
    {
      m.mapPm = textureOf(w, "map_Pm", line);
    }
    else
    {
      std::string shown(w.words[0].substr(0, 40));
      warn(line, "unknown statement '" + shown + "'");
    }
  }

  MtlLibrary finish()
  {
    if (warnings_ > library_.warnings.size())
    {
      library_.warnings.push_back(
          path_ + ": " + std::to_string(warnings_ - library_.warnings.size()) + " more warnings");
    }
    return std::move(library_);
  }

private:
  MtlMaterial* current() { return currentIndex_ ? &library_.materials[*currentIndex_] : nullptr; }

  void newMaterial(const Words& w, int line)
  {
    skipping_ = true;
    currentIndex_.reset();
    if (w.words.size() < 2)
    {
      warn(line, "newmtl without a name (its statements are skipped)");
      return;
    }
    const std::string name(w.restFrom(1));
    if (name.size() > kMaxMtlNameLength)
    {
      warn(line, "newmtl: a name longer than " + std::to_string(kMaxMtlNameLength) +
                     " characters (its statements are skipped)");
      return;
    }
    if (!isUtf8(name))
    {
      warn(line, "newmtl: a name that is not UTF-8 (its statements are skipped)");
      return;
    }
    if (names_.count(name) > 0)
    {
      warn(line, "newmtl " + name + ": a second material of this name (the first is kept)");
      return;
    }
    if (library_.materials.size() >= kMaxMtlMaterials)
    {
      warn(line, "newmtl " + name + ": more than " + std::to_string(kMaxMtlMaterials) +
                     " materials (the rest are skipped)");
      return;
    }
    MtlMaterial m;
    m.name = name;
    m.line = line;
    names_.insert(name);
    library_.materials.push_back(std::move(m));
    currentIndex_ = library_.materials.size() - 1;
    skipping_ = false;
  }

  const std::string& path_;
  MtlLibrary library_;
  std::set<std::string, std::less<>> names_; // a name's repeat found without a scan
  std::optional<size_t> currentIndex_;
  bool skipping_ = false;
  size_t warnings_ = 0;
};
} // namespace

bool MtlMaterial::hasPbrKeys() const
{
  return pr || pm || aniso || anisor || mapPr || mapPm;
}

const MtlMaterial* MtlLibrary::find(std::string_view name) const
{
  const auto it = std::find_if(materials.begin(), materials.end(),
                               [&](const MtlMaterial& m) { return m.name == name; });
  return it == materials.end() ? nullptr : &*it;
}

MtlLibrary parseMtl(std::string_view text, const std::string& path)
{
  Parser parser(path);
  int line = 0;
  size_t at = 0;
  while (at < text.size())
  {
    size_t end = text.find('\n', at);
    end = end == std::string_view::npos ? text.size() : end;
    std::string_view statement = text.substr(at, end - at);
    at = end + 1;
    ++line;
    if (statement.size() > kMaxMtlLineLength)
    {
      parser.warn(line, "a line longer than " + std::to_string(kMaxMtlLineLength) + " characters");
      continue;
    }
    // A comment runs from a '#' at the start or after a blank (a file name may hold one).
    for (size_t c = 0; c < statement.size(); ++c)
    {
      if (statement[c] == '#' && (c == 0 || isBlank(statement[c - 1])))
      {
        statement = statement.substr(0, c);
        break;
      }
    }
    if (statement.find('\0') != std::string_view::npos)
    {
      parser.warn(line, "a NUL character");
      continue;
    }
    try
    {
      parser.statement(statement, line);
    }
    catch (const Malformed& m)
    {
      parser.warn(line, m.reason);
    }
  }
  return parser.finish();
}

MtlLibrary readMtlFile(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
  {
    throw errorAbout(path, ec || !std::filesystem::exists(path, ec) ? "no such file"
                                                                    : "not a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw errorAbout(path, "cannot be read");
  }
  std::string text;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
  {
    text.append(buffer, static_cast<size_t>(in.gcount()));
    if (text.size() > kMaxMtlFileBytes)
    {
      throw errorAbout(path, "larger than the " + std::to_string(kMaxMtlFileBytes >> 20) +
                                 " MiB a material library may have");
    }
  }
  if (in.bad())
  {
    throw errorAbout(path, "cannot be read");
  }
  return parseMtl(text, path);
}
} // namespace aniso
