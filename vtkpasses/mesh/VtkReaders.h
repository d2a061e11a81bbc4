#pragma once
// The formats VTK's own readers read: .obj (vtkOBJReader), .vtp (XML polydata), .vtk (legacy, any
// dataset: non-polygonal ones reduced to their outer surface), .vtu (XML unstructured grid: its
// outer surface, vtkDataSetSurfaceFilter, with the grid's point and cell arrays), .vtm (vtkXMLMultiBlockDataReader:
// every leaf dataset, non-polygonal ones reduced to their outer surface like .vtk) and
// .gltf/.glb (GltfReader.h, through tinygltf: parts with their materials and placements). These
// readers are not hardened against hostile files (VTK 9.1's
// legacy reader crashes on truncated input, for one), so only the mesh reader program
// (aniso-mesh-reader, MeshReaderProcess.h) runs them, never the application. Errors are
// aniso::Error "PATH: reason" with the reader's own words (what it printed, in CAPTURE).
#include "vtkpasses/mesh/MeshReaderProcess.h"
#include "vtkpasses/mesh/VtkErrorText.h"

#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
// The whole file as one surface (what loadMesh draws): a .vtm's leaves and a glTF's meshes
// merged. EXT is the lower-case extension, one of those above.
vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path, const std::string& ext,
                                         const VtkMessageCapture& capture);

// The file as its parts (what loadMeshBlocks returns), in file order, each named as the file
// names it (ReaderBlock, MeshReaderProcess.h: empty when the file has no name for it, repeats
// left to the loader) and unsanitised:
//   .obj: one block per g or o statement that is followed by a face, line or point statement
//     before the next g or o, named by the statement's words; faces before any g or o make a
//     block without a name. Each block holds the vertices its cells use, with their attributes.
//     vtkOBJReader keeps one cell per f, l and p statement, in file order, except that it drops
//     the faces without normals when other faces have normals and it has to duplicate vertices;
//     when its cells cannot be matched to the statements so, the file is one block and WARNINGS
//     says why. A g/o statement's cells that use several materials (usemtl) are one block per
//     material, named "GROUP/MATERIAL"; each block's material is the ReaderBlock::material
//     document of its usemtl material from the mtllib libraries (MeshLoader.h), and what went
//     wrong with them is in WARNINGS.
//   .vtm: one block per leaf of the composite tree, depth first, named by the NAME metadata of
//     each level from the top joined by "/" ("outer/inner"); a level without a name is
//     "block I", I its index among its siblings (the file's index attribute). An empty leaf is a
//     block without cells.
//   .gltf/.glb: GltfReader.h's readGltfBlocks (one block per mesh node and material, in the
//     mesh's frame, with its material and placement).
//   .vtk, .vtp: one block without a name.
std::vector<ReaderBlock> readBlocksWithVtk(const std::string& path, const std::string& ext,
                                           const VtkMessageCapture& capture,
                                           std::vector<std::string>& warnings);
} // namespace aniso
