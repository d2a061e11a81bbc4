// `aniso render` of glTF scenes end to end, running the built executable on files that
// tinygltf's own writer writes here (an independent writer): a dome, the unit sphere's cap of
// 80 degrees about glTF's +Y (Z-up: about +Z), with NORMAL, TANGENT (+X projected onto the
// tangent plane) and TEXCOORD_0 (u = (x + 1) / 2, v = (1 + y) / 2 in Z-up terms), of a brushed
// metal (metallic 1, roughness 0.3, KHR_materials_anisotropy strength 0.9: alpha 0.09 across,
// alpha_t 0.827 along the anisotropy direction: n 245 across, 0.92 along).
//  - The setup is symmetric under a quarter turn about Z along the image's axes: the camera
//    looks straight down Z at the dome (up +Y, so the image's columns run along +X and its rows
//    down -Y), the image is square, and the environment (written here) is a dark sky with a
//    round lamp at the zenith, so the highlight sits at the centre; on the plane y = 0 the
//    tangent t is the projected +X and on x = 0 the turned tangent n x t is the projected +Y
//    (off the axes the two fields differ, so the images are not each other's transpose there).
//    The broad axis stretches the highlight along the anisotropy direction: rotation 0 along X,
//    pi/2 along Y. Checked: the principal axis of the bright region's second moments
//    (intensity-weighted covariance) is at 0 and 90 degrees within 10, elongated (the
//    eigenvalues' ratio above 3); the 0 image's middle rows are the pi/2 image's middle columns
//    within 10 % relative L2, while the images differ by far more than that.
//  - A constant rotation of pi/4 on a dome without TEXCOORD_0 renders (the tangents are turned at
//    load, no map is needed) as the same dome with TEXCOORD_0 does (a 1x1 TPR map), within 5 %,
//    its highlight's axis at 45 degrees.
//  - anisotropyTexture of direction +t on the left half of the texture (u < 0.5, the dome's
//    x < 0) and +b on the right: the left part of the image is that of the constant direction
//    (rotation 0) within 15 %, while on the right the streak along X is gone (below a third of
//    the constant one's there).
//  - --list-parts prints the file's parts with their glTF material names; --export-gltf writes
//    the scene's parts (with their placements, the file's or --part's materials) that read back
//    through loadMeshBlocks with the same names, triangles, bounds, placements and n_u, n_v, F0,
//    albedo; without -o it writes no image, with -o both. An export file of another extension,
//    or in a folder that does not exist, is refused naming it. A part drawn with a field is
//    named as written without it.
#include "core/image/image.h"
#include "core/parameters/material_library.h"
#include "tests/app/cli_runner.h"
#include "tests/vtkpasses/mesh/gltf_test_files.h"
#include "vtkpasses/mesh/MeshLoader.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <vtkPolyData.h>

namespace
{
using aniso::Image;
using aniso_test::Outcome;
constexpr double kPi = 3.14159265358979323846;
constexpr int kSide = 64;

// What a plate's material and surface are.
struct Plate
{
  double rotation = 0.0;
  bool texcoords = true;
  bool texture = false; // anisotropyTexture "direction.png", 8 x 1: +t left, +b right
  bool dome = true;     // else glTF's square of the XZ plane, tangent +X
};

// The dome of material 0 as a new mesh: non-indexed triangles of 24 rings of 64 segments.
int domeMesh(tinygltf::Model& model, bool texcoords)
{
  constexpr int kRings = 24;
  constexpr int kSegments = 64;
  const auto vertex = [](int ring, int segment)
  {
    const double theta = ring * (80.0 / kRings) * kPi / 180.0;
    const double phi = segment * 2.0 * kPi / kSegments;
    return glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                      std::sin(theta) * std::sin(phi));
  };
  std::vector<float> positions;
  std::vector<float> tangents;
  std::vector<float> uvs;
  const auto add = [&](const glm::dvec3& n)
  {
    positions.insert(positions.end(), {float(n.x), float(n.y), float(n.z)});
    const glm::dvec3 t = glm::normalize(glm::dvec3(1, 0, 0) - n.x * n);
    tangents.insert(tangents.end(), {float(t.x), float(t.y), float(t.z), 1.0f});
    uvs.insert(uvs.end(), {float((n.x + 1) / 2), float((n.z + 1) / 2)});
  };
  for (int ring = 0; ring < kRings; ++ring)
  {
    for (int segment = 0; segment < kSegments; ++segment)
    {
      // Counter-clockwise seen from outside (+Y): phi runs from +X to +Z, which is clockwise
      // seen from +Y, so the second ring comes first.
      const glm::dvec3 a = vertex(ring, segment);
      const glm::dvec3 b = vertex(ring + 1, segment);
      const glm::dvec3 c = vertex(ring + 1, segment + 1);
      const glm::dvec3 d = vertex(ring, segment + 1);
      for (const glm::dvec3& v : {a, c, b})
      {
        add(v);
      }
      if (ring > 0)
      {
        for (const glm::dvec3& v : {a, d, c})
        {
          add(v);
        }
      }
    }
  }
  return aniso::test::triangleMesh(model, "dome", 0, positions, positions, tangents,
                                   texcoords ? uvs : std::vector<float>());
}

tinygltf::Model plateModel(const Plate& plate)
{
  tinygltf::Model model;
  model.asset.version = "2.0";
  tinygltf::Material brushed = aniso::test::metallicRoughness(model, "brushed", {0.9, 0.9, 0.9},
                                                              1.0, 0.3, 0.9, plate.rotation);
  if (plate.texture)
  {
    tinygltf::Value::Object texture;
    texture["index"] = tinygltf::Value(0);
    tinygltf::Value::Object anisotropy =
        brushed.extensions["KHR_materials_anisotropy"].Get<tinygltf::Value::Object>();
    anisotropy["anisotropyTexture"] = tinygltf::Value(texture);
    brushed.extensions["KHR_materials_anisotropy"] = tinygltf::Value(anisotropy);
    tinygltf::Image image;
    image.uri = "direction.png";
    model.images.push_back(image);
    tinygltf::Texture t;
    t.source = 0;
    model.textures.push_back(t);
  }
  model.materials = {brushed};
  tinygltf::Node node;
  node.name = "plate";
  node.mesh = plate.dome ? domeMesh(model, plate.texcoords)
                         : aniso::test::squareMesh(model, "plate", 0, {1, 0, 0}, plate.texcoords);
  model.nodes = {node};
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  return model;
}

// The highlight's shape: the principal axis of the second moments of the intensity above 40 %
// of the brightest pixel's, in degrees in [0, 180) counter-clockwise from +X in the world's XY
// (image columns along +X, rows down -Y), and the ratio of the moments along and across it.
struct Highlight
{
  double axisDegrees = 0.0;
  double elongation = 0.0;
};

double luminance(const Image& image, int x, int y)
{
  return (image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2)) / 3.0;
}

Highlight highlightOf(const Image& image)
{
  double brightest = 0.0;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      brightest = std::max(brightest, luminance(image, x, y));
    }
  }
  double w = 0.0;
  double mx = 0.0;
  double my = 0.0;
  for (int pass = 0; pass < 2; ++pass)
  {
    double sxx = 0.0;
    double syy = 0.0;
    double sxy = 0.0;
    for (int y = 0; y < image.height; ++y)
    {
      for (int x = 0; x < image.width; ++x)
      {
        const double weight = std::max(0.0, luminance(image, x, y) - 0.4 * brightest);
        const double px = x + 0.5;
        const double py = image.height - (y + 0.5); // up is +Y
        if (pass == 0)
        {
          w += weight;
          mx += weight * px;
          my += weight * py;
        }
        else
        {
          sxx += weight * (px - mx) * (px - mx);
          syy += weight * (py - my) * (py - my);
          sxy += weight * (px - mx) * (py - my);
        }
      }
    }
    if (pass == 0)
    {
      mx /= w;
      my /= w;
      continue;
    }
    const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
    const double mean = 0.5 * (sxx + syy);
    const double spread = std::hypot(0.5 * (sxx - syy), sxy);
    Highlight h;
    h.axisDegrees = std::fmod(angle * 180.0 / kPi + 180.0, 180.0);
    h.elongation = (mean + spread) / std::max(mean - spread, 1e-12);
    return h;
  }
  return {};
}

// The difference of two axes in degrees, modulo 180, in [0, 90].
double axisDifference(double a, double b)
{
  const double d = std::fmod(std::abs(a - b), 180.0);
  return std::min(d, 180.0 - d);
}

// sqrt(sum (a - b)^2 / sum a^2) over the RGB of the pixels in columns [x0, x1).
double relativeL2(const Image& a, const Image& b, int x0, int x1)
{
  double difference = 0.0;
  double norm = 0.0;
  for (int y = 0; y < a.height; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double va = a.at(x, y, c);
        const double vb = b.at(x, y, c);
        difference += (va - vb) * (va - vb);
        norm += va * va;
      }
    }
  }
  return std::sqrt(difference / std::max(norm, 1e-30));
}

// The mean luminance of the pixels in columns [x0, x1) and rows [y0, y1).
double meanLuminance(const Image& image, int x0, int x1, int y0, int y1)
{
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      sum += luminance(image, x, y);
    }
  }
  return sum / double((x1 - x0) * (y1 - y0));
}

class GltfRenderCli : public aniso_test::CliTest
{
protected:
  void SetUp() override
  {
    aniso_test::CliTest::SetUp();
    // A dark sky of 0.02 with a lamp at the zenith, radiance 30 (1 - theta / 10 deg)^2 out to
    // 10 degrees: round, so a quarter turn about Z leaves it as it is.
    const int width = 512;
    const int height = 256;
    Image sky(width, height, 3);
    for (int y = 0; y < height; ++y)
    {
      const double theta = (y + 0.5) / height * 180.0; // from the zenith, row 0 at the top
      const double lamp = theta < 10.0 ? 30.0 * (1.0 - theta / 10.0) * (1.0 - theta / 10.0) : 0.0;
      for (int x = 0; x < width; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          sky.at(x, y, c) = float(0.02 + lamp);
        }
      }
    }
    environment_ = path("zenith.exr").string();
    aniso::writeImage(environment_, sky);
    Image direction(8, 1, 3);
    for (int x = 0; x < 8; ++x)
    {
      const bool left = x < 4;
      direction.at(x, 0, 0) = left ? 1.0f : 0.5f;
      direction.at(x, 0, 1) = left ? 0.5f : 1.0f;
      direction.at(x, 0, 2) = 1.0f;
    }
    aniso::writeImage(path("direction.png").string(), direction);
  }

  std::string writePlate(const std::string& name, const Plate& plate) const
  {
    const std::string file = path(name).string();
    aniso::test::writeModel(plateModel(plate), file);
    return file;
  }

  // Renders FILE to NAME.exr, looking down Z, under the zenith lamp (sampled by its luminance
  // too: a small bright source).
  Image render(const std::string& file, const std::string& name) const
  {
    const std::string out = path(name + ".exr").string();
    const std::string size = std::to_string(kSide) + "x" + std::to_string(kSide);
    const std::vector<std::string> options = {
        "--env-sampling", "mis", "--view", "+z", "--samples",    "16",   "--frames", "4",
        "--jitter",       "off", "--size", size, "--background", "none", "-o",       out};
    std::vector<std::string> command = {"render", file, "--env", environment_};
    command.insert(command.end(), options.begin(), options.end());
    const Outcome r = run(command);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.exitCode == 0 ? aniso::readImage(out) : Image();
  }

  std::string environment_;
};

TEST_F(GltfRenderCli, RotationPiOverTwoTurnsTheHighlightAQuarter)
{
  const Image along = render(writePlate("along.gltf", {0.0}), "along");
  const Image across = render(writePlate("across.gltf", {kPi / 2.0}), "across");
  ASSERT_EQ(along.width, kSide);
  ASSERT_EQ(across.width, kSide);
  const Highlight a = highlightOf(along);
  const Highlight b = highlightOf(across);
  EXPECT_LT(axisDifference(a.axisDegrees, 0.0), 10.0) << a.axisDegrees;
  EXPECT_LT(axisDifference(b.axisDegrees, 90.0), 10.0) << b.axisDegrees;
  EXPECT_GT(a.elongation, 3.0);
  EXPECT_GT(b.elongation, 3.0);
  // The profiles through the centre: rows kSide/2 - 1 and kSide/2 of one, those columns of the
  // other, each averaged with its mirror image (the scene is mirror symmetric too) to halve the
  // sampling noise.
  const auto profile = [](const Image& image, int i, bool columns)
  {
    double sum = 0.0;
    for (int at : {i, kSide - 1 - i})
    {
      for (int middle : {kSide / 2 - 1, kSide / 2})
      {
        sum += columns ? luminance(image, middle, at) : luminance(image, at, middle);
      }
    }
    return sum;
  };
  const auto row = [&](int i) { return profile(along, i, false); };
  const auto column = [&](int i) { return profile(across, i, true); };
  double difference = 0.0;
  double norm = 0.0;
  for (int i = 0; i < kSide / 2; ++i)
  {
    difference += (row(i) - column(i)) * (row(i) - column(i));
    norm += row(i) * row(i);
  }
  EXPECT_LT(std::sqrt(difference / norm), 0.1);
  EXPECT_GT(relativeL2(along, across, 0, kSide), 0.5);
}

TEST_F(GltfRenderCli, AConstantRotationNeedsNoTextureCoordinates)
{
  const Image mapped = render(writePlate("mapped.gltf", {kPi / 4.0}), "mapped");
  const Image bare = render(writePlate("bare.gltf", {kPi / 4.0, false}), "bare");
  ASSERT_EQ(mapped.width, kSide);
  ASSERT_EQ(bare.width, kSide);
  EXPECT_LT(relativeL2(mapped, bare, 0, kSide), 0.05);
  const Highlight h = highlightOf(bare);
  EXPECT_LT(axisDifference(h.axisDegrees, 45.0), 10.0) << h.axisDegrees;
  EXPECT_GT(h.elongation, 3.0);
}

TEST_F(GltfRenderCli, ATextureDrivenDirectionVariesAcrossTheSurface)
{
  const Image constant = render(writePlate("constant.gltf", {0.0}), "constant");
  const Image textured = render(writePlate("textured.gltf", {0.0, true, true}), "textured");
  ASSERT_EQ(constant.width, kSide);
  ASSERT_EQ(textured.width, kSide);
  // The left quarter (x < -0.5 on the dome, well inside the texture's left half) alike.
  EXPECT_LT(relativeL2(constant, textured, 0, kSide / 4), 0.15);
  // The right quarter, in the rows of the streak along X (the middle eighth): dark.
  const int y0 = kSide / 2 - kSide / 16;
  const int y1 = kSide / 2 + kSide / 16;
  const double streak = meanLuminance(constant, 3 * kSide / 4, kSide, y0, y1);
  const double turned = meanLuminance(textured, 3 * kSide / 4, kSide, y0, y1);
  EXPECT_GT(streak, 0.0);
  EXPECT_LT(turned, streak / 3.0) << streak;
}

TEST_F(GltfRenderCli, ListPartsShowsTheFilesMaterialsAndExportReadsBack)
{
  // Two squares: "plate" at the origin, "lid" moved and turned (its node's TRS).
  Plate square;
  square.dome = false;
  tinygltf::Model model = plateModel(square);
  model.materials.push_back(
      aniso::test::metallicRoughness(model, "paint", {0.7, 0.1, 0.1}, 0.0, 0.6));
  tinygltf::Node lid;
  lid.name = "lid";
  lid.mesh = aniso::test::squareMesh(model, "lid", 1);
  lid.translation = {0.5, 2.0, -1.0};
  lid.rotation = {0.0, std::sin(kPi / 8.0), 0.0, std::cos(kPi / 8.0)};
  lid.scale = {1.5, 1.5, 1.5};
  model.nodes.push_back(lid);
  model.scenes[0].nodes.push_back(1);
  const std::string file = path("pair.gltf").string();
  aniso::test::writeModel(model, file);

  const Outcome listed = run({"render", file, "--list-parts"});
  ASSERT_EQ(listed.exitCode, 0) << listed.err;
  EXPECT_EQ(listed.out, "plate\t2 triangles\tbrushed\nlid\t2 triangles\tpaint\n");

  const aniso::LoadedBlocks original = aniso::loadMeshBlocks(file);
  ASSERT_EQ(original.blocks.size(), 2u);
  for (const bool image : {false, true})
  {
    SCOPED_TRACE(image ? "with -o" : "without -o");
    const std::string exported = path(image ? "both.gltf" : "scene.glb").string();
    const std::string picture = path("both.exr").string();
    std::vector<std::string> command = {"render",        file,         "--part", "lid=satin gold",
                                        "--env",         environment_, "--size", "32x32",
                                        "--export-gltf", exported};
    if (image)
    {
      command.insert(command.end(), {"--samples", "4", "-o", picture});
    }
    const Outcome r = run(command);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("exported 2 parts to " + exported), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("field is not written"), std::string::npos) << r.out;
    EXPECT_EQ(aniso_test::fs::exists(picture), image);
    const aniso::LoadedBlocks back = aniso::loadMeshBlocks(exported);
    ASSERT_EQ(back.blocks.size(), 2u);
    const aniso::Material& gold = aniso::builtinMaterials().at("satin gold");
    for (std::size_t i = 0; i < 2; ++i)
    {
      const aniso::MeshBlock& a = original.blocks[i];
      const aniso::MeshBlock& b = back.blocks[i];
      SCOPED_TRACE(a.name);
      EXPECT_EQ(b.name, a.name);
      EXPECT_EQ(b.mesh.polyData->GetNumberOfCells(), a.mesh.polyData->GetNumberOfCells());
      double boundsA[6];
      double boundsB[6];
      a.mesh.polyData->GetBounds(boundsA);
      b.mesh.polyData->GetBounds(boundsB);
      for (int k = 0; k < 6; ++k)
      {
        EXPECT_NEAR(boundsB[k], boundsA[k], 1e-5) << k;
      }
      for (std::size_t k = 0; k < 16; ++k)
      {
        EXPECT_NEAR(b.placement[k], a.placement[k], 1e-6) << k;
      }
      ASSERT_TRUE(a.material);
      ASSERT_TRUE(b.material);
      const aniso::Material& drawn = i == 1 ? gold : *a.material;
      EXPECT_EQ(b.material->name, drawn.name);
      for (const char* key : {"nu", "nv"})
      {
        const double n = drawn.value(key).number[0];
        EXPECT_NEAR(b.material->value(key).number[0], n, 1e-4 * (1.0 + n)) << key;
      }
      for (const char* key : {"f0", "albedo"})
      {
        for (int c = 0; c < 3; ++c)
        {
          EXPECT_NEAR(b.material->value(key).number[size_t(c)], drawn.value(key).number[size_t(c)],
                      1e-5)
              << key;
        }
      }
    }
  }
}

// A field that varies the material has no place in glTF: the export says which parts lose it
// (the built-in torus, drawn with the command line's material and its field), and says nothing
// of the kind without one.
TEST_F(GltfRenderCli, AnExportSaysWhichPartsLoseTheirField)
{
  const std::string exported = path("fields.glb").string();
  const Outcome r =
      run({"render", "--builtin", "torus", "--field", "TCoords:0", "--export-gltf", exported});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("exported 1 part to " + exported), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("torus: its field is not written"), std::string::npos) << r.out;
  const Outcome without = run({"render", "--builtin", "torus", "--export-gltf", exported});
  ASSERT_EQ(without.exitCode, 0) << without.err;
  EXPECT_EQ(without.out.find("field is not written"), std::string::npos) << without.out;
}

TEST_F(GltfRenderCli, AnExportFileThatCannotBeWrittenIsRefusedNamingIt)
{
  Plate square;
  square.dome = false;
  const std::string file = writePlate("plate.gltf", square);
  const Outcome r = run({"render", file, "--export-gltf", path("scene.obj").string()});
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("scene.obj"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(".glb or .gltf"), std::string::npos) << r.err;
  const std::string nowhere = path("absent/scene.glb").string();
  const Outcome missing = run({"render", file, "--export-gltf", nowhere});
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE(missing.err.find(nowhere), std::string::npos) << missing.err;
  EXPECT_FALSE(aniso_test::fs::exists(nowhere));
}
} // namespace
