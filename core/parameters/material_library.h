#pragma once
// Materials as named assets. A material holds a value for every material key: the declared
// parameters of ParameterScope::Material (n_u, n_v, F0, albedo, bump mapping, height scale, the
// tangent model) and the maps (texts naming files, empty for none). The parts of a scene
// reference materials of a library by name, so editing a library material changes every part
// that uses it; a part made unique gets a copy under a new name.
//
// Library files (and the "materials" section of a session) are JSON:
//
//   {
//     "format": "aniso-materials", "version": 1,
//     "materials": {
//       "brushed steel": {"nu": 800, "nv": 40, "f0": [0.562, 0.565, 0.578],
//                         "tangents": "auto", "normal-map": "grooves.png"},
//       ...
//     }
//   }
//
// Numbers as JSON numbers (written in the shortest form that reads back to the same double),
// colours as [r, g, b], texts and maps as strings. A key a material leaves out takes its default;
// a key that is no material key is an error naming it. Map paths under the file's directory are
// written relative to it and read back against it. Plain C++ (no Qt, no VTK).
#include "core/parameters/parameters.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace aniso
{
// The maps a material holds, by their scene keys.
inline constexpr std::string_view kMaterialMapKeys[] = {
    "normal-map", "quaternion-map", "tpr", "height-map", "albedo-map", "ao-map", "metallic-map"};

// Every material key: the Material-scope parameters in declaration order, then the maps.
const std::vector<std::string_view>& materialKeys();
bool isMaterialKey(std::string_view key);
bool isMaterialMapKey(std::string_view key);

// Throws aniso::Error "SUBJECT: reason" unless VALUE is valid for material key KEY (a declared
// parameter: its range, type and choices; a map: any text).
void checkMaterialValue(std::string_view key, const ParameterValue& value,
                        const std::string& subject);

struct Material
{
  using Values = std::map<std::string, ParameterValue, std::less<>>;

  std::string name;
  Values values; // every material key

  const ParameterValue& value(std::string_view key) const;
  bool operator==(const Material& o) const { return name == o.name && values == o.values; }
  bool operator!=(const Material& o) const { return !(*this == o); }
};

// A material of every key's default (brushed aluminium) named NAME.
Material defaultMaterial(std::string name);

// The name of the material a scene of one part starts with, and what a session of the
// single-material version becomes.
inline constexpr std::string_view kDefaultMaterialName = "brushed aluminium";
// The material of the window's start-up scene (scene/SceneModel.h, kStartMesh): aluminium
// brushed along the mesh's tangents, its lobe 500 times sharper along them than across them
// (n_u 10000, n_v 20), so on the built-in sphere (tangents along the parallels) each light is
// spread across the brushing into a thin streak from pole to pole.
inline constexpr std::string_view kStartMaterialName = "spun aluminium";

// Materials by name, in the order they were added.
class MaterialLibrary
{
public:
  const std::vector<Material>& materials() const { return materials_; }
  bool empty() const { return materials_.empty(); }
  // Null when there is none of that name.
  const Material* find(std::string_view name) const;
  // Throws aniso::Error "NAME: no such material".
  const Material& at(std::string_view name) const;
  bool contains(std::string_view name) const { return find(name) != nullptr; }

  // Adds MATERIAL or replaces the one of its name. Throws aniso::Error "NAME: reason" for an
  // empty name, a key that is no material key or an invalid value (the library unchanged).
  void put(const Material& material);
  // Sets one value of a material. Throws aniso::Error and changes nothing.
  void setValue(std::string_view name, std::string_view key, const ParameterValue& value);
  // False when there is none of that name.
  bool remove(std::string_view name);

  // BASE when no material has that name, else "BASE 2", "BASE 3", ...
  std::string uniqueName(std::string_view base) const;

  // A material a file gives (MATERIAL, named as the file names it) into the library: the name of
  // the library's material of that name, or of "NAME 2", "NAME 3", ..., that has the same values
  // (the file opened again, or a second part of the same material), else MATERIAL added under
  // the first of those names that is free. Throws aniso::Error as put does.
  std::string adopt(Material material);

  // The same materials, in whatever order (a session's JSON object keeps them by name).
  bool operator==(const MaterialLibrary& o) const;
  bool operator!=(const MaterialLibrary& o) const { return !(*this == o); }

private:
  std::vector<Material> materials_;
};

// The built-in metals: brushed aluminium (every default), spun aluminium (the start-up scene's),
// brushed steel, brushed titanium, turned brass (tangents around the part's Z axis), brushed
// copper, satin gold and polished chromium (isotropic), with F0 of the measured linear values of
// each metal.
const MaterialLibrary& builtinMaterials();

// The library as a document (see above); map paths under BASE_DIRECTORY relative to it (empty:
// kept as they are).
std::string materialLibraryToJson(const MaterialLibrary& library,
                                  const std::string& baseDirectory = {});
// Reads a document; relative map paths are resolved against BASE_DIRECTORY. Throws aniso::Error
// "SUBJECT: reason" naming the material and key at fault.
MaterialLibrary materialLibraryFromJson(const std::string& text, const std::string& baseDirectory,
                                        const std::string& subject);

// Files: throws aniso::Error "PATH: reason". Writing is atomic (a failure keeps any existing
// file as it was).
MaterialLibrary readMaterialLibrary(const std::string& path);
void writeMaterialLibrary(const std::string& path, const MaterialLibrary& library);

// Materials of a part by name or glob pattern: '*' any run of characters, '?' one character.
bool matchesPartPattern(std::string_view pattern, std::string_view name);
} // namespace aniso
