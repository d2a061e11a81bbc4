// glTF 2.0 files read as parts with their materials and placements (vtkpasses/mesh/GltfReader,
// through loadMeshBlocks and the reader program) and written back (GltfWriter). References:
// files written here by tinygltf's own writer from models built in code, hand-written JSON for
// what the extensions say, and the glTF specification's formulas worked by hand.
#include "core/error.h"
#include "core/image/image.h"
#include "core/parameters/material_library.h"
#include "tests/vtkpasses/mesh/gltf_test_files.h"
#include "tests/vtkpasses/mesh/mesh_test_files.h"
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "vtkpasses/mesh/GltfWriter.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/MeshReaderProcess.h"
#include "vtkpasses/mesh/PartPlacement.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <tiny_gltf.h>
#include <unistd.h>
#include <vector>
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
using test::kPi;
using test::squareMesh;
using test::writeModel;

class GltfReaderTest : public test::MeshFilesTest
{
};

void expectBounds(vtkPolyData* mesh, const std::array<double, 6>& expected, double tolerance)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(bounds[i], expected[size_t(i)], tolerance) << "bound " << i;
  }
}

// The message of loadMeshBlocks' error, or "" when it loads.
std::string loadError(const std::string& file)
{
  try
  {
    loadMeshBlocks(file);
  }
  catch (const Error& e)
  {
    return e.what();
  }
  return {};
}

double number(const Material& m, const char* key)
{
  return m.value(key).number[0];
}

void expectColor(const Material& m, const char* key, const glm::dvec3& expected, double tolerance)
{
  const auto& n = m.value(key).number;
  EXPECT_NEAR(n[0], expected.x, tolerance) << m.name << " " << key;
  EXPECT_NEAR(n[1], expected.y, tolerance) << m.name << " " << key;
  EXPECT_NEAR(n[2], expected.z, tolerance) << m.name << " " << key;
}

bool mentions(const std::vector<std::string>& lines, const std::string& a, const std::string& b)
{
  for (const std::string& line : lines)
  {
    if (line.find(a) != std::string::npos && line.find(b) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

// Two nodes: a red painted bracket (dielectric, roughness 0.5) and a brushed metal shaft
// (metallic, roughness 0.4, KHR_materials_anisotropy strength 0.6 along the tangent).
tinygltf::Model bracketAndShaft()
{
  tinygltf::Model model;
  model.asset.version = "2.0";
  const tinygltf::Material paint =
      test::metallicRoughness(model, "red paint", {0.8, 0.05, 0.05}, 0.0, 0.5);
  const tinygltf::Material metal =
      test::metallicRoughness(model, "", {0.91, 0.92, 0.93}, 1.0, 0.4, 0.6);
  model.materials = {paint, metal};
  tinygltf::Node bracket;
  bracket.name = "bracket";
  bracket.mesh = squareMesh(model, "bracket mesh", 0);
  bracket.translation = {0, 0, 5};
  tinygltf::Node shaft;
  shaft.mesh = squareMesh(model, "shaft", 1);
  model.nodes = {bracket, shaft};
  tinygltf::Scene scene;
  scene.nodes = {0, 1};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

TEST_F(GltfReaderTest, TwoNodesGiveTwoPartsWithTheirNamesMaterialsTangentsAndPlacements)
{
  // Checks: a part per mesh node, named by the node, else its mesh; its material named by the
  // glTF material, else "material I"; the factors mapped by the specification's formulas; the
  // file's TANGENT kept (turned Z-up); the node's translation as the placement, the surface in the
  // mesh's frame. Reference, by hand: paint: alpha = 0.5^2 = 0.25, n = 2 / 0.0625 - 2 = 30 on both
  // axes, F0 = 0.04, albedo = baseColor. Metal: alpha = 0.16, alpha_t = 0.16 + 0.84 * 0.36 =
  // 0.4624, n_u = 2 / 0.4624^2 - 2, n_v = 2 / 0.0256 - 2 = 76.125, F0 = baseColor, albedo 0.
  // glTF (x, y, z) is Z-up (x, -z, y): the tangent +Z is -Y, the translation (0, 0, 5) is
  // (0, -5, 0).
  for (const std::string name : {"parts.glb", "parts.gltf"})
  {
    SCOPED_TRACE(name);
    const std::string file = this->path(name);
    writeModel(bracketAndShaft(), file);
    const LoadedBlocks loaded = loadMeshBlocks(file);
    ASSERT_EQ(loaded.blocks.size(), 2u);
    EXPECT_EQ(loaded.blocks[0].name, "bracket");
    EXPECT_EQ(loaded.blocks[1].name, "shaft");
    ASSERT_TRUE(loaded.blocks[0].material && loaded.blocks[1].material);
    const Material& paint = *loaded.blocks[0].material;
    const Material& metal = *loaded.blocks[1].material;
    EXPECT_EQ(paint.name, "red paint");
    EXPECT_EQ(metal.name, "material 1");
    EXPECT_NEAR(number(paint, "nu"), 30.0, 1e-9);
    EXPECT_NEAR(number(paint, "nv"), 30.0, 1e-9);
    expectColor(paint, "f0", glm::dvec3(0.04), 1e-12);
    expectColor(paint, "albedo", {0.8, 0.05, 0.05}, 1e-12);
    EXPECT_NEAR(number(metal, "nu"), 2.0 / (0.4624 * 0.4624) - 2.0, 1e-9);
    EXPECT_NEAR(number(metal, "nv"), 76.125, 1e-9);
    expectColor(metal, "f0", {0.91, 0.92, 0.93}, 1e-12);
    expectColor(metal, "albedo", glm::dvec3(0.0), 0.0);
    EXPECT_EQ(metal.value("tpr").text, "") << "no rotation, no TPR map";

    vtkPolyData* shaft = loaded.blocks[1].mesh.polyData;
    vtkDataArray* tangents = shaft->GetPointData()->GetTangents();
    ASSERT_NE(tangents, nullptr);
    for (vtkIdType i = 0; i < tangents->GetNumberOfTuples(); ++i)
    {
      EXPECT_NEAR(tangents->GetComponent(i, 0), 0.0, 1e-6);
      EXPECT_NEAR(tangents->GetComponent(i, 1), -1.0, 1e-6);
      EXPECT_NEAR(tangents->GetComponent(i, 2), 0.0, 1e-6);
    }
    ASSERT_NE(shaft->GetPointData()->GetNormals(), nullptr);
    EXPECT_NEAR(shaft->GetPointData()->GetNormals()->GetComponent(0, 2), 1.0, 1e-6);
    ASSERT_NE(shaft->GetPointData()->GetTCoords(), nullptr);
    expectBounds(loaded.blocks[0].mesh.polyData, {-1, 1, -1, 1, 0, 0}, 1e-6);
    const PartMatrix moved{1, 0, 0, 0, 0, 1, 0, -5, 0, 0, 1, 0, 0, 0, 0, 1};
    for (size_t i = 0; i < 16; ++i)
    {
      EXPECT_NEAR(loaded.blocks[0].placement[i], moved[i], 1e-12) << i;
    }
    EXPECT_EQ(loaded.blocks[1].placement, kIdentityPlacement);
    EXPECT_EQ(loaded.blocks[0].mesh.report.triangles, 2);
  }
}

// A triangle (0,0,0), (1,0,0), (0,0,-1) of glTF, facing +Y, with TEXCOORD_0: 3 positions,
// 3 normals, 3 texture coordinates (96 bytes).
std::string triangleBuffer()
{
  const float values[] = {0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 1, 0, 0, 1, 0, 0, 1, 0,
                          0, 0, 1, 0, 0, 1};
  return std::string(reinterpret_cast<const char*>(values), sizeof values);
}

std::string triangleJson(const std::string& materials, const std::string& extra = {})
{
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
         R"("extensionsUsed":["KHR_materials_anisotropy"],)"
         // "arm": scale 2 and translation (1, 2, 3) as a column-major matrix; "hand" below it at
         // (0, 0, 1) turned 90 degrees about +Y (quaternion (0, sin 45, 0, cos 45)).
         R"("nodes":[{"name":"arm","matrix":[2,0,0,0, 0,2,0,0, 0,0,2,0, 1,2,3,1],"children":[1]},)"
         R"({"name":"hand","mesh":0,"translation":[0,0,1],)"
         R"("rotation":[0,0.7071067811865476,0,0.7071067811865476]},)"
         R"({"name":"finger","mesh":1}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1,"TEXCOORD_0":2},)"
         R"("material":0}]},{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1,"TEXCOORD_0":2},)"
         R"("material":1}]}],)" +
         materials + extra +
         R"("buffers":[{"uri":"triangle.bin","byteLength":96}],)"
         R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
         R"({"buffer":0,"byteOffset":36,"byteLength":36},{"buffer":0,"byteOffset":72,"byteLength":24}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
         R"("min":[0,0,-1],"max":[1,0,0]},{"bufferView":1,"componentType":5126,"count":3,"type":"VEC3"},)"
         R"({"bufferView":2,"componentType":5126,"count":3,"type":"VEC2"}]})";
}

TEST_F(GltfReaderTest, AHierarchysTransformsAndTheAnisotropyExtensionAreRead)
{
  // Checks: a child's placement is its parent's matrix times its own TRS, turned Z-up;
  // anisotropyRotation pi/2 swaps the exponents (no TPR map); anisotropyTexture gives a TPR map
  // whose direction varies across the surface as the texture's RG say; the strength from B.
  // Reference, by hand: world = T(1,2,3) S(2) T(0,0,1) R_y(90): the hand's origin at glTF
  // (1, 2, 5), Z-up (1, -5, 2); R_y(90) takes glTF +X to -Z, Z-up +X to +Y; so the placement is
  // rows (0 -2 0 1), (2 0 0 -5), (0 0 2 2). Material 0: roughness 0.5, strength 0.6, rotation
  // pi/2: n_u = 30 (across), n_v = 2 / 0.52^2 - 2. Material 1's texture: texel 0 RG (1, 0.5) is
  // the tangent, texel 1 (0.5, 1) the bitangent, B 1 so the strength is 0.6.
  this->write("triangle.bin", triangleBuffer());
  this->writeTexture("aniso.png", 2, 1, 3, {1.0f, 0.5f, 1.0f, 0.5f, 1.0f, 1.0f});
  const std::string file = this->write(
      "arm.gltf",
      triangleJson(R"("materials":[{"name":"turned","pbrMetallicRoughness":{"roughnessFactor":0.5},)"
                   R"("extensions":{"KHR_materials_anisotropy":{"anisotropyStrength":0.6,)"
                   R"("anisotropyRotation":1.5707963267948966}}},)"
                   R"({"name":"textured","pbrMetallicRoughness":{"roughnessFactor":0.5},)"
                   R"("extensions":{"KHR_materials_anisotropy":{"anisotropyStrength":0.6,)"
                   R"("anisotropyTexture":{"index":0}}}}],)",
                   R"("textures":[{"source":0}],"images":[{"uri":"aniso.png"}],)"));
  const LoadedBlocks loaded = loadMeshBlocks(file);
  ASSERT_EQ(loaded.blocks.size(), 1u) << "finger is no node of the scene";
  const MeshBlock& hand = loaded.blocks[0];
  EXPECT_EQ(hand.name, "hand");
  const PartMatrix expected{0, -2, 0, 1, 2, 0, 0, -5, 0, 0, 2, 2, 0, 0, 0, 1};
  for (size_t i = 0; i < 16; ++i)
  {
    EXPECT_NEAR(hand.placement[i], expected[i], 1e-12) << i;
  }
  // The triangle's corner glTF (1, 0, 0) is Z-up (1, 0, 0) in the mesh's frame and lands at
  // (1, -5, 2) + (0, 2, 0).
  expectBounds(hand.mesh.polyData, {0, 1, 0, 1, 0, 0}, 1e-6);
  expectBounds(placedSurface(hand.mesh.polyData, hand.placement), {-1, 1, -5, -3, 2, 2}, 1e-6);
  ASSERT_TRUE(hand.material);
  EXPECT_EQ(hand.material->name, "turned");
  EXPECT_NEAR(number(*hand.material, "nu"), 30.0, 1e-9);
  EXPECT_NEAR(number(*hand.material, "nv"), 2.0 / (0.52 * 0.52) - 2.0, 1e-9);
  EXPECT_EQ(hand.material->value("tpr").text, "");

  // The textured material: on the finger, made a scene node.
  std::string text = test::readText(file);
  text.replace(text.find(R"("nodes":[0])"), 11, R"("nodes":[2])");
  const LoadedBlocks finger = loadMeshBlocks(this->write("finger.gltf", text));
  ASSERT_EQ(finger.blocks.size(), 1u);
  ASSERT_TRUE(finger.blocks[0].material);
  const Material& textured = *finger.blocks[0].material;
  EXPECT_NEAR(number(textured, "nu"), 2.0 / (0.52 * 0.52) - 2.0, 1e-9);
  EXPECT_NEAR(number(textured, "nv"), 30.0, 1e-9);
  const std::string tpr = textured.value("tpr").text;
  ASSERT_FALSE(tpr.empty());
  const Image map = readImage(tpr);
  ASSERT_EQ(map.width, 2);
  ASSERT_EQ(map.height, 1);
  ASSERT_GE(map.channels, 2);
  // 8 bits store 0.5 as 128 / 255: a direction off by 2 / 255 at most.
  const size_t c = size_t(map.channels);
  EXPECT_NEAR(map.data[0], 1.0, 1e-4);
  EXPECT_NEAR(map.data[1], 0.0, 8e-3);
  EXPECT_NEAR(map.data[c], 0.0, 8e-3);
  EXPECT_NEAR(map.data[c + 1], 1.0, 1e-4);
}

TEST_F(GltfReaderTest, AConstantRotationWithoutTexcoordsTurnsTheTangents)
{
  // Checks: anisotropyRotation r = pi/6 (no swap: |r| <= pi/4) is a 1x1 TPR map
  // (cos r, sin r) on a part with TEXCOORD_0, the file's tangents kept; a part without
  // TEXCOORD_0 (where no map can be sampled) gets no map and its tangents turned by r instead.
  // Reference: the extension's direction cos r T + sin r B, B = N x T w, in glTF's frame: T +Z,
  // N +Y, B +X, so (sin r, 0, cos r), which is Z-up (sin r, -cos r, 0).
  const double r = kPi / 6.0;
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.materials = {test::metallicRoughness(model, "brushed", {1.0, 1.0, 1.0}, 1.0, 0.4, 0.8, r)};
  tinygltf::Node mapped;
  mapped.name = "mapped";
  mapped.mesh = squareMesh(model, "mapped", 0);
  tinygltf::Node bare;
  bare.name = "bare";
  bare.mesh = squareMesh(model, "bare", 0, {0, 0, 1}, false);
  model.nodes = {mapped, bare};
  tinygltf::Scene scene;
  scene.nodes = {0, 1};
  model.scenes.push_back(scene);
  const std::string file = this->path("turned.gltf");
  writeModel(model, file);
  const LoadedBlocks loaded = loadMeshBlocks(file);
  ASSERT_EQ(loaded.blocks.size(), 2u);
  for (const MeshBlock& block : loaded.blocks)
  {
    SCOPED_TRACE(block.name);
    ASSERT_TRUE(block.material);
    EXPECT_EQ(block.material->name, "brushed");
    vtkDataArray* tangents = block.mesh.polyData->GetPointData()->GetTangents();
    ASSERT_NE(tangents, nullptr);
    const bool withUvs = block.name == "mapped";
    EXPECT_EQ(block.mesh.polyData->GetPointData()->GetTCoords() != nullptr, withUvs);
    const glm::dvec3 expected =
        withUvs ? glm::dvec3(0, -1, 0) : glm::dvec3(std::sin(r), -std::cos(r), 0);
    for (vtkIdType i = 0; i < tangents->GetNumberOfTuples(); ++i)
    {
      EXPECT_NEAR(glm::distance(test::vec3(tangents, i), expected), 0.0, 1e-6) << i;
    }
    const std::string tpr = block.material->value("tpr").text;
    EXPECT_EQ(tpr.empty(), !withUvs);
    if (withUvs && !tpr.empty())
    {
      const Image map = readImage(tpr);
      ASSERT_EQ(map.width * map.height, 1);
      EXPECT_NEAR(map.data[0], std::cos(r), 1e-4);
      EXPECT_NEAR(map.data[1], std::sin(r), 1e-4);
    }
  }
}

TEST_F(GltfReaderTest, TexturesBecomeMapsAndAMissingOneIsAWarningNamingIt)
{
  // Checks: baseColorTexture becomes a linear albedo map (sRGB decoded), normalTexture the
  // normal map with bump mapping "normal", occlusionTexture the AO map; a texture whose file is
  // missing is a warning naming the file and the texture, and the material loads without it;
  // emissive is a warning. Reference: the sRGB curve at 0.5, 0.21404.
  this->write("triangle.bin", triangleBuffer());
  this->writeTexture("grey.png", 1, 1, 3, {0.5f, 0.5f, 0.5f});
  const std::string file = this->write(
      "maps.gltf",
      triangleJson(R"("materials":[{"name":"painted","emissiveFactor":[1,0,0],)"
                   R"("pbrMetallicRoughness":{"metallicFactor":0,"baseColorTexture":{"index":0}},)"
                   R"("occlusionTexture":{"index":0},"normalTexture":{"index":1}},{}],)",
                   R"("textures":[{"source":0},{"source":1}],)"
                   R"("images":[{"uri":"grey.png"},{"uri":"gone.png"}],)"));
  const LoadedBlocks loaded = loadMeshBlocks(file);
  ASSERT_EQ(loaded.blocks.size(), 1u);
  ASSERT_TRUE(loaded.blocks[0].material);
  const Material& m = *loaded.blocks[0].material;
  const std::vector<std::string>& warnings = loaded.blocks[0].mesh.report.readerWarnings;
  EXPECT_TRUE(mentions(warnings, "gone.png", "normalTexture")) << ::testing::PrintToString(warnings);
  EXPECT_TRUE(mentions(warnings, file + ": material painted: emissive is not rendered", ""))
      << ::testing::PrintToString(warnings);
  EXPECT_EQ(m.value("normal-map").text, "");
  ASSERT_FALSE(m.value("albedo-map").text.empty());
  const Image albedo = readImage(m.value("albedo-map").text);
  EXPECT_NEAR(albedo.data[0], 0.21404, 2e-3);
  ASSERT_FALSE(m.value("ao-map").text.empty());
  EXPECT_NEAR(readImage(m.value("ao-map").text).data[0], 0.5, 3e-3);
}

TEST_F(GltfReaderTest, WithoutTheImageModuleTexturesAreLeftOutNamingWhy)
{
  // Checks: the reader program loads the image module (core/image/image_module.h) only for an
  // image; a copy of the program without the module beside it still reads the mesh and its
  // factors, and each texture is a warning naming it and the module, not a crash or a refusal.
  // Reference: the same file read by the program in the build tree has the albedo map.
  this->write("triangle.bin", triangleBuffer());
  this->writeTexture("grey.png", 1, 1, 3, {0.5f, 0.5f, 0.5f});
  const std::string file = this->write(
      "albedo.gltf",
      triangleJson(R"("materials":[{"name":"painted","pbrMetallicRoughness":)"
                   R"({"metallicFactor":0,"baseColorTexture":{"index":0}}}],)",
                   R"("textures":[{"source":0}],"images":[{"uri":"grey.png"}],)"));
  const LoadedBlocks withModule = loadMeshBlocks(file);
  ASSERT_EQ(withModule.blocks.size(), 1u);
  ASSERT_TRUE(withModule.blocks[0].material);
  EXPECT_FALSE(withModule.blocks[0].material->value("albedo-map").text.empty());

  const std::filesystem::path alone = this->Dir / "alone";
  std::filesystem::create_directories(alone);
  const std::filesystem::path program = alone / "aniso-mesh-reader";
  std::filesystem::copy_file(meshReaderProgram(), program);
  ASSERT_EQ(::setenv("ANISO_MESH_READER", program.c_str(), 1), 0);
  std::string refused;
  LoadedBlocks withoutModule;
  try
  {
    withoutModule = loadMeshBlocks(file);
  }
  catch (const Error& e)
  {
    refused = e.what();
  }
  ::unsetenv("ANISO_MESH_READER");
  ASSERT_EQ(refused, "");
  ASSERT_EQ(withoutModule.blocks.size(), 1u);
  ASSERT_TRUE(withoutModule.blocks[0].material);
  EXPECT_EQ(withoutModule.blocks[0].material->value("albedo-map").text, "");
  EXPECT_EQ(withoutModule.blocks[0].mesh.polyData->GetNumberOfCells(),
            withModule.blocks[0].mesh.polyData->GetNumberOfCells());
  const std::vector<std::string>& warnings = withoutModule.blocks[0].mesh.report.readerWarnings;
  EXPECT_TRUE(mentions(warnings, "grey.png", "the image module does not load"))
      << ::testing::PrintToString(warnings);
}

// A square of the part's frame (z = 0, [0, 1]^2) with normals, tangents along +X, UVs.
vtkSmartPointer<vtkPolyData> square()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> uvs;
  uvs->SetName("TCoords");
  uvs->SetNumberOfComponents(2);
  for (const auto& [x, y] : std::vector<std::pair<float, float>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}})
  {
    points->InsertNextPoint(x, y, 0);
    normals->InsertNextTuple3(0, 0, 1);
    tangents->InsertNextTuple3(1, 0, 0);
    uvs->InsertNextTuple2(x, y);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType quad[4] = {0, 1, 2, 3};
  polys->InsertNextCell(4, quad);
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  surface->GetPointData()->SetNormals(normals);
  surface->GetPointData()->SetTangents(tangents);
  surface->GetPointData()->SetTCoords(uvs);
  return surface;
}

TEST_F(GltfReaderTest, ExportThenImportGivesThePartsMaterialsAndPlacementsBack)
{
  // Checks: writeGltfScene's parts read back with their names, materials (n_u, n_v, F0,
  // albedo), placements, surfaces and tangents, for .gltf and .glb. Reference: the parts written.
  Material steel = defaultMaterial("brushed steel");
  steel.values["nu"] = numberValue(800.0);
  steel.values["nv"] = numberValue(40.0);
  steel.values["f0"] = colorValue(0.562, 0.565, 0.578);
  Material paint = defaultMaterial("paint");
  paint.values["nu"] = numberValue(100.0);
  paint.values["nv"] = numberValue(100.0);
  paint.values["f0"] = colorValue(0.04, 0.04, 0.04);
  paint.values["albedo"] = colorValue(0.5, 0.1, 0.1);
  Material coated = defaultMaterial("coated");
  coated.values["nu"] = numberValue(5000.0);
  coated.values["nv"] = numberValue(20000.0);
  coated.values["f0"] = colorValue(0.9, 0.5, 0.2);
  coated.values["albedo"] = colorValue(0.3, 0.3, 0.3);
  const vtkSmartPointer<vtkPolyData> surface = square();
  const PartMatrix turned{0, -1, 0, 3, 1, 0, 0, 4, 0, 0, 2, 5, 0, 0, 0, 1};
  const std::vector<GltfPart> parts = {{"lid", surface, steel, turned},
                                       {"box", surface, paint, kIdentityPlacement},
                                       {"knob", surface, coated, kIdentityPlacement}};
  for (const std::string name : {"scene.gltf", "scene.glb"})
  {
    SCOPED_TRACE(name);
    const std::string file = this->path(name);
    writeGltfScene(file, parts);
    const LoadedBlocks loaded = loadMeshBlocks(file);
    ASSERT_EQ(loaded.blocks.size(), 3u);
    for (size_t p = 0; p < 3; ++p)
    {
      const MeshBlock& block = loaded.blocks[p];
      EXPECT_EQ(block.name, parts[p].name);
      ASSERT_TRUE(block.material);
      const Material& back = *block.material;
      EXPECT_EQ(back.name, parts[p].material.name);
      for (const char* key : {"nu", "nv"})
      {
        EXPECT_NEAR(number(back, key), number(parts[p].material, key),
                    1e-9 * number(parts[p].material, key))
            << back.name << " " << key;
      }
      for (const char* key : {"f0", "albedo"})
      {
        const auto& n = parts[p].material.value(key).number;
        expectColor(back, key, {n[0], n[1], n[2]}, 1e-12);
      }
      for (size_t i = 0; i < 16; ++i)
      {
        EXPECT_NEAR(block.placement[i], parts[p].placement[i], 1e-12) << block.name << " " << i;
      }
      expectBounds(block.mesh.polyData, {0, 1, 0, 1, 0, 0}, 1e-6);
      EXPECT_EQ(block.mesh.report.triangles, 2);
      vtkDataArray* tangents = block.mesh.polyData->GetPointData()->GetTangents();
      ASSERT_NE(tangents, nullptr);
      EXPECT_NEAR(tangents->GetComponent(0, 0), 1.0, 1e-6);
      vtkDataArray* uvs = block.mesh.polyData->GetPointData()->GetTCoords();
      ASSERT_NE(uvs, nullptr);
      double bounds[2] = {1, 0};
      for (vtkIdType i = 0; i < uvs->GetNumberOfTuples(); ++i)
      {
        bounds[0] = std::min(bounds[0], uvs->GetComponent(i, 1));
        bounds[1] = std::max(bounds[1], uvs->GetComponent(i, 1));
      }
      EXPECT_NEAR(bounds[0], 0.0, 1e-6);
      EXPECT_NEAR(bounds[1], 1.0, 1e-6);
    }
  }
}

TEST_F(GltfReaderTest, TruncatedAndMalformedFilesAreRefusedWithTheirName)
{
  // Checks: a .glb cut in half, a .gltf cut in half, malformed JSON and a missing buffer are
  // errors that begin with the file's path. Reference: the files made here.
  const std::string glb = this->path("whole.glb");
  writeModel(bracketAndShaft(), glb);
  const std::string glbBytes = test::readText(glb);
  const std::string gltf = this->path("whole.gltf");
  writeModel(bracketAndShaft(), gltf);
  const std::string gltfText = test::readText(gltf);
  for (const auto& [name, content] : std::vector<std::pair<std::string, std::string>>{
           {"cut.glb", glbBytes.substr(0, glbBytes.size() / 2)},
           {"cut.gltf", gltfText.substr(0, gltfText.size() / 2)},
           {"malformed.gltf", R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[}]})"},
           {"nobuffer.gltf", triangleJson(R"("materials":[],)")}})
  {
    const std::string file = this->write(name, content);
    const std::string message = loadError(file);
    EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
  }
}
} // namespace
} // namespace aniso
