#pragma once
// glTF files built in code and written by tinygltf's own writer (an independent writer) for the
// tests of the glTF reader and of `aniso render` on glTF scenes.
#include <array>
#include <cstring>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <tiny_gltf.h>
#include <vector>

namespace aniso::test
{
// A float accessor of TYPE over VALUES in MODEL's first buffer.
inline int accessor(tinygltf::Model& model, const std::vector<float>& values, int type,
                    int components)
{
  if (model.buffers.empty())
  {
    model.buffers.emplace_back();
  }
  std::vector<unsigned char>& data = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = values.size() * sizeof(float);
  data.resize(data.size() + view.byteLength);
  std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
  model.bufferViews.push_back(view);
  tinygltf::Accessor a;
  a.bufferView = int(model.bufferViews.size()) - 1;
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.count = values.size() / size_t(components);
  a.type = type;
  if (type == TINYGLTF_TYPE_VEC3)
  {
    a.minValues = {-1e9, -1e9, -1e9};
    a.maxValues = {1e9, 1e9, 1e9};
  }
  model.accessors.push_back(a);
  return int(model.accessors.size()) - 1;
}

// A metallic-roughness material; with STRENGTH, KHR_materials_anisotropy of that strength and
// ROTATION (and the extension listed as used by MODEL).
inline tinygltf::Material metallicRoughness(tinygltf::Model& model, const std::string& name,
                                            const std::array<double, 3>& baseColor, double metallic,
                                            double roughness, double strength = -1.0,
                                            double rotation = 0.0)
{
  tinygltf::Material material;
  material.name = name;
  material.pbrMetallicRoughness.baseColorFactor = {baseColor[0], baseColor[1], baseColor[2], 1.0};
  material.pbrMetallicRoughness.metallicFactor = metallic;
  material.pbrMetallicRoughness.roughnessFactor = roughness;
  if (strength >= 0.0)
  {
    tinygltf::Value::Object anisotropy;
    anisotropy["anisotropyStrength"] = tinygltf::Value(strength);
    anisotropy["anisotropyRotation"] = tinygltf::Value(rotation);
    material.extensions["KHR_materials_anisotropy"] = tinygltf::Value(anisotropy);
    if (model.extensionsUsed.empty())
    {
      model.extensionsUsed.push_back("KHR_materials_anisotropy");
    }
  }
  return material;
}

// A new mesh NAME of one triangle primitive (non-indexed) of MATERIAL: POSITION, NORMAL,
// TANGENT (xyzw) and, when UVS is not empty, TEXCOORD_0.
inline int triangleMesh(tinygltf::Model& model, const std::string& name, int material,
                        const std::vector<float>& positions, const std::vector<float>& normals,
                        const std::vector<float>& tangents, const std::vector<float>& uvs)
{
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = material;
  primitive.attributes["POSITION"] = accessor(model, positions, TINYGLTF_TYPE_VEC3, 3);
  primitive.attributes["NORMAL"] = accessor(model, normals, TINYGLTF_TYPE_VEC3, 3);
  primitive.attributes["TANGENT"] = accessor(model, tangents, TINYGLTF_TYPE_VEC4, 4);
  if (!uvs.empty())
  {
    primitive.attributes["TEXCOORD_0"] = accessor(model, uvs, TINYGLTF_TYPE_VEC2, 2);
  }
  tinygltf::Mesh mesh;
  mesh.name = name;
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);
  return int(model.meshes.size()) - 1;
}

// A square in glTF's XZ plane ([-1, 1]^2, facing +Y), non-indexed triangles, with NORMAL +Y,
// TANGENT (w 1) and, with TEXCOORDS, TEXCOORD_0 u = (x + 1) / 2, v = (z + 1) / 2, as the
// primitive of a new mesh of MATERIAL.
inline int squareMesh(tinygltf::Model& model, const std::string& name, int material,
                      const std::array<float, 3>& tangent = {0, 0, 1}, bool texcoords = true)
{
  const float p[6][3] = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
  std::vector<float> positions;
  std::vector<float> normals;
  std::vector<float> tangents;
  std::vector<float> uvs;
  for (const auto& q : p)
  {
    positions.insert(positions.end(), {q[0], q[1], q[2]});
    normals.insert(normals.end(), {0, 1, 0});
    tangents.insert(tangents.end(), {tangent[0], tangent[1], tangent[2], 1});
    if (texcoords)
    {
      uvs.insert(uvs.end(), {(q[0] + 1) / 2, (q[2] + 1) / 2});
    }
  }
  return triangleMesh(model, name, material, positions, normals, tangents, uvs);
}

// MODEL as FILE: binary for .glb, else JSON with its buffers and images embedded.
inline void writeModel(const tinygltf::Model& model, const std::string& file)
{
  tinygltf::TinyGLTF writer;
  const bool binary = std::filesystem::path(file).extension() == ".glb";
  ASSERT_TRUE(writer.WriteGltfSceneToFile(&model, file, true, true, !binary, binary)) << file;
}
} // namespace aniso::test
