#include "vtkpasses/mesh/GltfWriter.h"

#include "core/error.h"
#include "core/models/gltf_material.h"
#include "vtkpasses/mesh/GeometryAccess.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <tiny_gltf.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
// The Z-up world back into glTF's Y-up: (x, y, z) -> (x, z, -y), the inverse of the reader's.
glm::dvec3 toYUp(const glm::dvec3& v)
{
  return {v.x, v.z, -v.y};
}

// Appends LENGTH bytes at DATA to the buffer (4-byte aligned) as a buffer view of TARGET, and an
// accessor of COUNT elements of TYPE and COMPONENT_TYPE over it.
int addAccessor(tinygltf::Model& model, const void* data, size_t length, int target, size_t count,
                int type, int componentType)
{
  tinygltf::Buffer& buffer = model.buffers.front();
  while (buffer.data.size() % 4 != 0)
  {
    buffer.data.push_back(0);
  }
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.data.size();
  view.byteLength = length;
  view.target = target;
  const auto* bytes = static_cast<const unsigned char*>(data);
  buffer.data.insert(buffer.data.end(), bytes, bytes + length);
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size()) - 1;
  accessor.componentType = componentType;
  accessor.count = count;
  accessor.type = type;
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

// VALUES (floats) as an accessor of TYPE with COUNT elements; with BOUNDS, its min and max.
int addAccessor(tinygltf::Model& model, const std::vector<float>& values, int type, size_t count,
                int target, bool bounds)
{
  const int index = addAccessor(model, values.data(), values.size() * sizeof(float), target, count,
                                type, TINYGLTF_COMPONENT_TYPE_FLOAT);
  tinygltf::Accessor& accessor = model.accessors[size_t(index)];
  if (bounds)
  {
    const size_t components = values.size() / std::max<size_t>(count, 1);
    accessor.minValues.assign(components, std::numeric_limits<double>::max());
    accessor.maxValues.assign(components, std::numeric_limits<double>::lowest());
    for (size_t i = 0; i < values.size(); ++i)
    {
      accessor.minValues[i % components] = std::min(accessor.minValues[i % components], double(values[i]));
      accessor.maxValues[i % components] = std::max(accessor.maxValues[i % components], double(values[i]));
    }
  }
  return index;
}

int addIndices(tinygltf::Model& model, const std::vector<uint32_t>& indices)
{
  return addAccessor(model, indices.data(), indices.size() * sizeof(uint32_t),
                     TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, indices.size(), TINYGLTF_TYPE_SCALAR,
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
}

tinygltf::Material gltfMaterial(const Material& material, tinygltf::Model& model)
{
  const auto number = [&](const char* key) { return material.value(key).number[0]; };
  const auto color = [&](const char* key)
  {
    const auto& n = material.value(key).number;
    return glm::dvec3(n[0], n[1], n[2]);
  };
  const GltfFactors f = asToGltf(number("nu"), number("nv"), color("f0"), color("albedo"));
  tinygltf::Material out;
  out.name = material.name;
  out.pbrMetallicRoughness.baseColorFactor = {f.baseColor.x, f.baseColor.y, f.baseColor.z, 1.0};
  out.pbrMetallicRoughness.metallicFactor = f.metallic;
  out.pbrMetallicRoughness.roughnessFactor = f.roughness;
  tinygltf::Value::Object anisotropy;
  anisotropy["anisotropyStrength"] = tinygltf::Value(f.anisotropyStrength);
  anisotropy["anisotropyRotation"] = tinygltf::Value(f.anisotropyRotation);
  out.extensions["KHR_materials_anisotropy"] = tinygltf::Value(anisotropy);
  const auto used = [&](const std::string& name)
  {
    if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), name) ==
        model.extensionsUsed.end())
    {
      model.extensionsUsed.push_back(name);
    }
  };
  used("KHR_materials_anisotropy");
  if (f.hasSpecular)
  {
    tinygltf::Value::Object specular;
    specular["specularFactor"] = tinygltf::Value(f.specularFactor);
    tinygltf::Value::Array colorFactor = {tinygltf::Value(f.specularColor.x),
                                          tinygltf::Value(f.specularColor.y),
                                          tinygltf::Value(f.specularColor.z)};
    specular["specularColorFactor"] = tinygltf::Value(colorFactor);
    out.extensions["KHR_materials_specular"] = tinygltf::Value(specular);
    used("KHR_materials_specular");
  }
  return out;
}
} // namespace

void writeGltfScene(const std::string& path, const std::vector<GltfPart>& parts)
{
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "aniso";
  model.buffers.emplace_back();
  model.scenes.emplace_back();
  model.defaultScene = 0;
  std::map<std::string, int> materials;
  for (const GltfPart& part : parts)
  {
    vtkPolyData* surface = part.polyData;
    if (!surface || !surface->GetPoints() || surface->GetNumberOfPoints() == 0)
    {
      throw errorAbout(path, "part " + part.name + " has no surface to write");
    }
    checkPlacement(part.placement, path + ": part " + part.name);
    const vtkIdType count = surface->GetNumberOfPoints();
    vtkPointData* pd = surface->GetPointData();
    vtkDataArray* normals = pd->GetNormals();
    vtkDataArray* tangents = pd->GetTangents();
    vtkDataArray* tcoords = pd->GetTCoords();
    std::vector<float> positions;
    std::vector<float> normalValues;
    std::vector<float> tangentValues;
    std::vector<float> uvs;
    for (vtkIdType i = 0; i < count; ++i)
    {
      double p[3];
      surface->GetPoint(i, p);
      const glm::dvec3 q = toYUp({p[0], p[1], p[2]});
      positions.insert(positions.end(), {float(q.x), float(q.y), float(q.z)});
      if (normals && normals->GetNumberOfComponents() >= 3)
      {
        const glm::dvec3 n = toYUp({normals->GetComponent(i, 0), normals->GetComponent(i, 1),
                                    normals->GetComponent(i, 2)});
        normalValues.insert(normalValues.end(), {float(n.x), float(n.y), float(n.z)});
      }
      if (tangents && tangents->GetNumberOfComponents() >= 3)
      {
        const glm::dvec3 t = toYUp({tangents->GetComponent(i, 0), tangents->GetComponent(i, 1),
                                    tangents->GetComponent(i, 2)});
        tangentValues.insert(tangentValues.end(), {float(t.x), float(t.y), float(t.z), 1.0f});
      }
      if (tcoords && tcoords->GetNumberOfComponents() >= 2)
      {
        uvs.insert(uvs.end(), {float(tcoords->GetComponent(i, 0)),
                               float(1.0 - tcoords->GetComponent(i, 1))});
      }
    }
    std::vector<uint32_t> indices;
    geometry::forEachCell(surface->GetPolys(),
                          [&](vtkIdType n, const vtkIdType* ids)
                          {
                            for (vtkIdType k = 1; k + 1 < n; ++k)
                            {
                              indices.insert(indices.end(), {uint32_t(ids[0]), uint32_t(ids[k]),
                                                             uint32_t(ids[k + 1])});
                            }
                          });
    if (surface->GetNumberOfStrips() > 0)
    {
      throw errorAbout(path, "part " + part.name + " holds triangle strips (not written)");
    }
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = addAccessor(model, positions, TINYGLTF_TYPE_VEC3, size_t(count),
                                                   TINYGLTF_TARGET_ARRAY_BUFFER, true);
    if (!normalValues.empty())
    {
      primitive.attributes["NORMAL"] = addAccessor(model, normalValues, TINYGLTF_TYPE_VEC3,
                                                   size_t(count), TINYGLTF_TARGET_ARRAY_BUFFER, false);
    }
    if (!tangentValues.empty())
    {
      primitive.attributes["TANGENT"] = addAccessor(model, tangentValues, TINYGLTF_TYPE_VEC4,
                                                    size_t(count), TINYGLTF_TARGET_ARRAY_BUFFER, false);
    }
    if (!uvs.empty())
    {
      primitive.attributes["TEXCOORD_0"] = addAccessor(model, uvs, TINYGLTF_TYPE_VEC2, size_t(count),
                                                       TINYGLTF_TARGET_ARRAY_BUFFER, false);
    }
    primitive.indices = addIndices(model, indices);
    auto known = materials.find(part.material.name);
    if (known == materials.end())
    {
      model.materials.push_back(gltfMaterial(part.material, model));
      known = materials.emplace(part.material.name, int(model.materials.size()) - 1).first;
    }
    primitive.material = known->second;
    tinygltf::Mesh mesh;
    mesh.name = part.name;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);

    // The node's matrix: C^-1 P C with C the reader's Y-up to Z-up turn, column-major.
    // C^-1 P C maps a glTF point g to toYUp(P (C g)).
    tinygltf::Node node;
    node.name = part.name;
    node.mesh = int(model.meshes.size()) - 1;
    const PartMatrix& m = part.placement;
    const auto apply = [&](const glm::dvec3& v, double w)
    {
      const glm::dvec3 z(v.x, -v.z, v.y); // C
      glm::dvec3 out;
      for (int r = 0; r < 3; ++r)
      {
        out[r] = m[size_t(r * 4)] * z.x + m[size_t(r * 4 + 1)] * z.y + m[size_t(r * 4 + 2)] * z.z +
                 m[size_t(r * 4 + 3)] * w;
      }
      return toYUp(out);
    };
    node.matrix.resize(16, 0.0);
    const glm::dvec3 columns[4] = {apply({1, 0, 0}, 0), apply({0, 1, 0}, 0), apply({0, 0, 1}, 0),
                                   apply({0, 0, 0}, 1)};
    for (int c = 0; c < 4; ++c)
    {
      for (int r = 0; r < 3; ++r)
      {
        node.matrix[size_t(c * 4 + r)] = columns[c][r];
      }
    }
    node.matrix[15] = 1.0;
    model.nodes.push_back(node);
    model.scenes.front().nodes.push_back(int(model.nodes.size()) - 1);
  }
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  // Through a stream of our own: tinygltf's file writer reports no failure to open or write.
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out)
  {
    throw errorAbout(path, std::string("cannot be written (") + std::strerror(errno) + ")");
  }
  tinygltf::TinyGLTF writer;
  const bool written = writer.WriteGltfSceneToStream(&model, out, true, ext == ".glb");
  out.close();
  if (!written || !out)
  {
    throw errorAbout(path, "the glTF file could not be written");
  }
}

std::vector<std::string> partsWithFields(const std::vector<GltfPart>& parts)
{
  std::vector<std::string> names;
  for (const GltfPart& part : parts)
  {
    const std::string field = part.material.value("field").text;
    if (!field.empty() && field != "none")
    {
      names.push_back(part.name);
    }
  }
  return names;
}
} // namespace aniso
