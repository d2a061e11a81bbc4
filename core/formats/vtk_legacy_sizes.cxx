#include "core/formats/vtk_legacy_sizes.h"

#include "core/error.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
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
  const std::string fileType = lowerCase(typeTokens[0]);
  if (fileType != "ascii" && fileType != "binary")
  {
    return std::nullopt;
  }
  SizeScan scan(fileBytes, fileType == "binary");
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
            gridCells = std::max(0LL, *count(1) - 1);
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
  return scan.Problem;
}

void checkVtkLegacySizes(const std::string& path)
{
  if (const std::optional<std::string> problem = vtkLegacySizeProblem(path))
  {
    throw errorAbout(path, *problem);
  }
}
} // namespace aniso
