#include "vtkpasses/mesh/GltfReader.h"

#include "core/cache_directory.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/image/image.h"
#include "core/models/gltf_material.h"
#include "core/parameters/material_library.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <map>
#include <optional>
#include <set>
#include <system_error>
#include <tiny_gltf.h>
#include <unistd.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

// glTF's Y-up into the Z-up world: (x, y, z) -> (x, -z, y), a rotation.
const glm::dmat4 kYUpToZUp(1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1); // columns

// Images: tinygltf hands over the bytes as they are (no decoding in tinygltf; OpenImageIO decodes
// them later, from the cache file). MODEL is the model being read: tinygltf 2.5 hands over an
// image's buffer view without checking that it lies within its buffer (fuzz_glb read past a
// GLB's buffer that way), so the view is checked here first.
bool keepImageBytes(tinygltf::Image* image, const int index, std::string* error, std::string*,
                    int, int, const unsigned char* bytes, int size, void* model)
{
  if (image->bufferView >= 0 && model)
  {
    const tinygltf::Model& m = *static_cast<const tinygltf::Model*>(model);
    const auto view = static_cast<std::size_t>(image->bufferView);
    const bool inside =
        view < m.bufferViews.size() && m.bufferViews[view].buffer >= 0 &&
        static_cast<std::size_t>(m.bufferViews[view].buffer) < m.buffers.size() &&
        m.bufferViews[view].byteOffset <= m.buffers[std::size_t(m.bufferViews[view].buffer)].data.size() &&
        m.bufferViews[view].byteLength <=
            m.buffers[std::size_t(m.bufferViews[view].buffer)].data.size() -
                m.bufferViews[view].byteOffset;
    if (!inside)
    {
      if (error)
      {
        *error += "image " + std::to_string(index) + ": its buffer view " +
                  std::to_string(image->bufferView) + " runs past its buffer";
      }
      return false;
    }
  }
  image->image.assign(bytes, bytes + std::max(size, 0));
  image->as_is = true;
  return true;
}

std::string cacheDirectory()
{
  std::string base = defaultCacheDirectory();
  if (base.empty())
  {
    base = (fs::temp_directory_path() / "aniso").string();
  }
  const fs::path dir = fs::path(base) / "gltf";
  std::error_code ec;
  fs::create_directories(dir, ec);
  return dir.string();
}

// Writes BYTES to PATH unless a file of that name (a hash of the bytes) is there; atomic.
void writeOnce(const std::string& path, const std::vector<unsigned char>& bytes)
{
  std::error_code ec;
  if (fs::exists(path, ec))
  {
    return;
  }
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out)
    {
      fs::remove(temporary, ec);
      throw Error(path + ": could not be written");
    }
  }
  fs::rename(temporary, path, ec);
  if (ec)
  {
    fs::remove(temporary, ec);
    throw Error(path + ": could not be written (" + ec.message() + ")");
  }
}

std::string imageExtension(const tinygltf::Image& image)
{
  const std::vector<unsigned char>& b = image.image;
  if (b.size() >= 8 && b[0] == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G')
  {
    return ".png";
  }
  if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF)
  {
    return ".jpg";
  }
  if (image.mimeType == "image/png")
  {
    return ".png";
  }
  if (image.mimeType == "image/jpeg")
  {
    return ".jpg";
  }
  const std::string ext = fs::path(image.uri).extension().string();
  return ext.empty() || ext.size() > 6 ? ".img" : ext;
}

double numberOf(const tinygltf::Value& object, const char* key, double fallback)
{
  if (!object.IsObject() || !object.Has(key))
  {
    return fallback;
  }
  const tinygltf::Value& v = object.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

glm::dvec3 colorOf(const tinygltf::Value& object, const char* key, const glm::dvec3& fallback)
{
  if (!object.IsObject() || !object.Has(key))
  {
    return fallback;
  }
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsArray() || v.ArrayLen() < 3)
  {
    return fallback;
  }
  glm::dvec3 c;
  for (int i = 0; i < 3; ++i)
  {
    c[i] = v.Get(i).IsNumber() ? v.Get(i).GetNumberAsDouble() : fallback[i];
  }
  return c;
}

// A texture reference as glTF gives it in a textureInfo: index, texCoord, its extensions.
struct TextureRef
{
  int index = -1;
  int texCoord = 0;
  GltfTextureTransform transform;
  std::string slot; // "baseColorTexture", ...
};

GltfTextureTransform transformOf(const tinygltf::ExtensionMap& extensions, int* texCoord)
{
  GltfTextureTransform t;
  const auto it = extensions.find("KHR_texture_transform");
  if (it == extensions.end())
  {
    return t;
  }
  const tinygltf::Value& e = it->second;
  if (e.Has("offset") && e.Get("offset").IsArray() && e.Get("offset").ArrayLen() >= 2)
  {
    t.offset = {e.Get("offset").Get(0).GetNumberAsDouble(),
                e.Get("offset").Get(1).GetNumberAsDouble()};
  }
  t.rotation = numberOf(e, "rotation", 0.0);
  if (e.Has("scale") && e.Get("scale").IsArray() && e.Get("scale").ArrayLen() >= 2)
  {
    t.scale = {e.Get("scale").Get(0).GetNumberAsDouble(), e.Get("scale").Get(1).GetNumberAsDouble()};
  }
  if (e.Has("texCoord") && e.Get("texCoord").IsInt())
  {
    *texCoord = e.Get("texCoord").GetNumberAsInt();
  }
  return t;
}

template <class Info>
TextureRef refOf(const Info& info, const std::string& slot)
{
  TextureRef ref;
  ref.index = info.index;
  ref.texCoord = info.texCoord;
  ref.transform = transformOf(info.extensions, &ref.texCoord);
  ref.slot = slot;
  return ref;
}

// A textureInfo given as an extension's JSON value.
TextureRef refOfValue(const tinygltf::Value& value, const std::string& slot)
{
  TextureRef ref;
  ref.slot = slot;
  if (!value.IsObject())
  {
    return ref;
  }
  ref.index = value.Has("index") && value.Get("index").IsInt() ? value.Get("index").GetNumberAsInt()
                                                               : -1;
  ref.texCoord = value.Has("texCoord") && value.Get("texCoord").IsInt()
                     ? value.Get("texCoord").GetNumberAsInt()
                     : 0;
  if (value.Has("extensions") && value.Get("extensions").IsObject())
  {
    tinygltf::ExtensionMap extensions;
    const tinygltf::Value& e = value.Get("extensions");
    for (const std::string& key : e.Keys())
    {
      extensions[key] = e.Get(key);
    }
    ref.transform = transformOf(extensions, &ref.texCoord);
  }
  return ref;
}

class Reader
{
public:
  Reader(std::string path, std::vector<std::string>& warnings)
    : path_(std::move(path)), warnings_(warnings)
  {
  }

  std::vector<ReaderBlock> read(bool placeInGeometry);

private:
  struct MaterialOut
  {
    std::string json;
    GltfTextureTransform transform; // applied to TEXCOORD_0 of its primitives
    // A constant anisotropyRotation left after the swap of n_u and n_v (gltfToAs): json turns the
    // tangent by it with a 1x1 TPR map; a part without TEXCOORD_0 (no map can be sampled) takes
    // jsonWithoutMap and its TANGENTs turned by it at load instead.
    double tangentRotation = 0.0;
    std::string jsonWithoutMap;
    bool done = false;
  };

  void warn(const std::string& what) { warnings_.push_back(path_ + ": " + what); }
  const MaterialOut& material(int index);
  std::string materialName(int index) const;
  // The image file of texture REF, in the cache; empty (with a warning) when there is none.
  std::string imageFile(const TextureRef& ref, const std::string& subject);
  std::optional<Image> decoded(const TextureRef& ref, const std::string& subject);
  std::string bake(const std::string& key, const Image& image);

  void addNode(int node, const glm::dmat4& parent, int depth, bool placeInGeometry,
               std::vector<ReaderBlock>& blocks);
  vtkSmartPointer<vtkPolyData> primitives(const tinygltf::Mesh& mesh,
                                          const std::vector<int>& which,
                                          const GltfTextureTransform& transform,
                                          const glm::dmat4& geometry, const std::string& subject);

  std::string path_;
  std::vector<std::string>& warnings_;
  tinygltf::Model model_;
  std::map<int, MaterialOut> materials_;
  std::map<int, std::string> imageFiles_;
  std::set<int> visited_;
  std::string cache_;
};

std::string Reader::materialName(int index) const
{
  const std::string& given = model_.materials[size_t(index)].name;
  return given.empty() ? "material " + std::to_string(index) : given;
}

std::string Reader::imageFile(const TextureRef& ref, const std::string& subject)
{
  const std::string what = subject + ": " + ref.slot;
  if (ref.index < 0 || size_t(ref.index) >= model_.textures.size())
  {
    warn(what + ": texture " + std::to_string(ref.index) + " does not exist: left out");
    return {};
  }
  const int source = model_.textures[size_t(ref.index)].source;
  if (source < 0 || size_t(source) >= model_.images.size())
  {
    warn(what + ": texture " + std::to_string(ref.index) + " has no image: left out");
    return {};
  }
  const auto known = imageFiles_.find(source);
  if (known != imageFiles_.end())
  {
    return known->second;
  }
  const tinygltf::Image& image = model_.images[size_t(source)];
  const std::string name = !image.uri.empty() && image.uri.compare(0, 5, "data:") != 0
                               ? "'" + image.uri + "'"
                               : "image " + std::to_string(source);
  std::string file;
  if (image.image.empty())
  {
    warn(what + ": texture " + name + " is missing or empty: left out");
  }
  else
  {
    if (cache_.empty())
    {
      cache_ = cacheDirectory();
    }
    file = (fs::path(cache_) /
            (hex16(fnv1a(image.image.data(), image.image.size())) + imageExtension(image)))
               .string();
    try
    {
      writeOnce(file, image.image);
    }
    catch (const Error& e)
    {
      warn(what + ": texture " + name + ": " + e.what() + ": left out");
      file.clear();
    }
  }
  imageFiles_[source] = file;
  return file;
}

std::optional<Image> Reader::decoded(const TextureRef& ref, const std::string& subject)
{
  const std::string file = imageFile(ref, subject);
  if (file.empty())
  {
    return std::nullopt;
  }
  try
  {
    return readImage(file);
  }
  catch (const Error& e)
  {
    const tinygltf::Image& image = model_.images[size_t(model_.textures[size_t(ref.index)].source)];
    warn(subject + ": " + ref.slot + ": texture " +
         (image.uri.empty() || image.uri.compare(0, 5, "data:") == 0 ? "" : "'" + image.uri + "' ") +
         "does not decode (" + e.what() + "): left out");
    // A cache file that does not decode is of no use to anyone.
    std::error_code ec;
    fs::remove(file, ec);
    imageFiles_[model_.textures[size_t(ref.index)].source].clear();
    return std::nullopt;
  }
}

std::string Reader::bake(const std::string& key, const Image& image)
{
  if (cache_.empty())
  {
    cache_ = cacheDirectory();
  }
  uint64_t hash = fnv1a(key.data(), key.size());
  hash = fnv1a(reinterpret_cast<const unsigned char*>(image.data.data()),
               image.data.size() * sizeof(float), hash);
  const std::string file = (fs::path(cache_) / (hex16(hash) + ".exr")).string();
  std::error_code ec;
  if (!fs::exists(file, ec))
  {
    writeImage(file, image);
  }
  return file;
}

const Reader::MaterialOut& Reader::material(int index)
{
  MaterialOut& out = materials_[index];
  if (out.done)
  {
    return out;
  }
  out.done = true;
  const tinygltf::Material& m = model_.materials[size_t(index)];
  const std::string name = materialName(index);
  const std::string subject = "material " + name;
  Material material = defaultMaterial(name);

  GltfFactors factors;
  const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() >= 3)
  {
    factors.baseColor = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
  }
  factors.metallic = pbr.metallicFactor;
  factors.roughness = pbr.roughnessFactor;
  std::vector<TextureRef> textures;
  std::optional<tinygltf::Value> anisotropy;
  for (const auto& [key, value] : m.extensions)
  {
    if (key == "KHR_materials_anisotropy")
    {
      anisotropy = value;
      factors.anisotropyStrength = numberOf(value, "anisotropyStrength", 0.0);
      factors.anisotropyRotation = numberOf(value, "anisotropyRotation", 0.0);
    }
    else if (key == "KHR_materials_specular")
    {
      factors.specularFactor = numberOf(value, "specularFactor", 1.0);
      factors.specularColor = colorOf(value, "specularColorFactor", glm::dvec3(1.0));
      if (value.Has("specularTexture") || value.Has("specularColorTexture"))
      {
        warn(subject + ": KHR_materials_specular's textures are not rendered (its factors are)");
      }
    }
    else if (key == "KHR_materials_ior")
    {
      factors.ior = numberOf(value, "ior", 1.5);
    }
    else if (key == "KHR_materials_emissive_strength")
    {
    }
    else
    {
      warn(subject + ": extension " + key + " is not read");
    }
  }
  const bool emissive = m.emissiveTexture.index >= 0 ||
                        (m.emissiveFactor.size() >= 3 &&
                         (m.emissiveFactor[0] > 0 || m.emissiveFactor[1] > 0 ||
                          m.emissiveFactor[2] > 0));
  if (emissive)
  {
    warn(subject + ": emissive is not rendered");
  }

  // The texture transform of the first texture; the others are expected to share it.
  std::optional<GltfTextureTransform> transform;
  const auto use = [&](const TextureRef& ref)
  {
    if (ref.texCoord != 0)
    {
      warn(subject + ": " + ref.slot + " uses TEXCOORD_" + std::to_string(ref.texCoord) +
           ": read with TEXCOORD_0");
    }
    if (!transform)
    {
      transform = ref.transform;
    }
    else if (!(*transform == ref.transform))
    {
      warn(subject + ": " + ref.slot + " has another KHR_texture_transform than the material's "
                     "first texture: the first's is used");
    }
  };

  // metallicRoughnessTexture: metalness (B) into a metallic map, roughness (G) by its mean.
  bool metallicMap = false;
  if (pbr.metallicRoughnessTexture.index >= 0)
  {
    const TextureRef ref = refOf(pbr.metallicRoughnessTexture, "metallicRoughnessTexture");
    use(ref);
    if (std::optional<Image> image = decoded(ref, subject))
    {
      Image metal(image->width, image->height, 1);
      double roughness = 0.0;
      const int c = image->channels;
      for (size_t i = 0; i < metal.data.size(); ++i)
      {
        const float* texel = &image->data[i * size_t(c)];
        metal.data[i] = float(factors.metallic * (c >= 3 ? texel[2] : texel[0]));
        roughness += c >= 2 ? texel[1] : texel[0];
      }
      roughness /= double(metal.data.size());
      factors.roughness *= roughness;
      warn(subject + ": the roughness of metallicRoughnessTexture is rendered by its mean (" +
           std::to_string(roughness) + ", a constant roughness)");
      material.values["metallic-map"] = textValue(bake("metallic", metal));
      metallicMap = true;
    }
  }

  // anisotropyTexture: direction into a TPR map, strength by its mean.
  std::optional<Image> tpr;
  double rotationLeft = 0.0;
  if (anisotropy && anisotropy->Has("anisotropyTexture"))
  {
    const TextureRef ref = refOfValue(anisotropy->Get("anisotropyTexture"), "anisotropyTexture");
    use(ref);
    if (std::optional<Image> image = decoded(ref, subject))
    {
      Image map(image->width, image->height, 3);
      const int c = image->channels;
      double strength = 0.0;
      double low = 1.0;
      double high = 0.0;
      for (size_t i = 0; i < size_t(image->width) * size_t(image->height); ++i)
      {
        const float* texel = &image->data[i * size_t(c)];
        const glm::dvec2 rg(texel[0], c >= 2 ? texel[1] : 0.5);
        const glm::dvec2 d = gltfAnisotropyDirection(rg, factors.anisotropyRotation);
        map.data[i * 3] = float(d.x);
        map.data[i * 3 + 1] = float(d.y);
        const double b = c >= 3 ? texel[2] : 1.0;
        strength += b;
        low = std::min(low, b);
        high = std::max(high, b);
      }
      strength /= double(size_t(image->width) * size_t(image->height));
      if (high - low > 2.0 / 255.0)
      {
        warn(subject + ": the strength of anisotropyTexture (B) varies; it is rendered by its "
                       "mean (" +
             std::to_string(strength) + ")");
      }
      factors.anisotropyStrength *= strength;
      factors.anisotropyRotation = 0.0; // the TPR map turns the tangent
      tpr = std::move(map);
    }
  }
  const GltfAsValues as = gltfToAs(factors);
  if (!tpr && as.tangentRotation != 0.0)
  {
    rotationLeft = as.tangentRotation;
    Image map;
    map.width = 1;
    map.height = 1;
    map.channels = 3;
    map.data = {float(std::cos(rotationLeft)), float(std::sin(rotationLeft)), 0.0f};
    tpr = std::move(map);
  }
  material.values["nu"] = numberValue(as.nu);
  material.values["nv"] = numberValue(as.nv);
  if (metallicMap)
  {
    // The map mixes per texel: F0 = mix(0.04, F0, m), albedo (1 - m); the material holds the
    // values at m = 1 and m = 0.
    const glm::dvec3 base = glm::clamp(factors.baseColor, 0.0, 1.0);
    material.values["f0"] = colorValue(base.x, base.y, base.z);
    material.values["albedo"] = colorValue(base.x, base.y, base.z);
    if (factors.hasSpecular || factors.specularColor != glm::dvec3(1.0) ||
        factors.specularFactor != 1.0 || factors.ior != 1.5)
    {
      warn(subject + ": with metallicRoughnessTexture the dielectric F0 is 0.04 (its specular and "
                     "ior are not rendered)");
    }
  }
  else
  {
    material.values["f0"] = colorValue(as.f0.x, as.f0.y, as.f0.z);
    material.values["albedo"] = colorValue(as.albedo.x, as.albedo.y, as.albedo.z);
  }

  if (pbr.baseColorTexture.index >= 0)
  {
    const TextureRef ref = refOf(pbr.baseColorTexture, "baseColorTexture");
    use(ref);
    if (std::optional<Image> image = decoded(ref, subject))
    {
      // sRGB-encoded in glTF; the albedo map is linear.
      Image linear = *image;
      for (size_t i = 0; i < linear.data.size(); ++i)
      {
        if (linear.channels == 4 && i % 4 == 3)
        {
          continue;
        }
        const double v = std::clamp(double(linear.data[i]), 0.0, 1.0);
        linear.data[i] =
            float(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
      }
      material.values["albedo-map"] = textValue(bake("albedo", linear));
      if (factors.metallic > 0.0)
      {
        warn(subject + ": baseColorTexture tints the diffuse albedo only, not F0");
      }
    }
  }
  // A texture used as it is: its file as map KEY when it decodes; a FACTOR (normalTexture's
  // scale, occlusionTexture's strength) other than 1 is not rendered.
  const auto plainMap = [&](const auto& info, const char* slot, const char* key,
                            const char* factorName, double factor)
  {
    if (info.index < 0)
    {
      return false;
    }
    const TextureRef ref = refOf(info, slot);
    use(ref);
    const std::string file = imageFile(ref, subject);
    if (file.empty() || !decoded(ref, subject))
    {
      return false;
    }
    material.values[key] = textValue(file);
    if (factor != 1.0)
    {
      warn(subject + ": " + slot + "'s " + factorName + " " + std::to_string(factor) +
           " is not rendered (1 is)");
    }
    return true;
  };
  if (plainMap(m.normalTexture, "normalTexture", "normal-map", "scale", m.normalTexture.scale))
  {
    material.values["bump"] = textValue("normal");
  }
  plainMap(m.occlusionTexture, "occlusionTexture", "ao-map", "strength",
           m.occlusionTexture.strength);
  out.transform = transform.value_or(GltfTextureTransform{});
  const auto json = [](const Material& one)
  {
    MaterialLibrary library;
    library.put(one);
    return materialLibraryToJson(library);
  };
  if (rotationLeft != 0.0)
  {
    out.tangentRotation = rotationLeft;
    out.jsonWithoutMap = json(material);
  }
  if (tpr)
  {
    material.values["tpr"] = textValue(bake("tpr", *tpr));
  }
  out.json = json(material);
  return out;
}

// Reads accessor ACCESSOR as COUNT x COMPONENTS doubles (normalised integers as the
// specification says); nullopt with a reason when it does not fit its buffer.
std::optional<std::vector<double>> readAccessor(const tinygltf::Model& model, int accessor,
                                                int components, std::string& reason)
{
  if (accessor < 0 || size_t(accessor) >= model.accessors.size())
  {
    reason = "accessor " + std::to_string(accessor) + " does not exist";
    return std::nullopt;
  }
  const tinygltf::Accessor& a = model.accessors[size_t(accessor)];
  if (a.sparse.isSparse)
  {
    reason = "accessor " + std::to_string(accessor) + " is sparse (not read)";
    return std::nullopt;
  }
  const int have = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  const int size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  if (have < components || size <= 0 || a.bufferView < 0 ||
      size_t(a.bufferView) >= model.bufferViews.size())
  {
    reason = "accessor " + std::to_string(accessor) + " is not of the expected type";
    return std::nullopt;
  }
  const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
  {
    reason = "buffer view " + std::to_string(a.bufferView) + " has no buffer";
    return std::nullopt;
  }
  const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
  const size_t element = size_t(have) * size_t(size);
  const size_t stride = view.byteStride > 0 ? view.byteStride : element;
  const size_t count = a.count;
  const size_t start = view.byteOffset + a.byteOffset;
  const bool fits = view.byteOffset <= buffer.size() && view.byteLength <= buffer.size() - view.byteOffset &&
                    a.byteOffset <= view.byteLength &&
                    (count == 0 || (stride >= element && (count - 1) <= (view.byteLength - a.byteOffset) / stride &&
                                    (count - 1) * stride + element <= view.byteLength - a.byteOffset));
  if (!fits)
  {
    reason = "accessor " + std::to_string(accessor) + " reaches beyond its buffer";
    return std::nullopt;
  }
  std::vector<double> out(count * size_t(components));
  for (size_t i = 0; i < count; ++i)
  {
    const unsigned char* p = buffer.data() + start + i * stride;
    for (int c = 0; c < components; ++c)
    {
      const unsigned char* q = p + size_t(c) * size_t(size);
      double v = 0.0;
      switch (a.componentType)
      {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
      {
        float f;
        std::memcpy(&f, q, sizeof f);
        v = f;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        v = *q;
        v = a.normalized ? v / 255.0 : v;
        break;
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        v = static_cast<int8_t>(*q);
        v = a.normalized ? std::max(v / 127.0, -1.0) : v;
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      {
        uint16_t s;
        std::memcpy(&s, q, sizeof s);
        v = a.normalized ? s / 65535.0 : s;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT:
      {
        int16_t s;
        std::memcpy(&s, q, sizeof s);
        v = a.normalized ? std::max(s / 32767.0, -1.0) : s;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      {
        uint32_t s;
        std::memcpy(&s, q, sizeof s);
        v = s;
        break;
      }
      default:
        reason = "accessor " + std::to_string(accessor) + " has an unknown component type";
        return std::nullopt;
      }
      out[i * size_t(components) + size_t(c)] = v;
    }
  }
  return out;
}

vtkSmartPointer<vtkPolyData> Reader::primitives(const tinygltf::Mesh& mesh,
                                                const std::vector<int>& which,
                                                const GltfTextureTransform& transform,
                                                const glm::dmat4& geometry,
                                                const std::string& subject)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkCellArray> polys;
  std::vector<float> normals;
  std::vector<float> tangents;
  std::vector<float> tcoords;
  bool allNormals = true;
  bool allTangents = true;
  bool allTcoords = true;
  // Custom attributes ("_NAME", glTF 2.0 section 3.7.2.1): kept as point arrays when every
  // triangle primitive merged here has one of the same width.
  struct Custom
  {
    int components = 0;
    std::vector<float> values;
    size_t primitives = 0;
  };
  std::map<std::string, Custom> custom;
  size_t trianglePrimitives = 0;
  const glm::dmat3 linear(geometry);
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(linear));
  for (int p : which)
  {
    const tinygltf::Primitive& primitive = mesh.primitives[size_t(p)];
    const std::string what = subject + ": primitive " + std::to_string(p);
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        primitive.mode != TINYGLTF_MODE_TRIANGLE_FAN)
    {
      warn(what + ": points or lines (mode " + std::to_string(primitive.mode) + "): left out");
      continue;
    }
    const auto attribute = [&](const char* name) -> int
    {
      const auto it = primitive.attributes.find(name);
      return it == primitive.attributes.end() ? -1 : it->second;
    };
    std::string reason;
    if (attribute("POSITION") < 0)
    {
      warn(what + ": no POSITION: left out");
      continue;
    }
    const std::optional<std::vector<double>> positions =
        readAccessor(model_, attribute("POSITION"), 3, reason);
    if (!positions)
    {
      warn(what + ": POSITION: " + reason + ": left out");
      continue;
    }
    const size_t count = positions->size() / 3;
    const auto optional = [&](const char* name, int components) -> std::optional<std::vector<double>>
    {
      if (attribute(name) < 0)
      {
        return std::nullopt;
      }
      std::string why;
      std::optional<std::vector<double>> values =
          readAccessor(model_, attribute(name), components, why);
      if (values && values->size() != count * size_t(components))
      {
        why = "has " + std::to_string(values->size() / size_t(components)) + " values for " +
              std::to_string(count) + " vertices";
        values.reset();
      }
      if (!values)
      {
        warn(what + ": " + name + ": " + why + ": dropped");
      }
      return values;
    };
    const std::optional<std::vector<double>> n = optional("NORMAL", 3);
    const std::optional<std::vector<double>> t = optional("TANGENT", 4);
    const std::optional<std::vector<double>> uv = optional("TEXCOORD_0", 2);
    // Read before the indices, whose failure leaves the primitive out after they are counted.
    std::map<std::string, std::vector<double>> customValues;
    for (const auto& [name, accessor] : primitive.attributes)
    {
      if (name.empty() || name[0] != '_' || accessor < 0 ||
          size_t(accessor) >= model_.accessors.size())
      {
        continue;
      }
      const int components =
          tinygltf::GetNumComponentsInType(uint32_t(model_.accessors[size_t(accessor)].type));
      if (components < 1 || components > 4)
      {
        warn(what + ": " + name + ": not a scalar or vector: dropped");
        continue;
      }
      if (const std::optional<std::vector<double>> values = optional(name.c_str(), components))
      {
        customValues[name] = *values;
      }
    }
    std::vector<uint32_t> indices;
    if (primitive.indices >= 0)
    {
      const std::optional<std::vector<double>> read = readAccessor(model_, primitive.indices, 1, reason);
      const int type = model_.accessors.size() > size_t(primitive.indices)
                           ? model_.accessors[size_t(primitive.indices)].componentType
                           : 0;
      if (!read || (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                    type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                    type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
      {
        warn(what + ": indices: " + (read ? "not of an unsigned integer type" : reason) +
             ": left out");
        continue;
      }
      indices.assign(read->begin(), read->end());
    }
    else
    {
      indices.resize(count);
      for (size_t i = 0; i < count; ++i)
      {
        indices[i] = uint32_t(i);
      }
    }
    const vtkIdType base = points->GetNumberOfPoints();
    for (size_t i = 0; i < count; ++i)
    {
      const glm::dvec3 q =
          glm::dvec3(geometry * glm::dvec4((*positions)[i * 3], (*positions)[i * 3 + 1],
                                           (*positions)[i * 3 + 2], 1.0));
      points->InsertNextPoint(q.x, q.y, q.z);
    }
    for (auto& [name, values] : customValues)
    {
      const int components = int(values.size() / std::max<size_t>(count, 1));
      Custom& kept = custom[name];
      if (kept.primitives != trianglePrimitives ||
          (kept.components != 0 && kept.components != components))
      {
        kept.primitives = size_t(-1); // missing from an earlier primitive, or another width
        continue;
      }
      kept.components = components;
      ++kept.primitives;
      for (size_t i = 0; i < count; ++i)
      {
        if (components == 3)
        {
          // A direction, turned with the geometry like TANGENT.
          const glm::dvec3 v =
              linear * glm::dvec3(values[i * 3], values[i * 3 + 1], values[i * 3 + 2]);
          kept.values.insert(kept.values.end(), {float(v.x), float(v.y), float(v.z)});
        }
        else
        {
          for (int c = 0; c < components; ++c)
          {
            kept.values.push_back(float(values[i * size_t(components) + size_t(c)]));
          }
        }
      }
    }
    ++trianglePrimitives;
    allNormals = allNormals && n.has_value();
    allTangents = allTangents && t.has_value();
    allTcoords = allTcoords && uv.has_value();
    for (size_t i = 0; i < count; ++i)
    {
      if (n)
      {
        const glm::dvec3 v = normalMatrix * glm::dvec3((*n)[i * 3], (*n)[i * 3 + 1], (*n)[i * 3 + 2]);
        normals.insert(normals.end(), {float(v.x), float(v.y), float(v.z)});
      }
      if (t)
      {
        const glm::dvec3 v = linear * glm::dvec3((*t)[i * 4], (*t)[i * 4 + 1], (*t)[i * 4 + 2]);
        tangents.insert(tangents.end(), {float(v.x), float(v.y), float(v.z)});
      }
      if (uv)
      {
        const glm::dvec2 w = applyTextureTransform(transform, {(*uv)[i * 2], (*uv)[i * 2 + 1]});
        tcoords.insert(tcoords.end(), {float(w.x), float(1.0 - w.y)});
      }
    }
    size_t outOfRange = 0;
    const auto triangle = [&](uint32_t a, uint32_t b, uint32_t c)
    {
      if (a >= count || b >= count || c >= count)
      {
        ++outOfRange;
        return;
      }
      const vtkIdType ids[3] = {base + a, base + b, base + c};
      polys->InsertNextCell(3, ids);
    };
    if (primitive.mode == TINYGLTF_MODE_TRIANGLES)
    {
      for (size_t i = 0; i + 2 < indices.size(); i += 3)
      {
        triangle(indices[i], indices[i + 1], indices[i + 2]);
      }
    }
    else if (primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP)
    {
      for (size_t i = 0; i + 2 < indices.size(); ++i)
      {
        if (i % 2 == 0)
        {
          triangle(indices[i], indices[i + 1], indices[i + 2]);
        }
        else
        {
          triangle(indices[i + 1], indices[i], indices[i + 2]);
        }
      }
    }
    else
    {
      for (size_t i = 1; i + 1 < indices.size(); ++i)
      {
        triangle(indices[0], indices[i], indices[i + 1]);
      }
    }
    if (outOfRange > 0)
    {
      warn(what + ": " + std::to_string(outOfRange) +
           " triangles with a vertex index out of range: left out");
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(polys);
  const vtkIdType total = points->GetNumberOfPoints();
  const auto array = [&](const char* name, int components, const std::vector<float>& values)
  {
    vtkNew<vtkFloatArray> out;
    out->SetName(name);
    out->SetNumberOfComponents(components);
    out->SetNumberOfTuples(total);
    std::copy(values.begin(), values.end(), out->GetPointer(0));
    return vtkSmartPointer<vtkFloatArray>(out);
  };
  if (total > 0 && allNormals)
  {
    polyData->GetPointData()->SetNormals(array("Normals", 3, normals));
  }
  if (total > 0 && allTangents)
  {
    polyData->GetPointData()->SetTangents(array("Tangents", 3, tangents));
  }
  if (total > 0 && allTcoords)
  {
    polyData->GetPointData()->SetTCoords(array("TCoords", 2, tcoords));
  }
  for (const auto& [name, kept] : custom)
  {
    if (total > 0 && kept.primitives == trianglePrimitives)
    {
      polyData->GetPointData()->AddArray(array(name.c_str(), kept.components, kept.values));
    }
    else
    {
      warn(subject + ": " + name +
           ": not on every primitive of the part (or of varying width): "
           "dropped");
    }
  }
  return polyData;
}

// Turns POLYDATA's tangents by ANGLE about its normals, t' = cos t + sin (n x t)
// (KHR_materials_anisotropy's direction with the bitangent n x t); false when it has no normals
// or tangents.
bool turnTangents(vtkPolyData* polyData, double angle)
{
  vtkDataArray* normals = polyData->GetPointData()->GetNormals();
  vtkDataArray* tangents = polyData->GetPointData()->GetTangents();
  if (!normals || !tangents)
  {
    return false;
  }
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  for (vtkIdType i = 0; i < tangents->GetNumberOfTuples(); ++i)
  {
    double n[3];
    double t[3];
    normals->GetTuple(i, n);
    tangents->GetTuple(i, t);
    const glm::dvec3 nv(n[0], n[1], n[2]);
    const glm::dvec3 tv(t[0], t[1], t[2]);
    const glm::dvec3 turned = c * tv + s * glm::cross(nv, tv);
    tangents->SetTuple3(i, turned.x, turned.y, turned.z);
  }
  return true;
}

glm::dmat4 localMatrix(const tinygltf::Node& node)
{
  if (node.matrix.size() == 16)
  {
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c)
    {
      for (int r = 0; r < 4; ++r)
      {
        m[c][r] = node.matrix[size_t(c * 4 + r)];
      }
    }
    return m;
  }
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3)
  {
    m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  }
  if (node.rotation.size() == 4)
  {
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const double length = glm::length(q);
    const glm::dmat3 r = length > 0.0 ? glm::mat3_cast(q / length) : glm::dmat3(1.0);
    for (int c = 0; c < 3; ++c)
    {
      m[c] = glm::dvec4(r[c], 0.0);
    }
  }
  if (node.scale.size() == 3)
  {
    for (int c = 0; c < 3; ++c)
    {
      m[c] *= node.scale[size_t(c)];
    }
  }
  return m;
}

void Reader::addNode(int node, const glm::dmat4& parent, int depth, bool placeInGeometry,
                     std::vector<ReaderBlock>& blocks)
{
  if (node < 0 || size_t(node) >= model_.nodes.size() || depth > 256 || !visited_.insert(node).second)
  {
    warn("node " + std::to_string(node) + " does not exist or is its own ancestor: left out");
    return;
  }
  const tinygltf::Node& n = model_.nodes[size_t(node)];
  const glm::dmat4 world = parent * localMatrix(n);
  if (n.mesh >= 0 && size_t(n.mesh) < model_.meshes.size())
  {
    const tinygltf::Mesh& mesh = model_.meshes[size_t(n.mesh)];
    const std::string name = !n.name.empty()      ? n.name
                             : !mesh.name.empty() ? mesh.name
                                                  : "node " + std::to_string(node);
    // The primitives of each material, in the order of their first primitive.
    std::vector<std::pair<int, std::vector<int>>> groups;
    for (size_t p = 0; p < mesh.primitives.size(); ++p)
    {
      int m = mesh.primitives[p].material;
      m = m >= 0 && size_t(m) < model_.materials.size() ? m : -1;
      auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == m; });
      if (it == groups.end())
      {
        groups.push_back({m, {}});
        it = groups.end() - 1;
      }
      it->second.push_back(int(p));
    }
    const glm::dmat4 zUpWorld = kYUpToZUp * world * glm::inverse(kYUpToZUp);
    for (const auto& [m, which] : groups)
    {
      ReaderBlock block;
      block.name = groups.size() == 1 ? name : name + "/primitive " + std::to_string(which.front());
      GltfTextureTransform transform;
      const MaterialOut* out = m >= 0 ? &material(m) : nullptr;
      if (out)
      {
        block.material = out->json;
        transform = out->transform;
      }
      block.polyData = primitives(mesh, which, transform, placeInGeometry ? kYUpToZUp * world : kYUpToZUp,
                                  "part " + block.name);
      if (out && out->tangentRotation != 0.0 && !block.polyData->GetPointData()->GetTCoords())
      {
        block.material = out->jsonWithoutMap;
        if (!turnTangents(block.polyData, out->tangentRotation))
        {
          warn("part " + block.name + ": material " + materialName(m) +
               ": anisotropyRotation is not rendered (the part has neither TEXCOORD_0 nor "
               "NORMAL and TANGENT)");
        }
      }
      if (!placeInGeometry)
      {
        for (int r = 0; r < 4; ++r)
        {
          for (int c = 0; c < 4; ++c)
          {
            block.placement[size_t(r * 4 + c)] = zUpWorld[c][r];
          }
        }
        // Exactly affine: the last row as the specification has it.
        block.placement[12] = block.placement[13] = block.placement[14] = 0.0;
        block.placement[15] = 1.0;
      }
      blocks.push_back(std::move(block));
    }
  }
  for (int child : n.children)
  {
    addNode(child, world, depth + 1, placeInGeometry, blocks);
  }
}

std::vector<ReaderBlock> Reader::read(bool placeInGeometry)
{
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keepImageBytes, &model_);
  std::string error;
  std::string warning;
  const std::string ext = fs::path(path_).extension().string();
  std::string lower = ext;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const bool ok = lower == ".glb" ? loader.LoadBinaryFromFile(&model_, &error, &warning, path_)
                                  : loader.LoadASCIIFromFile(&model_, &error, &warning, path_);
  const auto firstLine = [](std::string text)
  {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    {
      text.pop_back();
    }
    // nlohmann's "[json.exception.parse_error.101] " is noise to the reader of the message.
    if (text.compare(0, 16, "[json.exception.") == 0 && text.find("] ") != std::string::npos)
    {
      text = text.substr(text.find("] ") + 2);
    }
    const size_t end = text.find('\n');
    return end == std::string::npos ? text : text.substr(0, end) + " ...";
  };
  if (!ok)
  {
    throw errorAbout(path_, "not a readable glTF file (" +
                                firstLine(error.empty() ? "tinygltf gave no reason" : error) + ")");
  }
  if (!warning.empty())
  {
    warn("glTF: " + firstLine(warning));
  }
  std::vector<int> roots;
  if (!model_.scenes.empty())
  {
    const int scene = model_.defaultScene >= 0 && size_t(model_.defaultScene) < model_.scenes.size()
                          ? model_.defaultScene
                          : 0;
    roots = model_.scenes[size_t(scene)].nodes;
  }
  else
  {
    std::vector<bool> child(model_.nodes.size(), false);
    for (const tinygltf::Node& n : model_.nodes)
    {
      for (int c : n.children)
      {
        if (c >= 0 && size_t(c) < child.size())
        {
          child[size_t(c)] = true;
        }
      }
    }
    for (size_t n = 0; n < model_.nodes.size(); ++n)
    {
      if (!child[n])
      {
        roots.push_back(int(n));
      }
    }
  }
  std::vector<ReaderBlock> blocks;
  for (int root : roots)
  {
    addNode(root, glm::dmat4(1.0), 0, placeInGeometry, blocks);
  }
  if (blocks.empty())
  {
    throw errorAbout(path_, "no faces (the glTF scene holds no mesh)");
  }
  return blocks;
}
} // namespace

std::vector<ReaderBlock> readGltfBlocks(const std::string& path, std::vector<std::string>& warnings)
{
  return Reader(path, warnings).read(false);
}

vtkSmartPointer<vtkPolyData> readGltfSurface(const std::string& path,
                                             std::vector<std::string>& warnings)
{
  const std::vector<ReaderBlock> blocks = Reader(path, warnings).read(true);
  vtkNew<vtkAppendPolyData> append;
  for (const ReaderBlock& block : blocks)
  {
    append->AddInputData(block.polyData);
  }
  append->Update();
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  merged->DeepCopy(append->GetOutput());
  return merged;
}
} // namespace aniso
