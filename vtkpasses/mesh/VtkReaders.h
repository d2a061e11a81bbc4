#pragma once
// The formats VTK's own readers read: .obj (vtkOBJReader), .vtp (XML polydata), .vtk (legacy, any
// dataset: non-polygonal ones reduced to their outer surface) and .gltf/.glb (vtkGLTFReader:
// every mesh of the default scene with its node transforms applied, merged, turned from glTF's
// Y-up into the Z-up world and its texture origin to the bottom left, as Blender's importer
// does). These readers are not hardened against hostile files (VTK 9.1's legacy reader crashes
// on truncated input, for one), so only the mesh reader program (aniso-mesh-reader,
// MeshReaderProcess.h) runs them, never the application. Errors are aniso::Error "PATH: reason"
// with the reader's own words (what it printed, in CAPTURE).
#include "vtkpasses/mesh/VtkErrorText.h"

#include <string>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
// EXT is the lower-case extension, one of the four above.
vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path, const std::string& ext,
                                         const VtkMessageCapture& capture);
} // namespace aniso
