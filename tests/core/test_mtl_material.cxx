// core/formats/mtl_material: an MTL material as the Ashikhmin-Shirley material, against the
// formulas of glTF's KHR_materials_anisotropy and of the Beckmann-Blinn-Phong correspondence
// computed here from their definitions, and the MTL specification's meaning of each key.
#include "core/formats/mtl.h"
#include "core/formats/mtl_material.h"
#include "core/parameters/material_library.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

bool anyWarning(const std::vector<std::string>& warnings, const std::string& part1,
                const std::string& part2 = {})
{
  for (const std::string& w : warnings)
  {
    if (w.find(part1) != std::string::npos && w.find(part2) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

void expectColor(const Material& m, const char* key, double r, double g, double b)
{
  const auto& c = m.value(key).number;
  EXPECT_NEAR(c[0], r, 1e-12) << key;
  EXPECT_NEAR(c[1], g, 1e-12) << key;
  EXPECT_NEAR(c[2], b, 1e-12) << key;
}

MtlMaterial onlyMaterial(const std::string& text, const std::string& path = "m.mtl")
{
  const MtlLibrary library = parseMtl(text, path);
  EXPECT_TRUE(library.warnings.empty());
  EXPECT_EQ(library.materials.size(), 1u);
  return library.materials.front();
}

TEST(MtlMaterial, MetallicRoughnessFollowsKhrMaterialsAnisotropy)
{
  // Checks: alpha = r^2, alpha_t = mix(alpha, 1, s^2) along t, alpha_b = alpha, n = 2/alpha^2-2;
  // F0 = mix(0.04, base, m), albedo = base (1 - m), for a PBR material read from a .mtl.
  const MtlMaterial mtl = onlyMaterial("newmtl pbr\nKd 0.8 0.4 0.2\nPr 0.5\nPm 0.25\naniso 0.6\n");
  std::vector<std::string> warnings;
  const Material m = materialFromMtl(mtl, "m.mtl", warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(m.name, "pbr");
  const double alpha = 0.25;
  const double alphaT = alpha + (1.0 - alpha) * 0.36;
  EXPECT_NEAR(m.value("nu").number[0], 2.0 / (alphaT * alphaT) - 2.0, 1e-9);
  EXPECT_NEAR(m.value("nv").number[0], 30.0, 1e-9);
  expectColor(m, "f0", 0.04 + 0.76 * 0.25, 0.04 + 0.36 * 0.25, 0.04 + 0.16 * 0.25);
  expectColor(m, "albedo", 0.6, 0.3, 0.15);
  MaterialLibrary library;
  EXPECT_NO_THROW(library.put(m)) << "every value within its declared range";

  // A full metal without anisotropy is isotropic with F0 the base and no diffuse albedo:
  // r = 0.1^(1/4), alpha = sqrt(0.1), n = 2 / 0.1 - 2 = 18.
  const Material metal =
      materialFromMtl(onlyMaterial("newmtl metal\nKd 0.9 0.6 0.3\nPr " +
                                   std::to_string(std::pow(0.1, 0.25)) + "\nPm 1\n"),
                      "m.mtl", warnings);
  EXPECT_NEAR(metal.value("nu").number[0], 18.0, 1e-4);
  EXPECT_NEAR(metal.value("nv").number[0], 18.0, 1e-4);
  expectColor(metal, "f0", 0.9, 0.6, 0.3);
  expectColor(metal, "albedo", 0.0, 0.0, 0.0);
}

TEST(MtlMaterial, PbrExponentsStayInTheDeclaredRange)
{
  // Checks: Pr 0 (alpha 0, an infinite exponent) gives nu's declared maximum on both axes; Pr 1
  // with full anisotropy the broadest lobe, 0.
  const double top = parameterSpec("nu").maximum;
  std::vector<std::string> warnings;
  const Material mirror =
      materialFromMtl(onlyMaterial("newmtl m\nPr 0\naniso 0\n"), "m.mtl", warnings);
  EXPECT_DOUBLE_EQ(mirror.value("nu").number[0], top);
  EXPECT_DOUBLE_EQ(mirror.value("nv").number[0], top);
  const Material broad =
      materialFromMtl(onlyMaterial("newmtl b\nPr 1\naniso 1\n"), "m.mtl", warnings);
  EXPECT_DOUBLE_EQ(broad.value("nu").number[0], 0.0);
  EXPECT_DOUBLE_EQ(broad.value("nv").number[0], 0.0);
  // r = 0.5 along b (alpha 0.25, n 30); s = 1: alpha_t = 1, n_u = 0.
  const Material streak =
      materialFromMtl(onlyMaterial("newmtl s\nPr 0.5\naniso 1\n"), "m.mtl", warnings);
  EXPECT_NEAR(streak.value("nu").number[0], 0.0, 1e-12);
  EXPECT_NEAR(streak.value("nv").number[0], 30.0, 1e-9);
}

TEST(MtlMaterial, PbrWithoutRoughnessTakesItFromNs)
{
  // Checks: Pm without Pr: alpha = sqrt(2 / (Ns + 2)), so n_u = n_v = Ns; no Kd: base 0.8.
  std::vector<std::string> warnings;
  const Material m = materialFromMtl(onlyMaterial("newmtl p\nNs 50\nPm 0\n"), "m.mtl", warnings);
  EXPECT_NEAR(m.value("nu").number[0], 50.0, 1e-9);
  EXPECT_NEAR(m.value("nv").number[0], 50.0, 1e-9);
  expectColor(m, "albedo", 0.8, 0.8, 0.8);
  expectColor(m, "f0", 0.04, 0.04, 0.04);
}

TEST(MtlMaterial, AMetallicMapAloneMakesTheMetallicOneOnlyWhenItExists)
{
  // Checks: map_Pm without Pm: metallic 1 (F0 = Kd, the map mixes it) when the map exists; when
  // it does not, the MTL default metallic 0 (F0 0.04, albedo Kd).
  const fs::path dir = fs::temp_directory_path() / "aniso_test_mtl_metallic_map";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string mtlPath = (dir / "m.mtl").string();
  const MtlMaterial mtl = onlyMaterial("newmtl m\nKd 0.6 0.4 0.2\nmap_Pm metal.png\n", mtlPath);
  std::vector<std::string> warnings;
  Material m = materialFromMtl(mtl, mtlPath, warnings);
  expectColor(m, "f0", 0.04, 0.04, 0.04);
  expectColor(m, "albedo", 0.6, 0.4, 0.2);
  EXPECT_EQ(warnings.size(), 1u);
  std::ofstream(dir / "metal.png") << "not read here";
  warnings.clear();
  m = materialFromMtl(mtl, mtlPath, warnings);
  expectColor(m, "f0", 0.6, 0.4, 0.2);
  expectColor(m, "albedo", 0.6, 0.4, 0.2);
  EXPECT_EQ(m.value("metallic-map").text, (dir / "metal.png").string());
  EXPECT_TRUE(warnings.empty());
  fs::remove_all(dir);
}

TEST(MtlMaterial, PhongTakesKdKsAndNsAsTheyAre)
{
  // Checks: without PBR keys albedo = Kd, F0 = Ks clamped to [0, 1], n_u = n_v = Ns clamped to
  // the declared range; absent Ks: a dielectric's 0.04.
  std::vector<std::string> warnings;
  const Material m = materialFromMtl(
      onlyMaterial("newmtl phong\nKd 0.6 0.5 0.4\nKs 1.5 0.25 0\nNs 250\n"), "m.mtl", warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_DOUBLE_EQ(m.value("nu").number[0], 250.0);
  EXPECT_DOUBLE_EQ(m.value("nv").number[0], 250.0);
  expectColor(m, "f0", 1.0, 0.25, 0.0);
  expectColor(m, "albedo", 0.6, 0.5, 0.4);
  const Material huge =
      materialFromMtl(onlyMaterial("newmtl h\nKd 2 0 0\nNs 1e8\n"), "m.mtl", warnings);
  EXPECT_DOUBLE_EQ(huge.value("nu").number[0], parameterSpec("nu").maximum);
  expectColor(huge, "f0", 0.04, 0.04, 0.04);
  expectColor(huge, "albedo", 1.0, 0.0, 0.0);
}

TEST(MtlMaterial, TexturesResolveAgainstTheMtlDirectoryAndMissingOnesWarn)
{
  // Checks: map_Kd -> albedo-map, norm -> normal-map with bump "normal", map_Bump -> height-map
  // with -bm scaling height-scale, map_Pm -> metallic-map with F0 mix(0.04, Kd, Pm) and albedo
  // Kd; paths absolute under the .mtl's directory; a missing texture a warning naming the .mtl,
  // its line and the texture, the material without that map; the maps without a material key
  // (map_Ks, map_Ns, map_Pr), texture transforms and anisor warned as not applied.
  const fs::path dir = fs::temp_directory_path() / "aniso_test_mtl_material";
  fs::remove_all(dir);
  fs::create_directories(dir / "tex");
  for (const char* name : {"tex/albedo.png", "n.png", "h.png", "metal.png"})
  {
    std::ofstream(dir / name) << "not read here";
  }
  const std::string mtlPath = (dir / "lib.mtl").string();
  const MtlMaterial mtl = onlyMaterial("newmtl textured\n"        // 1
                                       "Kd 0.5 0.5 0.5\n"         // 2
                                       "Pm 0.5\n"                 // 3
                                       "Pr 1\n"                   // 4
                                       "anisor 0.25\n"            // 5
                                       "map_Kd tex/albedo.png\n"  // 6
                                       "norm n.png\n"             // 7
                                       "bump -bm 2 h.png\n"       // 8
                                       "map_Pm metal.png\n"       // 9
                                       "map_Ks -s 2 2 gone.png\n" // 10
                                       "map_Pr rough.png\n",      // 11
                                       mtlPath);
  std::vector<std::string> warnings;
  Material m = materialFromMtl(mtl, mtlPath, warnings);
  EXPECT_EQ(m.value("albedo-map").text, (dir / "tex/albedo.png").string());
  EXPECT_EQ(m.value("normal-map").text, (dir / "n.png").string());
  EXPECT_EQ(m.value("bump").text, "normal");
  EXPECT_EQ(m.value("height-map").text, (dir / "h.png").string());
  EXPECT_DOUBLE_EQ(m.value("height-scale").number[0],
                   2.0 * parameterSpec("height-scale").defaultValue[0]);
  EXPECT_EQ(m.value("metallic-map").text, (dir / "metal.png").string());
  expectColor(m, "f0", 0.27, 0.27, 0.27);
  expectColor(m, "albedo", 0.5, 0.5, 0.5);
  EXPECT_TRUE(anyWarning(warnings, mtlPath + ":5: anisor", "not applied"));
  EXPECT_TRUE(anyWarning(warnings, mtlPath + ":10: map_Ks gone.png", "not applied"));
  EXPECT_TRUE(anyWarning(warnings, mtlPath + ":11: map_Pr rough.png", "not applied"));
  EXPECT_EQ(warnings.size(), 3u);

  // The same material with its textures gone.
  for (const char* name : {"tex/albedo.png", "n.png", "h.png", "metal.png"})
  {
    fs::remove(dir / name);
  }
  warnings.clear();
  m = materialFromMtl(mtl, mtlPath, warnings);
  for (const char* key : {"albedo-map", "normal-map", "height-map", "metallic-map"})
  {
    EXPECT_EQ(m.value(key).text, "") << key;
  }
  EXPECT_EQ(m.value("bump").text, "none");
  EXPECT_TRUE(anyWarning(warnings, mtlPath + ":6: map_Kd tex/albedo.png: no such file"));
  EXPECT_TRUE(anyWarning(warnings, mtlPath + ":7: norm n.png: no such file"));
  EXPECT_TRUE(anyWarning(warnings, mtlPath + ":8: map_Bump h.png: no such file"));
  EXPECT_TRUE(anyWarning(warnings, mtlPath + ":9: map_Pm metal.png: no such file"));
  // Without its metallic map the material is the plain metallic-roughness mapping.
  expectColor(m, "albedo", 0.25, 0.25, 0.25);
  MaterialLibrary library;
  EXPECT_NO_THROW(library.put(m));
  fs::remove_all(dir);
}
} // namespace
} // namespace aniso
