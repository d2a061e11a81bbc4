// Data arrays travel from each format that carries them to the loaded surface, with their
// values at the right vertices and faces: files written by independent writers (VTK's
// vtkXMLPolyDataWriter, vtkPolyDataWriter, vtkXMLUnstructuredGridWriter and
// vtkXMLMultiBlockDataWriter; tinygltf's writer) or by hand (PLY). Every value is a known
// function of its vertex's position (point data) or its face's centroid (cell data), so the
// checks hold whatever order the loader leaves the vertices in. Also: NaN and Inf values are
// counted by describeArrays and its listing line; prepareSurface keeps the arrays through
// normal splitting and makes no NaN tangent from them.
#include "tests/vtkpasses/mesh/gltf_test_files.h"
#include "tests/vtkpasses/mesh/mesh_test_files.h"
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/MeshArrays.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/SurfacePreparation.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkHexahedron.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationStringKey.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace aniso
{
namespace
{
class MeshFieldsTest : public test::MeshFilesTest
{
};

glm::dvec3 flowAt(const glm::dvec3& p)
{
  return {p.x + 1.0, -2.0 * p.y, 3.0 * p.z + 0.5};
}

double pressureAt(const glm::dvec3& centroid)
{
  return 10.0 * centroid.x - centroid.y;
}

glm::dvec3 centroidOf(vtkPolyData* mesh, vtkIdType cell)
{
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  mesh->GetCellPoints(cell, count, ids);
  glm::dvec3 sum(0.0);
  for (vtkIdType k = 0; k < count; ++k)
  {
    sum += test::point(mesh, ids[k]);
  }
  return sum / double(count);
}

// The built-in plate (triangles) with point array "flow" and cell array "pressure".
vtkSmartPointer<vtkPolyData> plateWithFields()
{
  vtkSmartPointer<vtkPolyData> plate = makePlate(4);
  plate->GetPointData()->SetTangents(nullptr);
  plate->GetPointData()->RemoveArray("Tangents");
  vtkNew<vtkFloatArray> flow;
  flow->SetName("flow");
  flow->SetNumberOfComponents(3);
  flow->SetNumberOfTuples(plate->GetNumberOfPoints());
  for (vtkIdType i = 0; i < plate->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 v = flowAt(test::point(plate, i));
    flow->SetTuple3(i, v.x, v.y, v.z);
  }
  plate->GetPointData()->AddArray(flow);
  vtkNew<vtkDoubleArray> pressure;
  pressure->SetName("pressure");
  pressure->SetNumberOfTuples(plate->GetNumberOfCells());
  for (vtkIdType c = 0; c < plate->GetNumberOfCells(); ++c)
  {
    pressure->SetValue(c, pressureAt(centroidOf(plate, c)));
  }
  plate->GetCellData()->AddArray(pressure);
  return plate;
}

void expectFlow(vtkPolyData* mesh, const std::string& name = "flow")
{
  vtkDataArray* flow = mesh->GetPointData()->GetArray(name.c_str());
  ASSERT_NE(flow, nullptr) << name;
  ASSERT_EQ(flow->GetNumberOfComponents(), 3);
  ASSERT_EQ(flow->GetNumberOfTuples(), mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 expected = flowAt(test::point(mesh, i));
    EXPECT_NEAR(glm::length(test::vec3(flow, i) - expected), 0.0, 1e-5) << "point " << i;
  }
}

void expectPressure(vtkPolyData* mesh)
{
  vtkDataArray* pressure = mesh->GetCellData()->GetArray("pressure");
  ASSERT_NE(pressure, nullptr);
  ASSERT_EQ(pressure->GetNumberOfTuples(), mesh->GetNumberOfCells());
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    EXPECT_NEAR(pressure->GetComponent(c, 0), pressureAt(centroidOf(mesh, c)), 1e-9)
        << "cell " << c;
  }
}

TEST_F(MeshFieldsTest, VtpAndLegacyVtkKeepPointAndCellArrays)
{
  vtkSmartPointer<vtkPolyData> plate = plateWithFields();
  vtkNew<vtkXMLPolyDataWriter> xml;
  xml->SetInputData(plate);
  xml->SetFileName(this->path("plate.vtp").c_str());
  ASSERT_EQ(xml->Write(), 1);
  vtkNew<vtkPolyDataWriter> legacy;
  legacy->SetInputData(plate);
  legacy->SetFileName(this->path("plate.vtk").c_str());
  ASSERT_EQ(legacy->Write(), 1);
  for (const char* name : {"plate.vtp", "plate.vtk"})
  {
    SCOPED_TRACE(name);
    const LoadedMesh mesh = loadMesh(this->path(name));
    EXPECT_EQ(mesh.polyData->GetNumberOfCells(), plate->GetNumberOfCells());
    expectFlow(mesh.polyData);
    expectPressure(mesh.polyData);
    EXPECT_EQ(vectorArrayNames(mesh.polyData), std::vector<std::string>{"flow"});
  }
}

// Two unit hexahedra side by side along X ([0, 2] x [0, 1] x [0, 1]): the outer surface has 10
// quads (20 triangles); each face carries the pressure of its hexahedron (0 for x < 1, 1 beyond)
// and each vertex the point array.
vtkSmartPointer<vtkUnstructuredGrid> twoHexahedra()
{
  vtkNew<vtkPoints> points;
  for (int x = 0; x <= 2; ++x)
  {
    for (int y = 0; y <= 1; ++y)
    {
      for (int z = 0; z <= 1; ++z)
      {
        points->InsertNextPoint(x, y, z);
      }
    }
  }
  const auto id = [](int x, int y, int z) { return vtkIdType(x * 4 + y * 2 + z); };
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  vtkNew<vtkDoubleArray> pressure;
  pressure->SetName("pressure");
  for (int x = 0; x < 2; ++x)
  {
    const vtkIdType ids[8] = {id(x, 0, 0), id(x + 1, 0, 0), id(x + 1, 1, 0), id(x, 1, 0),
                              id(x, 0, 1), id(x + 1, 0, 1), id(x + 1, 1, 1), id(x, 1, 1)};
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
    pressure->InsertNextValue(x);
  }
  grid->GetCellData()->AddArray(pressure);
  vtkNew<vtkFloatArray> flow;
  flow->SetName("flow");
  flow->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    const glm::dvec3 v = flowAt({p[0], p[1], p[2]});
    flow->InsertNextTuple3(v.x, v.y, v.z);
  }
  grid->GetPointData()->AddArray(flow);
  return grid;
}

void expectHexahedraSurface(vtkPolyData* mesh)
{
  EXPECT_EQ(mesh->GetNumberOfCells(), 20);
  EXPECT_EQ(mesh->GetNumberOfPoints(), 12);
  expectFlow(mesh);
  vtkDataArray* pressure = mesh->GetCellData()->GetArray("pressure");
  ASSERT_NE(pressure, nullptr);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    mesh->GetCellPoints(c, count, ids);
    double lowest = 2.0;
    double highest = 0.0;
    for (vtkIdType k = 0; k < count; ++k)
    {
      lowest = std::min(lowest, test::point(mesh, ids[k]).x);
      highest = std::max(highest, test::point(mesh, ids[k]).x);
    }
    // A face of the first hexahedron lies within x <= 1, of the second within x >= 1.
    const double expected = highest <= 1.0 ? 0.0 : 1.0;
    EXPECT_TRUE(highest <= 1.0 || lowest >= 1.0) << "cell " << c;
    EXPECT_EQ(pressure->GetComponent(c, 0), expected) << "cell " << c;
  }
}

// VTK's legacy writer stores an array's information keys in INFORMATION blocks (here the L2
// norm range the array caches once asked, a component range key of VTK's and a units label):
// such files read, ASCII and binary, with their arrays. The same file with a key's value turned
// into no number, or one value short, is refused naming the line and the key, before VTK's
// reader, which never ends on it (tests/data/fuzz/vtk/information-value-not-a-number.vtk).
TEST_F(MeshFieldsTest, LegacyInformationBlocksReadAndMalformedOnesAreRefused)
{
  vtkSmartPointer<vtkPolyData> plate = plateWithFields();
  vtkDataArray* flow = plate->GetPointData()->GetArray("flow");
  double range[2];
  flow->GetRange(range, -1); // caches vtkDataArray::L2_NORM_RANGE in the array's information
  flow->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), "m/s");
  const double componentRange[2] = {-1.0, 2.5};
  flow->GetInformation()->Set(vtkDataArray::COMPONENT_RANGE(), componentRange, 2);
  for (const int type : {VTK_ASCII, VTK_BINARY})
  {
    const std::string name = type == VTK_ASCII ? "ascii.vtk" : "binary.vtk";
    SCOPED_TRACE(name);
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetInputData(plate);
    writer->SetFileType(type);
    writer->SetFileName(this->path(name).c_str());
    ASSERT_EQ(writer->Write(), 1);
    std::ifstream in(this->path(name), std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t rangeKey = text.find("NAME L2_NORM_RANGE LOCATION vtkDataArray");
    ASSERT_NE(rangeKey, std::string::npos) << "VTK's writer wrote no INFORMATION block";
    ASSERT_NE(text.find("NAME UNITS_LABEL LOCATION vtkDataArray"), std::string::npos);
    const LoadedMesh mesh = loadMesh(this->path(name));
    expectFlow(mesh.polyData);
    expectPressure(mesh.polyData);

    // The L2 norm range's DATA line ("DATA 2 LOW HIGH"): its first value made no number, then
    // its second value left out.
    const size_t data = text.find("DATA 2 ", rangeKey);
    ASSERT_NE(data, std::string::npos);
    const size_t end = text.find('\n', data);
    const size_t firstValue = data + 7;
    const size_t secondValue = text.find(' ', firstValue) + 1;
    const std::string notANumber =
        text.substr(0, firstValue) + "1ETA" + text.substr(text.find(' ', firstValue));
    const std::string oneShort = text.substr(0, secondValue - 1) + text.substr(end);
    for (const auto& [bad, why] : {std::pair{notANumber, std::string("is not a number")},
                                  std::pair{oneShort, std::string("2 values declared, 1 on its")}})
    {
      const std::string badPath = this->path("bad-" + name);
      std::ofstream(badPath, std::ios::binary | std::ios::trunc) << bad;
      try
      {
        loadMesh(badPath);
        ADD_FAILURE() << "read: " << why;
      }
      catch (const Error& e)
      {
        const std::string what = e.what();
        EXPECT_NE(what.find("bad-" + name), std::string::npos) << what;
        EXPECT_NE(what.find("vtkDataArray::L2_NORM_RANGE"), std::string::npos) << what;
        EXPECT_NE(what.find(why), std::string::npos) << what;
        EXPECT_NE(what.find("line "), std::string::npos) << what;
      }
    }
  }
}

TEST_F(MeshFieldsTest, VtuIsReadAsItsOuterSurfaceWithItsArrays)
{
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(twoHexahedra());
  writer->SetFileName(this->path("cells.vtu").c_str());
  ASSERT_EQ(writer->Write(), 1);
  const LoadedMesh mesh = loadMesh(this->path("cells.vtu"));
  expectHexahedraSurface(mesh.polyData);
  EXPECT_NE(meshFilePatterns().find("*.vtu"), std::string::npos);
}

TEST_F(MeshFieldsTest, VtmBlocksKeepTheirOwnArrays)
{
  vtkNew<vtkMultiBlockDataSet> tree;
  tree->SetNumberOfBlocks(2);
  tree->SetBlock(0, plateWithFields());
  tree->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "plate");
  tree->SetBlock(1, twoHexahedra());
  tree->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "cells");
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  writer->SetInputData(tree);
  writer->SetFileName(this->path("scene.vtm").c_str());
  ASSERT_EQ(writer->Write(), 1);
  const LoadedBlocks loaded = loadMeshBlocks(this->path("scene.vtm"));
  ASSERT_EQ(loaded.blocks.size(), 2u);
  EXPECT_EQ(loaded.blocks[0].name, "plate");
  expectFlow(loaded.blocks[0].mesh.polyData);
  expectPressure(loaded.blocks[0].mesh.polyData);
  EXPECT_EQ(loaded.blocks[1].name, "cells");
  expectHexahedraSurface(loaded.blocks[1].mesh.polyData);
}

TEST_F(MeshFieldsTest, PlyPropertiesBeyondPositionsBecomePointArrays)
{
  // A square of two triangles; flow_x, flow_y, flow_z make the vector "flow", "temperature" a
  // scalar (one NaN), "red" a colour channel; the normals stay the contract's "Normals".
  const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::string ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                    "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
                    "property float nz\nproperty double flow_x\nproperty double flow_y\n"
                    "property double flow_z\nproperty float temperature\nproperty uchar red\n"
                    "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < 4; ++i)
  {
    const glm::dvec3 p(corners[i][0], corners[i][1], 0.0);
    const glm::dvec3 v = flowAt(p);
    ply += std::to_string(p.x) + " " + std::to_string(p.y) + " 0 0 0 1 " + std::to_string(v.x) +
           " " + std::to_string(v.y) + " " + std::to_string(v.z) + " " +
           (i == 2 ? std::string("nan") : std::to_string(20 + i)) + " " + std::to_string(100 + i) +
           "\n";
  }
  ply += "3 0 1 2\n3 0 2 3\n";
  const LoadedMesh mesh = loadMesh(this->write("square.ply", ply));
  ASSERT_EQ(mesh.polyData->GetNumberOfPoints(), 4);
  expectFlow(mesh.polyData);
  ASSERT_NE(mesh.polyData->GetPointData()->GetNormals(), nullptr);
  vtkDataArray* temperature = mesh.polyData->GetPointData()->GetArray("temperature");
  vtkDataArray* red = mesh.polyData->GetPointData()->GetArray("red");
  ASSERT_NE(temperature, nullptr);
  ASSERT_NE(red, nullptr);
  EXPECT_EQ(mesh.polyData->GetPointData()->GetArray("flow_x"), nullptr);
  // Double properties stay double; float and byte ones are float.
  EXPECT_EQ(mesh.polyData->GetPointData()->GetArray("flow")->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(temperature->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(red->GetDataType(), VTK_FLOAT);
  int nan = 0;
  for (vtkIdType i = 0; i < 4; ++i)
  {
    const glm::dvec3 p = test::point(mesh.polyData, i);
    const int corner = p.x < 0.5 ? (p.y < 0.5 ? 0 : 3) : (p.y < 0.5 ? 1 : 2);
    if (corner == 2)
    {
      EXPECT_TRUE(std::isnan(temperature->GetComponent(i, 0)));
      ++nan;
    }
    else
    {
      EXPECT_EQ(temperature->GetComponent(i, 0), 20 + corner);
    }
    EXPECT_EQ(red->GetComponent(i, 0), 100 + corner);
  }
  EXPECT_EQ(nan, 1);
  // The load's report tells the NaN value.
  ASSERT_EQ(mesh.report.nonFiniteArrayValues.size(), 1u);
  EXPECT_EQ(mesh.report.nonFiniteArrayValues[0].first, "point array 'temperature'");
  EXPECT_EQ(mesh.report.nonFiniteArrayValues[0].second, 1);
  const std::vector<std::string> notes = mesh.report.notes();
  EXPECT_NE(std::find(notes.begin(), notes.end(),
                      "point array 'temperature': 1 value is NaN or Inf (kept)"),
            notes.end());
  const std::vector<ArrayInfo> arrays = describeArrays(mesh.polyData);
  bool listed = false;
  for (const ArrayInfo& info : arrays)
  {
    if (info.name == "temperature")
    {
      listed = true;
      EXPECT_FALSE(info.perCell);
      EXPECT_EQ(info.components, 1);
      EXPECT_EQ(info.nonFinite, 1);
      EXPECT_EQ(info.minimum, 20.0);
      EXPECT_EQ(info.maximum, 23.0);
      EXPECT_EQ(formatArrayInfo(info), "temperature\tpoint\t1 component\t20..23\t1 NaN/Inf");
    }
  }
  EXPECT_TRUE(listed);
}

TEST_F(MeshFieldsTest, GltfUnderscoreAttributesBecomePointArraysTurnedZUp)
{
  // The square of the glTF tests (in glTF's XZ plane) with "_flow" (VEC3) and "_heat" (SCALAR)
  // per vertex. glTF is Y-up: a direction (a, b, c) becomes (a, -c, b) like the geometry.
  tinygltf::Model model;
  model.materials.push_back(test::metallicRoughness(model, "m", {0.5, 0.5, 0.5}, 1.0, 0.3));
  const int mesh = test::squareMesh(model, "square", 0);
  tinygltf::Primitive& primitive = model.meshes[size_t(mesh)].primitives[0];
  const int count = int(model.accessors[size_t(primitive.attributes["POSITION"])].count);
  std::vector<float> flow;
  std::vector<float> heat;
  for (int i = 0; i < count; ++i)
  {
    flow.insert(flow.end(), {float(i), 1.0f, 2.0f * float(i)});
    heat.push_back(0.5f * float(i));
  }
  // The accessor helper appends buffer views: the primitive is looked up again afterwards.
  const int flowAccessor = test::accessor(model, flow, TINYGLTF_TYPE_VEC3, 3);
  const int heatAccessor = test::accessor(model, heat, TINYGLTF_TYPE_SCALAR, 1);
  model.meshes[size_t(mesh)].primitives[0].attributes["_flow"] = flowAccessor;
  model.meshes[size_t(mesh)].primitives[0].attributes["_heat"] = heatAccessor;
  tinygltf::Node node;
  node.mesh = mesh;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  model.asset.version = "2.0";
  test::writeModel(model, this->path("square.glb"));

  // Non-indexed: the loader merges equal vertices, so check each value against its own kind:
  // "_flow" (a, b, c) -> (a, -c, b) means y = -2x and z = 1, "_heat" is half of x's source.
  const LoadedMesh loaded = loadMesh(this->path("square.glb"));
  vtkDataArray* turned = loaded.polyData->GetPointData()->GetArray("_flow");
  vtkDataArray* scalar = loaded.polyData->GetPointData()->GetArray("_heat");
  ASSERT_NE(turned, nullptr);
  ASSERT_NE(scalar, nullptr);
  EXPECT_EQ(turned->GetNumberOfComponents(), 3);
  EXPECT_EQ(scalar->GetNumberOfComponents(), 1);
  for (vtkIdType i = 0; i < loaded.polyData->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 v = test::vec3(turned, i);
    EXPECT_NEAR(v.y, -2.0 * v.x, 1e-6) << i;
    EXPECT_NEAR(v.z, 1.0, 1e-6) << i;
    EXPECT_NEAR(scalar->GetComponent(i, 0), 0.5 * v.x, 1e-6) << i;
  }
}

// prepareSurface recomputes normals with splitting: the arrays follow the duplicated vertices
// and the cells; array:flow with NaN and Inf values gives finite unit tangents, the bad
// vertices counted.
TEST(MeshFields, PreparationKeepsArraysAndCountsNonFiniteField)
{
  vtkSmartPointer<vtkPolyData> plate = plateWithFields();
  plate->GetPointData()->SetNormals(nullptr);
  plate->GetPointData()->RemoveArray("Normals");
  vtkDataArray* flow = plate->GetPointData()->GetArray("flow");
  flow->SetComponent(0, 1, std::numeric_limits<double>::quiet_NaN());
  flow->SetComponent(1, 0, std::numeric_limits<double>::infinity());
  MeshReport report;
  vtkSmartPointer<vtkPolyData> clean = sanitizeSurface(plate, "plate", report);
  SurfaceOptions options;
  options.brushing = parseBrushingModel("array:flow");
  const PreparedSurface prepared = prepareSurface(clean, options, "plate");
  vtkPolyData* out = prepared.polyData;
  EXPECT_TRUE(prepared.report.normalsComputed);
  EXPECT_EQ(prepared.report.nonFiniteFieldTangents, 2);
  // Besides those, the field (x + 1, -2y, 0.5) is along the plate's normal +Z where x = -1 and
  // y = 0 (the splitting of the plate's border vertices aside, one vertex each).
  int64_t alongNormal = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = test::point(out, i);
    alongNormal += std::abs(p.x + 1.0) < 1e-12 && std::abs(p.y) < 1e-12 ? 1 : 0;
  }
  EXPECT_GE(alongNormal, 1);
  EXPECT_EQ(prepared.report.fallbackTangents, 2 + alongNormal);
  EXPECT_EQ(prepared.report.tangentSource, "array:flow");
  ASSERT_NE(out->GetPointData()->GetArray("flow"), nullptr);
  ASSERT_NE(out->GetCellData()->GetArray("pressure"), nullptr);
  expectPressure(out);
  bool told = false;
  for (const std::string& note : prepared.report.notes())
  {
    told = told || note == "2 vertices where the tangent field is NaN or Inf got a fixed "
                           "fallback tangent";
  }
  EXPECT_TRUE(told);
  vtkDataArray* tangents = out->GetPointData()->GetTangents();
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 t = test::vec3(tangents, i);
    EXPECT_NEAR(glm::length(t), 1.0, 1e-6) << i;
  }
  const std::vector<ArrayInfo> arrays = describeArrays(out);
  for (const ArrayInfo& info : arrays)
  {
    if (info.name == "flow")
    {
      EXPECT_EQ(info.nonFinite, 2);
    }
  }
}
} // namespace
} // namespace aniso
