// loadMeshBlocks on OBJ files with MTL material libraries (VtkReaders' OBJ statement scan,
// core/formats/mtl). References: an .obj and .mtl written by VTK's vtkOBJExporter from a render
// window of actors with their vtkProperty colours and specular power (the values set on the
// properties are the reference); hand-written files whose definition is the reference, for the
// PBR keys, materials switching inside a group, malformed lines and missing files.
#include "core/error.h"
#include "core/parameters/material_library.h"
#include "tests/vtkpasses/mesh/mesh_test_files.h"
#include "vtkpasses/mesh/MeshLoader.h"

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>
#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkOBJExporter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;
using test::readText;

class ObjMaterialsTest : public test::MeshFilesTest
{
};

const MeshBlock& blockNamed(const LoadedBlocks& loaded, const std::string& name)
{
  for (const MeshBlock& block : loaded.blocks)
  {
    if (block.name == name)
    {
      return block;
    }
  }
  std::string names;
  for (const MeshBlock& block : loaded.blocks)
  {
    names += " '" + block.name + "'";
  }
  throw std::runtime_error("no part " + name + " among" + names);
}

std::vector<std::string> namesOf(const LoadedBlocks& loaded)
{
  std::vector<std::string> names;
  for (const MeshBlock& block : loaded.blocks)
  {
    names.push_back(block.name);
  }
  return names;
}

bool warned(const MeshBlock& block, const std::string& part1, const std::string& part2 = {})
{
  for (const std::string& w : block.mesh.report.readerWarnings)
  {
    if (w.find(part1) != std::string::npos && w.find(part2) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

void expectColor(const Material& m, const char* key, const std::array<double, 3>& expected,
                 double tolerance)
{
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(m.value(key).number[c], expected[c], tolerance) << m.name << " " << key;
  }
}

// What vtkOBJExporter writes of an actor's property (VTK 9.1, IO/Export/vtkOBJExporter.cxx):
// Kd its diffuse coefficient times its diffuse colour, Ks its specular coefficient times its
// specular colour, Ns its specular power.
struct ActorFinish
{
  std::array<double, 3> diffuse;
  std::array<double, 3> specular;
  double power;
};

TEST_F(ObjMaterialsTest, PartsOfVtkObjExporterCarryTheirPropertiesAsMaterials)
{
  // Checks: vtkOBJExporter's .obj and .mtl of two actors load as two parts, each with its own
  // material: albedo = diffuse x diffuse colour, F0 = specular x specular colour, n_u = n_v =
  // the specular
  // power (Phong mapping), within the %g precision the exporter writes.
  const std::array<ActorFinish, 2> finishes = {
      ActorFinish{{0.8, 0.2, 0.1}, {0.9, 0.85, 0.7}, 40.0},
      ActorFinish{{0.1, 0.3, 0.9}, {0.25, 0.25, 0.25}, 10.0}};
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  // A second sphere, not a cube: VTK 9.1's exporter numbers a texture coordinate (vt) by its
  // vertex's index in the whole file, past the vt lines it writes, so vtkOBJReader makes a
  // wrong surface of a textured actor's file.
  vtkNew<vtkSphereSource> other;
  other->SetCenter(3, 0, 0);
  other->SetThetaResolution(12);
  other->SetPhiResolution(6);
  vtkAlgorithm* sources[] = {sphere, other};
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (size_t i = 0; i < finishes.size(); ++i)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sources[i]->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    const ActorFinish& f = finishes[i];
    actor->GetProperty()->SetDiffuseColor(f.diffuse[0], f.diffuse[1], f.diffuse[2]);
    actor->GetProperty()->SetSpecularColor(f.specular[0], f.specular[1], f.specular[2]);
    actor->GetProperty()->SetSpecular(0.5);
    actor->GetProperty()->SetSpecularPower(f.power);
    renderer->AddActor(actor);
    actors.push_back(actor);
  }
  vtkNew<vtkOBJExporter> exporter;
  exporter->SetRenderWindow(window);
  exporter->SetFilePrefix(this->path("scene").c_str());
  exporter->Write();
  const std::string obj = this->path("scene.obj");
  ASSERT_TRUE(fs::exists(obj));
  ASSERT_TRUE(fs::exists(this->path("scene.mtl")));

  const LoadedBlocks loaded = loadMeshBlocks(obj);
  ASSERT_EQ(loaded.blocks.size(), 2u) << readText(obj).substr(0, 400);
  EXPECT_TRUE(loaded.warnings.empty());
  for (size_t i = 0; i < finishes.size(); ++i)
  {
    const MeshBlock& block = loaded.blocks[i];
    ASSERT_TRUE(block.material) << block.name << "\n" << readText(this->path("scene.mtl"));
    const Material& m = *block.material;
    const ActorFinish& f = finishes[i];
    constexpr double kPrinted = 1e-5; // %g: six significant digits
    EXPECT_NEAR(m.value("nu").number[0], f.power, kPrinted * f.power);
    EXPECT_NEAR(m.value("nv").number[0], f.power, kPrinted * f.power);
    expectColor(m, "albedo", f.diffuse, kPrinted);
    expectColor(m, "f0", {0.5 * f.specular[0], 0.5 * f.specular[1], 0.5 * f.specular[2]}, kPrinted);
  }
  EXPECT_NE(loaded.blocks[0].material->name, loaded.blocks[1].material->name);
  EXPECT_EQ(loaded.blocks[0].mesh.polyData->GetNumberOfPolys(),
            sphere->GetOutput()->GetNumberOfPolys());
  EXPECT_EQ(loaded.blocks[1].mesh.polyData->GetNumberOfPolys(),
            other->GetOutput()->GetNumberOfPolys());
}

// A tetrahedron's four faces, under names and materials the test chooses.
const std::string kTetraVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";

TEST_F(ObjMaterialsTest, MetallicRoughnessKeysMapAsKhrMaterialsAnisotropy)
{
  // Checks: a part whose material has Pr, Pm, aniso gets alpha = Pr^2, alpha_t = mix(alpha, 1,
  // aniso^2), n = 2/alpha^2 - 2 per axis, F0 = mix(0.04, Kd, Pm), albedo = Kd (1 - Pm); its
  // map_Kd (found, relative to the .mtl's folder) becomes the albedo map; anisor is warned as
  // not applied, naming the .mtl and its line.
  fs::create_directories(this->Dir / "materials" / "tex");
  this->write("materials/tex/paint.png", "not read by the loader");
  const std::string mtl = this->write("materials/pbr.mtl", "newmtl brushed\n"
                                                           "Kd 0.9 0.8 0.5\n"
                                                           "Pr 0.3\n"
                                                           "Pm 0.75\n"
                                                           "aniso 0.8\n"
                                                           "anisor 0.25\n"
                                                           "map_Kd tex/paint.png\n");
  const std::string obj =
      this->write("part.obj", "mtllib materials/pbr.mtl\n" + kTetraVertices +
                                  "g plate\nusemtl brushed\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const LoadedBlocks loaded = loadMeshBlocks(obj);
  ASSERT_EQ(namesOf(loaded), (std::vector<std::string>{"plate"}));
  const MeshBlock& block = loaded.blocks[0];
  ASSERT_TRUE(block.material);
  const Material& m = *block.material;
  EXPECT_EQ(m.name, "brushed");
  const double alpha = 0.3 * 0.3;
  const double alphaT = alpha + (1.0 - alpha) * 0.64;
  EXPECT_NEAR(m.value("nu").number[0], 2.0 / (alphaT * alphaT) - 2.0, 1e-9);
  EXPECT_NEAR(m.value("nv").number[0], 2.0 / (alpha * alpha) - 2.0, 1e-9);
  expectColor(m, "f0", {0.04 + 0.86 * 0.75, 0.04 + 0.76 * 0.75, 0.04 + 0.46 * 0.75}, 1e-12);
  expectColor(m, "albedo", {0.9 * 0.25, 0.8 * 0.25, 0.5 * 0.25}, 1e-12);
  EXPECT_EQ(fs::path(m.value("albedo-map").text), this->Dir / "materials" / "tex" / "paint.png");
  EXPECT_TRUE(warned(block, mtl + ":6: anisor", "not applied"));
}

TEST_F(ObjMaterialsTest, AGroupOfSeveralMaterialsIsSplitIntoGroupSlashMaterial)
{
  // Checks: usemtl switching inside group "body" makes parts "body/red" and "body/blue" (the
  // faces of each material wherever they come in the group); group "lid" of one material is
  // one part "lid" with it; the material state carries over a g statement, as in OBJ; faces
  // before any usemtl in a split group keep the group's name and no material.
  this->write("two.mtl", "newmtl red\nKd 1 0 0\nKs 0.1 0.1 0.1\nNs 20\n"
                         "newmtl blue\nKd 0 0 1\nKs 0.2 0.2 0.2\nNs 80\n");
  const std::string obj =
      this->write("split.obj", "mtllib two.mtl\n" + kTetraVertices +
                                   "g body\nf 1 3 2\nusemtl red\nf 1 2 4\nusemtl blue\nf 1 4 3\n"
                                   "usemtl red\nf 2 3 4\ng lid\nf 1 2 4\n");
  const LoadedBlocks loaded = loadMeshBlocks(obj);
  ASSERT_EQ(namesOf(loaded), (std::vector<std::string>{"body", "body/red", "body/blue", "lid"}));
  EXPECT_FALSE(loaded.blocks[0].material);
  const MeshBlock& red = blockNamed(loaded, "body/red");
  ASSERT_TRUE(red.material);
  EXPECT_EQ(red.material->name, "red");
  EXPECT_EQ(red.mesh.polyData->GetNumberOfPolys(), 2);
  EXPECT_DOUBLE_EQ(red.material->value("nu").number[0], 20.0);
  expectColor(*red.material, "albedo", {1, 0, 0}, 0.0);
  const MeshBlock& blue = blockNamed(loaded, "body/blue");
  ASSERT_TRUE(blue.material);
  EXPECT_EQ(blue.mesh.polyData->GetNumberOfPolys(), 1);
  EXPECT_DOUBLE_EQ(blue.material->value("nv").number[0], 80.0);
  expectColor(*blue.material, "f0", {0.2, 0.2, 0.2}, 0.0);
  const MeshBlock& lid = blockNamed(loaded, "lid");
  ASSERT_TRUE(lid.material);
  EXPECT_EQ(lid.material->name, "red");
  EXPECT_EQ(*lid.material, *red.material) << "parts of one material share it";
}

TEST_F(ObjMaterialsTest, MalformedMtlLinesMissingTexturesAndUnknownMaterialsAreWarnings)
{
  // Checks: a malformed line of the .mtl is a warning "MTL:LINE: reason" and the rest of the
  // material is read; a missing texture is a warning naming the .mtl and the texture, the
  // material loading without it; usemtl of a name no library defines warns, naming it, and its
  // part loads without a material.
  const std::string mtl = this->write("bad.mtl", "newmtl ok\n"
                                                 "Kd 0.5 oops 0.5\n"
                                                 "Ks 0.3 0.3 0.3\n"
                                                 "Ns 64\n"
                                                 "norm missing-normals.png\n");
  const std::string obj = this->write(
      "bad.obj", "mtllib bad.mtl\n" + kTetraVertices +
                     "o a\nusemtl ok\nf 1 3 2\nf 1 2 4\no b\nusemtl nowhere\nf 1 4 3\n");
  const LoadedBlocks loaded = loadMeshBlocks(obj);
  ASSERT_EQ(namesOf(loaded), (std::vector<std::string>{"a", "b"}));
  const MeshBlock& a = loaded.blocks[0];
  ASSERT_TRUE(a.material);
  EXPECT_DOUBLE_EQ(a.material->value("nu").number[0], 64.0);
  expectColor(*a.material, "f0", {0.3, 0.3, 0.3}, 0.0);
  expectColor(*a.material, "albedo", {0.8, 0.8, 0.8}, 0.0); // Kd refused: MTL's usual default
  EXPECT_EQ(a.material->value("normal-map").text, "");
  EXPECT_TRUE(warned(a, mtl + ":2: Kd: 'oops'"));
  EXPECT_TRUE(warned(a, mtl + ":5: norm missing-normals.png: no such file"));
  EXPECT_FALSE(loaded.blocks[1].material);
  EXPECT_TRUE(warned(loaded.blocks[1], obj + ":11: usemtl nowhere: no such material"));
}

TEST_F(ObjMaterialsTest, AMissingMtlIsOneWarningNamingItAndThePartsLoad)
{
  // Checks: mtllib of a file that does not exist: one warning naming it; the parts load as
  // without materials; usemtl names from it warn each once.
  const std::string obj =
      this->write("lonely.obj", "mtllib gone.mtl\n" + kTetraVertices +
                                    "g a\nusemtl m\nf 1 3 2\ng b\nusemtl m\nf 1 2 4\n");
  const LoadedBlocks loaded = loadMeshBlocks(obj);
  ASSERT_EQ(namesOf(loaded), (std::vector<std::string>{"a", "b"}));
  const std::vector<std::string>& warnings = loaded.blocks[0].mesh.report.readerWarnings;
  int namingIt = 0;
  for (const std::string& w : warnings)
  {
    namingIt += w.find(this->path("gone.mtl") + ": no such file") != std::string::npos;
  }
  EXPECT_EQ(namingIt, 1);
  EXPECT_FALSE(loaded.blocks[0].material);
  EXPECT_FALSE(loaded.blocks[1].material);
  EXPECT_EQ(loaded.blocks[0].mesh.polyData->GetNumberOfPolys(), 1);
}

TEST_F(ObjMaterialsTest, ATruncatedObjWithMaterialsLoadsAsWithoutThem)
{
  // Checks: vtkOBJExporter's file cut at every tenth of its length gives what the same cut
  // with its mtllib and usemtl lines made comments gives (the same error, or the same faces), so
  // the materials change nothing of how a truncated file is refused or loaded; each part that loads
  // with a material has the exporter's values.
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetDiffuseColor(0.2, 0.6, 0.4);
  actor->GetProperty()->SetSpecularPower(33);
  renderer->AddActor(actor);
  vtkNew<vtkOBJExporter> exporter;
  exporter->SetRenderWindow(window);
  exporter->SetFilePrefix(this->path("whole").c_str());
  exporter->Write();
  const std::string text = readText(this->path("whole.obj"));
  ASSERT_GT(text.size(), 100u);
  // The same text with its material statements made comments of the same length, so a cut
  // ends at the same byte and line in both.
  std::string plain = text;
  for (const char* statement : {"\nmtllib", "\nusemtl"})
  {
    for (size_t at = plain.find(statement); at != std::string::npos;
         at = plain.find(statement, at + 1))
    {
      plain[at + 1] = '#';
    }
  }
  ASSERT_NE(plain, text);
  auto outcome = [](const std::string& file)
  {
    try
    {
      const LoadedBlocks loaded = loadMeshBlocks(file);
      vtkIdType faces = 0;
      for (const MeshBlock& block : loaded.blocks)
      {
        faces += block.mesh.polyData->GetNumberOfPolys();
        if (block.material)
        {
          EXPECT_NEAR(block.material->value("nu").number[0], 33.0, 1e-9);
          expectColor(*block.material, "albedo", {0.2, 0.6, 0.4}, 1e-6);
        }
      }
      return "faces " + std::to_string(faces);
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
      return "error " + message.substr(std::min(message.size(), file.size()));
    }
  };
  for (int tenth = 1; tenth < 10; ++tenth)
  {
    SCOPED_TRACE("cut at tenth " + std::to_string(tenth));
    const size_t cut = text.size() * static_cast<size_t>(tenth) / 10;
    const std::string withMaterials = this->write("cut.obj", text.substr(0, cut));
    const std::string without = this->write("plain.obj", plain.substr(0, cut));
    EXPECT_EQ(outcome(withMaterials), outcome(without));
  }
}
TEST_F(ObjMaterialsTest, WarningsAboutMaterialsAreCapped)
{
  // Checks: an OBJ of 300 usemtl names that no library defines, a face each, loads its 300
  // parts with 200 such warnings and one saying that more are left out (every part carries the
  // file's warnings, so they must not grow with the file).
  std::string text = kTetraVertices;
  for (int i = 0; i < 300; ++i)
  {
    text += "g part" + std::to_string(i) + "\nusemtl m" + std::to_string(i) + "\nf 1 2 3\n";
  }
  const std::string obj = this->write("many.obj", text);
  const LoadedBlocks loaded = loadMeshBlocks(obj);
  ASSERT_EQ(loaded.blocks.size(), 300u);
  int unknown = 0;
  int leftOut = 0;
  for (const std::string& w : loaded.blocks[0].mesh.report.readerWarnings)
  {
    unknown += w.find(": no such material") != std::string::npos;
    leftOut += w == obj + ": more warnings about its materials are left out";
  }
  EXPECT_EQ(unknown, 200);
  EXPECT_EQ(leftOut, 1);
}

// Debian's assimp-testmodels (scripts/setup.sh installs it): OBJ files and libraries written by
// other programs (3ds Max's exporter among them). Their .mtl values, read off the files, are the
// reference.
const fs::path kAssimpObj = "/usr/share/assimp/models/OBJ";

TEST_F(ObjMaterialsTest, AssimpsCubeSwitchingMaterialsPerFaceIsSplitByMaterial)
{
  // Checks: cube_usemtl.obj, one group "cube" whose faces switch between mtl3 (defined in no
  // library), mtl and mtl2, gives parts cube/mtl3 (2 faces, no material, a warning naming it),
  // cube/mtl (6 faces: Ns 200, Ks 0.05, Kd 1) and cube/mtl2 (4 faces: Ns 16, Ks 0.375, Kd 1).
  const std::string obj = (kAssimpObj / "cube_usemtl.obj").string();
  ASSERT_TRUE(fs::exists(obj)) << "install assimp-testmodels (scripts/setup.sh)";
  const LoadedBlocks loaded = loadMeshBlocks(obj);
  ASSERT_EQ(namesOf(loaded), (std::vector<std::string>{"cube/mtl3", "cube/mtl", "cube/mtl2"}));
  EXPECT_FALSE(loaded.blocks[0].material);
  EXPECT_TRUE(warned(loaded.blocks[0], obj + ":21: usemtl mtl3: no such material"));
  const std::array<std::pair<double, double>, 2> nsKs = {{{200.0, 0.05}, {16.0, 0.375}}};
  const std::array<vtkIdType, 3> faces = {2, 6, 4};
  for (size_t b = 0; b < 3; ++b)
  {
    EXPECT_EQ(loaded.blocks[b].mesh.polyData->GetNumberOfPolys(), faces[b]) << b;
  }
  for (size_t b = 1; b < 3; ++b)
  {
    ASSERT_TRUE(loaded.blocks[b].material);
    const Material& m = *loaded.blocks[b].material;
    EXPECT_DOUBLE_EQ(m.value("nu").number[0], nsKs[b - 1].first);
    EXPECT_DOUBLE_EQ(m.value("nv").number[0], nsKs[b - 1].first);
    expectColor(m, "f0", {nsKs[b - 1].second, nsKs[b - 1].second, nsKs[b - 1].second}, 1e-12);
    expectColor(m, "albedo", {1, 1, 1}, 0.0);
  }
}

TEST_F(ObjMaterialsTest, AssimpsSpiderPartsCarryTheirTexturedMaterials)
{
  // Checks: spider.obj's 19 groups are 19 parts, each of its usemtl material; group "OK" uses
  // Skin (Kd 0.827451 0.792157 0.772549, Ks 0, Ns 0, map_Kd .\wal67ar_small.jpg, a Windows
  // path beside the .mtl that exists); the legs share BeinTex.
  const std::string obj = (kAssimpObj / "spider.obj").string();
  ASSERT_TRUE(fs::exists(obj)) << "install assimp-testmodels (scripts/setup.sh)";
  const LoadedBlocks loaded = loadMeshBlocks(obj);
  ASSERT_EQ(loaded.blocks.size(), 19u);
  for (const MeshBlock& block : loaded.blocks)
  {
    EXPECT_TRUE(block.material) << block.name;
  }
  const MeshBlock& head = blockNamed(loaded, "OK");
  ASSERT_TRUE(head.material);
  const Material& skin = *head.material;
  EXPECT_EQ(skin.name, "Skin");
  expectColor(skin, "albedo", {0.827451, 0.792157, 0.772549}, 0.0);
  expectColor(skin, "f0", {0, 0, 0}, 0.0);
  EXPECT_DOUBLE_EQ(skin.value("nu").number[0], 0.0);
  EXPECT_EQ(fs::path(skin.value("albedo-map").text), kAssimpObj / "wal67ar_small.jpg");
  ASSERT_TRUE(blockNamed(loaded, "Bein1Li").material);
  EXPECT_EQ(blockNamed(loaded, "Bein1Li").material->name, "BeinTex");
  EXPECT_EQ(*blockNamed(loaded, "Bein1Li").material, *blockNamed(loaded, "Bein4Li").material);
}

TEST_F(ObjMaterialsTest, AssimpsMaterialNamesWithSpacesAreMatched)
{
  // Checks: space_in_material_name.obj's "usemtl  Hard Shiny Plastic White " (blanks around)
  // finds the .mtl's "newmtl Hard Shiny Plastic White" (Kd 0.141176 0.184314 0.411765, Ns 400,
  // Ks 0).
  const std::string obj = (kAssimpObj / "space_in_material_name.obj").string();
  ASSERT_TRUE(fs::exists(obj)) << "install assimp-testmodels (scripts/setup.sh)";
  const LoadedBlocks loaded = loadMeshBlocks(obj);
  ASSERT_EQ(loaded.blocks.size(), 1u);
  ASSERT_TRUE(loaded.blocks[0].material);
  const Material& m = *loaded.blocks[0].material;
  EXPECT_EQ(m.name, "Hard Shiny Plastic White");
  expectColor(m, "albedo", {0.141176, 0.184314, 0.411765}, 0.0);
  EXPECT_DOUBLE_EQ(m.value("nu").number[0], 400.0);
}
} // namespace
} // namespace aniso
