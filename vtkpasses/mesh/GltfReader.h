#pragma once
// glTF 2.0 (.gltf with its buffers and images, data: URIs, .glb) through tinygltf, read in the
// mesh reader program only (aniso-mesh-reader, MeshReaderProcess.h: tinygltf is not hardened
// against hostile files). What is read and how materials map is in docs/FORMATS.md, "glTF 2.0";
// the mapping itself is core/models/gltf_material.h.
//
// Parts: one per node of the default scene (the first scene when none is named default; the
// root nodes when the file has no scene) that instances a mesh, depth first in the scene's
// order, named by the node, else its mesh, else "node I" (I the node's index). The mesh's
// triangle primitives (strips and fans triangulated; points and lines left out with a warning)
// of one material are merged; when the mesh's primitives have different materials, each
// material's primitives are a part of their own, "NAME/primitive I" (I the first of them).
// Geometry: POSITION, NORMAL, TANGENT (its xyz; the handedness w is not kept) and TEXCOORD_0,
// turned from glTF's Y-up to the Z-up world by (x, y, z) -> (x, -z, y) and the texture origin to
// the bottom left (v -> 1 - v), as Blender's importer does; the texture transform
// (KHR_texture_transform) of the material's textures applied to TEXCOORD_0 before that. The
// surface stays in the mesh's frame and the node's world transform (parents' composed, TRS or
// matrix) is ReaderBlock::placement, turned Z-up too (C W C^-1). Custom attributes, whose names
// begin with "_" (a scalar or a vector of 2 to 4 floats or normalised integers), become point
// arrays of that name when every primitive of the part has them; 3-component ones are
// directions, turned Z-up with the geometry like TANGENT.
// Materials: ReaderBlock::material, one library material per glTF material, named by it, else
// "material I". A constant anisotropyRotation left after gltfToAs' swap turns the tangent
// through a 1x1 TPR map; on a part without TEXCOORD_0 (no map can be sampled there) the part's
// TANGENTs are turned about its NORMALs at load instead and its material has no map. Texture images
// (files, data: URIs, .glb buffer views) are copied into defaultCacheDirectory()/gltf
// (core/lut/lut_cache.h; the system's temporary directory when there is none) under the hash of
// their bytes; maps derived from them (linear albedo, metalness, TPR) are baked there as EXR, so
// the material names files. A texture that is missing or does not decode gives a warning naming the
// file and the texture, and its map is left out.
#include "vtkpasses/mesh/MeshReaderProcess.h"

#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso
{
// The parts as above. Throws aniso::Error "PATH: reason" for a file that is no glTF (malformed
// JSON, a truncated .glb, a missing or short buffer) or holds no triangles. WARNINGS get
// "PATH: ..." lines for what is left out.
std::vector<ReaderBlock> readGltfBlocks(const std::string& path, std::vector<std::string>& warnings);

// The whole file as one surface (what loadMesh draws): every part placed by its placement and
// merged.
vtkSmartPointer<vtkPolyData> readGltfSurface(const std::string& path,
                                             std::vector<std::string>& warnings);
} // namespace aniso
