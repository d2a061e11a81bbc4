// STEP and IGES through loadMeshBlocks (CadReader in the reader program). Each test says what it
// checks and against what reference: the files are written here by OpenCASCADE's own XCAF
// writers (STEPCAFControl_Writer, IGESCAFControl_Writer) from a document built here
// (cad_test_documents.h), whose names, colours and placements are the reference; a cylinder's tangents are compared with the
// analytic circle tangent and axis.
#include "core/error.h"
#include "tests/vtkpasses/mesh/cad_test_documents.h"
#include "tests/vtkpasses/mesh/mesh_test_files.h"
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "vtkpasses/mesh/BrushingModel.h"
#include "vtkpasses/mesh/CadReader.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/SurfacePreparation.h"

#include <TDocStd_Document.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gp_Trsf.hxx>
#include <gtest/gtest.h>
#include <iterator>
#include <map>
#include <string>
#include <unistd.h>
#include <vector>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

using namespace cadtest;

class CadReaderTest : public test::MeshFilesTest
{
protected:
  std::string writeStep(const Handle(TDocStd_Document) & document, const std::string& name) const
  {
    EXPECT_TRUE(writeStepFile(document, this->path(name))) << name;
    return this->path(name);
  }

  std::string writeIges(const Handle(TDocStd_Document) & document, const std::string& name) const
  {
    EXPECT_TRUE(writeIgesFile(document, this->path(name))) << name;
    return this->path(name);
  }
};

const MeshBlock* blockNamed(const LoadedBlocks& loaded, const std::string& name)
{
  for (const MeshBlock& block : loaded.blocks)
  {
    if (block.name == name)
    {
      return &block;
    }
  }
  return nullptr;
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

void expectMatrixNear(const PartMatrix& got, const PartMatrix& expected, const std::string& what)
{
  for (size_t i = 0; i < 16; ++i)
  {
    EXPECT_NEAR(got[i], expected[i], 1e-9) << what << " element " << i;
  }
}

void expectPaint(const MeshBlock& block, const Rgb& colour)
{
  ASSERT_TRUE(block.material) << block.name;
  const auto& albedo = block.material->value("albedo").number;
  // STEP and IGES keep colours as text: a few digits.
  EXPECT_NEAR(albedo[0], colour.r, 2e-3) << block.name;
  EXPECT_NEAR(albedo[1], colour.g, 2e-3) << block.name;
  EXPECT_NEAR(albedo[2], colour.b, 2e-3) << block.name;
  const auto& f0 = block.material->value("f0").number;
  EXPECT_EQ(f0, (std::array<double, 3>{0.04, 0.04, 0.04})) << block.name;
}

// The bounding box of a part's surface in its own frame.
std::array<double, 6> boundsOf(vtkPolyData* mesh)
{
  std::array<double, 6> b{};
  mesh->GetBounds(b.data());
  return b;
}

// A STEP assembly reads back as its tree: the leaf instances with their paths of instance
// names, the repeated pin twice with its own placement each (the sub-assembly's placement
// times the pin's), the products' colours as painted materials, each surface in its product's
// frame (the plate's box from the origin, the pin's cylinder around Z).
TEST_F(CadReaderTest, StepAssemblyKeepsTreeNamesColoursAndPlacements)
{
  const std::string file = this->writeStep(referenceDocument(), "rig.step");
  const LoadedBlocks loaded = loadMeshBlocks(file);
  EXPECT_EQ(namesOf(loaded),
            (std::vector<std::string>{"rig/base", "rig/pins/pin-a", "rig/pins/pin-b"}));
  EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
  const Reference r = reference();
  const MeshBlock* base = blockNamed(loaded, "rig/base");
  const MeshBlock* pinA = blockNamed(loaded, "rig/pins/pin-a");
  const MeshBlock* pinB = blockNamed(loaded, "rig/pins/pin-b");
  ASSERT_TRUE(base && pinA && pinB);
  expectMatrixNear(base->placement, kIdentityPlacement, "base");
  expectMatrixNear(pinA->placement, matrixOf(r.pins * r.pinA), "pin-a");
  expectMatrixNear(pinB->placement, matrixOf(r.pins * r.pinB), "pin-b");
  expectPaint(*base, kPlateColour);
  expectPaint(*pinA, kPinColour);
  expectPaint(*pinB, kPinColour);
  EXPECT_EQ(pinA->material->name, pinB->material->name); // one colour, one material

  const std::array<double, 6> plate = boundsOf(base->mesh.polyData);
  const std::array<double, 6> plateExpected{0.0, 20.0, 0.0, 10.0, 0.0, 2.0};
  for (size_t i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(plate[i], plateExpected[i], 1e-6) << "plate bound " << i;
  }
  const std::array<double, 6> pin = boundsOf(pinA->mesh.polyData);
  EXPECT_NEAR(pin[4], 0.0, 1e-6);
  EXPECT_NEAR(pin[5], kPinHeight, 1e-6);
  EXPECT_NEAR(pin[1], kPinRadius, 1e-6);
  EXPECT_NEAR(pin[0], -kPinRadius, 1e-2);
  // Every node of the pin lies on its cylinder or its caps.
  vtkPolyData* pinMesh = pinA->mesh.polyData;
  for (vtkIdType i = 0; i < pinMesh->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 p = test::point(pinMesh, i);
    EXPECT_LE(std::hypot(p.x, p.y), kPinRadius + 1e-6);
  }
  EXPECT_EQ(pinA->mesh.report.triangles, pinB->mesh.report.triangles);
  EXPECT_TRUE(pinA->mesh.report.hasNormals);
}

// The merged surface (loadMesh) puts each part where its placement does: its bounding box is
// the union of the placed parts' (the plate from 0 to 20 in X, the tilted pin-b above it).
TEST_F(CadReaderTest, StepAsOneSurfaceIsThePlacedParts)
{
  const std::string file = this->writeStep(referenceDocument(), "rig.step");
  const LoadedMesh merged = loadMesh(file);
  const LoadedBlocks loaded = loadMeshBlocks(file);
  int64_t triangles = 0;
  for (const MeshBlock& block : loaded.blocks)
  {
    triangles += block.mesh.report.triangles;
  }
  EXPECT_EQ(merged.report.triangles, triangles);
  // pin-a's top: z = 2 (pins) + 12.
  const std::array<double, 6> b = boundsOf(merged.polyData);
  EXPECT_NEAR(b[0], 0.0, 1e-6);
  EXPECT_NEAR(b[1], 20.0, 1e-6);
  EXPECT_NEAR(b[4], 0.0, 1e-6);
  // pin-b turned 0.5 rad about X, its base at z = 3: its top circle reaches
  // 3 + 12 cos 0.5 + 3 sin 0.5.
  EXPECT_NEAR(b[5], 3.0 + kPinHeight * std::cos(0.5) + kPinRadius * std::sin(0.5), 1e-2);
}

// IGES has no assembly structure of XCAF's kind: what it keeps is checked, the parts' geometry
// (each placed pin where the STEP file puts it), the top's name and a colour.
TEST_F(CadReaderTest, IgesKeepsGeometryNamesAndColours)
{
  const std::string file = this->writeIges(referenceDocument(), "rig.igs");
  const LoadedBlocks loaded = loadMeshBlocks(file);
  ASSERT_FALSE(loaded.blocks.empty());
  std::string names;
  for (const MeshBlock& block : loaded.blocks)
  {
    names += block.name + "; ";
  }
  // The merged surface covers the same space as the STEP file's.
  const LoadedMesh merged = loadMesh(file);
  const LoadedMesh fromStep = loadMesh(this->writeStep(referenceDocument(), "rig.step"));
  const std::array<double, 6> b = boundsOf(merged.polyData);
  const std::array<double, 6> expected = boundsOf(fromStep.polyData);
  for (size_t i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(b[i], expected[i], 1e-2) << "bound " << i << " of parts " << names;
  }
  // OpenCASCADE's IGES writer and reader keep the top's name and one compound of every placed
  // solid: one part "rig", placed where it is, painted with the colour its faces carry (the
  // plate's: the instanced pins' product colour does not survive the IGES round trip, measured).
  EXPECT_EQ(namesOf(loaded), std::vector<std::string>{"rig"});
  expectMatrixNear(loaded.blocks[0].placement, kIdentityPlacement, "rig");
  expectPaint(loaded.blocks[0], kPlateColour);
}

// A cylinder's B-rep tangents: on its side, face-u runs around the axis (the angle to the
// analytic circle tangent Z x (p - axis) below 1e-3 rad at every node) and face-v along it;
// "auto" takes face-u for a CAD part.
TEST_F(CadReaderTest, CylinderTangentsRunAroundAndAlongItsAxis)
{
  const std::string file = this->writeStep(cylinderDocument(), "pin.step");
  const LoadedBlocks loaded = loadMeshBlocks(file);
  ASSERT_EQ(loaded.blocks.size(), 1u);
  vtkPolyData* mesh = loaded.blocks[0].mesh.polyData;
  ASSERT_TRUE(mesh->GetPointData()->GetArray(kBRepTangentUArray));
  ASSERT_TRUE(mesh->GetPointData()->GetArray(kBRepTangentVArray));

  const PreparedSurface automatic = prepareSurface(mesh, SurfaceOptions{}, file);
  EXPECT_EQ(automatic.report.tangentSource, "face-u");
  SurfaceOptions alongU;
  alongU.brushing = parseBrushingModel("face-u");
  SurfaceOptions alongV;
  alongV.brushing = parseBrushingModel("face-v");
  const PreparedSurface u = prepareSurface(mesh, alongU, file);
  const PreparedSurface v = prepareSurface(mesh, alongV, file);
  EXPECT_EQ(u.report.fallbackTangents, 0);
  EXPECT_EQ(v.report.fallbackTangents, 0);

  int sideNodes = 0;
  double worstAround = 0.0;
  double worstAlong = 0.0;
  vtkPolyData* surface = u.polyData;
  vtkDataArray* normals = surface->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    const glm::dvec3 n = test::vec3(normals, i);
    if (std::abs(n.z) > 1e-6)
    {
      continue; // a cap's node
    }
    ++sideNodes;
    const glm::dvec3 p = test::point(surface, i);
    // The outward normal of the side is radial.
    EXPECT_NEAR(glm::dot(n, glm::normalize(glm::dvec3(p.x, p.y, 0.0))), 1.0, 1e-6);
    const glm::dvec3 circle =
        glm::normalize(glm::cross(glm::dvec3(0, 0, 1), glm::dvec3(p.x, p.y, 0)));
    const glm::dvec3 tu = test::vec3(surface->GetPointData()->GetTangents(), i);
    worstAround = std::max(worstAround, std::acos(std::min(1.0, std::abs(glm::dot(tu, circle)))));
    const glm::dvec3 tv = test::vec3(v.polyData->GetPointData()->GetTangents(), i);
    worstAlong = std::max(worstAlong, std::acos(std::min(1.0, std::abs(tv.z))));
  }
  EXPECT_GT(sideNodes, 20);
  // The nodes' positions and their UV agree to the mesher's precision (2.3e-4 rad measured at
  // the worst node, on the seam).
  EXPECT_LT(worstAround, 1e-3);
  EXPECT_LT(worstAlong, 1e-3);
}

// A finer deflection makes more triangles: relative 0.01 -> 0.0005 of the part's diagonal, and
// absolute 0.5 mm -> 0.005 mm; the angle likewise (45 -> 5 degrees at a coarse deflection).
TEST_F(CadReaderTest, DeflectionSetsTheTessellation)
{
  const std::string file = this->writeStep(cylinderDocument(), "pin.step");
  auto triangles = [&](const std::string& deflection, double angle)
  {
    MeshReadOptions options;
    options.cadDeflection = parseCadDeflection(deflection, "test");
    options.cadAngleDegrees = angle;
    return loadMeshBlocks(file, options).blocks.at(0).mesh.report.triangles;
  };
  const int64_t coarse = triangles("0.01", 90.0);
  const int64_t fine = triangles("0.0005", 90.0);
  EXPECT_GT(fine, coarse);
  EXPECT_GT(triangles("0.005mm", 90.0), triangles("0.5mm", 90.0));
  EXPECT_GT(triangles("0.5", 5.0), triangles("0.5", 45.0));
  // The default is 0.001 of the diagonal at 20 degrees.
  EXPECT_EQ(loadMeshBlocks(file).blocks.at(0).mesh.report.triangles, triangles("0.001", 20.0));
}

TEST_F(CadReaderTest, DeflectionTextIsParsedStrictly)
{
  EXPECT_FALSE(parseCadDeflection("0.002", "x").absolute);
  EXPECT_DOUBLE_EQ(parseCadDeflection("0.002", "x").value, 0.002);
  EXPECT_TRUE(parseCadDeflection("0.05mm", "x").absolute);
  EXPECT_DOUBLE_EQ(parseCadDeflection("0.05mm", "x").value, 0.05);
  EXPECT_EQ(toString(parseCadDeflection("0.05mm", "x")), "0.05mm");
  for (const char* bad : {"", "mm", "0", "-1", "2", "nan", "0.1 mm", "1e-3x", "inf"})
  {
    EXPECT_THROW(parseCadDeflection(bad, "--cad-deflection"), Error) << bad;
  }
}

// A STEP file cut in half and a file of garbage are refused, the message naming the file.
TEST_F(CadReaderTest, TruncatedAndGarbageFilesAreRefusedWithTheirPath)
{
  const std::string whole = this->writeStep(referenceDocument(), "rig.step");
  std::ifstream in(whole, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string cut = this->path("cut.step");
  std::ofstream(cut, std::ios::binary) << text.substr(0, text.size() / 2);
  const std::string igesWhole = this->writeIges(referenceDocument(), "rig.iges");
  std::ifstream igesIn(igesWhole, std::ios::binary);
  const std::string iges((std::istreambuf_iterator<char>(igesIn)),
                         std::istreambuf_iterator<char>());
  const std::string igesCut = this->path("cut.iges");
  std::ofstream(igesCut, std::ios::binary) << iges.substr(0, iges.size() / 2);
  const std::string garbage = this->path("garbage.stp");
  std::ofstream(garbage, std::ios::binary) << "this is no STEP file\n\x01\x02\xff garbage";
  const std::string garbageIges = this->path("garbage.igs");
  std::ofstream(garbageIges, std::ios::binary) << std::string(4000, 'x');
  // A file that closes properly but holds no entity.
  const std::string empty = this->path("empty.step");
  std::ofstream(empty, std::ios::binary)
      << "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n";
  for (const std::string& file : {cut, igesCut, garbage, garbageIges, empty})
  {
    try
    {
      loadMeshBlocks(file);
      ADD_FAILURE() << file << " was read";
    }
    catch (const Error& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind(file + ": ", 0), 0u) << e.what();
    }
    EXPECT_THROW(loadMesh(file), Error) << file;
  }
}
} // namespace
} // namespace aniso
