#pragma once
// Wavefront material libraries (.mtl), as OBJ files name them with mtllib: named materials with
// the statements this project maps onto its material (mtl_material.h), as the file writes them.
//
// Read: newmtl NAME; Kd, Ks (r g b, or one value for grey); Ns; d (opacity, also "d -halo F")
// and Tr (transparency, 1 - d); the PBR extension's Pr (roughness), Pm (metallic), Ps (sheen),
// aniso (anisotropy strength), anisor (anisotropy rotation); the textures map_Kd, map_Ks,
// map_Ns, map_Bump / bump (a height map, as the MTL specification has it), norm (a tangent-space
// normal map), map_Pr, map_Pm, each with its options (-bm, -o, -s, -t, -mm, -imfchan, -clamp,
// -blendu, -blendv, -boost, -cc, -texres, -type) before the file name, which is the rest of the
// line (spaces kept; backslashes, as Windows writers leave them, made forward slashes).
// Statements of the format that nothing here uses (Ka, Ke, Ni, illum, Tf, map_Ka, map_d, disp,
// refl, ...) are passed over in silence. Keywords are compared without case ("map_bump").
//
// Robust to any bytes: a malformed line (a number that is no finite number or out of its range,
// too few or too many values, an unknown statement or texture option, a statement before any
// newmtl, a repeated material name, a name or file name that is not UTF-8, a line over
// kMaxMtlLineLength) is skipped with a warning
// "PATH:LINE: reason"; parseMtl never throws. At most kMaxMtlMaterials materials and
// kMaxMtlWarnings warnings (then one telling how many more) are kept.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace aniso
{
inline constexpr std::size_t kMaxMtlFileBytes = 16u << 20;
inline constexpr std::size_t kMaxMtlLineLength = 4096;
inline constexpr std::size_t kMaxMtlNameLength = 1024;
inline constexpr std::size_t kMaxMtlMaterials = 65536;
inline constexpr std::size_t kMaxMtlWarnings = 100;

struct MtlTexture
{
  std::string file;            // as written (relative to the .mtl's directory, or absolute)
  double bumpMultiplier = 1.0; // -bm
  bool transformed = false;    // -o, -s or -t other than the identity
  int line = 0;                // where the statement is, for messages
};

using MtlColor = std::array<double, 3>;

struct MtlMaterial
{
  std::string name;
  int line = 0; // its newmtl
  std::optional<MtlColor> kd, ks;
  std::optional<double> ns;                // specular exponent, >= 0
  std::optional<double> opacity;           // d, or 1 - Tr; in [0, 1]
  std::optional<double> pr, pm, ps, aniso; // in [0, 1]
  std::optional<double> anisor;            // any finite value
  int anisorLine = 0;
  std::optional<MtlTexture> mapKd, mapKs, mapNs, bump, norm, mapPr, mapPm;

  // Whether any key of the PBR extension's metallic-roughness model is given (Pr, Pm, aniso,
  // anisor, map_Pr, map_Pm): then the material is read as metallic-roughness, else as Phong.
  bool hasPbrKeys() const;
};

struct MtlLibrary
{
  std::vector<MtlMaterial> materials; // in file order, names unique
  std::vector<std::string> warnings;  // "PATH:LINE: reason"

  // Null when there is none of that name.
  const MtlMaterial* find(std::string_view name) const;
};

// The materials of TEXT, PATH naming it in warnings. Never throws.
MtlLibrary parseMtl(std::string_view text, const std::string& path);

// The file at PATH. Throws aniso::Error "PATH: reason" when it cannot be read or is larger than
// kMaxMtlFileBytes; whatever it holds otherwise is parseMtl's.
MtlLibrary readMtlFile(const std::string& path);
} // namespace aniso
