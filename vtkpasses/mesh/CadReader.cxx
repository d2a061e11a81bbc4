#include "vtkpasses/mesh/CadReader.h"

#include "core/error.h"
#include "core/parameters/material_library.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Poly_Triangulation.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_Label.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDF_Tool.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <gp_Trsf.hxx>
#include <map>
#include <optional>
#include <set>
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
bool isStep(const std::string& ext)
{
  return ext == ".step" || ext == ".stp";
}

std::string labelName(const TDF_Label& label)
{
  Handle(TDataStd_Name) name;
  if (label.IsNull() || !label.FindAttribute(TDataStd_Name::GetID(), name))
  {
    return {};
  }
  const TCollection_AsciiString utf8(name->Get()); // UTF-8, as no replacement is given
  return utf8.ToCString();
}

std::optional<Quantity_Color> surfaceColour(const Handle(XCAFDoc_ColorTool) & colours,
                                            const TDF_Label& label)
{
  Quantity_Color colour;
  if (!label.IsNull() && (colours->GetColor(label, XCAFDoc_ColorSurf, colour) ||
                          colours->GetColor(label, XCAFDoc_ColorGen, colour)))
  {
    return colour;
  }
  return std::nullopt;
}

PartMatrix matrixOf(const TopLoc_Location& location)
{
  const gp_Trsf trsf = location.Transformation();
  PartMatrix m = kIdentityPlacement;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      m[static_cast<size_t>(r * 4 + c)] = trsf.Value(r + 1, c + 1);
    }
  }
  return m;
}

// The last bytes of the file, to tell a file cut short before OpenCASCADE reads what is left
// of it as a smaller, valid model.
std::string fileTail(const std::string& path, std::streamoff bytes)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg();
  const std::streamoff start = std::max<std::streamoff>(0, size - bytes);
  in.seekg(start);
  std::string tail(static_cast<size_t>(size - start), '\0');
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  return tail;
}

void checkComplete(const std::string& path, const std::string& ext)
{
  const std::string tail = fileTail(path, 4096);
  if (isStep(ext))
  {
    if (tail.find("END-ISO-10303-21;") == std::string::npos)
    {
      throw errorAbout(path, "the STEP file is cut short (no closing END-ISO-10303-21;)");
    }
    return;
  }
  // An IGES file ends with its terminate section: a line whose column 73 is 'T'.
  size_t end = tail.find_last_not_of("\r\n \t\x1a");
  const size_t lineStart = end == std::string::npos ? 0 : tail.find_last_of('\n', end);
  const std::string last =
      end == std::string::npos
          ? std::string()
          : tail.substr(lineStart == std::string::npos ? 0 : lineStart + 1,
                        end - (lineStart == std::string::npos ? 0 : lineStart + 1) + 1);
  if (last.size() < 73 || last[72] != 'T')
  {
    throw errorAbout(path, "the IGES file is cut short (no terminate section at its end)");
  }
}

// A STEP file names each entity instance once (ISO 10303-21) and refers only to instances it
// names. OpenCASCADE 7.6 takes the last of two instances of one name, and leaves a reference to
// a name that is not there empty; its geometry translation checks neither the type nor the
// presence of what a reference gives: a LINE whose point is a LINE, or an AXIS2_PLACEMENT_3D
// whose point is missing, crashes it in StepToGeom::MakeCartesianPoint (fuzz_step;
// tests/data/fuzz/step). So a file that names an instance twice, or refers to one it does not
// name, is refused first. An instance's name is a "#N =" at the start of a line or after a ';';
// any other "#N" is a reference, except inside comments (/* ... */) and strings ('...', taken
// to end at the end of their line, so that a quote left open, which OpenCASCADE gets over, hides
// no more than its line). A reference of the wrong type is not caught here: that crash is left
// to the reader program's process (docs/RELIABILITY.md).
void checkStepInstances(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::set<std::string> names;
  std::vector<std::string> references;
  bool statementStart = true;
  size_t i = 0;
  auto isDigit = [&text](size_t k)
  { return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k])); };
  while (i < text.size())
  {
    const char c = text[i];
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '*')
    {
      const size_t close = text.find("*/", i + 2);
      i = close == std::string::npos ? text.size() : close + 2;
      continue;
    }
    if (c == ';' || c == '\n')
    {
      statementStart = true;
      ++i;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c)))
    {
      ++i;
      continue;
    }
    if (c == '\'')
    {
      const size_t close = text.find_first_of("'\n", i + 1); // '' reads as two strings
      i = close == std::string::npos ? text.size() : text[close] == '\'' ? close + 1 : close;
      statementStart = false;
      continue;
    }
    if (c == '#' && isDigit(i + 1))
    {
      size_t end = i + 1;
      while (isDigit(end))
      {
        ++end;
      }
      const std::string name = text.substr(i + 1, end - i - 1);
      size_t equals = end;
      while (equals < text.size() && std::isspace(static_cast<unsigned char>(text[equals])))
      {
        ++equals;
      }
      if (statementStart && equals < text.size() && text[equals] == '=')
      {
        if (!names.insert(name).second)
        {
          throw errorAbout(path, "the STEP file names entity #" + name + " twice");
        }
      }
      else
      {
        references.push_back(name);
      }
      i = end;
      statementStart = false;
      continue;
    }
    statementStart = false;
    ++i;
  }
  for (const std::string& name : references)
  {
    if (names.count(name) == 0)
    {
      throw errorAbout(path, "the STEP file refers to entity #" + name + ", which it does not name");
    }
  }
}

const char* statusText(IFSelect_ReturnStatus status)
{
  switch (status)
  {
  case IFSelect_RetVoid:
    return "holds nothing OpenCASCADE can read";
  case IFSelect_RetError:
    return "is malformed (OpenCASCADE reports an error in its structure)";
  case IFSelect_RetFail:
    return "could not be read (OpenCASCADE's reader failed)";
  case IFSelect_RetStop:
    return "reading was stopped";
  case IFSelect_RetDone:
    break;
  }
  return "could not be read";
}

// An XCAF document of the application's, closed when this goes: its labels and attributes hold
// handles to each other, so a document left open is never freed (a leak per file read, which
// fuzz_step and fuzz_iges found; the reader program reads one file, a harness many).
class OpenDocument
{
public:
  OpenDocument()
  {
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document_);
  }
  ~OpenDocument()
  {
    try
    {
      XCAFApp_Application::GetApplication()->Close(document_);
    }
    catch (const Standard_Failure&)
    {
    }
  }
  OpenDocument(const OpenDocument&) = delete;
  OpenDocument& operator=(const OpenDocument&) = delete;
  const Handle(TDocStd_Document)& get() const { return document_; }

private:
  Handle(TDocStd_Document) document_;
};

// Reads the file into DOCUMENT.
void readDocument(Handle(TDocStd_Document) document, const std::string& path,
                  const std::string& ext)
{
  const std::string kind = isStep(ext) ? "STEP" : "IGES";
  IFSelect_ReturnStatus status = IFSelect_RetFail;
  bool transferred = false;
  if (isStep(ext))
  {
    STEPCAFControl_Reader reader;
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    reader.SetLayerMode(false);
    status = reader.ReadFile(path.c_str());
    transferred = status == IFSelect_RetDone && reader.Transfer(document);
  }
  else
  {
    IGESCAFControl_Reader reader;
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    reader.SetLayerMode(false);
    status = reader.ReadFile(path.c_str());
    transferred = status == IFSelect_RetDone && reader.Transfer(document);
  }
  if (status != IFSelect_RetDone)
  {
    throw errorAbout(path, "the " + kind + " file " + statusText(status));
  }
  if (!transferred)
  {
    throw errorAbout(path, "no shape of the " + kind + " file could be transferred");
  }
}

struct Leaf
{
  std::string name;
  TDF_Label instance; // the component label (null for a free shape that is a part)
  TDF_Label product;  // the part's own label
  TopLoc_Location placement;
};

// Depth first through the assembly tree under LABEL (a free shape or a component).
void collectLeaves(const TDF_Label& label, const std::string& parentName,
                   const TopLoc_Location& parentPlacement, std::vector<Leaf>& leaves, int depth)
{
  constexpr int kMaxDepth = 64; // an assembly that refers to itself must not recurse forever
  if (depth > kMaxDepth)
  {
    return;
  }
  TDF_Label product = label;
  TopLoc_Location placement = parentPlacement;
  TDF_Label instance;
  if (XCAFDoc_ShapeTool::IsReference(label))
  {
    instance = label;
    XCAFDoc_ShapeTool::GetReferredShape(label, product);
    placement = parentPlacement * XCAFDoc_ShapeTool::GetLocation(label);
  }
  std::string own = labelName(instance);
  if (own.empty())
  {
    own = labelName(product);
  }
  const std::string name = parentName.empty() ? own
                           : own.empty()      ? parentName
                                              : parentName + "/" + own;
  if (XCAFDoc_ShapeTool::IsAssembly(product))
  {
    TDF_LabelSequence components;
    XCAFDoc_ShapeTool::GetComponents(product, components, false);
    for (TDF_LabelSequence::Iterator it(components); it.More(); it.Next())
    {
      collectLeaves(it.Value(), name, placement, leaves, depth + 1);
    }
    return;
  }
  leaves.push_back({name, instance, product, placement});
}

struct Vec
{
  double x = 0.0, y = 0.0, z = 0.0;
};

Vec vecOf(const gp_XYZ& v)
{
  return {v.X(), v.Y(), v.Z()};
}

double dot(const Vec& a, const Vec& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

Vec scaled(const Vec& a, double s)
{
  return {a.x * s, a.y * s, a.z * s};
}

Vec minus(const Vec& a, const Vec& b)
{
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

Vec cross(const Vec& a, const Vec& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// D made orthogonal to the unit N and unit; zero where nothing of it is left (a pole, where the
// derivative vanishes, or a derivative along the normal).
Vec tangentIn(const Vec& d, const Vec& n)
{
  const double length = std::sqrt(dot(d, d));
  const Vec t = minus(d, scaled(n, dot(d, n)));
  const double tLength = std::sqrt(dot(t, t));
  if (!(length > 0.0) || !(tLength > 1e-6 * length) || !std::isfinite(tLength))
  {
    return {};
  }
  return scaled(t, 1.0 / tLength);
}

// The colour of each face of a product (indexed as TopExp::MapShapes numbers them, from 1): its
// own (a sub-shape label of the product with a colour: a face, or a shell or solid holding it),
// else the product's.
std::vector<std::optional<Quantity_Color>> faceColours(const Handle(XCAFDoc_ColorTool) & colours,
                                                       const TDF_Label& product,
                                                       const TopTools_IndexedMapOfShape& faces)
{
  std::vector<std::optional<Quantity_Color>> result(static_cast<size_t>(faces.Extent()) + 1,
                                                    surfaceColour(colours, product));
  TDF_LabelSequence subShapes;
  XCAFDoc_ShapeTool::GetSubShapes(product, subShapes);
  // Larger sub-shapes first, so that a face's own colour wins over its shell's.
  std::vector<std::pair<int, TDF_Label>> ordered;
  for (TDF_LabelSequence::Iterator it(subShapes); it.More(); it.Next())
  {
    const TopoDS_Shape sub = XCAFDoc_ShapeTool::GetShape(it.Value());
    ordered.emplace_back(sub.IsNull() ? 0 : static_cast<int>(sub.ShapeType()), it.Value());
  }
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& entry : ordered)
  {
    const std::optional<Quantity_Color> colour = surfaceColour(colours, entry.second);
    if (!colour)
    {
      continue;
    }
    const TopoDS_Shape sub = XCAFDoc_ShapeTool::GetShape(entry.second);
    for (TopExp_Explorer ex(sub, TopAbs_FACE); ex.More(); ex.Next())
    {
      const int index = faces.FindIndex(ex.Current());
      if (index > 0)
      {
        result[static_cast<size_t>(index)] = colour;
      }
    }
  }
  return result;
}

struct ProductSurface
{
  vtkSmartPointer<vtkPolyData> polyData;
  int faces = 0;
  int failedFaces = 0;
  std::optional<Quantity_Color> colour; // the colour covering most of its area
  int colours = 0;                      // distinct face colours
};

// The product's faces tessellated into one surface with normals and the B-rep tangents.
ProductSurface tessellate(const TopoDS_Shape& shape, const CadReadOptions& options,
                          const std::vector<std::optional<Quantity_Color>>& colourOfFace,
                          const TopTools_IndexedMapOfShape& faceIndex)
{
  ProductSurface result;
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  double linear = options.deflection;
  if (!options.deflectionAbsolute)
  {
    const double diagonal = box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
    linear = options.deflection * (diagonal > 0.0 ? diagonal : 1.0);
  }
  {
    BRepMesh_IncrementalMesh mesher(shape, linear, false, options.angleRadians, false);
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tangentsU;
  tangentsU->SetName(kBRepTangentUArray);
  tangentsU->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tangentsV;
  tangentsV->SetName(kBRepTangentVArray);
  tangentsV->SetNumberOfComponents(3);
  std::map<std::array<double, 3>, double> areaOfColour;

  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next())
  {
    ++result.faces;
    const TopoDS_Face& face = TopoDS::Face(ex.Current());
    TopLoc_Location location;
    const Handle(Poly_Triangulation)& triangulation = BRep_Tool::Triangulation(face, location);
    if (triangulation.IsNull() || triangulation->NbTriangles() == 0 ||
        triangulation->NbNodes() == 0)
    {
      ++result.failedFaces;
      continue;
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    const gp_Trsf trsf = location.Transformation();
    const int nodes = triangulation->NbNodes();
    const vtkIdType base = points->GetNumberOfPoints();
    std::vector<Vec> position(static_cast<size_t>(nodes) + 1);
    for (int i = 1; i <= nodes; ++i)
    {
      position[static_cast<size_t>(i)] = vecOf(triangulation->Node(i).Transformed(trsf).XYZ());
    }
    // The triangles' normals at their corners: the normal where the surface has none.
    std::vector<Vec> triangleNormals(static_cast<size_t>(nodes) + 1);
    double area = 0.0;
    for (int t = 1; t <= triangulation->NbTriangles(); ++t)
    {
      int a = 0, b = 0, c = 0;
      triangulation->Triangle(t).Get(a, b, c);
      if (reversed)
      {
        std::swap(b, c);
      }
      if (a < 1 || b < 1 || c < 1 || a > nodes || b > nodes || c > nodes)
      {
        continue;
      }
      const vtkIdType ids[3] = {base + a - 1, base + b - 1, base + c - 1};
      triangles->InsertNextCell(3, ids);
      const Vec& p = position[static_cast<size_t>(a)];
      const Vec weighted = cross(minus(position[static_cast<size_t>(b)], p),
                                 minus(position[static_cast<size_t>(c)], p));
      area += 0.5 * std::sqrt(dot(weighted, weighted));
      for (int id : {a, b, c})
      {
        Vec& sum = triangleNormals[static_cast<size_t>(id)];
        sum = {sum.x + weighted.x, sum.y + weighted.y, sum.z + weighted.z};
      }
    }
    const int index = faceIndex.FindIndex(face);
    if (index > 0 && colourOfFace[static_cast<size_t>(index)])
    {
      const Quantity_Color& colour = *colourOfFace[static_cast<size_t>(index)];
      areaOfColour[{colour.Red(), colour.Green(), colour.Blue()}] += area;
    }

    BRepAdaptor_Surface surface(face, false);
    const bool hasUv = triangulation->HasUVNodes();
    for (int i = 1; i <= nodes; ++i)
    {
      const Vec& p = position[static_cast<size_t>(i)];
      points->InsertNextPoint(p.x, p.y, p.z);
      Vec n;
      Vec du;
      Vec dv;
      bool surfaceNormal = false;
      if (hasUv)
      {
        const gp_Pnt2d uv = triangulation->UVNode(i);
        BRepLProp_SLProps props(surface, uv.X(), uv.Y(), 1, 1e-9);
        du = vecOf(props.D1U().XYZ());
        dv = vecOf(props.D1V().XYZ());
        if (props.IsNormalDefined())
        {
          n = vecOf(props.Normal().XYZ());
          n = reversed ? scaled(n, -1.0) : n;
          surfaceNormal = true;
        }
      }
      if (!surfaceNormal)
      {
        const Vec& sum = triangleNormals[static_cast<size_t>(i)];
        const double length = std::sqrt(dot(sum, sum));
        n = length > 0.0 ? scaled(sum, 1.0 / length) : Vec{};
      }
      const Vec tu = tangentIn(du, n);
      const Vec tv = tangentIn(reversed ? scaled(dv, -1.0) : dv, n);
      normals->InsertNextTuple3(n.x, n.y, n.z);
      tangentsU->InsertNextTuple3(tu.x, tu.y, tu.z);
      tangentsV->InsertNextTuple3(tv.x, tv.y, tv.z);
    }
  }
  double largest = 0.0;
  for (const auto& entry : areaOfColour)
  {
    if (!result.colour || entry.second > largest)
    {
      largest = entry.second;
      result.colour =
          Quantity_Color(entry.first[0], entry.first[1], entry.first[2], Quantity_TOC_RGB);
    }
  }
  result.colours = static_cast<int>(areaOfColour.size());
  result.polyData = vtkSmartPointer<vtkPolyData>::New();
  result.polyData->SetPoints(points);
  result.polyData->SetPolys(triangles);
  result.polyData->GetPointData()->SetNormals(normals);
  result.polyData->GetPointData()->AddArray(tangentsU);
  result.polyData->GetPointData()->AddArray(tangentsV);
  return result;
}

// A painted finish of COLOUR: a dielectric coat over a diffuse base of that colour.
std::string paintMaterial(const Quantity_Color& colour, const std::string& stem)
{
  const std::string hex = Quantity_Color::ColorToHex(colour).ToCString();
  Material material = defaultMaterial(stem + " paint " + hex);
  auto unit = [](double v) { return std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0); };
  material.values["f0"] = colorValue(0.04, 0.04, 0.04);
  material.values["albedo"] =
      colorValue(unit(colour.Red()), unit(colour.Green()), unit(colour.Blue()));
  MaterialLibrary library;
  library.put(material);
  return materialLibraryToJson(library);
}

std::string labelKey(const TDF_Label& label)
{
  TCollection_AsciiString entry;
  TDF_Tool::Entry(label, entry);
  return entry.ToCString();
}

std::vector<ReaderBlock> readBlocks(const std::string& path, const std::string& ext,
                                    const CadReadOptions& options,
                                    std::vector<std::string>& warnings)
{
  checkComplete(path, ext);
  if (isStep(ext))
  {
    checkStepInstances(path);
  }
  const OpenDocument open;
  const Handle(TDocStd_Document)& document = open.get();
  readDocument(document, path, ext);
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  const Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(document->Main());
  TDF_LabelSequence roots;
  shapes->GetFreeShapes(roots);
  std::vector<Leaf> leaves;
  for (TDF_LabelSequence::Iterator it(roots); it.More(); it.Next())
  {
    collectLeaves(it.Value(), {}, TopLoc_Location(), leaves, 0);
  }
  if (leaves.empty())
  {
    throw errorAbout(path, "the file holds no shape");
  }
  const std::string stem = std::filesystem::path(path).stem().string();
  std::map<std::string, ProductSurface> products;
  std::vector<ReaderBlock> blocks;
  for (const Leaf& leaf : leaves)
  {
    const std::string subject = path + ": part " + (leaf.name.empty() ? stem : leaf.name);
    const std::string key = labelKey(leaf.product);
    auto found = products.find(key);
    if (found == products.end())
    {
      const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(leaf.product);
      TopTools_IndexedMapOfShape faceIndex;
      TopExp::MapShapes(shape, TopAbs_FACE, faceIndex);
      ProductSurface surface =
          tessellate(shape, options, faceColours(colours, leaf.product, faceIndex), faceIndex);
      if (surface.failedFaces > 0 && surface.failedFaces < surface.faces)
      {
        warnings.push_back(subject + ": " + std::to_string(surface.failedFaces) + " of its " +
                           std::to_string(surface.faces) + " faces did not tessellate (left out)");
      }
      found = products.emplace(key, std::move(surface)).first;
    }
    const ProductSurface& surface = found->second;
    if (surface.polyData->GetNumberOfPolys() == 0)
    {
      warnings.push_back(subject + (surface.faces == 0
                                        ? ": has no faces (left out)"
                                        : ": none of its faces tessellated (left out)"));
      continue;
    }
    std::optional<Quantity_Color> colour = surfaceColour(colours, leaf.instance);
    if (!colour && surface.colour)
    {
      colour = surface.colour;
      if (surface.colours > 1)
      {
        warnings.push_back(subject + ": its faces have " + std::to_string(surface.colours) +
                           " colours; it takes " + Quantity_Color::ColorToHex(*colour).ToCString() +
                           ", the one covering most of its area");
      }
    }
    ReaderBlock block(leaf.name, surface.polyData);
    block.placement = matrixOf(leaf.placement);
    if (colour)
    {
      block.material = paintMaterial(*colour, stem);
    }
    blocks.push_back(std::move(block));
  }
  if (blocks.empty())
  {
    throw errorAbout(path, "no face of its " + std::to_string(leaves.size()) +
                               " parts could be tessellated");
  }
  return blocks;
}

double positiveNumber(const std::string& argument, const std::string& value)
{
  char* end = nullptr;
  const double number = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(number) || !(number > 0.0))
  {
    throw Error("aniso-mesh-reader: " + argument + ": not a positive number");
  }
  return number;
}
} // namespace

std::vector<ReaderBlock> readCadBlocks(const std::string& path, const std::string& ext,
                                       const CadReadOptions& options,
                                       std::vector<std::string>& warnings)
{
  try
  {
    return readBlocks(path, ext, options, warnings);
  }
  catch (const Standard_Failure& failure)
  {
    throw errorAbout(path,
                     std::string("OpenCASCADE failed on this file: ") + failure.GetMessageString());
  }
}

vtkSmartPointer<vtkPolyData> readCadSurface(const std::string& path, const std::string& ext,
                                            const CadReadOptions& options,
                                            std::vector<std::string>& warnings)
{
  const std::vector<ReaderBlock> blocks = readCadBlocks(path, ext, options, warnings);
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tangentsU;
  tangentsU->SetName(kBRepTangentUArray);
  tangentsU->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tangentsV;
  tangentsV->SetName(kBRepTangentVArray);
  tangentsV->SetNumberOfComponents(3);
  for (const ReaderBlock& block : blocks)
  {
    const PartMatrix& m = block.placement;
    // Directions by the linear part; normals by its inverse transpose (the cofactor matrix,
    // whose scale the normalisation removes).
    auto linear = [&m](const double* v) -> Vec
    {
      return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[4] * v[0] + m[5] * v[1] + m[6] * v[2],
              m[8] * v[0] + m[9] * v[1] + m[10] * v[2]};
    };
    const Vec c0 = cross({m[4], m[5], m[6]}, {m[8], m[9], m[10]});
    const Vec c1 = cross({m[8], m[9], m[10]}, {m[0], m[1], m[2]});
    const Vec c2 = cross({m[0], m[1], m[2]}, {m[4], m[5], m[6]});
    const double det = dot({m[0], m[1], m[2]}, c0);
    auto unit = [](const Vec& v) -> Vec
    {
      const double length = std::sqrt(dot(v, v));
      return length > 0.0 ? scaled(v, 1.0 / length) : Vec{};
    };
    vtkPolyData* part = block.polyData;
    vtkPointData* pd = part->GetPointData();
    vtkDataArray* n = pd->GetNormals();
    vtkDataArray* u = pd->GetArray(kBRepTangentUArray);
    vtkDataArray* v = pd->GetArray(kBRepTangentVArray);
    const vtkIdType base = points->GetNumberOfPoints();
    for (vtkIdType i = 0; i < part->GetNumberOfPoints(); ++i)
    {
      double p[3];
      part->GetPoint(i, p);
      const Vec q = linear(p);
      points->InsertNextPoint(q.x + m[3], q.y + m[7], q.z + m[11]);
      double t[3];
      n->GetTuple(i, t);
      Vec placed = {c0.x * t[0] + c1.x * t[1] + c2.x * t[2],
                    c0.y * t[0] + c1.y * t[1] + c2.y * t[2],
                    c0.z * t[0] + c1.z * t[1] + c2.z * t[2]};
      placed = unit(det < 0.0 ? scaled(placed, -1.0) : placed);
      normals->InsertNextTuple3(placed.x, placed.y, placed.z);
      u->GetTuple(i, t);
      placed = unit(linear(t));
      tangentsU->InsertNextTuple3(placed.x, placed.y, placed.z);
      v->GetTuple(i, t);
      placed = unit(linear(t));
      tangentsV->InsertNextTuple3(placed.x, placed.y, placed.z);
    }
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    vtkCellArray* polys = part->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
    {
      vtkIdType moved[3] = {base + ids[0], base + ids[1], base + ids[2]};
      if (det < 0.0)
      {
        std::swap(moved[1], moved[2]); // a mirroring placement turns the winding round
      }
      triangles->InsertNextCell(3, moved);
    }
  }
  merged->SetPoints(points);
  merged->SetPolys(triangles);
  merged->GetPointData()->SetNormals(normals);
  merged->GetPointData()->AddArray(tangentsU);
  merged->GetPointData()->AddArray(tangentsV);
  return merged;
}

CadReadOptions parseCadArguments(const std::vector<std::string>& arguments)
{
  CadReadOptions options;
  for (const std::string& argument : arguments)
  {
    const size_t equals = argument.find('=');
    if (equals == std::string::npos)
    {
      continue;
    }
    const std::string key = argument.substr(0, equals);
    const std::string value = argument.substr(equals + 1);
    if (key == kCadRelativeDeflectionKey)
    {
      options.deflection = positiveNumber(argument, value);
      options.deflectionAbsolute = false;
    }
    else if (key == kCadAbsoluteDeflectionKey)
    {
      options.deflection = positiveNumber(argument, value);
      options.deflectionAbsolute = true;
    }
    else if (key == kCadAngleKey)
    {
      options.angleRadians = positiveNumber(argument, value) * 3.14159265358979323846 / 180.0;
    }
  }
  return options;
}
} // namespace aniso
