// Meshes at the edges of the number range, through the whole CPU path (loadMesh, then
// prepareSurface): a tetrahedron scaled by 1e30 and by 1e-30, and one of unit size placed 1e7
// from the origin, keep their four faces and get the same unit normals as at unit size (the
// analytic face normals of the tetrahedron are the reference) and finite unit tangents
// orthogonal to them; a vertex beyond the float range (1e39) leaves only slivers, dropped as
// zero-area faces. Texture coordinates (and normals) with a NaN are discarded whole, from PLY
// and from OBJ (VTK's reader). A mesh without texture coordinates given maps renders without
// them (the variant holds none of their code) rather than failing, every pixel finite. And the
// tiny, huge and far tetrahedra render the image of the unit one (the view is invariant under
// scaling and moving mesh, camera and lights together).
#include "core/env/environment.h"
#include "core/error.h"
#include "core/lights/light.h"
#include "tests/vtkpasses/mesh/mesh_test_helpers.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/SurfacePreparation.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace
{
// The corner at the origin and the three unit points, faces wound outwards.
std::string tetrahedronOff(double scale, double offset)
{
  const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::ostringstream text;
  text.precision(17);
  text << "OFF\n4 4 0\n";
  for (const auto& c : corners)
    text << offset + scale * c[0] << ' ' << offset + scale * c[1] << ' ' << offset + scale * c[2]
         << '\n';
  text << "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  return text.str();
}

// The outward normals of those faces.
const glm::dvec3 kFaceNormals[4] = {{0.0, 0.0, -1.0},
                                    {0.0, -1.0, 0.0},
                                    {-1.0, 0.0, 0.0},
                                    glm::normalize(glm::dvec3(1.0, 1.0, 1.0))};

class MeshExtremes : public ::testing::Test
{
protected:
  void SetUp() override
  {
    dir_ = fs::temp_directory_path() / ("aniso_mesh_extremes_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text)
  {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }

  fs::path dir_;
};

TEST_F(MeshExtremes, TinyHugeAndFarTetrahedraGetTheNormalsOfTheUnitOne)
{
  struct Case
  {
    const char* name;
    double scale;
    double offset;
  };
  for (const Case& c : {Case{"unit.off", 1.0, 0.0}, Case{"huge.off", 1e30, 0.0},
                        Case{"tiny.off", 1e-30, 0.0}, Case{"far.off", 1.0, 1e7}})
  {
    SCOPED_TRACE(c.name);
    const aniso::LoadedMesh mesh =
        aniso::loadMesh(write(c.name, tetrahedronOff(c.scale, c.offset)));
    EXPECT_EQ(mesh.report.triangles, 4);
    EXPECT_EQ(mesh.report.zeroAreaTrianglesDropped, 0);
    EXPECT_EQ(mesh.report.nonFiniteVertices, 0);
    const aniso::PreparedSurface prepared = aniso::prepareSurface(mesh.polyData, {}, c.name);
    vtkPolyData* surface = prepared.polyData;
    ASSERT_EQ(surface->GetNumberOfPolys(), 4);
    vtkDataArray* normals = surface->GetPointData()->GetArray("Normals");
    vtkDataArray* tangents = surface->GetPointData()->GetArray("Tangents");
    ASSERT_NE(normals, nullptr);
    ASSERT_NE(tangents, nullptr);
    // Every triangle's three vertices carry its analytic face normal (sharp edges split).
    std::vector<bool> seen(4, false);
    aniso::test::forEachTriangle(surface,
                                 [&](vtkIdType a, vtkIdType b, vtkIdType d)
                                 {
                                   const glm::dvec3 first = aniso::test::vec3(normals, a);
                                   int face = -1;
                                   for (int f = 0; f < 4; ++f)
                                     if (glm::length(first - kFaceNormals[f]) < 1e-5)
                                       face = f;
                                   ASSERT_GE(face, 0)
                                       << first.x << ' ' << first.y << ' ' << first.z;
                                   seen[std::size_t(face)] = true;
                                   for (vtkIdType id : {a, b, d})
                                   {
                                     const glm::dvec3 n = aniso::test::vec3(normals, id);
                                     const glm::dvec3 t = aniso::test::vec3(tangents, id);
                                     EXPECT_LT(glm::length(n - kFaceNormals[face]), 1e-5);
                                     EXPECT_NEAR(glm::length(t), 1.0, 1e-5);
                                     EXPECT_NEAR(glm::dot(t, n), 0.0, 1e-5);
                                   }
                                 });
    for (int f = 0; f < 4; ++f)
      EXPECT_TRUE(seen[std::size_t(f)]) << "face " << f;
  }
}

TEST_F(MeshExtremes, AVertexBeyondTheFloatRangeMakesSliversThatAreDropped)
{
  // The corner (0, 0, 1) moved to 1e39 (beyond float; the readers keep doubles): the three faces
  // using it are needles whose area is below 1e-10 of their longest edge squared, dropped as
  // zero-area; the base triangle is left, and the far vertex goes with its faces.
  std::string text = tetrahedronOff(1.0, 0.0);
  text.replace(text.find("0 0 1\n"), 6, "0 0 1e39\n");
  const aniso::LoadedMesh mesh = aniso::loadMesh(write("beyond.off", text));
  EXPECT_EQ(mesh.report.nonFiniteVertices, 0);
  EXPECT_EQ(mesh.report.zeroAreaTrianglesDropped, 3);
  EXPECT_EQ(mesh.report.unusedVerticesRemoved, 1);
  EXPECT_EQ(mesh.report.triangles, 1);
  EXPECT_TRUE(aniso::test::allFinite(mesh.polyData));
  double bounds[6];
  mesh.polyData->GetBounds(bounds);
  EXPECT_EQ(bounds[5], 0.0); // the base triangle lies in z = 0
}

// Texture coordinates with a NaN entry are discarded as a whole (a half-kept UV map would tear):
// the mesh loads without them, the count and the user's note say why, and the tangents fall
// back to the default brushing (axis:1,0,0), as for a mesh that never had UVs.
TEST_F(MeshExtremes, TextureCoordinatesWithANanAreDiscardedWhole)
{
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                          "property float y\nproperty float z\nproperty float s\nproperty float t\n"
                          "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n0 0 1 nan 1\n"
                          "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const aniso::LoadedMesh mesh = aniso::loadMesh(write("nanuv.ply", ply));
  EXPECT_EQ(mesh.report.triangles, 4);
  EXPECT_EQ(mesh.report.invalidTCoords, 1);
  EXPECT_FALSE(mesh.report.hasTCoords);
  EXPECT_EQ(mesh.polyData->GetPointData()->GetArray("TCoords"), nullptr);
  const std::vector<std::string> notes = mesh.report.notes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "texture coordinates discarded (1 entry is NaN or Inf)");
  const aniso::PreparedSurface prepared = aniso::prepareSurface(mesh.polyData, {}, "nanuv.ply");
  EXPECT_EQ(prepared.report.tangentSource, "axis:1,0,0");
}

// The same for OBJ, read by VTK's reader, whose number parsing turns "nan" into a finite value
// without a word: the loader checks the file's vt and vn lines itself. A NaN normal discards
// the file's normals the same way (they are then recomputed).
TEST_F(MeshExtremes, ObjTextureCoordinatesAndNormalsWithANanAreDiscardedWhole)
{
  const std::string corners = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  const std::string uvs = "vt 0 0\nvt 1 0\nvt 0 1\nvt nan 1\n";
  {
    const aniso::LoadedMesh mesh =
        aniso::loadMesh(write("nanuv.obj", corners + uvs +
                                               "f 1/1 3/3 2/2\nf 1/1 2/2 4/4\nf 1/1 4/4 3/3\n"
                                               "f 2/2 3/3 4/4\n"));
    EXPECT_EQ(mesh.report.triangles, 4);
    EXPECT_EQ(mesh.report.invalidTCoords, 1);
    EXPECT_FALSE(mesh.report.hasTCoords);
    EXPECT_EQ(mesh.polyData->GetPointData()->GetTCoords(), nullptr);
    const std::vector<std::string> notes = mesh.report.notes();
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0], "texture coordinates discarded (1 entry is NaN or Inf)");
    const aniso::PreparedSurface prepared = aniso::prepareSurface(mesh.polyData, {}, "nanuv.obj");
    EXPECT_EQ(prepared.report.tangentSource, "axis:1,0,0");
  }
  {
    // Finite texture coordinates stay (the check does not discard valid files).
    const aniso::LoadedMesh mesh = aniso::loadMesh(
        write("uv.obj", corners + "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 1\n" +
                            "f 1/1 3/3 2/2\nf 1/1 2/2 4/4\nf 1/1 4/4 3/3\nf 2/2 3/3 4/4\n"));
    EXPECT_EQ(mesh.report.invalidTCoords, 0);
    EXPECT_TRUE(mesh.report.hasTCoords);
  }
  {
    const aniso::LoadedMesh mesh = aniso::loadMesh(
        write("nann.obj", corners + "vn 0 0 1\nvn inf 0 1\n" +
                              "f 1//1 3//1 2//1\nf 1//2 2//2 4//2\nf 1//1 4//1 3//1\n"
                              "f 2//1 3//1 4//1\n"));
    EXPECT_EQ(mesh.report.invalidNormals, 1);
    EXPECT_FALSE(mesh.report.hasNormals);
    EXPECT_EQ(mesh.polyData->GetPointData()->GetNormals(), nullptr);
  }
}

// OBJ vertices with a NaN, or beyond the float range VTK's OBJ reader stores them in, are
// NaN/Inf vertices like those of the other formats (the reader alone would put them at 0 or at
// the previous vertex's values): counted, their faces dropped, the rest of the mesh kept, as the
// same tetrahedron from OFF shows (nan.off in docs/MESHES.md).
TEST_F(MeshExtremes, ObjVerticesWithANanOrBeyondFloatAreDroppedWithTheirFaces)
{
  for (const char* bad : {"v nan 0 0", "v 0 1e39 0", "v 0 0 -inf"})
  {
    SCOPED_TRACE(bad);
    const std::string obj = std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n") + bad +
                            "\nv 0.5 0.5 -1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 5 2 3\n"
                            "f 6 2 1\n";
    const aniso::LoadedMesh mesh = aniso::loadMesh(write("nanv.obj", obj));
    EXPECT_EQ(mesh.report.nonFiniteVertices, 1);
    EXPECT_EQ(mesh.report.nonFiniteFacesDropped, 1);
    EXPECT_EQ(mesh.report.duplicateVerticesMerged, 0);
    EXPECT_EQ(mesh.report.triangles, 5);
    EXPECT_EQ(mesh.report.points, 5);
    EXPECT_TRUE(aniso::test::allFinite(mesh.polyData));
    // The vertex after the bad one keeps its own coordinates.
    double bounds[6];
    mesh.polyData->GetBounds(bounds);
    EXPECT_EQ(bounds[4], -1.0);
  }
}

TEST_F(MeshExtremes, MapsOnAMeshWithoutTextureCoordinatesAreLeftOut)
{
  ANISO_REQUIRE_DISPLAY();
  const aniso::LoadedMesh mesh = aniso::loadMesh(write("plain.off", tetrahedronOff(1.0, 0.0)));
  ASSERT_FALSE(mesh.report.hasTCoords);
  aniso::RenderSettings settings;
  settings.surface = aniso::prepareSurface(mesh.polyData, {}, "plain.off").polyData;
  settings.environment = std::make_shared<aniso::StudioEnvironment>();
  settings.cubeSize = 32;
  settings.width = 24;
  settings.height = 24;
  settings.material.samples = 4;
  auto flat = std::make_shared<aniso::Image>(4, 4, 3);
  for (int i = 0; i < 16; ++i)
    flat->data[std::size_t(3 * i + 2)] = 1.0f; // the unperturbed normal (0, 0, 1)
  settings.material.normalMap = flat;
  settings.material.occlusionMap = std::make_shared<aniso::Image>(4, 4, 1);
  const aniso::RenderResult r = aniso::renderOffscreen(settings);
  EXPECT_TRUE(r.mapsDropped);
  EXPECT_FALSE(r.variant.tcoords);
  EXPECT_FALSE(r.variant.normalMap);
  EXPECT_FALSE(r.variant.occlusionMap);
  EXPECT_GT(r.coveredPixels, 0);
  EXPECT_EQ(aniso::test::nonFiniteValues(r.linear), 0);
}
} // namespace

namespace
{
// What the drawing depends on, given in the mesh's coordinates: the mesh scaled by SCALE about
// the origin and moved by OFFSET along (1, 1, 1); the camera (placed around the mesh's bounding
// sphere, as the window's is) and the point light moved with it, the light's intensity times
// SCALE^2 so that its irradiance on the surface stays the same.
enum class Shading
{
  Environment, // the anisotropic material under the studio, the camera placed by the renderer
  PointLight   // the lit AS model under one point light, a given camera
};

aniso::RenderResult renderTetrahedron(const std::string& path, double scale, double offset,
                                      Shading shading)
{
  const aniso::LoadedMesh mesh = aniso::loadMesh(path);
  aniso::RenderSettings settings;
  settings.surface = aniso::prepareSurface(mesh.polyData, {}, path).polyData;
  settings.environment = std::make_shared<aniso::StudioEnvironment>();
  settings.cubeSize = 32;
  settings.width = 48;
  settings.height = 48;
  settings.material.samples = 8;
  settings.jitter = false;
  settings.view.direction = glm::dvec3(1.0, -2.0, 1.5); // three faces in view
  if (shading == Shading::PointLight)
  {
    glm::dvec3 centre;
    double radius = 0.0;
    aniso::boundingSphere(settings.surface, centre, radius);
    settings.camera = aniso::placeCamera(settings.view, centre, radius);
    aniso::LitModelSettings lit;
    aniso::Light light;
    light.type = aniso::LightType::Point;
    light.vector = glm::dvec3(1.5, -2.0, 2.0) * scale + glm::dvec3(offset);
    light.intensity = glm::dvec3(6.0) * (scale * scale);
    lit.lights = {light};
    settings.installMaterial = aniso::litModelInstaller(lit);
  }
  return aniso::renderOffscreen(settings);
}
} // namespace

// The view is invariant under scaling and translating the mesh together with the camera and the
// point lights (the camera frames the object, the environment lighting depends on directions
// only), so the unit tetrahedron at the origin is the reference for the same one scaled by 1e30
// or 1e-30 or moved 1e7 away: the renderer draws each in a frame normalised to the unit bounding
// sphere, and the images must agree up to float rounding of the vertex positions (bound: every
// channel within 1e-3 of the unit image's brightest radiance, coverage included, and the same
// pixels covered). Before that frame, 1e30 drew a black surface on a uniform background, 1e-30
// nothing, and 1e7 streaks.
TEST_F(MeshExtremes, TinyHugeAndFarTetrahedraDrawLikeTheUnitOne)
{
  ANISO_REQUIRE_DISPLAY();
  for (Shading shading : {Shading::Environment, Shading::PointLight})
  {
    SCOPED_TRACE(shading == Shading::Environment ? "environment" : "point light");
    const aniso::RenderResult unit =
        renderTetrahedron(write("unit.off", tetrahedronOff(1.0, 0.0)), 1.0, 0.0, shading);
    ASSERT_EQ(aniso::test::nonFiniteValues(unit.linear), 0);
    ASSERT_GT(unit.coveredPixels, 48 * 48 / 10);
    float peak = 0.0f;
    for (std::size_t i = 0; i < unit.linear.data.size(); ++i)
      if (i % 4 != 3) // radiance, not coverage
        peak = std::max(peak, unit.linear.data[i]);
    ASSERT_GT(peak, 0.0f);
    struct Case
    {
      const char* name;
      double scale;
      double offset;
    };
    for (const Case& c :
         {Case{"huge.off", 1e30, 0.0}, Case{"tiny.off", 1e-30, 0.0}, Case{"far.off", 1.0, 1e7}})
    {
      SCOPED_TRACE(c.name);
      const aniso::RenderResult r = renderTetrahedron(
          write(c.name, tetrahedronOff(c.scale, c.offset)), c.scale, c.offset, shading);
      ASSERT_EQ(aniso::test::nonFiniteValues(r.linear), 0);
      EXPECT_EQ(r.coveredPixels, unit.coveredPixels);
      ASSERT_EQ(r.linear.data.size(), unit.linear.data.size());
      double worst = 0.0;
      for (std::size_t i = 0; i < r.linear.data.size(); ++i)
        worst = std::max(worst, double(std::abs(r.linear.data[i] - unit.linear.data[i])));
      std::printf("%s, %s: largest channel difference to the unit image %.3g (unit peak %.3g)\n",
                  shading == Shading::Environment ? "environment" : "point light", c.name, worst,
                  double(peak));
      EXPECT_LE(worst, 1e-3 * double(peak));
    }
  }
}
