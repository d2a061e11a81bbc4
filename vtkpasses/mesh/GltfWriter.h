#pragma once
// A scene of parts written as glTF 2.0 (.gltf with its buffer embedded as a data: URI, or .glb)
// through tinygltf's writer, each part's material as metallic-roughness with
// KHR_materials_anisotropy (and KHR_materials_specular where F0 is no dielectric's 0.04 over a
// diffuse albedo): core/models/gltf_material.h's asToGltf, the inverse of what GltfReader reads,
// so reading the file back gives the parts' n_u, n_v, F0 and albedo again. Written: per part a
// node (named by the part, its placement turned back to Y-up as its matrix) with a mesh of one
// triangle primitive (POSITION, NORMAL from "Normals", TANGENT from "Tangents" with w = 1,
// TEXCOORD_0 with v -> 1 - v; polygons fanned into triangles, lines and points left out); one
// glTF material per library material, named by it. Not written: the maps (the material's
// textures), a data field that varies the material across the surface (partsWithFields names
// the parts that have one, so that the writer's callers can say so), the scene's lighting and
// camera.
#include "core/parameters/material_library.h"
#include "core/placement.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace aniso
{
struct GltfPart
{
  std::string name;
  vtkPolyData* polyData = nullptr; // in the part's own frame, Z-up
  Material material;
  PartMatrix placement = kIdentityPlacement;
};

// Throws aniso::Error "PATH: reason" when the file cannot be written or a part has no surface.
// The extension picks the container: ".glb" binary, else JSON text.
void writeGltfScene(const std::string& path, const std::vector<GltfPart>& parts);

// The parts whose material has a field ("field" other than none): written without it.
std::vector<std::string> partsWithFields(const std::vector<GltfPart>& parts);
} // namespace aniso
