#include "vtkpasses/mesh/StlReader.h"

#include "core/error.h"
#include "vtkpasses/mesh/GeometryAccess.h"

#include <array>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <unordered_map>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
using Corner = std::array<double, 3>;

struct CornerHash
{
  size_t operator()(const Corner& c) const
  {
    size_t seed = 0;
    for (double v : c)
    {
      uint64_t bits = 0;
      const double normalised = v + 0.0; // -0 and +0 compare equal, so they must hash equal
      std::memcpy(&bits, &normalised, sizeof(bits));
      seed ^= std::hash<uint64_t>()(bits) + 0x9e3779b97f4a7c15ull + (seed << 6) + (seed >> 2);
    }
    return seed;
  }
};

// Points with bit-identical corners shared.
class CornerSet
{
public:
  vtkIdType add(const Corner& corner)
  {
    auto found = this->Ids.find(corner);
    if (found != this->Ids.end())
    {
      return found->second;
    }
    const vtkIdType id = this->Points->InsertNextPoint(corner.data());
    this->Ids.emplace(corner, id);
    return id;
  }

  vtkPoints* points() { return this->Points; }

private:
  vtkNew<vtkPoints> Points;
  std::unordered_map<Corner, vtkIdType, CornerHash> Ids;
};

uint32_t readLittleEndian32(const unsigned char* bytes)
{
  return static_cast<uint32_t>(bytes[0]) | static_cast<uint32_t>(bytes[1]) << 8 |
         static_cast<uint32_t>(bytes[2]) << 16 | static_cast<uint32_t>(bytes[3]) << 24;
}

float readFloat(const unsigned char* bytes)
{
  const uint32_t bits = readLittleEndian32(bytes);
  float value = 0.0f;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

constexpr size_t kHeaderBytes = 84;   // 80 bytes of text and the triangle count
constexpr size_t kTriangleBytes = 50; // normal, three corners, attribute word

vtkSmartPointer<vtkPolyData> readBinary(const std::string& bytes, size_t triangles)
{
  CornerSet corners;
  vtkNew<vtkCellArray> polys;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  for (size_t t = 0; t < triangles; ++t)
  {
    const unsigned char* facet = data + kHeaderBytes + t * kTriangleBytes + 12; // skip normal
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      const unsigned char* corner = facet + 12 * k;
      ids[k] = corners.add({static_cast<double>(readFloat(corner)),
                            static_cast<double>(readFloat(corner + 4)),
                            static_cast<double>(readFloat(corner + 8))});
    }
    polys->InsertNextCell(3, ids);
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(corners.points());
  polyData->SetPolys(polys);
  return polyData;
}

class AsciiStlParser
{
public:
  AsciiStlParser(const std::string& path, const std::string& text) : Path(path), Text(text) {}

  vtkSmartPointer<vtkPolyData> parse(std::vector<std::string>& warnings)
  {
    std::vector<vtkIdType> loop;
    bool inLoop = false;
    bool sawEnd = false;
    std::string word;
    while (this->next(word))
    {
      if (word == "outer")
      {
        inLoop = true;
        loop.clear();
      }
      else if (word == "vertex")
      {
        Corner corner;
        for (double& c : corner)
        {
          c = this->number();
        }
        loop.push_back(this->Corners.add(corner));
      }
      else if (word == "endloop")
      {
        // Loops of fewer than three corners go in too, for the validation to count.
        if (!loop.empty())
        {
          this->Polys->InsertNextCell(static_cast<vtkIdType>(loop.size()), loop.data());
        }
        loop.clear();
        inLoop = false;
      }
      else if (word == "endsolid")
      {
        sawEnd = true;
      }
    }
    if (inLoop || !sawEnd)
    {
      warnings.push_back("the ASCII STL ends early (no endsolid); complete facets were kept");
    }
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(this->Corners.points());
    polyData->SetPolys(this->Polys);
    return polyData;
  }

private:
  bool next(std::string& word)
  {
    const std::string& t = this->Text;
    while (this->Position < t.size() && std::isspace(static_cast<unsigned char>(t[this->Position])))
    {
      this->Line += t[this->Position] == '\n' ? 1 : 0;
      ++this->Position;
    }
    const size_t begin = this->Position;
    while (this->Position < t.size() &&
           !std::isspace(static_cast<unsigned char>(t[this->Position])))
    {
      ++this->Position;
    }
    word = t.substr(begin, this->Position - begin);
    return !word.empty();
  }

  double number()
  {
    std::string word;
    if (!this->next(word))
    {
      throw errorAbout(this->Path,
                       "line " + std::to_string(this->Line) + ": truncated inside a vertex line");
    }
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (*end != '\0')
    {
      throw errorAbout(this->Path, "line " + std::to_string(this->Line) + ": '" +
                                       word.substr(0, 32) + "' is not a number");
    }
    return value;
  }

  const std::string& Path;
  const std::string& Text;
  size_t Position = 0;
  size_t Line = 1;
  CornerSet Corners;
  vtkNew<vtkCellArray> Polys;
};

bool looksAscii(const std::string& bytes)
{
  const size_t first = bytes.find_first_not_of(" \t\r\n");
  return first != std::string::npos && bytes.compare(first, 5, "solid") == 0 &&
         bytes.find('\0') == std::string::npos;
}
} // namespace

vtkSmartPointer<vtkPolyData> readStl(const std::string& path, std::vector<std::string>& warnings)
{
  const std::string bytes = geometry::readFileBytes(path);
  if (bytes.size() >= kHeaderBytes)
  {
    const uint64_t announced =
        readLittleEndian32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
    if (kHeaderBytes + announced * kTriangleBytes == bytes.size())
    {
      return readBinary(bytes, static_cast<size_t>(announced));
    }
  }
  if (looksAscii(bytes))
  {
    return AsciiStlParser(path, bytes).parse(warnings);
  }
  if (bytes.size() < kHeaderBytes + kTriangleBytes)
  {
    throw errorAbout(path, "not an STL file (neither ASCII nor long enough for a binary STL)");
  }
  const size_t held = (bytes.size() - kHeaderBytes) / kTriangleBytes;
  const uint64_t announced =
      readLittleEndian32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
  warnings.push_back("the binary STL header announces " + std::to_string(announced) +
                     " triangles; the file holds " + std::to_string(held));
  return readBinary(bytes, held);
}
} // namespace aniso
