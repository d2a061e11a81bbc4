#pragma once
// Loading a surface mesh file into the triangle surface the renderer draws.
//
// Formats, chosen by the file extension (case-insensitive):
//   .obj (vtkOBJReader), .ply (PlyReader), .stl (StlReader), .off (OffReader), .vtk (legacy, any
//   dataset: non-polygonal ones are reduced to their outer surface), .vtp (XML polydata), .vtu
//   (XML unstructured grid, vtkXMLUnstructuredGridReader: its outer surface), .vtm
//   (XML multiblock, vtkXMLMultiBlockDataReader: every leaf dataset, non-polygonal ones reduced
//   to their surface like .vtk), .gltf/.glb (tinygltf, GltfReader.h: every mesh of the default
//   scene with its node transforms applied, and its materials), .step/.stp/.iges/.igs (OpenCASCADE, CadReader.h: the
//   assembly's parts tessellated by MeshReadOptions, with the faces' own normals and their
//   parameterisation's tangents; lengths in millimetres). PLY, STL and OFF have their own readers:
//   VTK has none for OFF, and its PLY and STL readers are not safe on hostile files. loadMesh
//   merges a file's parts into one surface; loadMeshBlocks keeps them apart.
// glTF is Y-up by specification; the loader turns it into the Z-up world the way Blender's
// importer does, (x, y, z) -> (x, -z, y), normals and tangents included; its texture origin is
// the image's top left, so v becomes 1 - v (VTK's origin is the bottom left), as in Blender.
//
// The result then goes through sanitizeSurface() (MeshValidation.h): triangles only, no NaN, no
// zero-area faces, exact duplicates merged, and float "Normals"/"TCoords"/"Tangents" arrays when
// the file had them. Normals and tangents that are missing are made by SurfacePreparation.h.
// The file's other point and cell arrays (data fields) are kept (docs/FORMATS.md, "Data arrays").
//
// Errors are aniso::Error "PATH: reason": missing or unreadable file, empty file, unknown
// extension, whatever the reader reported (VTK's error and warning output is captured while
// reading, so nothing is printed; warnings end up in MeshReport::readerWarnings), no faces left.
// vtkOBJReader parses numbers with an input stream that turns "nan", "inf" and values beyond the
// float range into finite ones without a word; the loader checks the OBJ's own v, vt and vn lines
// so that such entries count as NaN vertices, texture coordinates and normals, as in the other
// formats. OBJ positions are stored as float by that reader (the other readers keep doubles).
// Hostile input (truncated, garbage, out-of-range indices) gives an error or a smaller mesh,
// never a crash: VTK's readers (OBJ, VTK, VTP, VTM), tinygltf (glTF) and OpenCASCADE (STEP,
// IGES) run in a program of their own,
// aniso-mesh-reader, started for each file (posix_spawn, never a fork of this process;
// MeshReaderProcess.h), with a memory limit (a .vtm's budget counts the files it names) and a
// time limit, which hands the surface or the parts back as VTK XML; a crash there becomes
// "PATH: the reader crashed on this file ...". loadMesh and loadMeshBlocks serialise themselves,
// since VTK's message output is process-wide; while one runs, VTK messages from other threads
// are captured too, so call them where no rendering runs concurrently (the GUI thread does).
#include "core/parameters/material_library.h"
#include "core/placement.h"
#include "vtkpasses/mesh/MeshValidation.h"

#include <optional>
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
// How far a CAD part's triangles may lie from its surface (BRepMesh's linear deflection): a
// fraction of the part's bounding-box diagonal, or a length in millimetres (absolute). The text
// form: "0.001" (relative) or "0.05mm" (absolute).
struct CadDeflection
{
  double value = 0.001;
  bool absolute = false;
};
// Throws aniso::Error "SUBJECT: reason" unless TEXT is a number in the declared cad-deflection's
// range (core/parameters: 1e-6 to 0.5) or a positive number followed by "mm".
CadDeflection parseCadDeflection(const std::string& text, const std::string& subject);
std::string toString(const CadDeflection& deflection); // parses back to the same

// How files are read. Default-constructed: as they always were (and CAD files at a deflection of
// 0.001 of each part's diagonal and 20 degrees).
struct MeshReadOptions
{
  CadDeflection cadDeflection;
  double cadAngleDegrees = 20.0; // the largest angle between normals along a triangle's edge
};

struct LoadedMesh
{
  vtkSmartPointer<vtkPolyData> polyData; // triangles, see MeshValidation.h for its arrays
  MeshReport report;
};

LoadedMesh loadMesh(const std::string& path, const MeshReadOptions& options = {});

// A file as the parts (blocks) it holds, each with its name, instead of one merged surface:
//   .obj: one part per g or o statement, named by its words (faces before any g or o, or after
//     one without words: named by the file's stem); a statement followed by no face, line or
//     point before the next g or o makes no part. Each part has the vertices its faces use.
//     Materials: the libraries its mtllib statements name (relative to the .obj) are read in
//     the reader program (core/formats/mtl, mapped by core/formats/mtl_material). A group whose
//     faces use one material (usemtl, which holds across g and o until the next usemtl) carries
//     it; a group whose faces use several is one part per material, named "GROUP/MATERIAL"
//     (the material alone outside any named group; the faces before the group's first usemtl
//     keep the group's name, without material). A missing library, a usemtl of a material no
//     library defines, a malformed .mtl line and a missing texture are warnings in the parts'
//     readerWarnings naming the file; the parts load without what failed (docs/FORMATS.md).
//   .vtm: one part per leaf dataset, depth first, named by the NAME metadata of each level from
//     the top joined by "/" ("outer/inner"), "block I" for a level without a name (I its index
//     among its siblings, as in the file's index attributes).
//   .gltf/.glb: one part per node of the default scene that instances a mesh (its primitives
//     merged), with its node transform applied and turned Z-up like loadMesh's, named by the
//     node's name, else its mesh's, else "node I" (I the node's index in the file).
//   .step/.stp/.iges/.igs: one part per leaf instance of the assembly (CadReader.h), named by
//     the instance names (else product names) from the top joined by "/", with its placement
//     and, for a coloured part, a painted material (F0 0.04, albedo the colour).
//   every other format: one part named by the file's stem, exactly loadMesh's result.
// Names are unique within the file: a repeat gets " 2", " 3", ... Each part is sanitised like
// loadMesh's result (MeshValidation.h), with its own report (its source the file's path; what
// the reader printed goes into every part's readerWarnings, since it was about the file; a point
// attribute without one value per vertex is dropped by the reader program and told there, not
// counted in malformedArraysDropped). A part that fails sanitising (no faces left, ...) is
// skipped with the warning "PATH: part NAME: reason"; the others load. Throws aniso::Error
// "PATH: reason" when the file fails as a whole, or when no part is usable (with one part, its
// reason as loadMesh gives it).
// What the file says of a part's finish and place, when it says anything: MATERIAL, when set,
// holds every material key (the file's values mapped onto the Ashikhmin-Shirley material, the
// rest their defaults) under the file's name for it; parts of one file that share a material of
// the file share its name. PLACEMENT goes from the part's own frame (the surface's coordinates)
// to the file's scene (an instance's placement in an assembly). A material or placement the
// reader sent malformed is dropped with a warning "PATH: part NAME: reason".
// Polylines (line cells) are parts of their own in every format that carries them (OBJ's l
// statements, VTK legacy and VTP files' LINES, VTM leaves): a block's lines follow its faces'
// part as the part "NAME lines" (" 2", ... when that name is taken), sanitised by sanitizeLines
// (LineSet.h: tangents along the lines); a block of lines only is that part alone, and a block
// whose lines are all unusable loses them with a warning "PATH: part NAME lines: reason". A
// file of lines only that has none usable throws as loadMesh does ("PATH: reason"). loadMesh
// (one surface) drops lines as before.
struct MeshBlock
{
  std::string name; // unique within the file (suffix " 2", " 3" on repeats)
  LoadedMesh mesh;  // sanitised like loadMesh's result (MeshValidation), with its report
  // True for a line set (LineSet.h): MESH holds polylines with "Tangents" and no faces, drawn
  // as illuminated lines, not prepared as a surface.
  bool lines = false;
  std::optional<Material> material;
  PartMatrix placement = kIdentityPlacement;
};

struct LoadedBlocks
{
  std::vector<MeshBlock> blocks;     // in file order; never empty on success
  std::vector<std::string> warnings; // "PATH: part NAME: reason" for each block skipped
};

LoadedBlocks loadMeshBlocks(const std::string& path, const MeshReadOptions& options = {});

// The extensions loadMesh and loadMeshBlocks accept, for help texts and file dialogs:
// "*.obj *.ply ...".
std::string meshFilePatterns();
} // namespace aniso
