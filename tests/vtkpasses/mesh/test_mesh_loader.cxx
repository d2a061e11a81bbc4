// loadMesh: every format round-trips a box written here by hand (or by VTK's writers) with the
// triangle count, vertex count and bounds of its definition; degenerate and hostile files give
// an error naming the file, or a mesh with the stated counts, and never a crash or stderr noise.
#include "core/error.h"
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "vtkpasses/mesh/MeshLoader.h"

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
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkSTLWriter.h>
#include <vtkXMLPolyDataWriter.h>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

// The reference box [-1, 2] x [0, 3] x [-0.5, 0.5]: 8 corners, 6 quads wound outwards.
const double kBox[8][3] = {{-1, 0, -0.5}, {2, 0, -0.5}, {2, 3, -0.5}, {-1, 3, -0.5},
                           {-1, 0, 0.5},  {2, 0, 0.5},  {2, 3, 0.5},  {-1, 3, 0.5}};
const int kQuads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                          {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
const double kBoxBounds[6] = {-1, 2, 0, 3, -0.5, 0.5};

std::string boxObj()
{
  std::string s = "# box\n";
  for (const auto& p : kBox)
  {
    s += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) +
         "\n";
  }
  for (const auto& q : kQuads)
  {
    s += "f " + std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " +
         std::to_string(q[2] + 1) + " " + std::to_string(q[3] + 1) + "\n";
  }
  return s;
}

std::string vertexLines()
{
  std::string s;
  for (const auto& p : kBox)
  {
    s += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  }
  return s;
}

std::string quadLines()
{
  std::string s;
  for (const auto& q : kQuads)
  {
    s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) +
         " " + std::to_string(q[3]) + "\n";
  }
  return s;
}

std::string boxOff()
{
  return "OFF\n# a box\n8 6 12\n" + vertexLines() + quadLines();
}

std::string boxPly()
{
  return "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
         "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n" +
         vertexLines() + quadLines();
}

std::string boxLegacyVtk()
{
  return "# vtk DataFile Version 3.0\nbox\nASCII\nDATASET POLYDATA\nPOINTS 8 float\n" +
         vertexLines() + "POLYGONS 6 30\n" + quadLines();
}

std::string boxStl()
{
  std::string s = "solid box\n";
  for (const auto& q : kQuads)
  {
    for (const auto& tri : {std::array<int, 3>{q[0], q[1], q[2]}, {q[0], q[2], q[3]}})
    {
      s += " facet normal 0 0 0\n  outer loop\n";
      for (int id : tri)
      {
        s += "   vertex " + std::to_string(kBox[id][0]) + " " + std::to_string(kBox[id][1]) + " " +
             std::to_string(kBox[id][2]) + "\n";
      }
      s += "  endloop\n endfacet\n";
    }
  }
  return s + "endsolid box\n";
}

vtkSmartPointer<vtkPolyData> boxPolyData()
{
  auto box = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (const auto& p : kBox)
  {
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& q : kQuads)
  {
    const vtkIdType ids[4] = {q[0], q[1], q[2], q[3]};
    polys->InsertNextCell(4, ids);
  }
  box->SetPoints(points);
  box->SetPolys(polys);
  return box;
}

std::string base64(const std::string& bytes)
{
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3)
  {
    const uint32_t v = static_cast<uint32_t>(static_cast<unsigned char>(bytes[i])) << 16 |
                       static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                       static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 2]));
    for (int k = 3; k >= 0; --k)
    {
      out += table[(v >> (6 * k)) & 63u];
    }
  }
  const size_t rest = bytes.size() - i;
  if (rest > 0)
  {
    uint32_t v = static_cast<uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (rest == 2)
    {
      v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    }
    out += table[(v >> 18) & 63u];
    out += table[(v >> 12) & 63u];
    out += rest == 2 ? table[(v >> 6) & 63u] : '=';
    out += '=';
  }
  return out;
}

template <typename T>
void appendRaw(std::string& buffer, const T& value)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  buffer.append(bytes, sizeof(T));
}

// The box as glTF data: 8 float positions then 36 uint16 indices (two triangles per quad).
std::string boxGltfBuffer()
{
  std::string buffer;
  for (const auto& p : kBox)
  {
    for (double c : p)
    {
      appendRaw(buffer, static_cast<float>(c));
    }
  }
  for (const auto& q : kQuads)
  {
    for (int id : {q[0], q[1], q[2], q[0], q[2], q[3]})
    {
      appendRaw(buffer, static_cast<uint16_t>(id));
    }
  }
  return buffer; // 96 + 72 bytes, a multiple of 4
}

// Two nodes instance the box: one as is, one moved by +10 along glTF's X.
std::string boxGltfJson(const std::string& bufferUri, size_t bufferLength)
{
  std::string uri = bufferUri.empty() ? "" : ",\"uri\":\"" + bufferUri + "\"";
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],)"
         R"("nodes":[{"mesh":0},{"mesh":0,"translation":[10,0,0]}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
         R"("buffers":[{"byteLength":)" +
         std::to_string(bufferLength) + uri +
         R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":96},)"
         R"({"buffer":0,"byteOffset":96,"byteLength":72}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":8,"type":"VEC3",)"
         R"("min":[-1,0,-0.5],"max":[2,3,0.5]},)"
         R"({"bufferView":1,"componentType":5123,"count":36,"type":"SCALAR"}]})";
}

std::string boxGltf()
{
  const std::string buffer = boxGltfBuffer();
  return boxGltfJson("data:application/octet-stream;base64," + base64(buffer), buffer.size());
}

// GLB container: 12-byte header, a JSON chunk padded with spaces, a BIN chunk.
std::string boxGlb()
{
  const std::string buffer = boxGltfBuffer();
  std::string json = boxGltfJson("", buffer.size());
  while (json.size() % 4 != 0)
  {
    json += ' ';
  }
  std::string glb;
  appendRaw(glb, uint32_t{0x46546C67}); // "glTF"
  appendRaw(glb, uint32_t{2});
  appendRaw(glb, static_cast<uint32_t>(12 + 8 + json.size() + 8 + buffer.size()));
  appendRaw(glb, static_cast<uint32_t>(json.size()));
  appendRaw(glb, uint32_t{0x4E4F534A}); // "JSON"
  glb += json;
  appendRaw(glb, static_cast<uint32_t>(buffer.size()));
  appendRaw(glb, uint32_t{0x004E4942}); // "BIN\0"
  glb += buffer;
  return glb;
}

class MeshLoaderTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    this->Dir = fs::temp_directory_path() /
                ("aniso-test-mesh-loader-" +
                 std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(this->Dir);
    fs::create_directories(this->Dir);
  }
  void TearDown() override { fs::remove_all(this->Dir); }

  std::string write(const std::string& name, const std::string& content) const
  {
    const fs::path path = this->Dir / name;
    std::ofstream out(path, std::ios::binary);
    out << content;
    return path.string();
  }

  // Loads and checks that VTK printed nothing on stderr while doing so.
  LoadedMesh loadQuietly(const std::string& path) const
  {
    ::testing::internal::CaptureStderr();
    try
    {
      LoadedMesh mesh = loadMesh(path);
      EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << path;
      return mesh;
    }
    catch (...)
    {
      EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << path;
      throw;
    }
  }

  // The error message, which must start with "PATH: ".
  std::string loadError(const std::string& path) const
  {
    try
    {
      this->loadQuietly(path);
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      return message.substr(std::min(message.size(), path.size() + 2));
    }
    ADD_FAILURE() << path << " loaded although it should not";
    return {};
  }

  // Hostile input: either an error naming the file without VTK's internals, or a usable mesh.
  void expectErrorOrValidMesh(const std::string& path) const
  {
    try
    {
      LoadedMesh mesh = this->loadQuietly(path);
      EXPECT_GT(mesh.polyData->GetNumberOfPolys(), 0) << path;
      EXPECT_TRUE(test::allFinite(mesh.polyData)) << path;
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find("ERROR: In"), std::string::npos) << message;
      EXPECT_GT(message.size(), path.size() + 2) << message;
    }
  }

  fs::path Dir;
};

void expectBox(const LoadedMesh& mesh, const std::string& what)
{
  SCOPED_TRACE(what);
  ASSERT_TRUE(mesh.polyData);
  EXPECT_EQ(mesh.polyData->GetNumberOfPolys(), 12);
  EXPECT_EQ(mesh.polyData->GetNumberOfCells(), 12);
  EXPECT_EQ(mesh.polyData->GetNumberOfPoints(), 8);
  EXPECT_EQ(mesh.report.triangles, 12);
  double bounds[6];
  mesh.polyData->GetBounds(bounds);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(bounds[i], kBoxBounds[i], 1e-6) << "bound " << i;
  }
  // Closed box wound outwards: volume 3 * 3 * 1 = 9 (triangulation must keep the winding).
  EXPECT_NEAR(test::signedVolume(mesh.polyData), 9.0, 1e-5);
  EXPECT_TRUE(mesh.report.notes().empty());
  EXPECT_EQ(mesh.report.zeroAreaTrianglesDropped, 0);
  EXPECT_EQ(mesh.report.boundaryEdges, 0);
  EXPECT_EQ(mesh.report.nonManifoldEdges, 0);
}

TEST_F(MeshLoaderTest, EveryFormatRoundTripsTheBox)
{
  expectBox(this->loadQuietly(this->write("box.obj", boxObj())), "obj");
  expectBox(this->loadQuietly(this->write("box.OBJ", boxObj())), "upper-case extension");
  expectBox(this->loadQuietly(this->write("box.off", boxOff())), "off");
  expectBox(this->loadQuietly(this->write("box.ply", boxPly())), "ascii ply");
  expectBox(this->loadQuietly(this->write("box.stl", boxStl())), "ascii stl");
  expectBox(this->loadQuietly(this->write("box.vtk", boxLegacyVtk())), "legacy vtk");

  vtkSmartPointer<vtkPolyData> box = boxPolyData();
  vtkNew<vtkXMLPolyDataWriter> vtp;
  vtp->SetInputData(box);
  vtp->SetFileName((this->Dir / "box.vtp").string().c_str());
  ASSERT_EQ(vtp->Write(), 1);
  expectBox(this->loadQuietly((this->Dir / "box.vtp").string()), "vtp");

  vtkNew<vtkPLYWriter> ply;
  ply->SetInputData(box);
  ply->SetFileTypeToBinary();
  ply->SetFileName((this->Dir / "binary.ply").string().c_str());
  ASSERT_EQ(ply->Write(), 1);
  expectBox(this->loadQuietly((this->Dir / "binary.ply").string()), "binary ply");

  // STL stores triangles only: the writer needs them triangulated.
  LoadedMesh triangulated = this->loadQuietly(this->write("for-stl.obj", boxObj()));
  vtkNew<vtkSTLWriter> stl;
  stl->SetInputData(triangulated.polyData);
  stl->SetFileTypeToBinary();
  stl->SetFileName((this->Dir / "binary.stl").string().c_str());
  ASSERT_EQ(stl->Write(), 1);
  expectBox(this->loadQuietly((this->Dir / "binary.stl").string()), "binary stl");
}

TEST_F(MeshLoaderTest, GltfNodesAreMergedWithTransformsAndTurnedZUp)
{
  // Two instances of the box, the second moved by +10 along X. glTF is Y-up: (x, y, z) becomes
  // (x, -z, y), so the box spans x [-1, 12], y [-0.5, 0.5], z [0, 3].
  const double expected[6] = {-1, 12, -0.5, 0.5, 0, 3};
  for (const std::string& name : {std::string("box.gltf"), std::string("box.glb")})
  {
    const std::string path = this->write(name, name == "box.gltf" ? boxGltf() : boxGlb());
    LoadedMesh mesh = this->loadQuietly(path);
    EXPECT_EQ(mesh.polyData->GetNumberOfPolys(), 24) << name;
    EXPECT_EQ(mesh.polyData->GetNumberOfPoints(), 16) << name;
    double bounds[6];
    mesh.polyData->GetBounds(bounds);
    for (int i = 0; i < 6; ++i)
    {
      EXPECT_NEAR(bounds[i], expected[i], 1e-6) << name << " bound " << i;
    }
    // A rotation keeps the winding: two boxes of volume 9, outwards.
    EXPECT_NEAR(test::signedVolume(mesh.polyData), 18.0, 1e-4) << name;
  }
}

TEST_F(MeshLoaderTest, GltfNormalsTangentsAndUvsBecomeTheContractArrays)
{
  // One quad in glTF's XZ plane facing +Y (glTF up), normal (0,1,0), tangent (1,0,0,1), UVs
  // with glTF's top-left origin. In the Z-up world it lies in XY facing +Z: normal (0,0,1),
  // tangent (1,0,0).
  std::string buffer;
  const float positions[4][3] = {{0, 0, 0}, {0, 0, -1}, {1, 0, -1}, {1, 0, 0}};
  for (const auto& p : positions)
  {
    for (float c : p)
    {
      appendRaw(buffer, c);
    }
  }
  for (int i = 0; i < 4; ++i)
  {
    for (float c : {0.0f, 1.0f, 0.0f})
    {
      appendRaw(buffer, c);
    }
  }
  for (int i = 0; i < 4; ++i)
  {
    for (float c : {1.0f, 0.0f, 0.0f, 1.0f})
    {
      appendRaw(buffer, c);
    }
  }
  const float uvs[4][2] = {{0, 1}, {0, 0}, {1, 0}, {1, 1}};
  for (const auto& uv : uvs)
  {
    appendRaw(buffer, uv[0]);
    appendRaw(buffer, uv[1]);
  }
  for (int id : {0, 3, 2, 0, 2, 1})
  {
    appendRaw(buffer, static_cast<uint16_t>(id));
  }
  const std::string json =
      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1,"TANGENT":2,)"
      R"("TEXCOORD_0":3},"indices":4}]}],"buffers":[{"byteLength":)" +
      std::to_string(buffer.size()) + R"(,"uri":"data:application/octet-stream;base64,)" +
      base64(buffer) +
      R"("}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},)"
      R"({"buffer":0,"byteOffset":48,"byteLength":48},{"buffer":0,"byteOffset":96,"byteLength":64},)"
      R"({"buffer":0,"byteOffset":160,"byteLength":32},{"buffer":0,"byteOffset":192,"byteLength":12}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3",)"
      R"("min":[0,0,-1],"max":[1,0,0]},{"bufferView":1,"componentType":5126,"count":4,"type":"VEC3"},)"
      R"({"bufferView":2,"componentType":5126,"count":4,"type":"VEC4"},)"
      R"({"bufferView":3,"componentType":5126,"count":4,"type":"VEC2"},)"
      R"({"bufferView":4,"componentType":5123,"count":6,"type":"SCALAR"}]})";
  LoadedMesh mesh = this->loadQuietly(this->write("quad.gltf", json));
  vtkPointData* pd = mesh.polyData->GetPointData();
  ASSERT_NE(pd->GetNormals(), nullptr);
  ASSERT_NE(pd->GetTangents(), nullptr);
  ASSERT_NE(pd->GetTCoords(), nullptr);
  EXPECT_STREQ(pd->GetNormals()->GetName(), "Normals");
  EXPECT_STREQ(pd->GetTangents()->GetName(), "Tangents");
  EXPECT_STREQ(pd->GetTCoords()->GetName(), "TCoords");
  EXPECT_EQ(pd->GetTangents()->GetNumberOfComponents(), 3);
  EXPECT_EQ(pd->GetNormals()->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(mesh.polyData->GetNumberOfPolys(), 2);
  for (vtkIdType i = 0; i < mesh.polyData->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(test::point(mesh.polyData, i).z, 0.0, 1e-7);
    EXPECT_NEAR(glm::length(test::vec3(pd->GetNormals(), i) - glm::dvec3(0, 0, 1)), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(test::vec3(pd->GetTangents(), i) - glm::dvec3(1, 0, 0)), 0.0, 1e-6);
    // The file's v runs down the image (v = 1 - y here); flipped, (u, v) = (x, y) as on the
    // built-in plate, and the tangent +X is dP/du.
    const glm::dvec3 p = test::point(mesh.polyData, i);
    EXPECT_NEAR(test::vec2(pd->GetTCoords(), i).x, p.x, 1e-6);
    EXPECT_NEAR(test::vec2(pd->GetTCoords(), i).y, p.y, 1e-6);
  }
  // Counter-clockwise seen from +Z after the turn.
  test::forEachTriangle(mesh.polyData,
                        [&](vtkIdType a, vtkIdType b, vtkIdType c) {
                          EXPECT_GT(test::faceNormalUnnormalised(mesh.polyData, a, b, c).z, 0.0);
                        });
}

TEST_F(MeshLoaderTest, ObjNormalsAndUvsAreKeptAsUnitFloatArrays)
{
  // A unit square with per-corner UVs and a non-normalised file normal (0, 0, 2).
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                          "vn 0 0 2\nf 1/1/1 2/2/1 3/3/1 4/4/1\n";
  LoadedMesh mesh = this->loadQuietly(this->write("square.obj", obj));
  vtkPointData* pd = mesh.polyData->GetPointData();
  ASSERT_NE(pd->GetNormals(), nullptr);
  ASSERT_NE(pd->GetTCoords(), nullptr);
  EXPECT_EQ(pd->GetTCoords()->GetNumberOfComponents(), 2);
  EXPECT_EQ(mesh.polyData->GetNumberOfPolys(), 2);
  for (vtkIdType i = 0; i < mesh.polyData->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = test::point(mesh.polyData, i);
    EXPECT_NEAR(glm::length(test::vec3(pd->GetNormals(), i) - glm::dvec3(0, 0, 1)), 0.0, 1e-6);
    // The file maps (x, y) to (u, v) = (x, y).
    EXPECT_NEAR(test::vec2(pd->GetTCoords(), i).x, p.x, 1e-6);
    EXPECT_NEAR(test::vec2(pd->GetTCoords(), i).y, p.y, 1e-6);
  }
}

TEST_F(MeshLoaderTest, FileProblemsAreReportedWithThePath)
{
  EXPECT_EQ(this->loadError((this->Dir / "missing.obj").string()), "no such file");
  fs::create_directories(this->Dir / "folder.obj");
  EXPECT_EQ(this->loadError((this->Dir / "folder.obj").string()),
            "is a directory, not a mesh file");
  EXPECT_EQ(this->loadError(this->write("empty.stl", "")), "empty file");
  EXPECT_EQ(this->loadError(this->write("mesh.xyz", boxObj())),
            "unknown mesh format '.xyz' (expected *.obj *.ply *.stl *.off *.vtk *.vtp *.vtu *.vtm *.gltf "
            "*.glb *.step *.stp *.iges *.igs)");
  EXPECT_EQ(this->loadError(this->write("mesh", boxObj())),
            "no file extension (expected *.obj *.ply *.stl *.off *.vtk *.vtp *.vtu *.vtm *.gltf *.glb "
            "*.step *.stp *.iges *.igs)");
}

TEST_F(MeshLoaderTest, ReaderErrorsBecomeTheMessageAndVtkOutputIsRestored)
{
  vtkOutputWindow* before = vtkOutputWindow::GetInstance();
  const std::string gltf = this->loadError(this->write("broken.gltf", "{\"asset\": garbage"));
  EXPECT_NE(gltf.find("syntax error"), std::string::npos) << gltf;
  EXPECT_EQ(gltf.find("0x"), std::string::npos) << "object addresses are noise: " << gltf;
  const std::string ply = this->loadError(
      this->write("broken.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"));
  EXPECT_FALSE(ply.empty());
  EXPECT_EQ(vtkOutputWindow::GetInstance(), before);
}

TEST_F(MeshLoaderTest, MeshesWithoutFacesAreRejected)
{
  EXPECT_EQ(this->loadError(this->write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")), "no faces");
  EXPECT_EQ(
      this->loadError(this->write(
          "lines.vtk", "# vtk DataFile Version 3.0\nl\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
                       "0 0 0 1 0 0 0 1 0\nLINES 1 4\n3 0 1 2\n")),
      "no faces (only 1 vertex or line cells)");
  EXPECT_EQ(this->loadError(this->write("nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")),
            "no faces");
}

TEST_F(MeshLoaderTest, NanVerticesDropTheirFacesAndAreCounted)
{
  // Corner 6 of the box is NaN: the three quads around it go, three stay (6 triangles).
  std::string off = "OFF\n8 6 12\n";
  for (int i = 0; i < 8; ++i)
  {
    off += i == 6 ? "nan 3 0.5\n"
                  : std::to_string(kBox[i][0]) + " " + std::to_string(kBox[i][1]) + " " +
                        std::to_string(kBox[i][2]) + "\n";
  }
  off += quadLines();
  LoadedMesh mesh = this->loadQuietly(this->write("nan.off", off));
  EXPECT_EQ(mesh.report.nonFiniteVertices, 1);
  EXPECT_EQ(mesh.report.nonFiniteFacesDropped, 3);
  EXPECT_EQ(mesh.polyData->GetNumberOfPolys(), 6);
  EXPECT_EQ(mesh.polyData->GetNumberOfPoints(), 7);
  EXPECT_TRUE(test::allFinite(mesh.polyData));
  EXPECT_FALSE(mesh.report.notes().empty());

  const std::string allNan = this->loadError(
      this->write("allnan.off", "OFF\n3 1 0\nnan 0 0\n1 inf 0\n0 1 nan\n3 0 1 2\n"));
  EXPECT_EQ(
      allNan,
      "no valid faces (1 with NaN/Inf vertices, 0 of zero area, 0 with invalid vertex indices)");
}

TEST_F(MeshLoaderTest, ZeroAreaTrianglesAreDroppedAndCounted)
{
  // The box plus a collinear triangle and one with a repeated corner.
  const std::string obj = boxObj() + "v 5 5 5\nv 6 6 6\nv 7 7 7\nf 9 10 11\nf 1 1 2\n";
  LoadedMesh mesh = this->loadQuietly(this->write("slivers.obj", obj));
  EXPECT_EQ(mesh.report.zeroAreaTrianglesDropped, 2);
  EXPECT_EQ(mesh.report.unusedVerticesRemoved, 3);
  EXPECT_EQ(mesh.polyData->GetNumberOfPolys(), 12);
  EXPECT_EQ(mesh.polyData->GetNumberOfPoints(), 8);

  const std::string allFlat =
      this->loadError(this->write("flat.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 1 1 3\n"));
  EXPECT_EQ(
      allFlat,
      "no valid faces (0 with NaN/Inf vertices, 2 of zero area, 0 with invalid vertex indices)");
}

TEST_F(MeshLoaderTest, ExactDuplicatesMergeButAttributeSeamsStay)
{
  // Each quad with its own four corners (24 vertices): without attributes they are the same 8
  // corners, so 16 merge.
  std::string separate;
  for (const auto& q : kQuads)
  {
    for (int id : q)
    {
      separate += "v " + std::to_string(kBox[id][0]) + " " + std::to_string(kBox[id][1]) + " " +
                  std::to_string(kBox[id][2]) + "\n";
    }
  }
  std::string faces;
  for (int f = 0; f < 6; ++f)
  {
    faces += "f " + std::to_string(4 * f + 1) + " " + std::to_string(4 * f + 2) + " " +
             std::to_string(4 * f + 3) + " " + std::to_string(4 * f + 4) + "\n";
  }
  LoadedMesh merged = this->loadQuietly(this->write("separate.obj", separate + faces));
  EXPECT_EQ(merged.report.duplicateVerticesMerged, 16);
  EXPECT_EQ(merged.polyData->GetNumberOfPoints(), 8);
  EXPECT_EQ(merged.report.boundaryEdges, 0); // closed again once merged

  // With a distinct normal per face the corners differ in an attribute: nothing merges.
  const char* normals[6] = {"0 0 -1", "0 0 1", "0 -1 0", "0 1 0", "-1 0 0", "1 0 0"};
  std::string withNormals = separate;
  for (const char* n : normals)
  {
    withNormals += std::string("vn ") + n + "\n";
  }
  for (int f = 0; f < 6; ++f)
  {
    withNormals += "f";
    for (int k = 1; k <= 4; ++k)
    {
      withNormals += " " + std::to_string(4 * f + k) + "//" + std::to_string(f + 1);
    }
    withNormals += "\n";
  }
  LoadedMesh kept = this->loadQuietly(this->write("hard-edges.obj", withNormals));
  EXPECT_EQ(kept.report.duplicateVerticesMerged, 0);
  EXPECT_EQ(kept.polyData->GetNumberOfPoints(), 24);
}

TEST_F(MeshLoaderTest, NonManifoldEdgesAndInvalidIndicesAreCountedNotFatal)
{
  // Three triangles on the edge (1, 2), plus a face pointing past the vertex list.
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 2 9\n";
  LoadedMesh mesh = this->loadQuietly(this->write("fin.obj", obj));
  EXPECT_EQ(mesh.report.nonManifoldEdges, 1);
  EXPECT_EQ(mesh.report.invalidCellsDropped, 1);
  EXPECT_EQ(mesh.polyData->GetNumberOfPolys(), 3);
}

TEST_F(MeshLoaderTest, InvalidFileNormalsAreDiscardedForRecomputation)
{
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nvn 0 0 1\nf 1//1 2//2 3//2\n";
  LoadedMesh mesh = this->loadQuietly(this->write("zero-normal.obj", obj));
  EXPECT_EQ(mesh.report.invalidNormals, 1);
  EXPECT_EQ(mesh.polyData->GetPointData()->GetNormals(), nullptr);
  EXPECT_FALSE(mesh.report.hasNormals);
}

TEST_F(MeshLoaderTest, ConcaveAndHugePolygonsAreTriangulatedInsideThem)
{
  // An L-shaped hexagon listed from the corner whose fan would leave the shape: ear cutting
  // must give the L's area, 3 + 2 = 5, with every triangle facing +Z.
  const std::string l = "OFF\n6 1 0\n1 3 0\n0 3 0\n0 0 0\n3 0 0\n3 1 0\n1 1 0\n6 0 1 2 3 4 5\n";
  LoadedMesh shape = this->loadQuietly(this->write("l.off", l));
  EXPECT_EQ(shape.polyData->GetNumberOfPolys(), 4);
  EXPECT_NEAR(test::surfaceArea(shape.polyData), 5.0, 1e-12);
  test::forEachTriangle(shape.polyData,
                        [&](vtkIdType a, vtkIdType b, vtkIdType c) {
                          EXPECT_GT(test::faceNormalUnnormalised(shape.polyData, a, b, c).z, 0.0);
                        });
  // A convex 3000-gon (beyond the ear-cutting limit: fanned): n - 2 triangles and the regular
  // polygon's area n/2 sin(2 pi / n).
  const int n = 3000;
  std::string big = "OFF\n" + std::to_string(n) + " 1 0\n";
  for (int i = 0; i < n; ++i)
  {
    const double a = 2.0 * test::kPi * i / n;
    big += std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  big += std::to_string(n);
  for (int i = 0; i < n; ++i)
  {
    big += " " + std::to_string(i);
  }
  LoadedMesh disc = this->loadQuietly(this->write("disc.off", big + "\n"));
  EXPECT_EQ(disc.polyData->GetNumberOfPolys(), n - 2);
  // Coordinates were written with 6 decimals: the area is good to about 1e-5.
  EXPECT_NEAR(test::surfaceArea(disc.polyData), 0.5 * n * std::sin(2.0 * test::kPi / n), 1e-4);
}

TEST(MeshValidation, AttributesWithoutOneValuePerVertexAreDropped)
{
  // A corrupt file's attribute shorter than the vertex list must not be read past its end.
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[3] = {0, 1, 2};
  polys->InsertNextCell(3, ids);
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  vtkNew<vtkFloatArray> shortNormals;
  shortNormals->SetNumberOfComponents(3);
  shortNormals->InsertNextTuple3(0, 0, 1);
  shortNormals->SetName("Normals");
  mesh->GetPointData()->SetNormals(shortNormals);
  MeshReport report;
  vtkSmartPointer<vtkPolyData> clean = sanitizeSurface(mesh, "short.vtp", report);
  EXPECT_EQ(report.malformedArraysDropped, 1);
  EXPECT_EQ(clean->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(clean->GetNumberOfPolys(), 1);
}

TEST_F(MeshLoaderTest, OffVariantsParse)
{
  // Counts on the header line, CRLF ends, comments, a pentagon (3 triangles) and a line.
  const std::string sameLine = "OFF 5 2 0\r\n# c\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0.5 1.5 0\r\n"
                               "0 1 0  # tip\r\n5 0 1 2 3 4\r\n2 0 2\r\n";
  LoadedMesh pentagon = this->loadQuietly(this->write("pentagon.off", sameLine));
  EXPECT_EQ(pentagon.polyData->GetNumberOfPolys(), 3);
  EXPECT_EQ(pentagon.report.nonSurfaceCellsDropped, 1);
  EXPECT_NEAR(test::surfaceArea(pentagon.polyData), 1.25, 1e-9); // square plus its roof

  // NOFF: per-vertex normals; STOFF: texture coordinates after the position; COFF colours
  // are skipped.
  const std::string noff = "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n";
  LoadedMesh withNormals = this->loadQuietly(this->write("n.off", noff));
  EXPECT_TRUE(withNormals.report.hasNormals);
  const std::string stcoff =
      "STCOFF\n3 1 0\n0 0 0 1 0 0 1 0 0\n1 0 0 0 1 0 1 1 0\n0 1 0 0 0 1 1 0 1\n3 0 1 2 255 0 0\n";
  LoadedMesh withUv = this->loadQuietly(this->write("st.off", stcoff));
  ASSERT_TRUE(withUv.report.hasTCoords);
  vtkDataArray* tc = withUv.polyData->GetPointData()->GetTCoords();
  for (vtkIdType i = 0; i < withUv.polyData->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = test::point(withUv.polyData, i);
    EXPECT_NEAR(test::vec2(tc, i).x, p.x, 1e-6);
    EXPECT_NEAR(test::vec2(tc, i).y, p.y, 1e-6);
  }
}

TEST_F(MeshLoaderTest, MalformedOffFilesNameTheProblem)
{
  EXPECT_EQ(this->loadError(this->write("binary.off", "OFF BINARY\n")),
            "binary OFF is not supported");
  EXPECT_EQ(this->loadError(this->write("four.off", "4OFF\n1 0 0\n0 0 0 0\n")),
            "only 3-D OFF is supported (4OFF and nOFF are not)");
  EXPECT_EQ(this->loadError(this->write("counts.off", "OFF\n-3 1 0\n")),
            "line 2: invalid vertex or face count '-3 1'");
  EXPECT_EQ(this->loadError(this->write("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n")),
            "line 6: vertex index 3 out of range (3 vertices)");
  EXPECT_EQ(this->loadError(this->write("word.off", "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n")),
            "line 4: 'x' is not a number");
  EXPECT_EQ(this->loadError(this->write("short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n")),
            "line 4: truncated: expected 3 vertices, found 2");
  EXPECT_EQ(this->loadError(this->write("face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n9 0 1 2\n")),
            "line 6: face lists 9 vertices but gives 3 indices");
  // A hostile header must not allocate a billion vertices before noticing the file is short.
  EXPECT_EQ(this->loadError(this->write("huge.off", "OFF\n1000000000 1000000000 0\n0 0 0\n")),
            "line 3: truncated: expected 1000000000 vertices, found 1");
}

TEST_F(MeshLoaderTest, TruncatedFilesFailCleanlyOrLoadWhatIsThere)
{
  vtkSmartPointer<vtkPolyData> box = boxPolyData();
  vtkNew<vtkXMLPolyDataWriter> vtp;
  vtp->SetInputData(box);
  vtp->SetDataModeToAscii();
  vtp->SetFileName((this->Dir / "source.vtp").string().c_str());
  ASSERT_EQ(vtp->Write(), 1);
  std::ifstream in(this->Dir / "source.vtp", std::ios::binary);
  const std::string vtpText((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());

  const std::vector<std::pair<std::string, std::string>> sources = {
      {"obj", boxObj()},       {"off", boxOff()}, {"ply", boxPly()},   {"stl", boxStl()},
      {"vtk", boxLegacyVtk()}, {"vtp", vtpText},  {"gltf", boxGltf()}, {"glb", boxGlb()}};
  for (const auto& [ext, content] : sources)
  {
    for (double fraction : {0.1, 0.33, 0.5, 0.8, 0.97})
    {
      const size_t length = static_cast<size_t>(fraction * static_cast<double>(content.size()));
      SCOPED_TRACE(ext + " cut to " + std::to_string(length) + " bytes");
      this->expectErrorOrValidMesh(
          this->write("cut" + std::to_string(length) + "." + ext, content.substr(0, length)));
    }
  }
}

TEST_F(MeshLoaderTest, AReaderCrashBecomesAnErrorInsteadOfEndingTheProcess)
{
  // OpenCASCADE 7.6 dereferences an empty handle for this STEP circle, whose placement is an
  // entity of another type (tests/data/fuzz/open/): the file kills the reading process. The
  // loader runs the readers in a child process, so the test process survives and gets an error
  // naming the file.
  const std::string step =
      std::string(ANISO_SOURCE_DIR) + "/tests/data/fuzz/open/step-circle-placement-of-wrong-type.step";
  EXPECT_EQ(this->loadError(step), "the reader crashed on this file (corrupt or unsupported content)");
  // VTK 9.1's legacy reader dereferenced a closed stream when a POLYGONS list ended early; such a
  // list is refused before VTK reads it (core/formats/vtk_legacy_sizes.h).
  const std::string legacy = boxLegacyVtk();
  const std::string cut = legacy.substr(0, legacy.size() - 12);
  const std::string cutError = this->loadError(this->write("cut.vtk", cut));
  EXPECT_NE(cutError.find("POLYGONS lists"), std::string::npos) << cutError;
  EXPECT_NE(cutError.find("the file ends after"), std::string::npos) << cutError;
  // A header that is not a dataset gives the fallback message, not the pipeline's jargon.
  EXPECT_EQ(this->loadError(this->write("head.vtk", "# vtk DataFile Version 3.0\nbox\nASCII")),
            "the reader failed (corrupt file, or not in this format)");
}

// VTK's readers run in the reader program (MeshReaderProcess.h), found through
// ANISO_MESH_READER first: stand-ins for it show that whatever that process does, the loader
// reports it with the file's name and the test process goes on. The real program reads the box.
TEST_F(MeshLoaderTest, TheReaderProgramsFailuresAreErrorsNamingTheFile)
{
  const std::string box = this->write("box.obj", boxObj());
  const auto withReader = [&](const std::string& program)
  {
    ::setenv("ANISO_MESH_READER", program.c_str(), 1);
    std::string message = this->loadError(box);
    ::unsetenv("ANISO_MESH_READER");
    return message;
  };
  const auto script = [&](const std::string& name, const std::string& body)
  {
    const std::string path = this->write(name, "#!/bin/sh\n" + body + "\n");
    std::filesystem::permissions(path, std::filesystem::perms::owner_all);
    return path;
  };
  const std::string missing = (this->Dir / "no-such-reader").string();
  EXPECT_EQ(withReader(missing), "aniso-mesh-reader: the mesh reader program is missing (looked "
                                 "for " + missing + ")");
  EXPECT_EQ(withReader(script("segv.sh", "kill -SEGV $$")),
            "the reader crashed on this file (corrupt or unsupported content)");
  EXPECT_EQ(withReader(script("silent.sh", "exit 0")),
            "the reader process ended without a result (corrupt file?)");
  EXPECT_EQ(withReader(script("noise.sh", "echo not a record")),
            "the reader process ended without a result (corrupt file?)");
  expectBox(this->loadQuietly(box), "obj through the reader program");
}

TEST_F(MeshLoaderTest, GarbageBytesFailCleanly)
{
  std::mt19937 random(12345u);
  std::uniform_int_distribution<int> byte(0, 255);
  for (const char* ext : {"obj", "off", "ply", "stl", "vtk", "vtp", "gltf", "glb"})
  {
    for (int trial = 0; trial < 4; ++trial)
    {
      std::string bytes(static_cast<size_t>(64 + 500 * trial), '\0');
      for (char& c : bytes)
      {
        c = static_cast<char>(byte(random));
      }
      SCOPED_TRACE(std::string(ext) + " trial " + std::to_string(trial));
      this->expectErrorOrValidMesh(
          this->write("garbage" + std::to_string(trial) + "." + ext, bytes));
    }
  }
  // Plausible headers followed by garbage.
  std::string tail(400, '\0');
  for (char& c : tail)
  {
    c = static_cast<char>(byte(random));
  }
  this->expectErrorOrValidMesh(this->write("h.ply", "ply\nformat binary_little_endian 1.0\n"
                                                    "element vertex 100000000\nproperty float x\n"
                                                    "end_header\n" +
                                                        tail));
  this->expectErrorOrValidMesh(this->write(
      "h.vtk",
      "# vtk DataFile Version 3.0\nx\nBINARY\nDATASET POLYDATA\nPOINTS 100000000 float\n" + tail));
  this->expectErrorOrValidMesh(
      this->write("h.obj", "v 1 2 3\nf 1 2 3\nf -7 99999999999 1\n" + tail));
}
} // namespace
} // namespace aniso
