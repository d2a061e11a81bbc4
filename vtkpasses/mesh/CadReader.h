#pragma once
// STEP (.step, .stp) and IGES (.iges, .igs) files through OpenCASCADE's XCAF readers
// (STEPCAFControl_Reader, IGESCAFControl_Reader into an XCAF document). OpenCASCADE is not
// hardened against hostile files, so only the reader program (aniso-mesh-reader,
// MeshReaderProcess.h) links and runs this, never the application.
//
// What a file gives (readCadBlocks):
//   - one block per leaf instance of the assembly tree (free shapes, their components, depth
//     first): a product placed twice is two blocks, each with the product's surface in the
//     product's own frame and the instance's placement (the locations from the root down,
//     multiplied) in ReaderBlock::placement;
//   - names joined by "/" from the top, each level named by its instance's name, else by its
//     product's ("assembly/sub/bolt"), as a .vtm's levels are;
//   - a colour, when the file gives one: the instance's surface colour (XCAFDoc_ColorSurf, else
//     XCAFDoc_ColorGen), else the colours of the product's faces, a face without its own taking
//     the product's. Faces of several colours give the part the colour that covers the largest
//     share of its area, with a warning naming the part (the part is not split by colour). The
//     colour becomes a painted material (ReaderBlock::material): F0 0.04 grey (a dielectric
//     coat), albedo the colour (linear RGB, as OpenCASCADE holds it), named "STEM paint #RRGGBB"
//     (the sRGB hex of the colour), so parts of one colour share it. A part without a colour gets
//     no material (the scene's default).
//   - lengths in the unit OpenCASCADE reads into: millimetres (it converts the file's unit).
//     CAD files are Z-up, as the world is: nothing is turned.
// Surfaces: each product's faces tessellated by BRepMesh_IncrementalMesh with CadReadOptions;
// point normals are the face surface's normal at each node (negated on reversed faces, whose
// triangles are turned round too); where the surface has none (a cone's apex), the mean of the
// node's triangles' normals. Two more point arrays carry the face's parameterisation:
// kBRepTangentUArray (dS/du) and kBRepTangentVArray (dS/dv, negated on a reversed face, so that
// (u, v, n) stays right-handed), each made orthogonal to the node's normal and unit, or zero
// where the derivative vanishes or lies along the normal (a pole). Faces share no nodes: each face
// keeps its own normals and tangents along its edges (the sanitiser merges nothing there, since
// the arrays differ).
// Errors: aniso::Error "PATH: reason" when OpenCASCADE refuses the file (IFSelect_RetFail,
// RetError, RetVoid), when the file is cut short (a STEP file without its closing
// "END-ISO-10303-21;", an IGES file without its terminate section), when nothing transfers, or
// when no face of the file tessellates. A face that does not tessellate is left out with a
// warning "PATH: part NAME: N of its M faces did not tessellate (left out)"; a part none of
// whose faces tessellates is left out with a warning too.
#include "vtkpasses/mesh/MeshReaderProcess.h"

#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
// The point arrays of a CAD part's surface that hold its faces' dS/du and dS/dv (float, 3).
inline constexpr const char* kBRepTangentUArray = "BRepTangentU";
inline constexpr const char* kBRepTangentVArray = "BRepTangentV";

// How the faces are tessellated.
struct CadReadOptions
{
  // The largest distance of a triangle from the surface (BRepMesh's linear deflection): when
  // deflectionAbsolute, in millimetres; else a fraction of the part's bounding-box diagonal.
  double deflection = 0.001;
  bool deflectionAbsolute = false;
  // The largest angle between the normals along one triangle edge (angular deflection), radians.
  double angleRadians = 20.0 * 3.14159265358979323846 / 180.0;
};

// The lower-case extensions this reader takes: ".step", ".stp", ".iges", ".igs".
inline bool isCadExtension(const std::string& ext)
{
  return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

// The file's leaf instances as above, in tree order; WARNINGS gets what was left out.
std::vector<ReaderBlock> readCadBlocks(const std::string& path, const std::string& ext,
                                       const CadReadOptions& options,
                                       std::vector<std::string>& warnings);

// The whole file as one surface (what loadMesh draws): the blocks above merged, each where its
// placement puts it (points, normals and B-rep tangents moved with it).
vtkSmartPointer<vtkPolyData> readCadSurface(const std::string& path, const std::string& ext,
                                            const CadReadOptions& options,
                                            std::vector<std::string>& warnings);

// The reader program's arguments that carry CadReadOptions (after PATH EXT FILE_SIZE and
// "blocks", MeshReaderProcess.h), as KEY=VALUE: the relative or the absolute deflection, and the
// angle in degrees. MeshLoader writes them from MeshReadOptions.
inline constexpr const char* kCadRelativeDeflectionKey = "cad-deflection";
inline constexpr const char* kCadAbsoluteDeflectionKey = "cad-deflection-mm";
inline constexpr const char* kCadAngleKey = "cad-angle";
// Reads them (others are ignored); throws aniso::Error "aniso-mesh-reader: reason" for a value
// that is no positive finite number.
CadReadOptions parseCadArguments(const std::vector<std::string>& arguments);
} // namespace aniso
