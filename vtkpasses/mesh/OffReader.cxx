#include "vtkpasses/mesh/OffReader.h"

#include "core/error.h"
#include "vtkpasses/mesh/GeometryAccess.h"

#include <cerrno>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <vector>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
// Walks the text one meaningful line at a time (comments stripped, blank lines skipped) and
// remembers the line number for messages.
class LineCursor
{
public:
  explicit LineCursor(const std::string& text) : Text(text) {}

  // Tokens of the next non-empty line; false at the end of the text.
  bool next(std::vector<std::string>& tokens)
  {
    while (this->Position < this->Text.size())
    {
      size_t end = this->Text.find('\n', this->Position);
      if (end == std::string::npos)
      {
        end = this->Text.size();
      }
      std::string line = this->Text.substr(this->Position, end - this->Position);
      this->Position = end + 1;
      ++this->LineNumber;
      const size_t hash = line.find('#');
      if (hash != std::string::npos)
      {
        line.erase(hash);
      }
      tokens.clear();
      std::istringstream stream(line);
      std::string token;
      while (stream >> token)
      {
        tokens.push_back(token);
      }
      if (!tokens.empty())
      {
        return true;
      }
    }
    return false;
  }

  size_t line() const { return this->LineNumber; }

private:
  const std::string& Text;
  size_t Position = 0;
  size_t LineNumber = 0;
};

struct Layout
{
  bool normals = false;
  bool colours = false;
  bool texture = false;
};

bool isOffKeyword(const std::string& token, Layout& layout, bool& higherDimension)
{
  if (token.size() < 3 || token.compare(token.size() - 3, 3, "OFF") != 0)
  {
    return false;
  }
  std::string prefix = token.substr(0, token.size() - 3);
  auto take = [&prefix](const std::string& part)
  {
    if (prefix.compare(0, part.size(), part) == 0)
    {
      prefix.erase(0, part.size());
      return true;
    }
    return false;
  };
  layout.texture = take("ST");
  layout.colours = take("C");
  layout.normals = take("N");
  higherDimension = take("4");
  higherDimension = take("n") || higherDimension;
  return prefix.empty();
}

bool parseDouble(const std::string& token, double& value)
{
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtod(begin, &end);
  // Overflow gives +-HUGE_VAL, which the mesh validation then counts as a non-finite vertex.
  return end != begin && *end == '\0';
}

bool parseIndex(const std::string& token, long long& value)
{
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(begin, &end, 10);
  return end != begin && *end == '\0' && errno != ERANGE;
}

class OffParser
{
public:
  OffParser(const std::string& path, const std::string& text) : Path(path), Cursor(text) {}

  vtkSmartPointer<vtkPolyData> parse()
  {
    std::vector<std::string> tokens;
    if (!this->Cursor.next(tokens))
    {
      throw errorAbout(this->Path, "no OFF header");
    }
    size_t countsAt = 0;
    bool higherDimension = false;
    if (isOffKeyword(tokens[0], this->Format, higherDimension))
    {
      if (higherDimension)
      {
        throw errorAbout(this->Path, "only 3-D OFF is supported (4OFF and nOFF are not)");
      }
      if (tokens.size() > 1 && tokens[1] == "BINARY")
      {
        throw errorAbout(this->Path, "binary OFF is not supported");
      }
      countsAt = 1; // the counts may share the header line
      if (tokens.size() == 1)
      {
        if (!this->Cursor.next(tokens))
        {
          this->fail("missing vertex and face counts after the OFF header");
        }
        countsAt = 0;
      }
    }
    this->readCounts(tokens, countsAt);

    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    auto normals = vtkSmartPointer<vtkFloatArray>::New();
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
    tcoords->SetName("TCoords");
    tcoords->SetNumberOfComponents(2);
    for (long long v = 0; v < this->VertexCount; ++v)
    {
      this->readVertex(tokens, points, normals, tcoords);
    }

    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    if (this->Format.normals)
    {
      polyData->GetPointData()->SetNormals(normals);
    }
    if (this->Format.texture)
    {
      polyData->GetPointData()->SetTCoords(tcoords);
    }
    vtkNew<vtkCellArray> polys;
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkCellArray> verts;
    std::vector<vtkIdType> ids;
    for (long long f = 0; f < this->FaceCount; ++f)
    {
      this->readFace(tokens, ids);
      // Points and lines go where the mesh validation counts them as non-surface cells.
      vtkCellArray* target = ids.size() >= 3   ? polys.Get()
                             : ids.size() == 2 ? lines.Get()
                                               : verts.Get();
      if (!ids.empty())
      {
        target->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      }
    }
    polyData->SetPolys(polys);
    polyData->SetLines(lines);
    polyData->SetVerts(verts);
    return polyData;
  }

private:
  [[noreturn]] void fail(const std::string& reason) const
  {
    throw errorAbout(this->Path, "line " + std::to_string(this->Cursor.line()) + ": " + reason);
  }

  void readCounts(std::vector<std::string>& tokens, size_t at)
  {
    if (tokens.size() < at + 2)
    {
      this->fail("expected the vertex, face and edge counts");
    }
    long long vertices = 0;
    long long faces = 0;
    if (!parseIndex(tokens[at], vertices) || !parseIndex(tokens[at + 1], faces) || vertices < 0 ||
        faces < 0)
    {
      this->fail("invalid vertex or face count '" + tokens[at] + " " + tokens[at + 1] + "'");
    }
    this->VertexCount = vertices;
    this->FaceCount = faces;
  }

  void readVertex(std::vector<std::string>& tokens, vtkPoints* points, vtkFloatArray* normals,
                  vtkFloatArray* tcoords)
  {
    if (!this->Cursor.next(tokens))
    {
      this->fail("truncated: expected " + std::to_string(this->VertexCount) + " vertices, found " +
                 std::to_string(points->GetNumberOfPoints()));
    }
    const size_t needed = 3 + (this->Format.normals ? 3 : 0) + (this->Format.texture ? 2 : 0);
    if (tokens.size() < needed)
    {
      this->fail("vertex needs " + std::to_string(needed) + " numbers, found " +
                 std::to_string(tokens.size()));
    }
    double values[3];
    this->numbers(tokens, 0, 3, values);
    points->InsertNextPoint(values);
    if (this->Format.normals)
    {
      this->numbers(tokens, 3, 3, values);
      normals->InsertNextTuple(values);
    }
    if (this->Format.texture)
    {
      // Texture coordinates come last, after any colour.
      this->numbers(tokens, tokens.size() - 2, 2, values);
      tcoords->InsertNextTuple(values);
    }
  }

  void numbers(const std::vector<std::string>& tokens, size_t first, size_t count, double* out)
  {
    for (size_t i = 0; i < count; ++i)
    {
      if (!parseDouble(tokens[first + i], out[i]))
      {
        this->fail("'" + tokens[first + i] + "' is not a number");
      }
    }
  }

  void readFace(std::vector<std::string>& tokens, std::vector<vtkIdType>& ids)
  {
    ids.clear();
    if (!this->Cursor.next(tokens))
    {
      this->fail("truncated: expected " + std::to_string(this->FaceCount) + " faces");
    }
    long long count = 0;
    if (!parseIndex(tokens[0], count) || count < 0)
    {
      this->fail("'" + tokens[0] + "' is not a face vertex count");
    }
    if (static_cast<unsigned long long>(count) > tokens.size() - 1)
    {
      this->fail("face lists " + std::to_string(count) + " vertices but gives " +
                 std::to_string(tokens.size() - 1) + " indices");
    }
    for (long long i = 1; i <= count; ++i)
    {
      long long index = 0;
      if (!parseIndex(tokens[static_cast<size_t>(i)], index))
      {
        this->fail("'" + tokens[static_cast<size_t>(i)] + "' is not a vertex index");
      }
      if (index < 0 || index >= this->VertexCount)
      {
        this->fail("vertex index " + std::to_string(index) + " out of range (" +
                   std::to_string(this->VertexCount) + " vertices)");
      }
      ids.push_back(static_cast<vtkIdType>(index));
    }
  }

  const std::string& Path;
  LineCursor Cursor;
  Layout Format;
  long long VertexCount = 0;
  long long FaceCount = 0;
};
} // namespace

vtkSmartPointer<vtkPolyData> readOff(const std::string& path)
{
  const std::string text = geometry::readFileBytes(path);
  if (text.find('\0') != std::string::npos)
  {
    throw errorAbout(path, "not a text OFF file (contains NUL bytes)");
  }
  return OffParser(path, text).parse();
}
} // namespace aniso
