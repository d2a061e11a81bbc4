// Materials as named assets (core/parameters/material_library.h): which keys a material holds
// (against the declarations' scopes), the library's JSON round trip (exact, against the values
// written), the built-in metals (against the declared ranges), and bad documents (each error
// names the file, the material and the key).
#include "core/error.h"
#include "core/parameters/material_library.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;
using aniso::Material;
using aniso::MaterialLibrary;

template <typename F>
std::string errorOf(F&& f)
{
  try
  {
    f();
  }
  catch (const aniso::Error& e)
  {
    return e.what();
  }
  ADD_FAILURE() << "no aniso::Error thrown";
  return {};
}

// Every Material-scope declaration and every map is a material key, nothing else is.
TEST(MaterialLibrary, MaterialKeysAreTheMaterialScopeParametersAndTheMaps)
{
  std::vector<std::string_view> expected;
  for (const aniso::ParameterSpec& spec : aniso::parameterSpecs())
  {
    if (spec.scope == aniso::ParameterScope::Material)
    {
      expected.push_back(spec.name);
    }
  }
  for (std::string_view map : aniso::kMaterialMapKeys)
  {
    expected.push_back(map);
  }
  EXPECT_EQ(aniso::materialKeys(), expected);
  for (const char* key : {"nu", "nv", "f0", "albedo", "tangents", "bump", "normal-map"})
  {
    EXPECT_TRUE(aniso::isMaterialKey(key)) << key;
  }
  for (const char* key : {"samples", "env", "exposure", "method", "mesh"})
  {
    EXPECT_FALSE(aniso::isMaterialKey(key)) << key;
  }
}

// Random values of every material key (in range) come back bit for bit, in library order.
TEST(MaterialLibrary, JsonRoundTripIsExact)
{
  std::mt19937 random(7u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  MaterialLibrary library;
  for (const char* name : {"zeta", "alpha \"quoted\"", "grün"})
  {
    Material m = aniso::defaultMaterial(name);
    m.values["nu"] = aniso::numberValue(1.0 + unit(random) * 9999.0);
    m.values["nv"] = aniso::numberValue(unit(random) * 100.0);
    m.values["f0"].number = {unit(random), unit(random), unit(random)};
    m.values["height-scale"] = aniso::numberValue(0.5 * unit(random));
    m.values["tangents"].text = "around:0,0,1@0.25,0,0";
    m.values["bump"].text = "normal";
    m.values["normal-map"].text = "/elsewhere/grooves.png";
    library.put(m);
  }
  const MaterialLibrary back = aniso::materialLibraryFromJson(
      aniso::materialLibraryToJson(library), {}, "library.json");
  EXPECT_EQ(back, library);
  ASSERT_EQ(back.materials().size(), 3u);
  EXPECT_EQ(back.materials()[0].name, "zeta");
  EXPECT_EQ(back.materials()[2].name, "grün");
}

// Maps under the file's folder are written relative to it and read back to the same path.
TEST(MaterialLibrary, FilesKeepMapPathsRelativeToTheirFolder)
{
  const fs::path dir = fs::temp_directory_path() / ("aniso-matlib-" + std::to_string(::getpid()));
  fs::create_directories(dir / "maps");
  const std::string map = (dir / "maps" / "grooves.png").string();
  MaterialLibrary library;
  Material m = aniso::defaultMaterial("grooved");
  m.values["normal-map"].text = map;
  m.values["tpr"].text = "circular:0.5,0.5"; // a pattern, not a path
  library.put(m);
  const std::string file = (dir / "lib.json").string();
  aniso::writeMaterialLibrary(file, library);
  std::ifstream in(file);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(text.find("\"maps/grooves.png\""), std::string::npos) << text;
  EXPECT_EQ(aniso::readMaterialLibrary(file), library);
  fs::remove_all(dir);
}

// The built-in metals are valid materials with distinct names, the first the declared default.
TEST(MaterialLibrary, BuiltinMetalsAreValid)
{
  const MaterialLibrary& builtin = aniso::builtinMaterials();
  ASSERT_GE(builtin.materials().size(), 5u);
  EXPECT_EQ(builtin.materials()[0], aniso::defaultMaterial(std::string(aniso::kDefaultMaterialName)));
  for (const Material& m : builtin.materials())
  {
    for (const auto& [key, value] : m.values)
    {
      EXPECT_NO_THROW(aniso::checkMaterialValue(key, value, m.name)) << m.name << " " << key;
    }
  }
  EXPECT_EQ(builtin.at("turned brass").value("tangents").text, "around:0,0,1");
}

TEST(MaterialLibrary, LeftOutKeysTakeTheirDefaults)
{
  const MaterialLibrary library = aniso::materialLibraryFromJson(
      R"({"format": "aniso-materials", "version": 1, "materials": {"m": {"nu": 12}}})", {}, "f");
  Material expected = aniso::defaultMaterial("m");
  expected.values["nu"] = aniso::numberValue(12.0);
  EXPECT_EQ(library.at("m"), expected);
}

TEST(MaterialLibrary, BadDocumentsNameTheFileMaterialAndKey)
{
  const auto read = [](const std::string& text)
  { return errorOf([&] { aniso::materialLibraryFromJson(text, {}, "lib.json"); }); };
  EXPECT_EQ(read("{"), read("{")); // deterministic
  EXPECT_EQ(read("{").rfind("lib.json: not JSON", 0), 0u) << read("{");
  EXPECT_NE(read(R"({"format": "aniso-session", "version": 1, "materials": {}})")
                .find("lib.json: not a material library"),
            std::string::npos);
  EXPECT_NE(read(R"({"format": "aniso-materials", "version": 9, "materials": {}})")
                .find("lib.json: version 9"),
            std::string::npos);
  std::string message =
      read(R"({"format": "aniso-materials", "version": 1, "materials": {"m": {"exposure": 1}}})");
  EXPECT_NE(message.find("lib.json: material \"m\": exposure: not a material key"),
            std::string::npos)
      << message;
  message = read(R"({"format": "aniso-materials", "version": 1, "materials": {"m": {"nu": -5}}})");
  EXPECT_EQ(message.rfind("lib.json: material \"m\": nu: ", 0), 0u) << message;
  message =
      read(R"({"format": "aniso-materials", "version": 1, "materials": {"m": {"f0": [1, 2]}}})");
  EXPECT_NE(message.find("f0: expected an array of three numbers"), std::string::npos) << message;
  message = read(
      R"({"format": "aniso-materials", "version": 1, "materials": {"m": {"bump": "wobbly"}}})");
  EXPECT_EQ(message.rfind("lib.json: material \"m\": bump: ", 0), 0u) << message;
}

TEST(MaterialLibrary, UniqueNamesAndEdits)
{
  MaterialLibrary library = aniso::builtinMaterials();
  EXPECT_EQ(library.uniqueName("brushed steel"), "brushed steel 2");
  EXPECT_EQ(library.uniqueName("new"), "new");
  library.setValue("brushed steel", "nu", aniso::numberValue(5.0));
  EXPECT_EQ(library.at("brushed steel").value("nu").number[0], 5.0);
  const MaterialLibrary before = library;
  EXPECT_THROW(library.setValue("brushed steel", "nu", aniso::numberValue(-1.0)), aniso::Error);
  EXPECT_THROW(library.setValue("absent", "nu", aniso::numberValue(1.0)), aniso::Error);
  EXPECT_THROW(library.setValue("brushed steel", "exposure", aniso::numberValue(1.0)), aniso::Error);
  EXPECT_EQ(library, before);
  EXPECT_TRUE(library.remove("brushed steel"));
  EXPECT_FALSE(library.contains("brushed steel"));
}

// Globs against hand-worked cases.
TEST(MaterialLibrary, PartPatterns)
{
  EXPECT_TRUE(aniso::matchesPartPattern("shaft", "shaft"));
  EXPECT_FALSE(aniso::matchesPartPattern("shaft", "shafts"));
  EXPECT_TRUE(aniso::matchesPartPattern("shaft*", "shaft 2"));
  EXPECT_TRUE(aniso::matchesPartPattern("*bolt?", "m8 bolt3"));
  EXPECT_FALSE(aniso::matchesPartPattern("*bolt?", "m8 bolt"));
  EXPECT_TRUE(aniso::matchesPartPattern("*", ""));
  EXPECT_TRUE(aniso::matchesPartPattern("a*b*c", "axxbyyc"));
  EXPECT_FALSE(aniso::matchesPartPattern("a*b*c", "axxbyy"));
}
} // namespace

// A file's material comes into the library under its own name, is found again when the same
// values come back (a second part, the file opened again), and steps aside for another
// material of that name under "NAME 2".
TEST(MaterialLibrary, AdoptKeepsTheFilesNameAndReusesEqualMaterials)
{
  MaterialLibrary library = aniso::builtinMaterials();
  const std::size_t builtins = library.materials().size();

  Material paint = aniso::defaultMaterial("red paint");
  paint.values["albedo"] = aniso::colorValue(0.8, 0.05, 0.05);
  paint.values["f0"] = aniso::colorValue(0.04, 0.04, 0.04);
  EXPECT_EQ(library.adopt(paint), "red paint");
  EXPECT_EQ(library.materials().size(), builtins + 1);
  EXPECT_EQ(library.adopt(paint), "red paint");
  EXPECT_EQ(library.materials().size(), builtins + 1);

  // Another red paint in another file: kept apart, the first untouched.
  Material other = paint;
  other.values["albedo"] = aniso::colorValue(0.6, 0.0, 0.0);
  EXPECT_EQ(library.adopt(other), "red paint 2");
  EXPECT_EQ(library.adopt(other), "red paint 2");
  EXPECT_EQ(library.at("red paint").value("albedo"), paint.value("albedo"));
  EXPECT_EQ(library.at("red paint 2").value("albedo"), other.value("albedo"));

  // A file material named like a built-in one does not replace it.
  Material steel = aniso::defaultMaterial("brushed steel");
  steel.values["nu"] = aniso::numberValue(3.0);
  EXPECT_EQ(library.adopt(steel), "brushed steel 2");
  EXPECT_EQ(library.at("brushed steel"), *aniso::builtinMaterials().find("brushed steel"));
  EXPECT_EQ(library.adopt(aniso::defaultMaterial("")), "material");
}
