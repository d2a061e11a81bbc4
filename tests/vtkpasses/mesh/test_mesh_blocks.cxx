// loadMeshBlocks: a file as its named parts. Each test says what it checks and against what
// reference: files written here by VTK's own writers (vtkXMLMultiBlockDataWriter, vtkGLTFWriter,
// vtkSTLWriter) from VTK's sources, whose cell counts are the reference, or written by hand, whose
// definition is the reference; the merged loadMesh of the same file is the cross-check.
#include "core/error.h"
#include "tests/vtkpasses/mesh/mesh_test_files.h"
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/PartPlacement.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkCompositeDataSet.h>
#include <vtkCubeSource.h>
#include <vtkGLTFWriter.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkSphereSource.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataWriter.h>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

class MeshBlocksTest : public test::MeshFilesTest
{
protected:
  // Loads and checks that nothing reached stderr meanwhile (VTK's output is captured).
  static LoadedBlocks loadQuietly(const std::string& file)
  {
    ::testing::internal::CaptureStderr();
    try
    {
      LoadedBlocks loaded = loadMeshBlocks(file);
      EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << file;
      return loaded;
    }
    catch (...)
    {
      EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << file;
      throw;
    }
  }

  // The error's reason; its message must start with "PATH: ".
  static std::string loadError(const std::string& file)
  {
    try
    {
      loadQuietly(file);
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
      return message.substr(std::min(message.size(), file.size() + 2));
    }
    ADD_FAILURE() << file << " loaded although it should not";
    return {};
  }

  // Hostile input: an error naming the file without VTK's internals, or parts with faces.
  static void expectErrorOrValidParts(const std::string& file)
  {
    try
    {
      const LoadedBlocks loaded = loadQuietly(file);
      ASSERT_FALSE(loaded.blocks.empty()) << file;
      for (const MeshBlock& block : loaded.blocks)
      {
        EXPECT_GT(block.mesh.polyData->GetNumberOfPolys(), 0) << file << " " << block.name;
        EXPECT_TRUE(test::allFinite(block.mesh.polyData)) << file << " " << block.name;
      }
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find("ERROR: In"), std::string::npos) << message;
    }
  }
};

std::vector<std::string> namesOf(const LoadedBlocks& loaded)
{
  std::vector<std::string> names;
  for (const MeshBlock& block : loaded.blocks)
  {
    names.push_back(block.name);
  }
  return names;
}

std::vector<int64_t> trianglesOf(const LoadedBlocks& loaded)
{
  std::vector<int64_t> counts;
  for (const MeshBlock& block : loaded.blocks)
  {
    EXPECT_EQ(block.mesh.report.triangles, block.mesh.polyData->GetNumberOfPolys()) << block.name;
    counts.push_back(block.mesh.polyData->GetNumberOfPolys());
  }
  return counts;
}

void expectBounds(vtkPolyData* mesh, const std::array<double, 6>& expected, double tolerance)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(bounds[i], expected[static_cast<size_t>(i)], tolerance) << "bound " << i;
  }
}

// The references: VTK's sources, whose polygons are counted here (a sphere's are triangles; a
// cube's six quads become two triangles each).
vtkSmartPointer<vtkPolyData> sphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(8);
  source->SetPhiResolution(6);
  source->Update();
  vtkSmartPointer<vtkPolyData> output = source->GetOutput();
  return output;
}

int64_t sphereTriangles()
{
  int64_t triangles = 0;
  vtkSmartPointer<vtkPolyData> mesh = sphere();
  test::forEachTriangle(mesh, [&](vtkIdType, vtkIdType, vtkIdType) { ++triangles; });
  EXPECT_EQ(triangles, mesh->GetNumberOfPolys()) << "the sphere source gives triangles only";
  return triangles;
}

vtkSmartPointer<vtkPolyData> cube(double cx, double cy, double cz)
{
  vtkNew<vtkCubeSource> source;
  source->SetCenter(cx, cy, cz);
  source->SetXLength(2);
  source->SetYLength(4);
  source->SetZLength(6);
  source->Update();
  vtkSmartPointer<vtkPolyData> output = source->GetOutput();
  EXPECT_EQ(output->GetNumberOfPolys(), 6);
  return output;
}

// One tetrahedron cell: not polygonal, so the loader takes its surface, 4 triangles.
vtkSmartPointer<vtkUnstructuredGrid> tetraGrid()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0, 0, 1);
  grid->SetPoints(points);
  const vtkIdType ids[4] = {0, 1, 2, 3};
  grid->InsertNextCell(VTK_TETRA, 4, ids);
  return grid;
}

// Three points joined by one line cell: no face.
vtkSmartPointer<vtkPolyData> polyline()
{
  auto line = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(1, 1, 0);
  line->SetPoints(points);
  vtkNew<vtkCellArray> lines;
  const vtkIdType ids[3] = {0, 1, 2};
  lines->InsertNextCell(3, ids);
  line->SetLines(lines);
  return line;
}

void setBlock(vtkMultiBlockDataSet* tree, unsigned int index, vtkDataObject* data, const char* name)
{
  tree->SetBlock(index, data);
  if (name)
  {
    tree->GetMetaData(index)->Set(vtkCompositeDataSet::NAME(), name);
  }
}

std::string writeVtm(const std::string& file, vtkMultiBlockDataSet* tree)
{
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  writer->SetInputData(tree);
  writer->SetFileName(file.c_str());
  EXPECT_EQ(writer->Write(), 1) << file;
  return file;
}

TEST_F(MeshBlocksTest, VtmLeavesArePartsNamedByTheirMetadataAndAnEmptyOneIsAWarning)
{
  // Checks: one part per leaf in file order, named by NAME, with the triangle counts of the
  // sources (the tetrahedron grid by its surface), and a leaf without faces (a polyline: VTK's
  // writer leaves out leaves without cells) a line part of its own, "wire lines" (LineSet.h),
  // with no warning. Reference: VTK's sources' own cells; the merged loadMesh of the same file
  // holds the sum of the faces.
  vtkNew<vtkMultiBlockDataSet> tree;
  setBlock(tree, 0, sphere(), "ball");
  setBlock(tree, 1, cube(0, 0, 0), "box");
  setBlock(tree, 2, tetraGrid(), "tetra");
  setBlock(tree, 3, polyline(), "wire");
  const std::string file = writeVtm(this->path("scene.vtm"), tree);

  const LoadedBlocks loaded = loadQuietly(file);
  EXPECT_EQ(namesOf(loaded), (std::vector<std::string>{"ball", "box", "tetra", "wire lines"}));
  EXPECT_EQ(trianglesOf(loaded), (std::vector<int64_t>{sphereTriangles(), 12, 4, 0}));
  EXPECT_TRUE(loaded.warnings.empty());
  for (const MeshBlock& block : loaded.blocks)
  {
    EXPECT_EQ(block.mesh.report.source, file);
  }
  ASSERT_EQ(loaded.blocks.size(), 4u);
  EXPECT_TRUE(loaded.blocks[3].lines);
  EXPECT_EQ(loaded.blocks[3].mesh.report.lineSegments, 2);
  // The box keeps the source's bounds: [-1, 1] x [-2, 2] x [-3, 3].
  expectBounds(loaded.blocks[1].mesh.polyData, {-1, 1, -2, 2, -3, 3}, 1e-6);
  EXPECT_EQ(loadMesh(file).report.triangles, sphereTriangles() + 12 + 4);
}

TEST_F(MeshBlocksTest, AVtmEntryWithoutDataIsASkippedPart)
{
  // Checks: an index entry without a file (VTK's reader makes it an empty leaf) is a part
  // without faces, skipped with a warning; the others load. Reference: VTK's writer's index
  // with such an entry added by hand.
  vtkNew<vtkMultiBlockDataSet> tree;
  setBlock(tree, 0, cube(0, 0, 0), "box");
  const std::string file = writeVtm(this->path("holes.vtm"), tree);
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const std::string end = "</vtkMultiBlockDataSet>";
  ASSERT_NE(text.find(end), std::string::npos);
  text.insert(text.find(end), "<DataSet index=\"1\" name=\"hole\"/>\n");
  this->write("holes.vtm", text);

  const LoadedBlocks loaded = loadQuietly(file);
  EXPECT_EQ(namesOf(loaded), (std::vector<std::string>{"box"}));
  EXPECT_EQ(loaded.warnings, std::vector<std::string>{file + ": part hole: no faces"});
}

TEST_F(MeshBlocksTest, NestedMultiblocksAreFlattenedWithPathNames)
{
  // Checks: a multiblock inside a multiblock is flattened depth first, names joined by "/",
  // a level without NAME called "block I" by its index. Reference: the tree built here.
  vtkNew<vtkMultiBlockDataSet> inner;
  setBlock(inner, 0, cube(0, 0, 0), "lid");
  setBlock(inner, 1, sphere(), nullptr);
  vtkNew<vtkMultiBlockDataSet> tree;
  setBlock(tree, 0, inner, "outer");
  setBlock(tree, 1, tetraGrid(), nullptr);
  const std::string file = writeVtm(this->path("nested.vtm"), tree);

  const LoadedBlocks loaded = loadQuietly(file);
  EXPECT_EQ(namesOf(loaded), (std::vector<std::string>{"outer/lid", "outer/block 1", "block 1"}));
  EXPECT_EQ(trianglesOf(loaded), (std::vector<int64_t>{12, sphereTriangles(), 4}));
  EXPECT_TRUE(loaded.warnings.empty());
}

TEST_F(MeshBlocksTest, BrokenVtmFilesAreErrorsNamingTheFile)
{
  // Checks: a truncated index, garbage bytes and an index naming a missing piece fail as a
  // whole with an error that names the file (never a crash, nothing on stderr). Reference: a
  // valid file written by vtkXMLMultiBlockDataWriter, then damaged.
  vtkNew<vtkMultiBlockDataSet> tree;
  setBlock(tree, 0, cube(0, 0, 0), "box");
  setBlock(tree, 1, sphere(), "ball");
  const std::string good = writeVtm(this->path("good.vtm"), tree);
  std::ifstream in(good, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(text.size(), 40u);

  EXPECT_FALSE(loadError(this->write("cut.vtm", text.substr(0, text.size() / 2))).empty());
  std::mt19937 random(7u);
  std::string garbage(600, '\0');
  for (char& c : garbage)
  {
    c = static_cast<char>(random() & 0xff);
  }
  EXPECT_FALSE(loadError(this->write("garbage.vtm", garbage)).empty());
  EXPECT_FALSE(loadError(this->write("notxml.vtm", "this is not a multiblock file\n")).empty());
  // The pieces are gone: the index alone cannot be read.
  fs::remove_all(this->Dir / "good");
  EXPECT_FALSE(loadError(good).empty());
}

TEST_F(MeshBlocksTest, ObjGroupsAndObjectsAreParts)
{
  // Checks: each g and o statement starts a part named by it, with the triangles of its own
  // faces (a quad counts two) and only the vertices they use. Reference: the file's definition;
  // the merged loadMesh holds every triangle.
  const std::string file = this->write("car.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                                  "v 5 5 5\nv 6 5 5\nv 6 6 5\nv 5 6 5\n"
                                                  "g front\nf 1 3 2\nf 1 2 4\n"
                                                  "o lid\nf 5 6 7 8\n"
                                                  "g back left\nf 1 4 3\nf 2 3 4\nf 1 3 4\n");
  const LoadedBlocks loaded = loadQuietly(file);
  EXPECT_EQ(namesOf(loaded), (std::vector<std::string>{"front", "lid", "back left"}));
  EXPECT_EQ(trianglesOf(loaded), (std::vector<int64_t>{2, 2, 3}));
  EXPECT_TRUE(loaded.warnings.empty());
  ASSERT_EQ(loaded.blocks.size(), 3u);
  EXPECT_EQ(loaded.blocks[1].mesh.polyData->GetNumberOfPoints(), 4);
  expectBounds(loaded.blocks[1].mesh.polyData, {5, 6, 5, 6, 5, 5}, 1e-6);
  EXPECT_EQ(loaded.blocks[0].mesh.polyData->GetNumberOfPoints(), 4);
  EXPECT_EQ(loaded.blocks[0].mesh.report.unusedVerticesRemoved, 0);
  EXPECT_EQ(loadMesh(file).report.triangles, 7);
}

TEST_F(MeshBlocksTest, ObjNamesComeFromTheStemAndRepeatsAreNumbered)
{
  // Checks: faces before any g/o and after a g without words are named by the file's stem; a
  // repeated name gets " 2", " 3"; a statement with no face before the next makes no part; a
  // part whose faces are all invalid is skipped with a warning, the others load. Reference: the
  // file's definition.
  const std::string file = this->write("kit.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                                  "f 1 2 3\n"
                                                  "g wing\nf 1 2 4\n"
                                                  "g\nf 1 3 4\n"
                                                  "o empty\n"
                                                  "g wing\nf 2 3 4\n"
                                                  "g broken\nf 1 2 99\n"
                                                  "g wing\nf 1 4 3\n");
  const LoadedBlocks loaded = loadQuietly(file);
  EXPECT_EQ(namesOf(loaded),
            (std::vector<std::string>{"kit", "wing", "kit 2", "wing 2", "wing 3"}));
  EXPECT_EQ(trianglesOf(loaded), (std::vector<int64_t>{1, 1, 1, 1, 1}));
  ASSERT_EQ(loaded.warnings.size(), 1u);
  EXPECT_EQ(loaded.warnings[0], file + ": part broken: no valid faces (0 with NaN/Inf vertices, 0 "
                                       "of zero area, 1 with invalid vertex indices)");
}

TEST_F(MeshBlocksTest, ObjFacesTheReaderDropsLeaveTheirPartWithAWarning)
{
  // Checks: where vtkOBJReader drops faces without normals (other faces have some, so it
  // duplicates vertices), the faces it keeps still go to their own parts and the part it
  // emptied is skipped with a warning. Reference: the file's definition and that rule of
  // vtkOBJReader (VTK 9.1, IO/Geometry/vtkOBJReader.cxx).
  const std::string file = this->write("mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                                    "vn 0 0 -1\nvn 0 -1 0\n"
                                                    "g with\nf 1//1 3//1 2//1\n"
                                                    "g without\nf 1 2 4\n"
                                                    "g also\nf 1//2 2//2 4//2\n");
  const LoadedBlocks loaded = loadQuietly(file);
  EXPECT_EQ(namesOf(loaded), (std::vector<std::string>{"with", "also"}));
  EXPECT_EQ(trianglesOf(loaded), (std::vector<int64_t>{1, 1}));
  ASSERT_EQ(loaded.warnings.size(), 1u);
  EXPECT_EQ(loaded.warnings[0], file + ": part without: no faces");
  ASSERT_EQ(loaded.blocks.size(), 2u);
  EXPECT_TRUE(loaded.blocks[1].mesh.report.hasNormals);
}

TEST_F(MeshBlocksTest, ObjAttributesWithoutOneValuePerVertexAreDroppedInEveryPart)
{
  // Checks: vtkOBJReader hands texture coordinates with fewer values than vertices when the file
  // has fewer vt than v lines (and faces give each vertex its own index); cut into parts they
  // must not be read past their end: they are dropped, each part loads its faces and says so in
  // its reader warnings. Reference: the file's definition.
  const std::string file = this->write("short.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                                    "vt 0 0\nvt 1 0\nvt 0 1\n"
                                                    "g a\nf 1/1 2/2 3/3\n"
                                                    "g b\nf 1 2 4\n");
  const LoadedBlocks loaded = loadQuietly(file);
  EXPECT_EQ(namesOf(loaded), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(trianglesOf(loaded), (std::vector<int64_t>{1, 1}));
  for (const MeshBlock& block : loaded.blocks)
  {
    EXPECT_FALSE(block.mesh.report.hasTCoords) << block.name;
    EXPECT_EQ(
        block.mesh.report.readerWarnings,
        std::vector<std::string>{"point attribute 'TCoords' has 3 values for 4 vertices: dropped"})
        << block.name;
  }
}

TEST_F(MeshBlocksTest, AnObjWithoutGroupsIsOnePartLikeLoadMesh)
{
  // Checks: without g/o the file is one part named by its stem, the same surface as loadMesh's.
  const std::string file = this->write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                                    "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const LoadedBlocks loaded = loadQuietly(file);
  ASSERT_EQ(namesOf(loaded), (std::vector<std::string>{"plain"}));
  const LoadedMesh whole = loadMesh(file);
  EXPECT_EQ(loaded.blocks[0].mesh.report.triangles, whole.report.triangles);
  EXPECT_EQ(loaded.blocks[0].mesh.polyData->GetNumberOfPoints(),
            whole.polyData->GetNumberOfPoints());
  EXPECT_NEAR(test::signedVolume(loaded.blocks[0].mesh.polyData),
              test::signedVolume(whole.polyData), 1e-12);
  EXPECT_EQ(loadError(this->write("none.obj", "v 0 0 0\nv 1 0 0\n")), "no faces");
}

TEST_F(MeshBlocksTest, APlainStlIsOnePartNamedByItsStem)
{
  // Checks: a format without parts gives one part named by the file's stem, exactly loadMesh's
  // result. Reference: vtkSTLWriter's file of VTK's sphere source, and loadMesh of it.
  const std::string file = this->path("ball.stl");
  vtkNew<vtkSTLWriter> writer;
  writer->SetInputData(sphere());
  writer->SetFileName(file.c_str());
  ASSERT_EQ(writer->Write(), 1);
  const LoadedBlocks loaded = loadQuietly(file);
  ASSERT_EQ(namesOf(loaded), (std::vector<std::string>{"ball"}));
  EXPECT_EQ(trianglesOf(loaded), (std::vector<int64_t>{sphereTriangles()}));
  EXPECT_TRUE(loaded.warnings.empty());
  const LoadedMesh whole = loadMesh(file);
  EXPECT_EQ(loaded.blocks[0].mesh.polyData->GetNumberOfPoints(),
            whole.polyData->GetNumberOfPoints());
  EXPECT_EQ(loaded.blocks[0].mesh.report.duplicateVerticesMerged,
            whole.report.duplicateVerticesMerged);
  EXPECT_EQ(loadError(this->write("empty.stl", "")), "empty file");
}

TEST_F(MeshBlocksTest, GltfWrittenByVtkGivesOnePartPerMeshNode)
{
  // Checks: each mesh node vtkGLTFWriter writes (it names them "mesh0", "mesh1", ...; its camera
  // and renderer nodes hold no mesh) is a part with the source's triangles, turned from glTF's
  // Y-up to Z-up like loadMesh: (x, y, z) -> (x, -z, y). Reference: VTK's sources, the writer
  // being VTK's (no render window needed).
  vtkNew<vtkMultiBlockDataSet> first;
  setBlock(first, 0, cube(1, 2, 3), nullptr);
  vtkNew<vtkMultiBlockDataSet> second;
  setBlock(second, 0, sphere(), nullptr);
  vtkNew<vtkMultiBlockDataSet> tree;
  setBlock(tree, 0, first, nullptr);
  setBlock(tree, 1, second, nullptr);
  const std::string file = this->path("city.gltf");
  vtkNew<vtkGLTFWriter> writer;
  writer->SetInputData(tree);
  writer->SetFileName(file.c_str());
  writer->InlineDataOn();
  ASSERT_EQ(writer->Write(), 1);

  const LoadedBlocks loaded = loadQuietly(file);
  EXPECT_EQ(namesOf(loaded), (std::vector<std::string>{"mesh0", "mesh1"}));
  EXPECT_EQ(trianglesOf(loaded), (std::vector<int64_t>{12, sphereTriangles()}));
  ASSERT_EQ(loaded.blocks.size(), 2u);
  // The cube [0, 2] x [0, 4] x [0, 6] in glTF's frame.
  expectBounds(loaded.blocks[0].mesh.polyData, {0, 2, -6, 0, 0, 4}, 1e-5);
  EXPECT_EQ(loadMesh(file).report.triangles, 12 + sphereTriangles());
}

// A tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) as glTF data: 4 float positions, 12 uint16
// indices (outward faces), 72 bytes.
std::string tetraBuffer()
{
  std::string buffer;
  const float points[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& p : points)
  {
    for (float c : p)
    {
      char bytes[sizeof(float)];
      std::memcpy(bytes, &c, sizeof(float));
      buffer.append(bytes, sizeof(float));
    }
  }
  for (int index : {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3})
  {
    const auto id = static_cast<uint16_t>(index);
    char bytes[sizeof(uint16_t)];
    std::memcpy(bytes, &id, sizeof(uint16_t));
    buffer.append(bytes, sizeof(uint16_t));
  }
  return buffer;
}

TEST_F(MeshBlocksTest, GltfPartsAreNamedByTheirNodesWithTheirTransforms)
{
  // Checks: a part per mesh node in the scene's depth-first order; named by the node, else by
  // its mesh, else "node I"; each part's surface in its mesh's frame turned Z-up, its placement
  // the child's transform composed with its parent's, turned Z-up.
  // Reference: the hand-written file: "car" (no mesh) at glTF (0, 5, 0) holds "wheel" at
  // (10, 0, 0), so the wheel's tetrahedron spans glTF [10, 11] x [5, 6] x [0, 1], Z-up
  // [10, 11] x [-1, 0] x [5, 6]; its placement is the translation by Z-up (10, 0, 5).
  this->write("tetra.bin", tetraBuffer());
  const std::string file = this->write(
      "car.gltf",
      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[3,1,2]}],)"
      R"("nodes":[{"name":"wheel","mesh":0,"translation":[10,0,0]},{"mesh":1},{"mesh":0},)"
      R"({"name":"car","children":[0],"translation":[0,5,0]}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]},)"
      R"({"name":"body","primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
      R"("buffers":[{"uri":"tetra.bin","byteLength":72}],)"
      R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},)"
      R"({"buffer":0,"byteOffset":48,"byteLength":24}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3",)"
      R"("min":[0,0,0],"max":[1,1,1]},)"
      R"({"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}]})");
  const LoadedBlocks loaded = loadQuietly(file);
  EXPECT_EQ(namesOf(loaded), (std::vector<std::string>{"wheel", "body", "node 2"}));
  EXPECT_EQ(trianglesOf(loaded), (std::vector<int64_t>{4, 4, 4}));
  ASSERT_EQ(loaded.blocks.size(), 3u);
  expectBounds(loaded.blocks[0].mesh.polyData, {0, 1, -1, 0, 0, 1}, 1e-6);
  expectBounds(placedSurface(loaded.blocks[0].mesh.polyData, loaded.blocks[0].placement),
               {10, 11, -1, 0, 5, 6}, 1e-6);
  const PartMatrix wheel{1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 5, 0, 0, 0, 1};
  for (size_t i = 0; i < 16; ++i)
  {
    EXPECT_NEAR(loaded.blocks[0].placement[i], wheel[i], 1e-12) << i;
  }
  expectBounds(loaded.blocks[1].mesh.polyData, {0, 1, -1, 0, 0, 1}, 1e-6);
  EXPECT_EQ(loaded.blocks[1].placement, kIdentityPlacement);
  // The rotation keeps the winding: each tetrahedron still encloses +1/6.
  EXPECT_NEAR(test::signedVolume(loaded.blocks[0].mesh.polyData), 1.0 / 6.0, 1e-6);
  // One surface (loadMesh): every part where its placement puts it.
  expectBounds(loadMesh(file).polyData, {0, 11, -1, 0, 0, 6}, 1e-6);
}

TEST_F(MeshBlocksTest, TheReaderProgramIsAskedForPartsAndItsFailuresNameTheFile)
{
  // Checks: the parts are read by the reader program (found through ANISO_MESH_READER first),
  // asked with the argument "blocks"; its crash or its silence is an error naming the file.
  // Reference: stand-in programs that record their arguments and then fail.
  const std::string obj = this->write("box.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\ng a\nf 1 2 3\n");
  const auto withReader = [&](const std::string& body)
  {
    const std::string program = this->write("reader.sh", "#!/bin/sh\n" + body + "\n");
    fs::permissions(program, fs::perms::owner_all);
    ::setenv("ANISO_MESH_READER", program.c_str(), 1);
    std::string message = loadError(obj);
    ::unsetenv("ANISO_MESH_READER");
    return message;
  };
  const std::string args = this->path("args.txt");
  EXPECT_EQ(withReader("echo \"$2 $3 $4\" > " + args + "; kill -SEGV $$"),
            "the reader crashed on this file (corrupt or unsupported content)");
  std::ifstream recorded(args);
  std::string line;
  std::getline(recorded, line);
  EXPECT_EQ(line, ".obj 36 blocks") << "extension, file size, mode";
  EXPECT_EQ(withReader("exit 0"), "the reader process ended without a result (corrupt file?)");
  EXPECT_EQ(namesOf(loadQuietly(obj)), (std::vector<std::string>{"a"}));
}

TEST_F(MeshBlocksTest, HostileFilesGiveAnErrorOrParts)
{
  // Checks: truncated and random files of every format with parts never crash, print nothing
  // and give an error naming the file or parts with faces. Reference: none beyond that.
  vtkNew<vtkMultiBlockDataSet> tree;
  setBlock(tree, 0, cube(0, 0, 0), "box");
  setBlock(tree, 1, tetraGrid(), "tetra");
  const std::string vtm = writeVtm(this->path("src.vtm"), tree);
  std::ifstream in(vtm, std::ios::binary);
  const std::string vtmText((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ng a\nf 1 3 2\nf 1 2 4\n"
                          "o b\nf 1 4 3\ng c\nf 2 3 4\n";
  std::mt19937 random(99u);
  for (const auto& [ext, content] :
       std::vector<std::pair<std::string, std::string>>{{"obj", obj}, {"vtm", vtmText}})
  {
    for (double fraction : {0.2, 0.5, 0.8, 0.95})
    {
      const size_t length = static_cast<size_t>(fraction * static_cast<double>(content.size()));
      SCOPED_TRACE(ext + " cut to " + std::to_string(length));
      expectErrorOrValidParts(
          this->write("cut" + std::to_string(length) + "." + ext, content.substr(0, length)));
    }
  }
  for (const char* ext : {"obj", "vtm", "gltf", "glb"})
  {
    std::string bytes(300, '\0');
    for (char& c : bytes)
    {
      c = static_cast<char>(random() & 0xff);
    }
    SCOPED_TRACE(std::string("garbage .") + ext);
    expectErrorOrValidParts(this->write(std::string("garbage.") + ext, bytes));
  }
  // A group line of garbage, faces with hostile indices.
  expectErrorOrValidParts(this->write("h.obj", "v 1 2 3\nv 0 0 0\nv 1 0 0\ng \x01\x02\xff\n"
                                               "f 1 2 3\nf -7 99999999999 1\no\nf 0 0 0\n"));
}
} // namespace
} // namespace aniso
