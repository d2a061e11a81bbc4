#include "vtkpasses/mesh/VtkReaders.h"

#include "core/error.h"
#include "core/formats/mtl.h"
#include "core/formats/vtk_legacy_sizes.h"
#include "core/formats/vtk_xml_headers.h"
#include "core/formats/mtl_material.h"
#include "core/parameters/material_library.h"
#include "vtkpasses/mesh/GeometryAccess.h"
#include "vtkpasses/mesh/GltfReader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <list>
#include <locale>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <system_error>
#include <unistd.h>
#include <vector>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleKey.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationIdTypeKey.h>
#include <vtkInformationIntegerKey.h>
#include <vtkInformationIntegerVectorKey.h>
#include <vtkInformationKeyLookup.h>
#include <vtkInformationStringKey.h>
#include <vtkInformationStringVectorKey.h>
#include <vtkInformationUnsignedLongKey.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

namespace aniso
{
namespace
{
template <typename Reader>
vtkSmartPointer<vtkPolyData> readPolyData(const std::string& path, const VtkMessageCapture& capture)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  throwIfReaderFailed(path, reader, capture);
  vtkSmartPointer<vtkPolyData> output = reader->GetOutput();
  return output;
}

// The number of points a cell of a fixed-size type has; for the types whose cells list as many
// as they have, the least they need, negated; 0 for a type VTK 9.1 does not know.
int cellTypePoints(int type)
{
  switch (type)
  {
    case VTK_EMPTY_CELL: return -0x10000; // no points needed; told apart from 0 below
    case VTK_VERTEX: return 1;
    case VTK_POLY_VERTEX: return -1;
    case VTK_LINE: return 2;
    case VTK_POLY_LINE: return -2;
    case VTK_TRIANGLE: return 3;
    case VTK_TRIANGLE_STRIP: return -3;
    case VTK_POLYGON: return -3;
    case VTK_PIXEL: return 4;
    case VTK_QUAD: return 4;
    case VTK_TETRA: return 4;
    case VTK_VOXEL: return 8;
    case VTK_HEXAHEDRON: return 8;
    case VTK_WEDGE: return 6;
    case VTK_PYRAMID: return 5;
    case VTK_PENTAGONAL_PRISM: return 10;
    case VTK_HEXAGONAL_PRISM: return 12;
    case VTK_QUADRATIC_EDGE: return 3;
    case VTK_QUADRATIC_TRIANGLE: return 6;
    case VTK_QUADRATIC_QUAD: return 8;
    case VTK_QUADRATIC_POLYGON: return -6;
    case VTK_QUADRATIC_TETRA: return 10;
    case VTK_QUADRATIC_HEXAHEDRON: return 20;
    case VTK_QUADRATIC_WEDGE: return 15;
    case VTK_QUADRATIC_PYRAMID: return 13;
    case VTK_BIQUADRATIC_QUAD: return 9;
    case VTK_TRIQUADRATIC_HEXAHEDRON: return 27;
    case VTK_TRIQUADRATIC_PYRAMID: return 19;
    case VTK_QUADRATIC_LINEAR_QUAD: return 6;
    case VTK_QUADRATIC_LINEAR_WEDGE: return 12;
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE: return 18;
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON: return 24;
    case VTK_BIQUADRATIC_TRIANGLE: return 7;
    case VTK_CUBIC_LINE: return 4;
    case VTK_CONVEX_POINT_SET: return -4;
    case VTK_POLYHEDRON: return -4;
    case VTK_LAGRANGE_CURVE: case VTK_BEZIER_CURVE: return -2;
    case VTK_LAGRANGE_TRIANGLE: case VTK_BEZIER_TRIANGLE: return -3;
    case VTK_LAGRANGE_QUADRILATERAL: case VTK_BEZIER_QUADRILATERAL: return -4;
    case VTK_LAGRANGE_TETRAHEDRON: case VTK_BEZIER_TETRAHEDRON: return -4;
    case VTK_LAGRANGE_HEXAHEDRON: case VTK_BEZIER_HEXAHEDRON: return -8;
    case VTK_LAGRANGE_WEDGE: case VTK_BEZIER_WEDGE: return -6;
    case VTK_LAGRANGE_PYRAMID: case VTK_BEZIER_PYRAMID: return -5;
    default: return 0;
  }
}

// VTK 9.1's surface filter takes an unstructured grid's cells as they are: a cell of a type
// with fewer points than the type has, a point id outside the points, offsets that do not add up
// or fewer cell types than cells make it read and write past its arrays (found by fuzz_vtk: a
// legacy grid of "CELLS 23 8" with two offsets, SEGV in
// vtkUnstructuredGridCellIterator::FetchPointIds). Such a grid is refused before the filter
// runs, naming the first cell at fault; a polyhedron's face stream is walked the same way.
void checkGridCells(vtkUnstructuredGrid* grid, const std::string& path)
{
  vtkCellArray* cells = grid->GetCells();
  const vtkIdType count = cells ? cells->GetNumberOfCells() : 0;
  if (count == 0)
  {
    return;
  }
  if (!cells->IsValid())
  {
    throw errorAbout(path, "its cells' offsets do not add up to their point ids");
  }
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  if (!types || types->GetNumberOfValues() != count)
  {
    throw errorAbout(path, std::to_string(count) + " cells but " +
                               std::to_string(types ? types->GetNumberOfValues() : 0) +
                               " cell types");
  }
  const vtkIdType points = grid->GetNumberOfPoints();
  vtkIdTypeArray* faces = grid->GetFaces();
  vtkIdTypeArray* faceLocations = grid->GetFaceLocations();
  auto at = [&](vtkIdType cell, const std::string& reason) {
    return errorAbout(path, "cell " + std::to_string(cell) + ": " + reason);
  };
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < count; ++c)
  {
    const int type = types->GetValue(c);
    const int need = cellTypePoints(type);
    if (need == 0)
    {
      throw at(c, "cell type " + std::to_string(type) + " is not one VTK knows");
    }
    cells->GetCellAtId(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    if ((need > 0 && n != need) || (need < 0 && need != -0x10000 && n < -need))
    {
      throw at(c, "cell type " + std::to_string(type) + " with " + std::to_string(n) +
                      " points");
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      const vtkIdType id = ids->GetId(i);
      if (id < 0 || id >= points)
      {
        throw at(c, "point id " + std::to_string(id) + " of " + std::to_string(points) +
                        " points");
      }
    }
    if (type != VTK_POLYHEDRON)
    {
      continue;
    }
    // The face stream: at the cell's location, the number of faces, then each face's number of
    // points and their ids.
    const vtkIdType location = faceLocations && c < faceLocations->GetNumberOfValues()
                                   ? faceLocations->GetValue(c)
                                   : -1;
    const vtkIdType size = faces ? faces->GetNumberOfValues() : 0;
    if (location < 0 || location >= size)
    {
      throw at(c, "a polyhedron without its faces");
    }
    vtkIdType p = location;
    const vtkIdType faceCount = faces->GetValue(p++);
    if (faceCount < 1 || faceCount > size)
    {
      throw at(c, "a polyhedron of " + std::to_string(faceCount) + " faces");
    }
    for (vtkIdType f = 0; f < faceCount; ++f)
    {
      const vtkIdType facePoints = p < size ? faces->GetValue(p++) : -1;
      if (facePoints < 3 || facePoints > size - p)
      {
        throw at(c, "a polyhedron face that runs past the face stream");
      }
      for (vtkIdType i = 0; i < facePoints; ++i)
      {
        const vtkIdType id = faces->GetValue(p++);
        if (id < 0 || id >= points)
        {
          throw at(c, "point id " + std::to_string(id) + " of " + std::to_string(points) +
                          " points in a polyhedron face");
        }
      }
    }
  }
}

// Polydata as it is; volumes and grids are shown by their outer surface.
vtkSmartPointer<vtkPolyData> surfaceOf(vtkDataSet* data, const std::string& path,
                                       const VtkMessageCapture& capture)
{
  if (auto* polyData = vtkPolyData::SafeDownCast(data))
  {
    return polyData;
  }
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    checkGridCells(grid, path);
  }
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(data);
  surface->Update();
  throwIfReaderFailed(path, surface, capture);
  vtkSmartPointer<vtkPolyData> output = surface->GetOutput();
  return output;
}

// vtkDataReader::ReadInformation (VTK 9.1) reads an array's INFORMATION block of N keys with
// stream extractions and never clears the stream's failure: a key whose DATA does not read (a
// value that is no number, fewer values than its count says) leaves the stream failed but not
// at its end, and the next key's search for a non-empty line then never ends (found by fuzz_vtk:
// the reader program spun until its 120 s limit). So before VTK reads a legacy file, each
// "INFORMATION N" line is followed here as VTK follows it, for the keys VTK knows
// (vtkInformationKeyLookup, as it looks them up): a numeric key's DATA line must hold its values
// (a vector key: its count, then that many), each a whole number as the stream reads it; a
// string vector key's count must be a count. Blocks of other shapes that VTK reads without an
// extraction (unknown keys, string keys, lines that are no NAME) pass.
void checkLegacyInformation(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  int number = 0;
  auto nextLine = [&]() -> bool
  {
    if (!std::getline(in, line))
    {
      return false;
    }
    ++number;
    line = line.c_str(); // VTK's line is a C string
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    return true;
  };
  auto refuse = [&](const std::string& why)
  {
    throw errorAbout(path, "line " + std::to_string(number) + ": " + why +
                               " (VTK's legacy reader does not recover from it)");
  };
  // The tokens of a text, split at white space.
  auto tokensOf = [](const std::string& text)
  {
    std::istringstream words(text);
    std::vector<std::string> tokens;
    for (std::string word; words >> word;)
    {
      tokens.push_back(word);
    }
    return tokens;
  };
  // Whether a token reads whole as a T through a stream (as VTK's Read(T*) reads it).
  auto readsAs = [](const std::string& token, auto value)
  {
    std::istringstream stream(token);
    stream.imbue(std::locale::classic());
    stream >> value;
    return !stream.fail() && stream.eof();
  };
  while (nextLine())
  {
    if (line.rfind("INFORMATION ", 0) != 0)
    {
      continue;
    }
    long long keys = 0;
    if (std::sscanf(line.c_str(), "INFORMATION %lld", &keys) != 1 || keys <= 0)
    {
      continue; // VTK does not read a block here
    }
    for (long long k = 0; k < keys; ++k)
    {
      bool more = nextLine();
      while (more && line.empty())
      {
        more = nextLine();
      }
      if (!more)
      {
        break; // VTK stops at the end of the file with an error
      }
      char name[256];
      char location[256];
      if (line.rfind("NAME ", 0) != 0 ||
          std::sscanf(line.c_str(), "NAME %255s LOCATION %255s", name, location) != 2)
      {
        continue; // a line VTK skips
      }
      vtkInformationKey* key = vtkInformationKeyLookup::Find(name, location);
      // The kinds VTK reads with extractions: a value (double, id, integer, unsigned long), a
      // count and that many values (double and integer vectors), a count of lines (strings).
      enum class Kind
      {
        Double,
        Integer,
        Unsigned,
        DoubleVector,
        IntegerVector,
        StringVector,
        Unread
      };
      Kind kind = Kind::Unread;
      if (vtkInformationDoubleKey::SafeDownCast(key))
      {
        kind = Kind::Double;
      }
      else if (vtkInformationIdTypeKey::SafeDownCast(key) ||
               vtkInformationIntegerKey::SafeDownCast(key))
      {
        kind = Kind::Integer;
      }
      else if (vtkInformationUnsignedLongKey::SafeDownCast(key))
      {
        kind = Kind::Unsigned;
      }
      else if (vtkInformationDoubleVectorKey::SafeDownCast(key))
      {
        kind = Kind::DoubleVector;
      }
      else if (vtkInformationIntegerVectorKey::SafeDownCast(key))
      {
        kind = Kind::IntegerVector;
      }
      else if (vtkInformationStringVectorKey::SafeDownCast(key))
      {
        kind = Kind::StringVector;
      }
      if (kind == Kind::Unread)
      {
        continue; // unknown keys, string keys (read as a line) and kinds VTK does not read
      }
      const std::string what = std::string("key ") + location + "::" + name;
      if (!nextLine())
      {
        break; // VTK stops at the end of the file with an error
      }
      const std::vector<std::string> tokens = tokensOf(line);
      if (tokens.size() < 2 || tokens[0].compare(0, 4, "DATA") != 0)
      {
        refuse(what + ": its DATA line is not \"DATA VALUES\"");
      }
      auto isValue = [&](const std::string& token, Kind of)
      {
        switch (of)
        {
        case Kind::Double:
        case Kind::DoubleVector:
          return readsAs(token, 0.0);
        case Kind::Unsigned:
          return readsAs(token, 0UL);
        case Kind::IntegerVector:
          return readsAs(token, 0);
        default:
          return readsAs(token, 0LL);
        }
      };
      if (kind == Kind::Double || kind == Kind::Integer || kind == Kind::Unsigned)
      {
        if (tokens.size() != 2 || !isValue(tokens[1], kind))
        {
          refuse(what + ": its value is not one number");
        }
        continue;
      }
      int count = 0;
      if (!readsAs(tokens[1], 0) || std::sscanf(tokens[1].c_str(), "%d", &count) != 1 || count < 0)
      {
        refuse(what + ": its count \"" + tokens[1] + "\" is not a count");
      }
      if (kind == Kind::StringVector)
      {
        for (int i = 0; i < count && nextLine(); ++i)
        {
        }
        continue;
      }
      if (tokens.size() != 2 + static_cast<size_t>(count))
      {
        refuse(what + ": " + std::to_string(count) + " values declared, " +
               std::to_string(tokens.size() - 2) + " on its DATA line");
      }
      for (size_t i = 2; i < tokens.size(); ++i)
      {
        if (!isValue(tokens[i], kind))
        {
          refuse(what + ": \"" + tokens[i] + "\" is not a number");
        }
      }
    }
  }
}

vtkSmartPointer<vtkPolyData> readLegacy(const std::string& path, const VtkMessageCapture& capture)
{
  checkVtkLegacySizes(path);
  checkLegacyInformation(path);
  vtkNew<vtkDataSetReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  throwIfReaderFailed(path, reader, capture);
  vtkDataSet* data = reader->GetOutput();
  if (!data)
  {
    throw errorAbout(path, "not a VTK legacy dataset");
  }
  return surfaceOf(data, path, capture);
}

// vtkOBJReader reads vertex coordinates as floats through an input stream: "nan", "inf" or a
// value beyond the float range fails the extraction and leaves 0 or the previous line's values
// in the vertex, a finite position that no later check can tell from a real one. So vertex
// lines with such a coordinate are rewritten (in a private copy) to hold FLT_MAX there, and the
// points that come out with a coordinate at +-FLT_MAX are made NaN, for sanitizeSurface to drop
// with their faces and count. Returns the copy's text, or nothing when every vertex is fine.
std::optional<std::string> objWithMarkedVertices(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string text;
  std::string line;
  bool marked = false;
  while (std::getline(in, line))
  {
    size_t at = line.find_first_not_of(" \t");
    if (at != std::string::npos && line.compare(at, 2, "v ") == 0)
    {
      std::string rewritten = line.substr(0, at + 1);
      at += 1;
      for (int field = 0; field < 3; ++field)
      {
        const size_t start = line.find_first_not_of(" \t", at);
        if (start == std::string::npos)
        {
          break;
        }
        size_t end = line.find_first_of(" \t\r", start);
        end = end == std::string::npos ? line.size() : end;
        const std::string token = line.substr(start, end - start);
        char* parsedEnd = nullptr;
        const double value = std::strtod(token.c_str(), &parsedEnd);
        const bool number = parsedEnd != token.c_str();
        const bool unfit = number && (!std::isfinite(value) ||
                                      std::abs(value) >= double(std::numeric_limits<float>::max()));
        rewritten += line.substr(at, start - at);
        rewritten += unfit ? "3.40282347e+38" : token;
        marked = marked || unfit;
        at = end;
      }
      line = rewritten + line.substr(at);
    }
    text += line;
    text += '\n';
  }
  if (!marked)
  {
    return std::nullopt;
  }
  return text;
}

// vtkOBJReader (VTK 9.1) indexes its texture coordinates while it parses a face, its normals
// and, once it has to duplicate vertices (a face's texture or normal indices differ from its
// vertex indices), its vertices afterwards, all without a range check; and it copies a usemtl
// name into a buffer of 100 bytes. "f 1/1 2/1 3/1" in a file without "vt" statements, or a
// normal index past the last "vn", crashes it (fuzz_obj; tests/data/fuzz/obj). So the file is
// read here first as that reader reads it (lines cut at a NUL byte, a face's corners parsed
// with its sscanf patterns from each word on, a lone "\\" at the end of a line continuing the
// face on the next line; a negative index counts back from the statements of its kind read so
// far) and refused when a face indexes a texture coordinate or a normal that is not there, when
// a face's vertex is not there in a file whose faces index texture coordinates or normals, or
// when a usemtl name is too long. Faces of vertices alone keep their bad indices, which the
// reader passes through for sanitizeSurface to drop. Where the reader itself stops (a corner it
// cannot parse), so does this.
void checkObjIndices(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  // Statements in the whole file: the reader's vertex, texture coordinate and normal arrays.
  long long totals[3] = {0, 0, 0};
  std::vector<std::string> lines;
  std::string line;
  auto isSpace = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  auto command = [&](const std::string& text, size_t& at)
  {
    at = 0;
    while (at < text.size() && isSpace(text[at]))
    {
      ++at;
    }
    const size_t start = at;
    while (at < text.size() && !isSpace(text[at]))
    {
      ++at;
    }
    return text.substr(start, at - start);
  };
  while (std::getline(in, line))
  {
    line = line.c_str(); // the reader's C string ends at a NUL byte
    lines.push_back(line);
    size_t at = 0;
    const std::string word = command(line, at);
    if (word == "v" || word == "vt" || word == "vn")
    {
      ++totals[word.size() == 1 ? 0 : word[1] == 't' ? 1 : 2];
    }
  }
  const char* const kinds[3] = {"vertex", "texture coordinate", "normal"};
  long long seen[3] = {0, 0, 0}; // statements before the current line
  bool attributes = false;       // some face indexes a texture coordinate or a normal
  int badVertexLine = 0;         // the first face with a vertex that is not there
  long long badVertex = 0;
  bool stopped = false; // where the reader stops reading the file
  for (size_t n = 0; n < lines.size() && !stopped; ++n)
  {
    size_t at = 0;
    const std::string word = command(lines[n], at);
    if (word == "v" || word == "vt" || word == "vn")
    {
      ++seen[word.size() == 1 ? 0 : word[1] == 't' ? 1 : 2];
      continue;
    }
    if (word == "usemtl")
    {
      std::istringstream rest(lines[n].substr(at));
      std::string name;
      if (rest >> name && name.size() >= 100)
      {
        throw errorAbout(path, "line " + std::to_string(n + 1) +
                                   ": a material name longer than 99 characters");
      }
      continue;
    }
    if (word != "f")
    {
      continue;
    }
    // An index of KIND as the reader turns it into a place in its array, or refused.
    auto check = [&](int kind, int index, size_t where)
    {
      const long long place = index < 0 ? seen[kind] + index : static_cast<long long>(index) - 1;
      if (place >= 0 && place < totals[kind])
      {
        return;
      }
      if (kind == 0)
      {
        if (badVertexLine == 0)
        {
          badVertexLine = static_cast<int>(where + 1);
          badVertex = index;
        }
        return;
      }
      throw errorAbout(path, "line " + std::to_string(where + 1) + ": a face refers to " +
                                 kinds[kind] + " " + std::to_string(index) +
                                 ", but the file has " + std::to_string(totals[kind]));
    };
    const std::string* text = &lines[n];
    while (!stopped)
    {
      while (at < text->size() && isSpace((*text)[at]))
      {
        ++at;
      }
      if (at >= text->size())
      {
        break;
      }
      const char* corner = text->c_str() + at;
      int v = 0;
      int t = 0;
      int normal = 0;
      if (std::sscanf(corner, "%d/%d/%d", &v, &t, &normal) == 3)
      {
        check(0, v, n);
        check(1, t, n);
        check(2, normal, n);
        attributes = true;
      }
      else if (std::sscanf(corner, "%d//%d", &v, &normal) == 2)
      {
        check(0, v, n);
        check(2, normal, n);
        attributes = true;
      }
      else if (std::sscanf(corner, "%d/%d", &v, &t) == 2)
      {
        check(0, v, n);
        check(1, t, n);
        attributes = true;
      }
      else if (std::sscanf(corner, "%d", &v) == 1)
      {
        check(0, v, n);
      }
      else if (std::string(corner) == "\\" && n + 1 < lines.size())
      {
        text = &lines[++n];
        at = 0;
        continue;
      }
      else
      {
        stopped = true; // a corner the reader cannot parse
      }
      while (at < text->size() && !isSpace((*text)[at]))
      {
        ++at;
      }
    }
  }
  if (attributes && badVertexLine != 0)
  {
    throw errorAbout(path, "line " + std::to_string(badVertexLine) + ": a face refers to vertex " +
                               std::to_string(badVertex) + ", but the file has " +
                               std::to_string(totals[0]));
  }
}

vtkSmartPointer<vtkPolyData> readObj(const std::string& path, const VtkMessageCapture& capture)
{
  checkObjIndices(path);
  const std::optional<std::string> marked = objWithMarkedVertices(path);
  const std::filesystem::path copy = std::filesystem::temp_directory_path() /
                                     ("aniso_obj_vertices_" + std::to_string(::getpid()) + ".obj");
  if (marked)
  {
    std::ofstream(copy, std::ios::binary) << *marked;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(marked ? copy.c_str() : path.c_str());
  reader->Update();
  if (marked)
  {
    std::error_code ignored;
    std::filesystem::remove(copy, ignored);
  }
  throwIfReaderFailed(path, reader, capture);
  vtkSmartPointer<vtkPolyData> output = reader->GetOutput();
  vtkPoints* points = output ? output->GetPoints() : nullptr;
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    constexpr double kFloatMax = double(std::numeric_limits<float>::max());
    if (std::abs(p[0]) >= kFloatMax || std::abs(p[1]) >= kFloatMax || std::abs(p[2]) >= kFloatMax)
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      points->SetPoint(i, nan, nan, nan);
    }
  }
  return output;
}

// Where each g/o statement's block begins and which block each f, l and p statement belongs to.
// A block is the cells of one g/o statement that use one material (usemtl), so a group whose
// faces use several materials is several blocks.
struct ObjStatements
{
  std::vector<std::string> names;     // one per block: its g/o statement's words ("" before any)
  std::vector<std::string> materials; // one per block: the usemtl name its cells use ("" none)
  std::vector<int> groups;            // one per block: its g/o statement's ordinal (0 before any)
  std::vector<int> materialLines;     // one per block: the line of its usemtl (0 none)
  std::vector<int> points;            // the block of each p statement, in file order
  std::vector<int> lines;             // l
  std::vector<int> faces;             // f
  std::vector<char> faceHasNormals;   // its first vertex gives a normal index (v//vn, v/vt/vn)
  std::vector<std::pair<std::string, int>> libraries; // mtllib words and line, in file order
};

// The statements as vtkOBJReader tells them apart: the first word of a line after white space.
ObjStatements scanObjStatements(const std::string& path)
{
  ObjStatements statements;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::string pendingName;
  int group = 0;
  std::string material;
  int materialLine = 0;
  int lineNumber = 0;
  std::map<std::pair<int, std::string>, int> blockOf; // (group, material) -> block
  int current = -1; // the block the next cell goes to; -1 until one comes
  auto isSpace = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (std::getline(in, line))
  {
    ++lineNumber;
    size_t start = 0;
    while (start < line.size() && isSpace(line[start]))
    {
      ++start;
    }
    size_t end = start;
    while (end < line.size() && !isSpace(line[end]))
    {
      ++end;
    }
    const std::string command = line.substr(start, end - start);
    auto rest = [&]
    {
      size_t first = end;
      while (first < line.size() && isSpace(line[first]))
      {
        ++first;
      }
      size_t last = line.size();
      while (last > first && isSpace(line[last - 1]))
      {
        --last;
      }
      return line.substr(first, last - first);
    };
    if (command == "g" || command == "o")
    {
      pendingName = rest();
      ++group;
      current = -1;
      continue;
    }
    if (command == "usemtl")
    {
      material = rest().substr(0, kMaxMtlNameLength);
      materialLine = lineNumber;
      current = -1;
      continue;
    }
    if (command == "mtllib")
    {
      statements.libraries.emplace_back(rest(), lineNumber);
      continue;
    }
    std::vector<int>* cells = command == "f"   ? &statements.faces
                              : command == "l" ? &statements.lines
                              : command == "p" ? &statements.points
                                               : nullptr;
    if (!cells)
    {
      continue;
    }
    if (current < 0)
    {
      const auto key = std::make_pair(group, material);
      const auto found = blockOf.find(key);
      if (found != blockOf.end())
      {
        current = found->second;
      }
      else
      {
        statements.names.push_back(pendingName);
        statements.materials.push_back(material);
        statements.groups.push_back(group);
        statements.materialLines.push_back(materialLine);
        current = static_cast<int>(statements.names.size()) - 1;
        blockOf.emplace(key, current);
      }
    }
    cells->push_back(current);
    if (cells == &statements.faces)
    {
      const char* vertex = line.c_str() + end;
      while (*vertex && isSpace(*vertex))
      {
        ++vertex;
      }
      int v = 0;
      int t = 0;
      int n = 0;
      const bool normal = std::sscanf(vertex, "%d/%d/%d", &v, &t, &n) == 3 ||
                          std::sscanf(vertex, "%d//%d", &v, &n) == 2;
      statements.faceHasNormals.push_back(normal ? 1 : 0);
    }
  }
  return statements;
}

// Point arrays without one value per point (corrupt files: vtkOBJReader makes such texture
// coordinates when the file has fewer vt than v lines and every face gives the vertex's own
// index) are dropped, each with a warning (WHAT names the part, or is empty): they cannot be cut
// into parts, and VTK's XML reader, which reads the parts back in the application, empties a
// piece that holds one. Cell arrays without one value per cell go the same way; with
// KEEP_CELL_DATA false (an OBJ about to be cut into parts, whose cells the cut regroups) all
// cell data go.
void dropMalformedArrays(vtkPolyData* polyData, const std::string& what,
                         std::vector<std::string>& warnings, bool keepCellData = true)
{
  const vtkIdType pointCount = polyData->GetNumberOfPoints();
  vtkPointData* pd = polyData->GetPointData();
  for (int a = pd->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    vtkAbstractArray* array = pd->GetAbstractArray(a);
    if (array && (array->GetNumberOfTuples() != pointCount || array->GetNumberOfComponents() < 1))
    {
      const std::string name = array->GetName() ? array->GetName() : "";
      warnings.push_back((what.empty() ? "" : what + ": ") + "point attribute '" + name + "' has " +
                         std::to_string(array->GetNumberOfTuples()) + " values for " +
                         std::to_string(pointCount) + " vertices: dropped");
      pd->RemoveArray(a);
    }
  }
  vtkCellData* cd = polyData->GetCellData();
  if (!keepCellData)
  {
    cd->Initialize();
    return;
  }
  const vtkIdType cellCount = polyData->GetNumberOfCells();
  for (int a = cd->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    vtkAbstractArray* array = cd->GetAbstractArray(a);
    if (array && (array->GetNumberOfTuples() != cellCount || array->GetNumberOfComponents() < 1))
    {
      const std::string name = array->GetName() ? array->GetName() : "";
      warnings.push_back((what.empty() ? "" : what + ": ") + "cell attribute '" + name + "' has " +
                         std::to_string(array->GetNumberOfTuples()) + " values for " +
                         std::to_string(cellCount) + " cells: dropped");
      cd->RemoveArray(a);
    }
  }
}

// INPUT's vertex, line and polygon cells (strips: none from vtkOBJReader) as BLOCKS polydata,
// each cell going to the block CELL_BLOCKS gives it (one list per kind, in INPUT's order). Each
// block holds the points its cells use, in the order of first use, with their attributes (every
// point array has one value per point: dropMalformedArrays). A point id out of range becomes -1,
// so that sanitizeSurface drops and counts the cell.
std::vector<vtkSmartPointer<vtkPolyData>> splitIntoBlocks(vtkPolyData* input, size_t blocks,
                                                          const std::vector<int>& vertBlocks,
                                                          const std::vector<int>& lineBlocks,
                                                          const std::vector<int>& polyBlocks)
{
  vtkPoints* points = input->GetPoints();
  const vtkIdType pointCount = points ? points->GetNumberOfPoints() : 0;
  vtkPointData* inPd = input->GetPointData();

  // Each block's cells of each kind, as (count, ids...) runs with the input's point ids.
  enum Kind
  {
    Verts,
    Lines,
    Polys,
    Kinds
  };
  std::vector<std::array<std::vector<vtkIdType>, Kinds>> cells(blocks);
  const std::array<std::pair<vtkCellArray*, const std::vector<int>*>, Kinds> sources = {
      {{input->GetVerts(), &vertBlocks},
       {input->GetLines(), &lineBlocks},
       {input->GetPolys(), &polyBlocks}}};
  for (int kind = 0; kind < Kinds; ++kind)
  {
    size_t cell = 0;
    const std::vector<int>& owner = *sources[kind].second;
    geometry::forEachCell(sources[kind].first,
                          [&](vtkIdType count, const vtkIdType* ids)
                          {
                            std::vector<vtkIdType>& run =
                                cells[static_cast<size_t>(owner[cell++])][kind];
                            run.push_back(count);
                            run.insert(run.end(), ids, ids + count);
                          });
  }

  std::vector<vtkSmartPointer<vtkPolyData>> result;
  std::vector<vtkIdType> newId(static_cast<size_t>(pointCount), -1);
  for (size_t b = 0; b < blocks; ++b)
  {
    std::vector<vtkIdType> source; // the input point of each block point
    auto block = vtkSmartPointer<vtkPolyData>::New();
    std::array<vtkNew<vtkCellArray>, Kinds> arrays;
    std::vector<vtkIdType> ids;
    for (int kind = 0; kind < Kinds; ++kind)
    {
      const std::vector<vtkIdType>& run = cells[b][kind];
      for (size_t at = 0; at < run.size();)
      {
        const vtkIdType count = run[at++];
        ids.clear();
        for (vtkIdType k = 0; k < count; ++k, ++at)
        {
          const vtkIdType id = run[at];
          if (id < 0 || id >= pointCount)
          {
            ids.push_back(-1);
            continue;
          }
          if (newId[static_cast<size_t>(id)] < 0)
          {
            newId[static_cast<size_t>(id)] = static_cast<vtkIdType>(source.size());
            source.push_back(id);
          }
          ids.push_back(newId[static_cast<size_t>(id)]);
        }
        arrays[kind]->InsertNextCell(count, ids.data());
      }
      cells[b][kind] = {};
    }
    vtkNew<vtkPoints> blockPoints;
    if (points)
    {
      blockPoints->SetDataType(points->GetDataType());
    }
    blockPoints->SetNumberOfPoints(static_cast<vtkIdType>(source.size()));
    vtkPointData* outPd = block->GetPointData();
    outPd->CopyAllOn();
    outPd->CopyAllocate(inPd, static_cast<vtkIdType>(source.size()));
    for (size_t i = 0; i < source.size(); ++i)
    {
      blockPoints->SetPoint(static_cast<vtkIdType>(i), points->GetPoint(source[i]));
      outPd->CopyData(inPd, source[i], static_cast<vtkIdType>(i));
      newId[static_cast<size_t>(source[i])] = -1;
    }
    block->SetPoints(blockPoints);
    block->SetVerts(arrays[Verts]);
    block->SetLines(arrays[Lines]);
    block->SetPolys(arrays[Polys]);
    result.push_back(block);
  }
  return result;
}

// The materials an OBJ's mtllib statements name, read in the reader program: each library
// relative to the .obj's directory, the first definition of a name winning. A library that
// cannot be read is one warning naming it; its materials are then unknown.
class ObjMaterials
{
public:
  ObjMaterials(const std::string& objPath, const ObjStatements& statements,
               std::vector<std::string>& warnings)
      : objPath_(objPath), warnings_(warnings)
  {
    const std::filesystem::path directory = std::filesystem::path(objPath).parent_path();
    std::set<std::string> seen;
    for (const auto& [words, line] : statements.libraries)
    {
      for (const std::string& name : libraryNames(directory, words))
      {
        const std::string file = (directory / name).lexically_normal().string();
        if (!seen.insert(file).second)
        {
          continue;
        }
        std::error_code ec;
        const uintmax_t size = std::filesystem::file_size(file, ec);
        if (!ec && size <= kMaxMtlFileBytes && bytesRead_ + size > kMaxLibraryBytes)
        {
          warn(objPath_ + ":" + std::to_string(line) + ": mtllib " + name + ": past the " +
               std::to_string(kMaxLibraryBytes >> 20) +
               " MiB of material libraries a file may name (not read)");
          continue;
        }
        bytesRead_ += ec ? 0 : size;
        try
        {
          libraries_.push_back({file, readMtlFile(file)});
          const MtlLibrary& library = libraries_.back().second;
          for (const std::string& w : library.warnings)
          {
            warn(w);
          }
          for (const MtlMaterial& material : library.materials)
          {
            definitions_.emplace(material.name,
                                 std::make_pair(&libraries_.back().first, &material));
          }
        }
        catch (const Error& e)
        {
          warn(objPath_ + ":" + std::to_string(line) + ": mtllib " + name + ": " + e.what() +
               " (the parts load without its materials)");
        }
      }
    }
  }

  // The material library document of the material NAME (usemtl's words at LINE), empty when
  // NAME is empty or none of the libraries defines it (a warning, once per name).
  std::string documentOf(const std::string& name, int line)
  {
    if (name.empty())
    {
      return {};
    }
    const auto known = documents_.find(name);
    if (known != documents_.end())
    {
      return known->second;
    }
    std::string& document = documents_[name];
    const auto definition = definitions_.find(name);
    if (definition != definitions_.end())
    {
      const auto [file, mtl] = definition->second;
      try
      {
        MaterialLibrary one;
        std::vector<std::string> told;
        one.put(materialFromMtl(*mtl, *file, told));
        for (const std::string& w : told)
        {
          warn(w);
        }
        document = materialLibraryToJson(one);
      }
      catch (const std::exception& e) // aniso::Error, or the JSON writer's
      {
        warn(*file + ": " + name + ": " + e.what() + " (the parts load without it)");
      }
      return document;
    }
    warn(objPath_ + ":" + std::to_string(line) + ": usemtl " + name + ": no such material in " +
         (libraries_.empty() ? std::string("any mtllib read") : "its material libraries") +
         " (its faces load without it)");
    return document;
  }

private:
  // Every part carries the file's warnings, so a file of many libraries or materials must not
  // make them without end.
  static constexpr size_t kMaxWarnings = 200;
  // Within the reader program's smallest memory budget (MeshReaderProcess.h), whatever the
  // .obj's size.
  static constexpr uintmax_t kMaxLibraryBytes = 4 * uintmax_t(kMaxMtlFileBytes);

  void warn(const std::string& warning)
  {
    if (told_ < kMaxWarnings)
    {
      warnings_.push_back(warning);
    }
    else if (told_ == kMaxWarnings)
    {
      warnings_.push_back(objPath_ + ": more warnings about its materials are left out");
    }
    ++told_;
  }

  // mtllib names one or more files, separated by blanks; a name with blanks in it is read as a
  // whole when a file of that name exists.
  static std::vector<std::string> libraryNames(const std::filesystem::path& directory,
                                               const std::string& words)
  {
    std::error_code ec;
    if (words.empty() || std::filesystem::is_regular_file(directory / words, ec))
    {
      return words.empty() ? std::vector<std::string>{} : std::vector<std::string>{words};
    }
    std::vector<std::string> names;
    std::istringstream split(words);
    for (std::string name; split >> name;)
    {
      names.push_back(name);
    }
    return names;
  }

  const std::string& objPath_;
  std::vector<std::string>& warnings_;
  // A list, so that the definitions' pointers into it stay valid as libraries are added.
  std::list<std::pair<std::string, MtlLibrary>> libraries_;
  // Each material name's first definition: its library's path and the material.
  std::map<std::string, std::pair<const std::string*, const MtlMaterial*>> definitions_;
  std::map<std::string, std::string> documents_;
  size_t told_ = 0;
  uintmax_t bytesRead_ = 0;
};

// The blocks' names: a g/o group whose cells use several materials is one part per material,
// named "GROUP/MATERIAL" (the material alone outside any named group; the group alone for its
// cells before any usemtl).
std::vector<std::string> objBlockNames(const ObjStatements& statements)
{
  std::map<int, std::set<std::string>> materialsOfGroup;
  for (size_t b = 0; b < statements.names.size(); ++b)
  {
    materialsOfGroup[statements.groups[b]].insert(statements.materials[b]);
  }
  std::vector<std::string> names;
  for (size_t b = 0; b < statements.names.size(); ++b)
  {
    const std::string& group = statements.names[b];
    const std::string& material = statements.materials[b];
    if (materialsOfGroup[statements.groups[b]].size() <= 1 || material.empty())
    {
      names.push_back(group);
    }
    else
    {
      names.push_back(group.empty() ? material : group + "/" + material);
    }
  }
  return names;
}

std::vector<ReaderBlock> readObjBlocks(const std::string& path, const VtkMessageCapture& capture,
                                       std::vector<std::string>& warnings)
{
  vtkSmartPointer<vtkPolyData> whole = readObj(path, capture);
  dropMalformedArrays(whole, std::string(), warnings, false);
  const ObjStatements statements = scanObjStatements(path);
  ObjMaterials materials(path, statements, warnings);
  // The file as one part: its material when all its cells use one.
  auto onePart = [&](const std::string& name)
  {
    ReaderBlock block(name, whole);
    const std::set<std::string> used(statements.materials.begin(), statements.materials.end());
    if (used.size() == 1)
    {
      block.material = materials.documentOf(*used.begin(), statements.materialLines.front());
    }
    return std::vector<ReaderBlock>{block};
  };
  if (statements.names.size() <= 1)
  {
    return onePart(statements.names.empty() ? std::string() : statements.names.front());
  }
  // vtkOBJReader's cells against the statements: every p and l statement is one vertex or line
  // cell, except where it duplicates vertices (then it keeps none); every f statement is one
  // polygon, except that it then drops the faces without normals if any face has normals.
  auto matches = [](vtkIdType cells, size_t count)
  { return cells == 0 || cells == static_cast<vtkIdType>(count); };
  std::vector<int> faces = statements.faces;
  const vtkIdType polys = whole->GetNumberOfPolys();
  if (polys != static_cast<vtkIdType>(faces.size()))
  {
    faces.clear();
    for (size_t f = 0; f < statements.faces.size(); ++f)
    {
      if (statements.faceHasNormals[f])
      {
        faces.push_back(statements.faces[f]);
      }
    }
  }
  const vtkIdType verts = whole->GetNumberOfVerts();
  const vtkIdType lines = whole->GetNumberOfLines();
  if (polys != static_cast<vtkIdType>(faces.size()) || !matches(verts, statements.points.size()) ||
      !matches(lines, statements.lines.size()) || whole->GetNumberOfStrips() != 0)
  {
    warnings.push_back("its groups could not be matched to the faces the OBJ reader kept: read "
                       "as one part");
    return onePart(std::string());
  }
  const std::vector<int> none;
  std::vector<vtkSmartPointer<vtkPolyData>> pieces =
      splitIntoBlocks(whole, statements.names.size(), verts ? statements.points : none,
                      lines ? statements.lines : none, faces);
  const std::vector<std::string> names = objBlockNames(statements);
  // A block whose cells the reader dropped stays, without cells, for the loader to report.
  std::vector<ReaderBlock> blocks;
  for (size_t b = 0; b < pieces.size(); ++b)
  {
    blocks.push_back({names[b], pieces[b]});
    blocks.back().material =
        materials.documentOf(statements.materials[b], statements.materialLines[b]);
  }
  return blocks;
}

// The leaves of TREE, depth first, named by their path of names from the top (PREFIX, then the
// level's NAME or "block I"); empty leaves and leaves that are no dataset as blocks without
// cells.
void collectLeaves(vtkDataObject* tree, const std::string& prefix, const std::string& path,
                   const VtkMessageCapture& capture, std::vector<ReaderBlock>& blocks)
{
  auto* multiBlock = vtkMultiBlockDataSet::SafeDownCast(tree);
  auto* partitioned = vtkPartitionedDataSet::SafeDownCast(tree);
  const unsigned int children = multiBlock    ? multiBlock->GetNumberOfBlocks()
                                : partitioned ? partitioned->GetNumberOfPartitions()
                                              : 0;
  for (unsigned int i = 0; i < children; ++i)
  {
    const bool hasMeta = multiBlock ? multiBlock->HasMetaData(i) : partitioned->HasMetaData(i);
    vtkInformation* meta = !hasMeta     ? nullptr
                           : multiBlock ? multiBlock->GetMetaData(i)
                                        : partitioned->GetMetaData(i);
    const char* given = meta && meta->Has(vtkCompositeDataSet::NAME())
                            ? meta->Get(vtkCompositeDataSet::NAME())
                            : nullptr;
    const std::string own = given && *given ? given : "block " + std::to_string(i);
    const std::string name = prefix.empty() ? own : prefix + "/" + own;
    vtkDataObject* child =
        multiBlock ? multiBlock->GetBlock(i) : partitioned->GetPartitionAsDataObject(i);
    if (vtkMultiBlockDataSet::SafeDownCast(child) || vtkPartitionedDataSet::SafeDownCast(child))
    {
      collectLeaves(child, name, path, capture, blocks);
    }
    else if (auto* data = vtkDataSet::SafeDownCast(child))
    {
      blocks.push_back({name, surfaceOf(data, path, capture)});
    }
    else
    {
      blocks.push_back({name, vtkSmartPointer<vtkPolyData>::New()});
    }
  }
}

// The compression headers of the pieces a multiblock file names (file="..." of its DataSet
// elements, relative to its folder), checked as a .vtp's are (checkVtkXmlHeaders): VTK's
// multiblock reader reads them with the same XML readers. Pieces that are not there are left to
// VTK's reader.
void checkVtmPieceHeaders(const std::string& path, vtkXMLDataElement* element, int depth = 0)
{
  if (depth > 64)
  {
    return;
  }
  const char* file = element->GetAttribute("file");
  if (file && *file && element->GetName() && std::strcmp(element->GetName(), "DataSet") == 0)
  {
    const std::filesystem::path piece = std::filesystem::path(path).parent_path() / file;
    std::error_code ec;
    if (std::filesystem::is_regular_file(piece, ec))
    {
      if (std::optional<std::string> problem = vtkXmlHeaderProblem(piece.string()))
      {
        throw errorAbout(path, "piece " + std::string(file) + ": " + *problem);
      }
    }
  }
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    checkVtmPieceHeaders(path, element->GetNestedElement(i), depth + 1);
  }
}

// vtkXMLMultiBlockDataReader (VTK 9.1) goes on to read the tree of a file whose VTKFile element
// holds no vtkMultiBlockDataSet element, through the null pointer its superclass left for it
// (RequestInformation, FillMetaData; found by fuzz_vtm). Such a file is refused first. A file
// that does not parse is left to VTK's reader, which stops on it with its own message.
void checkVtmPrimaryElement(const std::string& path)
{
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(path.c_str());
  if (!parser->Parse())
  {
    return;
  }
  vtkXMLDataElement* root = parser->GetRootElement();
  if (root && root->GetName() && std::strcmp(root->GetName(), "VTKFile") == 0 &&
      !root->FindNestedElementWithName("vtkMultiBlockDataSet"))
  {
    throw errorAbout(path, "its VTKFile element holds no vtkMultiBlockDataSet element");
  }
  if (root)
  {
    checkVtmPieceHeaders(path, root);
  }
}

std::vector<ReaderBlock> readVtmBlocks(const std::string& path, const VtkMessageCapture& capture)
{
  checkVtmPrimaryElement(path);
  vtkNew<vtkXMLMultiBlockDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  throwIfReaderFailed(path, reader, capture);
  vtkDataObject* tree = reader->GetOutputDataObject(0);
  if (!vtkMultiBlockDataSet::SafeDownCast(tree))
  {
    throw errorAbout(path, "not a VTK multiblock file");
  }
  std::vector<ReaderBlock> blocks;
  collectLeaves(tree, std::string(), path, capture, blocks);
  if (blocks.empty())
  {
    throw errorAbout(path, "no faces (the multiblock holds no dataset)");
  }
  return blocks;
}

vtkSmartPointer<vtkPolyData> readVtm(const std::string& path, const VtkMessageCapture& capture)
{
  const std::vector<ReaderBlock> blocks = readVtmBlocks(path, capture);
  // Leaves without points would leave the merge without the point arrays the others share.
  vtkNew<vtkAppendPolyData> append;
  int pieces = 0;
  for (const ReaderBlock& block : blocks)
  {
    if (block.polyData->GetNumberOfPoints() > 0)
    {
      append->AddInputData(block.polyData);
      ++pieces;
    }
  }
  if (pieces == 0)
  {
    return vtkSmartPointer<vtkPolyData>::New();
  }
  append->Update();
  throwIfReaderFailed(path, append, capture);
  vtkSmartPointer<vtkPolyData> merged = append->GetOutput();
  return merged;
}

} // namespace

vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path, const std::string& ext,
                                         const VtkMessageCapture& capture)
{
  if (ext == ".obj")
  {
    return readObj(path, capture);
  }
  if (ext == ".vtp")
  {
    checkVtkXmlHeaders(path);
    return readPolyData<vtkXMLPolyDataReader>(path, capture);
  }
  if (ext == ".vtk")
  {
    return readLegacy(path, capture);
  }
  if (ext == ".vtu")
  {
    checkVtkXmlHeaders(path);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    throwIfReaderFailed(path, reader, capture);
    vtkDataSet* grid = reader->GetOutput();
    if (!grid)
    {
      throw errorAbout(path, "not a VTK unstructured grid");
    }
    return surfaceOf(grid, path, capture);
  }
  if (ext == ".vtm")
  {
    return readVtm(path, capture);
  }
  std::vector<std::string> warnings;
  return readGltfSurface(path, warnings);
}

std::vector<ReaderBlock> readBlocksWithVtk(const std::string& path, const std::string& ext,
                                           const VtkMessageCapture& capture,
                                           std::vector<std::string>& warnings)
{
  if (ext == ".obj")
  {
    return readObjBlocks(path, capture, warnings);
  }
  std::vector<ReaderBlock> blocks;
  if (ext == ".vtm")
  {
    blocks = readVtmBlocks(path, capture);
  }
  else if (ext == ".gltf" || ext == ".glb")
  {
    blocks = readGltfBlocks(path, warnings);
  }
  else
  {
    blocks = {{std::string(), readWithVtk(path, ext, capture)}};
  }
  for (ReaderBlock& block : blocks)
  {
    dropMalformedArrays(block.polyData, block.name.empty() ? "" : "part " + block.name, warnings);
  }
  return blocks;
}
} // namespace aniso
