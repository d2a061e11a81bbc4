#include "core/formats/vtk_legacy_sizes.h"

#include "core/error.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <iterator>
#include <cstdlib>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <locale>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

namespace aniso
{
namespace
{
std::string lowerCase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::vector<std::string> tokensOf(const std::string& line)
{
  std::istringstream words(line);
  std::vector<std::string> tokens;
  for (std::string word; words >> word;)
  {
    tokens.push_back(word);
  }
  return tokens;
}

// A count as VTK's stream extraction reads it: the token's leading integer.
std::optional<long long> countOf(const std::string& token)
{
  std::istringstream stream(token);
  stream.imbue(std::locale::classic());
  long long value = 0;
  stream >> value;
  if (stream.fail())
  {
    return std::nullopt;
  }
  return value;
}

// The bytes a value of a legacy type name takes in a binary file, in eighths of a byte (a bit
// array packs eight values a byte); nothing for a name VTK's legacy reader does not know. VTK
// 9.1 matches a type name by its start (strncmp: "bitble" is a bit array, "int64" an int
// array); none of its names starts another, so the one name that starts TYPE is the match.
// Strings and variants take at least one byte.
std::optional<int> eighthsOf(const std::string& type)
{
  static const std::pair<const char*, int> kTypes[] = {
      {"bit", 1},           {"char", 8},          {"signed_char", 8},   {"unsigned_char", 8},
      {"short", 16},        {"unsigned_short", 16}, {"vtkidtype", 64},  {"int", 32},
      {"unsigned_int", 32}, {"long", 64},         {"unsigned_long", 64}, {"vtktypeint64", 64},
      {"vtktypeuint64", 64}, {"float", 32},       {"double", 64},       {"string", 8},
      {"utf8_string", 8},   {"variant", 8}};
  const std::string name = lowerCase(type);
  for (const auto& [known, eighths] : kTypes)
  {
    if (name.rfind(known, 0) == 0)
    {
      return eighths;
    }
  }
  return std::nullopt;
}

class SizeScan
{
public:
  SizeScan(std::uintmax_t fileBytes, bool binary)
      : FileBytes(fileBytes)
      , Binary(binary)
  {
  }

  // Checks COUNT x COMPONENTS values of a type of EIGHTHS eighths of a byte (in a binary file;
  // at least a byte each in an ASCII one), declared by KEYWORD on LINE; sets Problem when they
  // cannot fit or a number is negative.
  void check(const std::string& keyword, long long count, long long components, int eighths,
             const std::string& what)
  {
    if (this->Problem)
    {
      return;
    }
    if (count < 0 || components < 0)
    {
      this->Problem = "line " + std::to_string(this->Line) + ": " + keyword + " declares " +
                      std::to_string(std::min(count, components)) + " " + what +
                      ", a negative count";
      return;
    }
    // count x components x perValue <= the file's eighths of a byte, without overflow: for
    // positive integers a x b <= c exactly when a <= floor(c / b).
    const int perValue = this->Binary ? eighths : 8;
    const std::uintmax_t capacity = this->FileBytes * 8;
    if (components == 0 ||
        static_cast<std::uintmax_t>(count) <=
            capacity / static_cast<std::uintmax_t>(perValue) /
                static_cast<std::uintmax_t>(components))
    {
      return;
    }
    std::string size;
    if (!this->Binary)
    {
      size = "at least 1 byte each, as text";
    }
    else if (perValue % 8 == 0)
    {
      size = std::to_string(perValue / 8) + (perValue == 8 ? " byte each" : " bytes each");
    }
    else
    {
      size = "1 bit each";
    }
    std::string valueText = components == 1 ? std::to_string(count) + " " + what
                                            : std::to_string(count) + " " + what + " of " +
                                                  std::to_string(components) + " values";
    this->Problem = "line " + std::to_string(this->Line) + ": " + keyword + " declares " +
                    valueText + " (" + size + "), more than the file's " +
                    std::to_string(this->FileBytes) +
                    " bytes hold (the file is cut short or its counts are corrupt)";
  }

  std::uintmax_t FileBytes = 0;
  bool Binary = false;
  long long Line = 0;
  std::optional<std::string> Problem;
};

// The dataset section of a version 5 file (polygonal data, grids, structured points), walked
// token by token as VTK 9.1's readers walk it, up to its POINT_DATA or CELL_DATA. VTK's readers
// dereference the field data they failed to read there (vtkPolyDataReader::ReadMeshSimple
// deletes the null result of ReadFieldData: SEGV, fuzz_vtk; the structured-points, structured
// and rectilinear grid readers crash the same way; in POINT_DATA and CELL_DATA VTK refuses such a
// block itself), and after a value that does not read its ASCII
// readers go on from where the stream stopped, so that a "1field" among the points is read as
// the value 1 and a FIELD keyword. So a FIELD block must read (its header, each array's name,
// components, tuples and a type VTK knows) and every ASCII value of the walked arrays must read
// whole as a number. The walk stops, leaving the rest to VTK, at a keyword it does not follow
// (VTK refuses an unknown one), at string arrays and where binary data are cut short.
class SectionWalk
{
public:
  SectionWalk(const std::string& text, bool binary)
      : Text(text)
      , Binary(binary)
  {
  }

  // POLYGONAL: polygonal data, else an unstructured grid unless STRUCTURED (structured points,
  // structured and rectilinear grids, whose sections hold DIMENSIONS, SPACING, ORIGIN and
  // coordinates instead of cells).
  std::optional<std::string> run(bool polygonal, bool structured = false)
  {
    for (int i = 0; i < 3; ++i)
    {
      this->skipLine();
    }
    std::string token;
    if (!this->next(token) || lowerCase(token).rfind("dataset", 0) != 0 || !this->next(token))
    {
      return std::nullopt;
    }
    while (!this->Problem && this->next(token))
    {
      const std::string key = lowerCase(token);
      const long long line = this->Line;
      if (key.rfind("field", 0) == 0)
      {
        if (!this->field(line))
        {
          break;
        }
      }
      else if (key.rfind("points", 0) == 0)
      {
        long long count = 0;
        std::string type;
        if (!this->count(count) || !this->next(type) || !this->fits(count, 3, "POINTS", line) ||
            !this->values(count * 3, type, "POINTS", line))
        {
          break;
        }
      }
      else if ((polygonal && (key.rfind("vertices", 0) == 0 || key.rfind("lines", 0) == 0 ||
                              key.rfind("polygons", 0) == 0 ||
                              key.rfind("triangle_strips", 0) == 0)) ||
               (!polygonal && !structured && key.rfind("cells", 0) == 0))
      {
        long long offsets = 0;
        long long connectivity = 0;
        std::string word;
        std::string type;
        if (!this->count(offsets) || !this->count(connectivity))
        {
          break;
        }
        if (offsets < 1)
        {
          continue; // VTK reads an empty list and nothing after the counts
        }
        if (!this->next(word) || lowerCase(word) != "offsets" || !this->next(type) ||
            !this->values(offsets, type, "OFFSETS", this->Line) || !this->next(word) ||
            lowerCase(word) != "connectivity" || !this->next(type) ||
            !this->values(connectivity, type, "CONNECTIVITY", this->Line))
        {
          break;
        }
      }
      else if (structured &&
               (key.rfind("dimensions", 0) == 0 || key.rfind("spacing", 0) == 0 ||
                key.rfind("aspect_ratio", 0) == 0 || key.rfind("origin", 0) == 0))
      {
        std::string value;
        if (!this->next(value) || !this->next(value) || !this->next(value))
        {
          break;
        }
      }
      else if (structured && (key.rfind("x_coordinates", 0) == 0 ||
                              key.rfind("y_coordinates", 0) == 0 ||
                              key.rfind("z_coordinates", 0) == 0))
      {
        long long count = 0;
        std::string type;
        std::string keyword = token.substr(0, 1) + "_COORDINATES";
        std::transform(keyword.begin(), keyword.end(), keyword.begin(),
                       [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
        if (!this->count(count) || !this->next(type) || !this->values(count, type, keyword, line))
        {
          break;
        }
      }
      else if (!polygonal && !structured && key.rfind("cell_types", 0) == 0)
      {
        long long count = 0;
        if (!this->count(count) || !this->values(count, "int", "CELL_TYPES", line))
        {
          break;
        }
      }
      else
      {
        break; // POINT_DATA, CELL_DATA, or a keyword VTK refuses
      }
    }
    return this->Problem;
  }

private:
  // Moves past the next token (VTK's ReadString: white space skipped, then a run of other
  // characters); returns where it starts (At when there is none).
  size_t skipToken()
  {
    while (this->At < this->Text.size() &&
           std::isspace(static_cast<unsigned char>(this->Text[this->At])))
    {
      this->Line += this->Text[this->At] == '\n';
      ++this->At;
    }
    const size_t start = this->At;
    while (this->At < this->Text.size() &&
           !std::isspace(static_cast<unsigned char>(this->Text[this->At])))
    {
      ++this->At;
    }
    return start;
  }

  // The next token, copied.
  bool next(std::string& token)
  {
    const size_t start = this->skipToken();
    token = this->Text.substr(start, this->At - start);
    return !token.empty();
  }

  void skipLine()
  {
    const size_t end = this->Text.find('\n', this->At);
    this->At = end == std::string::npos ? this->Text.size() : end + 1;
    ++this->Line;
  }

  // A count as VTK's Read extracts it: the token's leading integer.
  bool count(long long& value)
  {
    std::string token;
    if (!this->next(token))
    {
      return false;
    }
    const std::optional<long long> read = countOf(token);
    if (!read)
    {
      return false;
    }
    value = *read;
    return true;
  }

  // COUNT values of TYPE after a declaration of KEYWORD on LINE, then an optional METADATA
  // block. False where the walk stops.
  bool values(long long count, const std::string& type, const std::string& keyword, long long line)
  {
    const std::optional<int> eighths = eighthsOf(type);
    const std::string name = lowerCase(type);
    const bool numeric = name.rfind("string", 0) != 0 && name.rfind("utf8_string", 0) != 0 &&
                         name.rfind("variant", 0) != 0;
    if (eighths && !numeric && keyword.rfind("FIELD", 0) != 0)
    {
      // VTK reads the strings (in a binary file each with a length of its own, which it
      // allocates) before it finds they are no numbers.
      this->Problem = "line " + std::to_string(line) + ": " + keyword + " of type " + type +
                      ": points and cell lists hold numbers";
      return false;
    }
    if (!eighths || !numeric || !this->fits(count, 1, keyword, line))
    {
      return false;
    }
    if (this->Binary)
    {
      this->skipLine(); // VTK's "suck up newline"
      const std::uintmax_t bytes =
          (static_cast<std::uintmax_t>(count) * static_cast<std::uintmax_t>(*eighths) + 7) / 8;
      if (bytes > this->Text.size() - this->At)
      {
        return false;
      }
      this->Line += std::count(this->Text.begin() + static_cast<std::ptrdiff_t>(this->At),
                               this->Text.begin() + static_cast<std::ptrdiff_t>(this->At + bytes),
                               '\n');
      this->At += bytes;
    }
    else
    {
      for (long long i = 0; i < count; ++i)
      {
        // The token in place (no copy: a large ASCII file holds millions of values).
        const size_t start = this->skipToken();
        if (this->At == start)
        {
          return false; // VTK refuses a file that ends here
        }
        const char* begin = this->Text.c_str() + start;
        char* end = nullptr;
        std::strtod(begin, &end);
        if (end != this->Text.c_str() + this->At)
        {
          const std::string token = this->Text.substr(start, this->At - start);
          std::string shown = token.substr(0, 32);
          std::replace_if(
              shown.begin(), shown.end(),
              [](char c) { return !std::isprint(static_cast<unsigned char>(c)); }, '?');
          this->Problem = "line " + std::to_string(this->Line) + ": value " +
                          std::to_string(i + 1) + " of " + keyword + " (declared on line " +
                          std::to_string(line) + "), \"" + shown +
                          (token.size() > 32 ? "...\"" : "\"") + ", is not a number";
          return false;
        }
      }
    }
    // An array's METADATA block: its lines up to an empty one.
    const size_t mark = this->At;
    const long long markLine = this->Line;
    std::string token;
    if (this->next(token) && lowerCase(token) == "metadata")
    {
      this->skipLine();
      while (this->At < this->Text.size())
      {
        const size_t end = this->Text.find('\n', this->At);
        const std::string text =
            this->Text.substr(this->At, (end == std::string::npos ? this->Text.size() : end) - this->At);
        this->skipLine();
        if (text.find_first_not_of(" \t\r") == std::string::npos)
        {
          break;
        }
      }
      return true;
    }
    this->At = mark;
    this->Line = markLine;
    return true;
  }

  // Whether COUNT x COMPONENTS values (declared by KEYWORD on LINE) can be in the file, at a bit
  // each at least; refused otherwise (and the product, which the walk then forms, cannot
  // overflow).
  bool fits(long long count, long long components, const std::string& keyword, long long line)
  {
    const std::uintmax_t bits = static_cast<std::uintmax_t>(this->Text.size()) * 8;
    if (count >= 0 && components >= 0 &&
        (components == 0 || static_cast<std::uintmax_t>(count) <=
                                bits / static_cast<std::uintmax_t>(components)))
    {
      return true;
    }
    this->Problem = "line " + std::to_string(line) + ": " + keyword + " declares " +
                    std::to_string(count) + " tuples of " + std::to_string(components) +
                    (count < 0 || components < 0
                         ? " values, a negative count"
                         : " values, which the file's " + std::to_string(this->Text.size()) +
                               " bytes cannot hold");
    return false;
  }

  // A FIELD block from its keyword on LINE: refused where VTK's ReadFieldData fails.
  bool field(long long line)
  {
    std::string name;
    long long arrays = 0;
    if (!this->next(name) || !this->count(arrays))
    {
      this->Problem = "line " + std::to_string(line) +
                      ": the FIELD header does not read as a name and an array count";
      return false;
    }
    for (long long a = 0; a < arrays; ++a)
    {
      std::string arrayName;
      long long components = 0;
      long long tuples = 0;
      std::string type;
      if (!this->next(arrayName))
      {
        this->Problem = "line " + std::to_string(line) + ": FIELD " + name + " ends after " +
                        std::to_string(a) + " of its " + std::to_string(arrays) +
                        " arrays (the file ends)";
        return false;
      }
      if (arrayName == "NULL_ARRAY")
      {
        continue;
      }
      const long long arrayLine = this->Line;
      if (!this->count(components) || !this->count(tuples) || !this->next(type) ||
          !eighthsOf(type))
      {
        this->Problem = "line " + std::to_string(arrayLine) + ": array " +
                        std::to_string(a + 1) + " of FIELD " + name + " (line " +
                        std::to_string(line) +
                        ") does not read as a name, components, tuples and a type VTK knows";
        return false;
      }
      if (!this->fits(tuples, components, "FIELD array " + arrayName, arrayLine) ||
          !this->values(components * tuples, type, "FIELD array " + arrayName, arrayLine))
      {
        return false;
      }
    }
    return true;
  }

  const std::string& Text;
  bool Binary = false;
  size_t At = 0;
  long long Line = 1;

public:
  std::optional<std::string> Problem;
};
} // namespace

std::optional<std::string> vtkLegacySizeProblem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw errorAbout(path, "cannot open the file");
  }
  std::error_code error;
  const std::uintmax_t fileBytes = std::filesystem::file_size(path, error);
  if (error)
  {
    throw errorAbout(path, "cannot read the file's size (" + error.message() + ")");
  }
  std::string line;
  auto nextLine = [&]() -> bool
  {
    if (!std::getline(in, line))
    {
      return false;
    }
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    return true;
  };
  // The header, the title and the file type (VTK refuses a file whose header does not read).
  int major = 0;
  if (!nextLine() || line.rfind("# vtk DataFile Version", 0) != 0)
  {
    return std::nullopt;
  }
  {
    // As VTK reads it: "MAJOR.MINOR", else version 0.0 (a "5.1" file whose version line reads
    // "51." is read as the older format).
    int minor = 0;
    if (std::sscanf(line.c_str() + 22, "%d.%d", &major, &minor) != 2)
    {
      major = 0;
    }
  }
  if (!nextLine() || !nextLine())
  {
    return std::nullopt;
  }
  const std::vector<std::string> typeTokens = tokensOf(line);
  if (typeTokens.empty())
  {
    return std::nullopt;
  }
  // VTK matches the file type by its start ("ASCII@" is ASCII).
  const std::string fileType = lowerCase(typeTokens[0]);
  const bool ascii = fileType.rfind("ascii", 0) == 0;
  if (!ascii && fileType.rfind("binary", 0) != 0)
  {
    return std::nullopt;
  }
  SizeScan scan(fileBytes, !ascii);
  scan.Line = 3;

  long long attributeCount = 0; // POINT_DATA or CELL_DATA's count
  long long fieldArraysLeft = 0;
  // A version 5 cell list's counts, checked again with the types of its OFFSETS and
  // CONNECTIVITY lines.
  std::string cellKeyword;
  long long cellLine = 0;
  // An unstructured grid's cell count (CELLS) and its line, for CELL_TYPES.
  long long gridCells = 0;
  long long gridCellsLine = 0;
  long long offsetCount = -1;
  long long connectivityCount = -1;

  // A cell list before version 5: CELLS values, each cell its point count and that many point
  // ids (ints, big-endian in a binary file). VTK 9.1 walks it by the counts it holds
  // (vtkCellArray::AppendLegacyFormat) without checking them against the list's size: a count
  // that runs past it reads past the list (SEGV, fuzz_vtk; such a list is what the binary
  // OFFSETS of a version 5 file become when its version line no longer reads). The list is read
  // here as VTK reads it, right after its keyword line, and walked. A list cut short or a value
  // that does not read whole is refused too: VTK 9.1 goes on building cells from such a list
  // (SEGV in AppendLegacyFormat on an ASCII list holding "16*17", fuzz_vtk).
  auto walkCellList = [&](const std::string& keyword, long long cells, long long values)
  {
    const long long keywordLine = scan.Line;
    std::vector<long long> list;
    list.reserve(static_cast<size_t>(values));
    if (scan.Binary)
    {
      std::string bytes(static_cast<size_t>(values) * 4, '\0');
      in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      if (in.gcount() != static_cast<std::streamsize>(bytes.size()))
      {
        scan.Problem = "line " + std::to_string(keywordLine) + ": " + keyword + " lists " +
                       std::to_string(values) + " values, the file ends after " +
                       std::to_string(in.gcount() / 4);
        return;
      }
      scan.Line += std::count(bytes.begin(), bytes.end(), '\n');
      for (size_t i = 0; i < bytes.size(); i += 4)
      {
        const auto byte = [&](size_t k) { return static_cast<std::uint32_t>(
                                              static_cast<unsigned char>(bytes[i + k])); };
        const std::uint32_t word = byte(0) << 24 | byte(1) << 16 | byte(2) << 8 | byte(3);
        list.push_back(static_cast<std::int32_t>(word));
      }
    }
    else
    {
      while (static_cast<long long>(list.size()) < values && nextLine())
      {
        ++scan.Line;
        for (const std::string& token : tokensOf(line))
        {
          std::istringstream stream(token);
          stream.imbue(std::locale::classic());
          int value = 0;
          stream >> value;
          if (stream.fail() || !stream.eof())
          {
            std::string shown = token.substr(0, 32);
            std::replace_if(
                shown.begin(), shown.end(),
                [](char c) { return !std::isprint(static_cast<unsigned char>(c)); }, '?');
            scan.Problem = "line " + std::to_string(scan.Line) + ": value " +
                           std::to_string(list.size() + 1) + " of the " + keyword +
                           " list, \"" + shown + (token.size() > 32 ? "...\"" : "\"") +
                           ", is not a whole number";
            return;
          }
          list.push_back(value);
          if (static_cast<long long>(list.size()) == values)
          {
            break;
          }
        }
      }
      if (static_cast<long long>(list.size()) < values)
      {
        scan.Problem = "line " + std::to_string(keywordLine) + ": " + keyword + " lists " +
                       std::to_string(values) + " values, the file ends after " +
                       std::to_string(list.size());
        return;
      }
    }
    // VTK appends cells until the list's end, whatever its cell count says: the counts must
    // walk the list to its end exactly, in as many cells as declared.
    const std::string prefix = "line " + std::to_string(keywordLine) + ": " + keyword + " lists " +
                               std::to_string(cells) + " cells in " + std::to_string(values) +
                               " values, but ";
    long long at = 0;
    long long cell = 0;
    for (; at < values; ++cell)
    {
      const long long points = list[static_cast<size_t>(at)];
      if (points < 0 || points > values - at - 1)
      {
        scan.Problem = prefix + "cell " + std::to_string(cell) + " declares " +
                       std::to_string(points) + " points, past the list's end";
        return;
      }
      at += 1 + points;
    }
    if (cell != cells)
    {
      scan.Problem = prefix + "its point counts make " + std::to_string(cell) + " cells";
    }
  };

  while (!scan.Problem && nextLine())
  {
    ++scan.Line;
    // A line of numbers (data) declares nothing, unless it may be a field array's header (whose
    // name may start with anything): skipped without splitting it.
    if (fieldArraysLeft == 0)
    {
      const size_t first = line.find_first_not_of(" \t");
      if (first == std::string::npos)
      {
        continue;
      }
      const char c = line[first];
      if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.')
      {
        continue;
      }
    }
    const std::vector<std::string> tokens = tokensOf(line);
    if (tokens.empty())
    {
      continue;
    }
    std::string keyword = tokens[0];
    std::transform(keyword.begin(), keyword.end(), keyword.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    auto count = [&](size_t i) -> std::optional<long long>
    { return i < tokens.size() ? countOf(tokens[i]) : std::nullopt; };
    auto eighths = [&](size_t i) -> std::optional<int>
    { return i < tokens.size() ? eighthsOf(tokens[i]) : std::nullopt; };

    if (keyword == "POINTS" || keyword == "X_COORDINATES" || keyword == "Y_COORDINATES" ||
        keyword == "Z_COORDINATES")
    {
      if (tokens.size() == 3 && count(1) && eighths(2))
      {
        scan.check(keyword, *count(1), keyword == "POINTS" ? 3 : 1, *eighths(2),
                   keyword == "POINTS" ? "points" : "coordinates");
      }
    }
    else if (keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" ||
             keyword == "TRIANGLE_STRIPS" || keyword == "CELLS")
    {
      if (tokens.size() == 3 && count(1) && count(2))
      {
        if (major >= 5)
        {
          // Checked with the types the OFFSETS and CONNECTIVITY lines name (VTK allocates
          // after it has read them), reported on this line.
          cellKeyword = keyword;
          cellLine = scan.Line;
          if (keyword == "CELLS")
          {
            gridCells = *count(1) > 0 ? *count(1) - 1 : 0;
            gridCellsLine = scan.Line;
          }
          offsetCount = *count(1);
          connectivityCount = *count(2);
        }
        else
        {
          scan.check(keyword, *count(2), 1, 32, "values of its cell list");
          if (keyword == "CELLS")
          {
            gridCells = *count(1);
            gridCellsLine = scan.Line;
          }
          if (!scan.Problem)
          {
            walkCellList(keyword, *count(1), *count(2));
          }
        }
      }
    }
    else if ((keyword == "OFFSETS" || keyword == "CONNECTIVITY") && !cellKeyword.empty())
    {
      if (tokens.size() == 2 && eighths(1))
      {
        const bool offsets = keyword == "OFFSETS";
        const long long current = scan.Line;
        scan.Line = cellLine;
        scan.check(cellKeyword, offsets ? offsetCount : connectivityCount, 1, *eighths(1),
                   offsets ? "offsets" : "connectivity values");
        scan.Line = current;
        if (!offsets)
        {
          cellKeyword.clear();
        }
      }
    }
    else if (keyword == "CELL_TYPES")
    {
      if (tokens.size() == 2 && count(1))
      {
        scan.check(keyword, *count(1), 1, 32, "cell types");
        // VTK 9.1's grid reader takes a type for each cell of the CELLS list from the types it
        // read (vtkUnstructuredGrid::SetCells): with fewer it reads past them (SEGV in
        // DecomposeAPolyhedronCell where a byte past them read as a polyhedron, fuzz_vtk).
        if (!scan.Problem && gridCellsLine > 0 && *count(1) < gridCells)
        {
          scan.Problem = "line " + std::to_string(scan.Line) + ": CELL_TYPES declares " +
                         std::to_string(*count(1)) + " cell types, fewer than the " +
                         std::to_string(gridCells) + " cells of CELLS on line " +
                         std::to_string(gridCellsLine);
        }
      }
    }
    else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      if (tokens.size() == 2 && count(1))
      {
        attributeCount = *count(1);
        scan.check(keyword, attributeCount, 0, 8, "tuples");
      }
    }
    else if (keyword == "SCALARS")
    {
      if ((tokens.size() == 3 || tokens.size() == 4) && eighths(2))
      {
        const std::optional<long long> components = tokens.size() == 4 ? count(3) : 1LL;
        if (components)
        {
          scan.check(keyword, attributeCount, *components, *eighths(2), "tuples");
        }
      }
    }
    else if (keyword == "COLOR_SCALARS")
    {
      if (tokens.size() == 3 && count(2))
      {
        scan.check(keyword, attributeCount, *count(2), 8, "tuples");
      }
    }
    else if (keyword == "VECTORS" || keyword == "NORMALS" || keyword == "TENSORS" ||
             keyword == "TENSORS6" || keyword == "GLOBAL_IDS" || keyword == "PEDIGREE_IDS")
    {
      if (tokens.size() == 3 && eighths(2))
      {
        const long long components = keyword == "VECTORS" || keyword == "NORMALS" ? 3
                                     : keyword == "TENSORS"                       ? 9
                                     : keyword == "TENSORS6"                      ? 6
                                                                                  : 1;
        scan.check(keyword, attributeCount, components, *eighths(2), "tuples");
      }
    }
    else if (keyword == "TEXTURE_COORDINATES")
    {
      if (tokens.size() == 4 && count(2) && eighths(3))
      {
        scan.check(keyword, attributeCount, *count(2), *eighths(3), "tuples");
      }
    }
    else if (keyword == "LOOKUP_TABLE")
    {
      // "LOOKUP_TABLE name" after SCALARS names a table; "LOOKUP_TABLE name size" is one, of
      // four components (unsigned chars in a binary file).
      if (tokens.size() == 3 && count(2))
      {
        scan.check(keyword, *count(2), 4, 8, "entries");
      }
    }
    else if (keyword == "FIELD")
    {
      if (tokens.size() == 3 && count(2))
      {
        fieldArraysLeft = *count(2);
        scan.check(keyword, fieldArraysLeft, 1, 8, "arrays");
      }
    }
    else if (fieldArraysLeft > 0 && tokens.size() == 4 && count(1) && count(2) && eighths(3))
    {
      // A field's array: name, components, tuples, type.
      scan.check("FIELD array " + tokens[0], *count(2), *count(1), *eighths(3), "tuples");
      --fieldArraysLeft;
    }
  }
  if (scan.Problem || major < 5)
  {
    return scan.Problem;
  }
  // The walk of the dataset section (version 5).
  std::string dataset;
  {
    std::ifstream again(path, std::ios::binary);
    for (int i = 0; i < 4 && std::getline(again, line); ++i)
    {
    }
    const std::vector<std::string> tokens = tokensOf(line);
    if (tokens.size() >= 2 && lowerCase(tokens[0]).rfind("dataset", 0) == 0)
    {
      dataset = lowerCase(tokens[1]);
    }
  }
  // The types as vtkDataSetReader tells them (by their start).
  const bool polygonal = dataset.rfind("polydata", 0) == 0;
  const bool structured = dataset.rfind("structured_points", 0) == 0 ||
                          dataset.rfind("structured_grid", 0) == 0 ||
                          dataset.rfind("rectilinear_grid", 0) == 0;
  if (!polygonal && !structured && dataset.rfind("unstructured_grid", 0) != 0)
  {
    return std::nullopt;
  }
  std::ifstream whole(path, std::ios::binary);
  std::string text(static_cast<size_t>(fileBytes), '\0');
  whole.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(std::max<std::streamsize>(0, whole.gcount())));
  return SectionWalk(text, scan.Binary).run(polygonal, structured);
}

void checkVtkLegacySizes(const std::string& path)
{
  if (const std::optional<std::string> problem = vtkLegacySizeProblem(path))
  {
    throw errorAbout(path, *problem);
  }
}
} // namespace aniso
