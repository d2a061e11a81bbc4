#pragma once
// Loading a surface mesh file into the triangle surface the renderer draws.
//
// Formats, chosen by the file extension (case-insensitive):
//   .obj (vtkOBJReader), .ply (PlyReader), .stl (StlReader), .off (OffReader), .vtk (legacy, any
//   dataset: non-polygonal ones are reduced to their outer surface), .vtp (XML polydata),
//   .gltf/.glb (vtkGLTFReader: every mesh of the default scene with its node transforms
//   applied, merged into one polydata). PLY, STL and OFF have their own readers: VTK has none
//   for OFF, and its PLY and STL readers are not safe on hostile files.
// glTF is Y-up by specification; the loader turns it into the Z-up world the way Blender's
// importer does, (x, y, z) -> (x, -z, y), normals and tangents included; its texture origin is
// the image's top left, so v becomes 1 - v (VTK's origin is the bottom left), as in Blender.
//
// The result then goes through sanitizeSurface() (MeshValidation.h): triangles only, no NaN, no
// zero-area faces, exact duplicates merged, and float "Normals"/"TCoords"/"Tangents" arrays when
// the file had them. Normals and tangents that are missing are made by SurfacePreparation.h.
//
// Errors are aniso::Error "PATH: reason": missing or unreadable file, empty file, unknown
// extension, whatever the reader reported (VTK's error and warning output is captured while
// reading, so nothing is printed; warnings end up in MeshReport::readerWarnings), no faces left.
// vtkOBJReader parses numbers with an input stream that turns "nan", "inf" and values beyond the
// float range into finite ones without a word; the loader checks the OBJ's own v, vt and vn lines
// so that such entries count as NaN vertices, texture coordinates and normals, as in the other
// formats. OBJ positions are stored as float by that reader (the other readers keep doubles).
// Hostile input (truncated, garbage, out-of-range indices) gives an error or a smaller mesh,
// never a crash: VTK's readers (OBJ, VTK, VTP, glTF) run in a program of their own,
// aniso-mesh-reader, started for each file (posix_spawn, never a fork of this process;
// MeshReaderProcess.h), with a memory limit and a time limit, which hands the surface back as
// VTK XML; a crash there becomes "PATH: the reader crashed on this file ...". loadMesh serialises itself, since
// VTK's message output is process-wide; while it runs, VTK messages from other threads are
// captured too, so call it where no rendering runs concurrently (the GUI thread does).
#include "vtkpasses/mesh/MeshValidation.h"

#include <string>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
struct LoadedMesh
{
  vtkSmartPointer<vtkPolyData> polyData; // triangles, see MeshValidation.h for its arrays
  MeshReport report;
};

LoadedMesh loadMesh(const std::string& path);

// The extensions loadMesh accepts, for help texts and file dialogs: "*.obj *.ply ...".
std::string meshFilePatterns();
} // namespace aniso
