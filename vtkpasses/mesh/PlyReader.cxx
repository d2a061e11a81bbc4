#include "vtkpasses/mesh/PlyReader.h"

#include "core/error.h"
#include "vtkpasses/mesh/GeometryAccess.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <utility>
#include <vector>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
enum class PlyType
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64
};

bool parseType(const std::string& name, PlyType& type)
{
  static const std::pair<const char*, PlyType> names[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& entry : names)
  {
    if (name == entry.first)
    {
      type = entry.second;
      return true;
    }
  }
  return false;
}

size_t typeSize(PlyType type)
{
  switch (type)
  {
  case PlyType::Int8:
  case PlyType::UInt8:
    return 1;
  case PlyType::Int16:
  case PlyType::UInt16:
    return 2;
  case PlyType::Int32:
  case PlyType::UInt32:
  case PlyType::Float32:
    return 4;
  case PlyType::Float64:
    return 8;
  }
  return 1;
}

struct Property
{
  std::string name;
  bool isList = false;
  PlyType countType = PlyType::UInt8;
  PlyType type = PlyType::Float32;
};

struct Element
{
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding
{
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

// Thrown inside the data reader, turned into "PATH: reason" with the element being read.
struct DataError
{
  std::string reason;
};

bool hostIsLittleEndian()
{
  const uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

// Values in file order, from ASCII tokens or binary bytes.
class ValueSource
{
public:
  ValueSource(const std::string& data, size_t start, Encoding encoding)
      : Data(data), Position(start), Format(encoding),
        Swap(encoding == Encoding::BinaryBigEndian
                 ? hostIsLittleEndian()
                 : encoding == Encoding::BinaryLittleEndian && !hostIsLittleEndian())
  {
  }

  size_t remaining() const { return this->Data.size() - this->Position; }

  double read(PlyType type)
  {
    if (this->Format == Encoding::Ascii)
    {
      return this->readToken();
    }
    const size_t size = typeSize(type);
    if (this->remaining() < size)
    {
      throw DataError{"truncated data"};
    }
    unsigned char bytes[8];
    std::memcpy(bytes, this->Data.data() + this->Position, size);
    this->Position += size;
    if (this->Swap)
    {
      for (size_t i = 0; i < size / 2; ++i)
      {
        std::swap(bytes[i], bytes[size - 1 - i]);
      }
    }
    return decode(type, bytes);
  }

private:
  static double decode(PlyType type, const unsigned char* bytes)
  {
    switch (type)
    {
    case PlyType::Int8:
      return static_cast<double>(static_cast<int8_t>(bytes[0]));
    case PlyType::UInt8:
      return static_cast<double>(bytes[0]);
    case PlyType::Int16:
      return static_cast<double>(copyAs<int16_t>(bytes));
    case PlyType::UInt16:
      return static_cast<double>(copyAs<uint16_t>(bytes));
    case PlyType::Int32:
      return static_cast<double>(copyAs<int32_t>(bytes));
    case PlyType::UInt32:
      return static_cast<double>(copyAs<uint32_t>(bytes));
    case PlyType::Float32:
      return static_cast<double>(copyAs<float>(bytes));
    case PlyType::Float64:
      return copyAs<double>(bytes);
    }
    return 0.0;
  }

  template <typename T>
  static T copyAs(const unsigned char* bytes)
  {
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

  double readToken()
  {
    const std::string& d = this->Data;
    while (this->Position < d.size() && std::isspace(static_cast<unsigned char>(d[this->Position])))
    {
      ++this->Position;
    }
    const size_t begin = this->Position;
    while (this->Position < d.size() &&
           !std::isspace(static_cast<unsigned char>(d[this->Position])))
    {
      ++this->Position;
    }
    if (begin == this->Position)
    {
      throw DataError{"truncated data"};
    }
    const std::string token = d.substr(begin, this->Position - begin);
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (*end != '\0')
    {
      throw DataError{"'" + token.substr(0, 32) + "' is not a number"};
    }
    return value;
  }

  const std::string& Data;
  size_t Position;
  Encoding Format;
  bool Swap;
};

std::vector<std::string> words(const std::string& line)
{
  std::vector<std::string> out;
  std::istringstream stream(line);
  std::string word;
  while (stream >> word)
  {
    out.push_back(word);
  }
  return out;
}

bool parseCount(const std::string& text, uint64_t& count)
{
  if (text.empty() || text[0] == '-')
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
  count = value;
  return *end == '\0' && errno != ERANGE;
}

class PlyParser
{
public:
  PlyParser(const std::string& path, const std::string& text) : Path(path), Text(text)
  {
    this->Normals->SetNumberOfComponents(3);
    this->TCoords->SetNumberOfComponents(2);
  }

  vtkSmartPointer<vtkPolyData> parse()
  {
    const size_t dataStart = this->parseHeader();
    this->checkSizes(dataStart);
    for (const Property& property : this->find("vertex")->properties)
    {
      if (property.name == "x" && property.type == PlyType::Float64)
      {
        this->Points->SetDataTypeToDouble(); // keep double-precision coordinates exact
      }
    }
    this->planExtraArrays();
    ValueSource source(this->Text, dataStart, this->Format);
    for (const Element& element : this->Elements)
    {
      for (uint64_t i = 0; i < element.count; ++i)
      {
        try
        {
          this->readElement(element, source);
        }
        catch (const DataError& e)
        {
          throw errorAbout(this->Path, "element '" + element.name + "' " + std::to_string(i) +
                                           " of " + std::to_string(element.count) + ": " +
                                           e.reason);
        }
      }
    }
    return this->output();
  }

private:
  static bool isKnownVertexProperty(const std::string& n)
  {
    for (const char* known : {"x", "y", "z", "nx", "ny", "nz", "u", "v", "s", "t", "texture_u",
                              "texture_v", "texture_s", "texture_t"})
    {
      if (n == known)
      {
        return true;
      }
    }
    return false;
  }

  // The vertex properties beyond positions, normals and texture coordinates become point
  // arrays named as the property; three in a row named NAME_x, NAME_y, NAME_z make one
  // 3-component array NAME (a vector field).
  void planExtraArrays()
  {
    const std::vector<Property>& properties = this->find("vertex")->properties;
    this->ExtraSlot.assign(properties.size(), {-1, 0});
    for (size_t i = 0; i < properties.size(); ++i)
    {
      const std::string& n = properties[i].name;
      if (properties[i].isList || isKnownVertexProperty(n))
      {
        continue;
      }
      const std::string stem = n.size() > 2 ? n.substr(0, n.size() - 2) : std::string();
      const auto named = [&](size_t k, const char* suffix) {
        return k < properties.size() && !properties[k].isList &&
               properties[k].name == stem + suffix;
      };
      const bool vector =
          !stem.empty() && named(i, "_x") && named(i + 1, "_y") && named(i + 2, "_z");
      // Float unless a value might not fit one exactly (double, 32-bit integers): a file of
      // byte-sized properties grows at most fourfold in memory.
      bool wide = false;
      for (size_t k = i; k < i + (vector ? 3 : 1); ++k)
      {
        const PlyType type = properties[k].type;
        wide =
            wide || type == PlyType::Float64 || type == PlyType::Int32 || type == PlyType::UInt32;
      }
      vtkSmartPointer<vtkDataArray> array;
      if (wide)
      {
        array = vtkSmartPointer<vtkDoubleArray>::New();
      }
      else
      {
        array = vtkSmartPointer<vtkFloatArray>::New();
      }
      const int slot = static_cast<int>(this->Extra.size());
      if (vector)
      {
        array->SetName(stem.c_str());
        array->SetNumberOfComponents(3);
        for (int c = 0; c < 3; ++c)
        {
          this->ExtraSlot[i + size_t(c)] = {slot, c};
        }
        i += 2;
      }
      else
      {
        array->SetName(n.c_str());
        array->SetNumberOfComponents(1);
        this->ExtraSlot[i] = {slot, 0};
      }
      this->Extra.push_back(array);
    }
    this->ExtraTuple.resize(this->Extra.size());
    for (size_t a = 0; a < this->Extra.size(); ++a)
    {
      this->ExtraTuple[a].assign(size_t(this->Extra[a]->GetNumberOfComponents()), 0.0);
    }
  }

  [[noreturn]] void fail(const std::string& reason) const { throw errorAbout(this->Path, reason); }

  // Returns the offset of the first data byte.
  size_t parseHeader()
  {
    size_t position = 0;
    bool sawFormat = false;
    bool first = true;
    while (true)
    {
      const size_t end = this->Text.find('\n', position);
      if (end == std::string::npos)
      {
        this->fail(first ? "not a PLY file" : "the header has no end_header line");
      }
      std::string line = this->Text.substr(position, end - position);
      position = end + 1;
      if (!line.empty() && line.back() == '\r')
      {
        line.pop_back();
      }
      const std::vector<std::string> w = words(line);
      if (first)
      {
        if (w.size() != 1 || w[0] != "ply")
        {
          this->fail("not a PLY file (no 'ply' magic line)");
        }
        first = false;
        continue;
      }
      if (w.empty() || w[0] == "comment" || w[0] == "obj_info")
      {
        continue;
      }
      if (w[0] == "end_header")
      {
        break;
      }
      if (w[0] == "format")
      {
        sawFormat = true;
        this->parseFormat(w);
      }
      else if (w[0] == "element")
      {
        Element element;
        if (w.size() != 3 || !parseCount(w[2], element.count))
        {
          this->fail("malformed header line '" + line.substr(0, 80) + "'");
        }
        element.name = w[1];
        this->Elements.push_back(element);
      }
      else if (w[0] == "property")
      {
        this->parseProperty(w, line);
      }
      else
      {
        this->fail("unknown header keyword '" + w[0].substr(0, 40) + "'");
      }
    }
    if (!sawFormat)
    {
      this->fail("the header has no format line");
    }
    return position;
  }

  void parseFormat(const std::vector<std::string>& w)
  {
    if (w.size() != 3 || w[2] != "1.0")
    {
      this->fail("unsupported format line (expected 'format ascii|binary_little_endian|"
                 "binary_big_endian 1.0')");
    }
    if (w[1] == "ascii")
    {
      this->Format = Encoding::Ascii;
    }
    else if (w[1] == "binary_little_endian")
    {
      this->Format = Encoding::BinaryLittleEndian;
    }
    else if (w[1] == "binary_big_endian")
    {
      this->Format = Encoding::BinaryBigEndian;
    }
    else
    {
      this->fail("unknown PLY format '" + w[1].substr(0, 40) + "'");
    }
  }

  void parseProperty(const std::vector<std::string>& w, const std::string& line)
  {
    if (this->Elements.empty())
    {
      this->fail("a property comes before any element");
    }
    Property property;
    bool valid = false;
    if (w.size() == 5 && w[1] == "list")
    {
      property.isList = true;
      property.name = w[4];
      valid = parseType(w[2], property.countType) && parseType(w[3], property.type) &&
              property.countType != PlyType::Float32 && property.countType != PlyType::Float64;
    }
    else if (w.size() == 3)
    {
      property.name = w[2];
      valid = parseType(w[1], property.type);
    }
    if (!valid)
    {
      this->fail("malformed or unsupported property line '" + line.substr(0, 80) + "'");
    }
    this->Elements.back().properties.push_back(property);
  }

  // Each element needs at least this many bytes: a header announcing more than the file holds
  // is rejected before anything is allocated.
  void checkSizes(size_t dataStart) const
  {
    const double available = static_cast<double>(this->Text.size() - dataStart);
    double needed = 0.0;
    for (const Element& element : this->Elements)
    {
      double perElement = 0.0;
      for (const Property& property : element.properties)
      {
        perElement += this->Format == Encoding::Ascii
                          ? 1.0
                          : static_cast<double>(
                                typeSize(property.isList ? property.countType : property.type));
      }
      needed += perElement * static_cast<double>(element.count);
    }
    if (needed > available)
    {
      this->fail("the header announces more data than the file holds (truncated or corrupt)");
    }
    const Element* vertex = this->find("vertex");
    if (!vertex || !hasProperty(*vertex, "x") || !hasProperty(*vertex, "y") ||
        !hasProperty(*vertex, "z"))
    {
      this->fail("no vertex element with x, y and z");
    }
  }

  const Element* find(const std::string& name) const
  {
    for (const Element& element : this->Elements)
    {
      if (element.name == name)
      {
        return &element;
      }
    }
    return nullptr;
  }

  static bool hasProperty(const Element& element, const std::string& name)
  {
    for (const Property& property : element.properties)
    {
      if (property.name == name && !property.isList)
      {
        return true;
      }
    }
    return false;
  }

  void readElement(const Element& element, ValueSource& source)
  {
    const bool isVertex = element.name == "vertex";
    const bool isFace = element.name == "face";
    double xyz[3] = {0.0, 0.0, 0.0};
    double normal[3] = {0.0, 0.0, 0.0};
    double uv[2] = {0.0, 0.0};
    int normalParts = 0;
    int uvParts = 0;
    bool faceRead = false;
    for (size_t p = 0; p < element.properties.size(); ++p)
    {
      const Property& property = element.properties[p];
      if (property.isList)
      {
        const double count = source.read(property.countType);
        if (!(count >= 0.0) || count != std::floor(count))
        {
          throw DataError{"invalid list length"};
        }
        const double itemBytes =
            this->Format == Encoding::Ascii ? 1.0 : static_cast<double>(typeSize(property.type));
        if (count * itemBytes > static_cast<double>(source.remaining()))
        {
          throw DataError{"truncated data"};
        }
        const bool indices = isFace && !faceRead &&
                             (property.name == "vertex_indices" || property.name == "vertex_index");
        this->FaceIds.clear();
        for (double k = 0; k < count; ++k)
        {
          const double value = source.read(property.type);
          if (indices)
          {
            // Non-integral or out-of-range ids become -1, which the mesh validation drops.
            const bool usable = value == std::floor(value) && std::abs(value) < 9.0e15;
            this->FaceIds.push_back(usable ? static_cast<vtkIdType>(value) : -1);
          }
        }
        if (indices)
        {
          this->Polys->InsertNextCell(static_cast<vtkIdType>(this->FaceIds.size()),
                                      this->FaceIds.data());
          faceRead = true;
        }
        continue;
      }
      const double value = source.read(property.type);
      if (!isVertex)
      {
        continue;
      }
      const std::string& n = property.name;
      if (&element == this->find("vertex") && this->ExtraSlot[p].first >= 0)
      {
        this->ExtraTuple[size_t(this->ExtraSlot[p].first)][size_t(this->ExtraSlot[p].second)] =
            value;
      }
      else if (n == "x" || n == "y" || n == "z")
      {
        xyz[n[0] - 'x'] = value;
      }
      else if (n == "nx" || n == "ny" || n == "nz")
      {
        normal[n[1] - 'x'] = value;
        ++normalParts;
      }
      else if (n == "u" || n == "s" || n == "texture_u" || n == "texture_s")
      {
        uv[0] = value;
        ++uvParts;
      }
      else if (n == "v" || n == "t" || n == "texture_v" || n == "texture_t")
      {
        uv[1] = value;
        ++uvParts;
      }
    }
    if (isVertex)
    {
      this->Points->InsertNextPoint(xyz);
      this->Normals->InsertNextTuple(normal);
      this->TCoords->InsertNextTuple(uv);
      for (size_t a = 0; a < this->Extra.size() && &element == this->find("vertex"); ++a)
      {
        this->Extra[a]->InsertNextTuple(this->ExtraTuple[a].data());
      }
      this->AllNormals = this->AllNormals && normalParts == 3;
      this->AllTCoords = this->AllTCoords && uvParts == 2;
    }
  }

  vtkSmartPointer<vtkPolyData> output()
  {
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(this->Points);
    polyData->SetPolys(this->Polys);
    const bool anyVertex = this->Points->GetNumberOfPoints() > 0;
    if (anyVertex && this->AllNormals)
    {
      this->Normals->SetName("Normals");
      polyData->GetPointData()->SetNormals(this->Normals);
    }
    if (anyVertex && this->AllTCoords)
    {
      this->TCoords->SetName("TCoords");
      polyData->GetPointData()->SetTCoords(this->TCoords);
    }
    if (anyVertex)
    {
      for (vtkDataArray* extra : this->Extra)
      {
        polyData->GetPointData()->AddArray(extra);
      }
    }
    return polyData;
  }

  const std::string& Path;
  const std::string& Text;
  Encoding Format = Encoding::Ascii;
  std::vector<Element> Elements;
  std::vector<vtkIdType> FaceIds;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Polys;
  vtkNew<vtkFloatArray> Normals;
  vtkNew<vtkFloatArray> TCoords;
  bool AllNormals = true;
  bool AllTCoords = true;
  std::vector<vtkSmartPointer<vtkDataArray>> Extra; // the arrays of planExtraArrays
  std::vector<std::pair<int, int>> ExtraSlot;  // per vertex property: (array, component) or -1
  std::vector<std::vector<double>> ExtraTuple; // the current vertex's values per array
};
} // namespace

vtkSmartPointer<vtkPolyData> readPly(const std::string& path)
{
  const std::string text = geometry::readFileBytes(path);
  return PlyParser(path, text).parse();
}
} // namespace aniso
