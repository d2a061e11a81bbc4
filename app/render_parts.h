#pragma once
// The scene of parts of `aniso render`: every mesh file given is loaded into parts (one a block
// of the file: loadMeshBlocks' OBJ groups and objects, VTM leaves, glTF mesh nodes; a file of one
// block is one part named by its stem), each drawn with a material: the command line's own (--nu,
// --nv, --f0, ... and its maps) unless --part PATTERN=MATERIAL assigns one of the material library
// (the built-in metals and --materials FILE). --hide PATTERN hides parts; --list-parts prints the
// parts.
#include "app/cli.h"
#include "core/parameters/material_library.h"
#include "core/placement.h"
#include "vtkpasses/mesh/GltfWriter.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/MeshArrays.h"
#include "vtkpasses/mesh/SurfacePreparation.h"
#include "vtkpasses/render/LineStyle.h"
#include "vtkpasses/render/MaterialSettings.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace aniso::cli
{
// Adds --materials, --part, --hide and --list-parts to COMMAND.
void addPartOptions(Command& command);

// A mesh of a file, by the name its part takes, with what the file says of its finish and place
// (MeshBlock::material and ::placement).
struct NamedMesh
{
  std::string name;
  LoadedMesh mesh;
  bool lines = false; // a line set (MeshBlock::lines): drawn as illuminated lines
  std::optional<Material> material;
  PartMatrix placement = kIdentityPlacement;
};

// The meshes of the file at PATH: its blocks (loadMeshBlocks), each named by its block, or the
// file's stem (the file name when it has none) when it has one; WARNINGS, the blocks skipped
// ("PATH: part NAME: reason"). Throws aniso::Error "PATH: reason" as loadMeshBlocks does.
struct FileMeshes
{
  std::vector<NamedMesh> meshes;
  std::vector<std::string> warnings;
};
FileMeshes meshesOfFile(const std::string& path, const MeshReadOptions& options = {});

// NAMES made unique in order: the second "bolt" becomes "bolt 2", the third "bolt 3" (skipping
// names given already).
std::vector<std::string> uniquePartNames(const std::vector<std::string>& names);

// A part of the scene before its surface is prepared.
struct ScenePart
{
  std::string name;
  std::string source; // the file (or builtin:NAME) it came from, for messages
  LoadedMesh mesh;
  bool lines = false; // a line set (MeshBlock::lines): not prepared as a surface, not exported
  const Material* material = nullptr; // of the library; null: the command line's material
  bool visible = true;
  std::optional<Material> fileMaterial; // what the file gives, until adoptFileMaterials
  PartMatrix placement = kIdentityPlacement; // from the part's own frame to the scene
};

// The mesh files PATHS loaded into parts, in order, their names made unique across the files
// (uniquePartNames). A file that fails to load, or a block of a file that cannot be used, is
// skipped with one line "aniso: warning: PATH: reason (skipped)" on WARNINGS; when no file
// loads, the error of the only file, or aniso::Error "PATH1, PATH2: no mesh could be loaded
// (PATH1: reason; ...)".
std::vector<ScenePart> loadParts(const std::vector<std::string>& paths, std::ostream& warnings,
                                 const MeshReadOptions& options = {});

// The materials the files give their parts, added to LIBRARY (MaterialLibrary::adopt: a file's
// material keeps its name unless the library holds another material of that name, a built-in,
// --materials FILE's or another file's, then it becomes "NAME 2", ...) and assigned to those
// parts. Run before assignParts, so --part wins.
void adoptFileMaterials(MaterialLibrary& library, std::vector<ScenePart>& parts);

// The library of the command line: the built-in metals and those of --materials FILE (which win
// over a built-in of the same name). Throws aniso::Error "FILE: reason" for a bad file.
MaterialLibrary partLibrary(const Arguments& arguments);

// Checks --part and --hide against the model (--part only applies to as-env without --compare)
// and every --part's material against LIBRARY: UsageError "--part: ..." naming what is wrong.
void checkPartOptions(const Arguments& arguments, const MaterialLibrary& library);

// Assigns --part's materials (the last matching one wins) and hides --hide's parts. A pattern
// that matches no part is a UsageError naming it; hiding every part is one too.
void assignParts(const Arguments& arguments, const MaterialLibrary& library,
                 std::vector<ScenePart>& parts);

// One line a part: "NAME<TAB>N triangles<TAB>MATERIAL" ("1 triangle"; "N line segments" for a
// line set), with "<TAB>hidden" for a hidden one; the command line's material is
// "(command line)".
void listParts(const std::vector<ScenePart>& parts, std::ostream& out);

// The data arrays of each part's loaded (sanitised) mesh: a line with the part's name ("<TAB>(no
// arrays)" after it when it has none), then one indented line per array (formatArrayInfo,
// vtkpasses/mesh/MeshArrays.h).
void listArrays(const std::vector<ScenePart>& parts, std::ostream& out);

// How a line part is drawn: line-width and line-width-unit of its library material (MATERIAL),
// else of the command line's PARAMETERS.
LineStyle lineStyleOf(const Material* material, const ParameterSet& parameters);

// The surface options of MATERIAL's tangents ("auto": the mesh's own, else from the UVs, else
// axis:1,0,0). Throws aniso::Error "MATERIAL: tangents: reason" for a bad model.
SurfaceOptions surfaceOptionsOf(const Material& material);

// The MaterialSettings of library material MATERIAL: the command line's PARAMETERS with the
// material's values set over its material keys (n_u, n_v, F0, albedo, height scale; the
// scene's samples, method and LUTs stay the command line's), its maps read like the command
// line's (bump "normal": the normal map; "quaternion": the quaternion map, else one baked from
// the normal map; "none": neither). QUALITY, when set, chooses the samples for its lobe (a line
// on OUT says how many). Throws aniso::Error naming the material or the map file.
MaterialSettings librarySettingsOf(const Material& material, const ParameterSet& parameters,
                                   std::optional<double> quality, std::ostream& out);
// The command line's material as a library material named "command line": PARAMETERS' values
// of the material keys (n_u, n_v, F0, albedo, ...; its maps are the command line's options, not
// kept here).
Material materialOfParameters(const ParameterSet& parameters);

// The visible PARTS for writeGltfScene: each its SURFACES[i] (prepared, in the part's own frame),
// placement and material (its library material, else COMMAND_LINE).
std::vector<GltfPart> gltfPartsOf(const std::vector<ScenePart>& parts,
                                  const std::vector<vtkSmartPointer<vtkPolyData>>& surfaces,
                                  const Material& commandLine);
} // namespace aniso::cli
