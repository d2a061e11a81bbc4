#include "core/formats/mtl_material.h"

#include "core/brdf/ashikhmin_shirley.h"
#include "core/models/gltf_material.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <system_error>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

constexpr double kDielectricF0 = 0.04;
constexpr double kDefaultDiffuse = 0.8;

double unit(double x)
{
  return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0;
}

std::array<double, 3> unitColor(const MtlColor& c)
{
  return {unit(c[0]), unit(c[1]), unit(c[2])};
}

double exponentInRange(double n)
{
  const ParameterSpec& spec = parameterSpec("nu");
  if (std::isnan(n))
  {
    return spec.minimum;
  }
  return std::clamp(n, spec.minimum, spec.maximum);
}

// The texture's file against the .mtl's directory; nothing (and a warning) when there is no such
// file.
std::optional<std::string> textureFile(const MtlTexture& texture, const std::string& key,
                                       const std::string& mtlPath,
                                       std::vector<std::string>& warnings)
{
  const fs::path written(texture.file);
  const fs::path file = written.is_absolute() ? written : fs::path(mtlPath).parent_path() / written;
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
  {
    warnings.push_back(mtlPath + ":" + std::to_string(texture.line) + ": " + key + " " +
                       texture.file + ": no such file (the material loads without it)");
    return std::nullopt;
  }
  const fs::path absolute = fs::absolute(file, ec);
  return (ec ? file : absolute).lexically_normal().string();
}

void warnUnused(const std::optional<MtlTexture>& texture, const std::string& key,
                const std::string& mtlPath, std::vector<std::string>& warnings)
{
  if (texture)
  {
    warnings.push_back(mtlPath + ":" + std::to_string(texture->line) + ": " + key + " " +
                       texture->file + ": not applied (the material has no such map)");
  }
}
} // namespace

Material materialFromMtl(const MtlMaterial& mtl, const std::string& mtlPath,
                         std::vector<std::string>& warnings)
{
  Material material = defaultMaterial(mtl.name);
  auto set = [&](const char* key, const ParameterValue& value) { material.values[key] = value; };
  auto setColor = [&](const char* key, const std::array<double, 3>& c)
  { set(key, colorValue(c[0], c[1], c[2])); };
  const std::array<double, 3> kd =
      mtl.kd ? unitColor(*mtl.kd)
             : std::array<double, 3>{kDefaultDiffuse, kDefaultDiffuse, kDefaultDiffuse};
  std::optional<std::string> metallicMap;
  if (mtl.mapPm)
  {
    metallicMap = textureFile(*mtl.mapPm, "map_Pm", mtlPath, warnings);
  }

  if (mtl.hasPbrKeys())
  {
    const double metallic = mtl.pm ? *mtl.pm : (metallicMap ? 1.0 : 0.0);
    // Without Pr, the roughness whose alpha = roughness^2 matches the exponent Ns.
    const double roughness = mtl.pr   ? *mtl.pr
                             : mtl.ns ? std::sqrt(roughnessFromExponent(*mtl.ns))
                                      : 1.0;
    // glTF's metallic-roughness with KHR_materials_anisotropy, rotation 0 (the tangent is the
    // anisotropy direction), the dielectric F0 glTF's default 0.04.
    GltfFactors factors;
    factors.baseColor = {kd[0], kd[1], kd[2]};
    factors.metallic = metallic;
    factors.roughness = roughness;
    factors.anisotropyStrength = mtl.aniso ? *mtl.aniso : 0.0;
    const GltfAsValues lobe = gltfToAs(factors);
    set("nu", numberValue(lobe.nu));
    set("nv", numberValue(lobe.nv));
    set("f0", colorValue(lobe.f0.x, lobe.f0.y, lobe.f0.z));
    // With a metallic map the shader does the metallic's share of the albedo (see the header).
    set("albedo", metallicMap ? colorValue(kd[0], kd[1], kd[2])
                              : colorValue(lobe.albedo.x, lobe.albedo.y, lobe.albedo.z));
    if (metallicMap)
    {
      set("metallic-map", textValue(*metallicMap));
    }
    if (mtl.anisor && std::fmod(*mtl.anisor, 1.0) != 0.0)
    {
      warnings.push_back(mtlPath + ":" + std::to_string(mtl.anisorLine) +
                         ": anisor: the anisotropy's rotation is not applied (the part's "
                         "tangents are kept)");
    }
  }
  else
  {
    const double n = exponentInRange(mtl.ns ? *mtl.ns : 0.0);
    set("nu", numberValue(n));
    set("nv", numberValue(n));
    setColor("f0", mtl.ks ? unitColor(*mtl.ks)
                          : std::array<double, 3>{kDielectricF0, kDielectricF0, kDielectricF0});
    setColor("albedo", kd);
    if (metallicMap)
    {
      set("metallic-map", textValue(*metallicMap));
    }
  }

  if (mtl.mapKd)
  {
    if (const auto file = textureFile(*mtl.mapKd, "map_Kd", mtlPath, warnings))
    {
      set("albedo-map", textValue(*file));
    }
  }
  if (mtl.norm)
  {
    if (const auto file = textureFile(*mtl.norm, "norm", mtlPath, warnings))
    {
      set("normal-map", textValue(*file));
      set("bump", textValue("normal"));
    }
  }
  if (mtl.bump)
  {
    if (const auto file = textureFile(*mtl.bump, "map_Bump", mtlPath, warnings))
    {
      set("height-map", textValue(*file));
      const ParameterSpec& scale = parameterSpec("height-scale");
      set("height-scale", numberValue(std::clamp(scale.defaultValue[0] * mtl.bump->bumpMultiplier,
                                                 scale.minimum, scale.maximum)));
    }
  }
  warnUnused(mtl.mapKs, "map_Ks", mtlPath, warnings);
  warnUnused(mtl.mapNs, "map_Ns", mtlPath, warnings);
  warnUnused(mtl.mapPr, "map_Pr", mtlPath, warnings);
  for (const auto* texture : {&mtl.mapKd, &mtl.norm, &mtl.bump, &mtl.mapPm})
  {
    if (*texture && (*texture)->transformed)
    {
      warnings.push_back(mtlPath + ":" + std::to_string((*texture)->line) + ": " +
                         (*texture)->file + ": its -o/-s/-t texture transform is not applied");
    }
  }
  return material;
}
} // namespace aniso
