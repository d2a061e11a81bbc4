// `aniso render A.ply B.ply ...`: scenes of parts end to end, running the built executable. The
// meshes are spheres of vtkSphereSource written by VTK's PLY writer (an independent writer):
// "left" (centre x = -1.5, 32 x 16 segments) and "right" (x = +1.5, 24 x 12), radius 1.
//  - --list-parts prints one line a part: its name (the file's stem, "left 2" for a second
//    left.ply), its triangles (vtkSphereSource makes 2 T (P - 2) of them for T segments around
//    and P from pole to pole: 896 and 480) and its material ("(command line)" unless --part
//    assigns one), "hidden" for a hidden part; it needs no -o and writes nothing.
//  - A file of several blocks is several parts (an OBJ of groups base and lid: loadMeshBlocks'
//    parts, named by the groups); a file of one block is one part named by its stem; names are
//    made unique across the files ("base 2" for base.ply).
//  - Under the uniform white environment a grey F0 reflects grey light (the channels equal) and
//    the built-in "satin gold", F0 (1, 0.782, 0.344), a reddish one (R > G > B, R > 1.5 B): with
//    --part left='satin gold' the left sphere's covered pixels are reddish and the right one's
//    grey; without --part both are grey. The right sphere keeps the command line's material,
//    so its pixels are those of the render without --part (an identity, to float rounding).
//    A --materials file's "satin gold" (blue here) wins over the built-in one.
//  - --hide right renders the image of left.ply given alone (identity): the right sphere's
//    pixels are gone and the camera fits the left one (nothing on the image's border).
//  - A VTP file of a sphere and a polyline (vtkXMLPolyDataWriter) is two parts, the sphere
//    named by the stem and its polyline "STEM lines" (N line segments); the lines alone
//    (--hide of the sphere) cover pixels, more than 2.5 times as many at --line-width 4 as at 1.
//  - Bad input ends with one line naming it: an unknown material, a pattern that matches no
//    part, a library file that is not JSON, a library material's missing map, every file
//    missing; a missing second file is one warning naming it, and the first still renders (the
//    image of the first alone).
#include "core/image/image.h"
#include "tests/app/cli_runner.h"
#include "tests/vtkpasses/render/render_test_helpers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkXMLPolyDataWriter.h>

namespace
{
using aniso_test::Outcome;

constexpr int kWidth = 96;
constexpr int kHeight = 48;

class RenderPartsCli : public aniso_test::CliTest
{
protected:
  void SetUp() override
  {
    aniso_test::CliTest::SetUp();
    left_ = writeSphere("left.ply", -1.5, 32, 16);
    right_ = writeSphere("right.ply", 1.5, 24, 12);
  }

  std::string writeSphere(const std::string& name, double x, int around, int poleToPole) const
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(x, 0.0, 0.0);
    sphere->SetRadius(1.0);
    sphere->SetThetaResolution(around);
    sphere->SetPhiResolution(poleToPole);
    sphere->Update();
    EXPECT_EQ(sphere->GetOutput()->GetNumberOfPolys(), 2 * around * (poleToPole - 2));
    const std::string file = path(name).string();
    vtkNew<vtkPLYWriter> writer;
    writer->SetInputConnection(sphere->GetOutputPort());
    writer->SetFileTypeToASCII();
    writer->SetFileName(file.c_str());
    EXPECT_EQ(writer->Write(), 1);
    return file;
  }

  // Renders ARGS (meshes and options) to NAME.exr under the uniform white environment and
  // returns the image (empty when the render failed).
  aniso::Image render(std::vector<std::string> args, const std::string& name,
                      Outcome* outcome = nullptr) const
  {
    const std::string out = path(name + ".exr").string();
    std::vector<std::string> command = {"render"};
    command.insert(command.end(), args.begin(), args.end());
    for (const char* option :
         {"--env",        "builtin:white", "--f0",   "0.6",      "--nu",   "200",      "--nv",
          "200",          "--samples",     "4",      "--frames", "1",      "--jitter", "off",
          "--background", "none",          "--size", "96x48",    "--view", "-y",       "-o"})
    {
      command.push_back(option);
    }
    command.push_back(out);
    const Outcome r = run(command);
    if (outcome)
    {
      *outcome = r;
    }
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.exitCode == 0 ? aniso::readImage(out) : aniso::Image();
  }

  std::string left_;
  std::string right_;
};

// The mean linear colour of the covered pixels in columns [x0, x1), and how many there are.
struct Region
{
  glm::dvec3 mean{0.0};
  int pixels = 0;
};

Region region(const aniso::Image& image, int x0, int x1)
{
  Region r;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      if (image.at(x, y, 3) < 1.0f)
      {
        continue;
      }
      ++r.pixels;
      for (int c = 0; c < 3; ++c)
      {
        r.mean[c] += image.at(x, y, c);
      }
    }
  }
  if (r.pixels > 0)
  {
    r.mean /= double(r.pixels);
  }
  return r;
}

void expectGrey(const Region& r, const std::string& what)
{
  ASSERT_GT(r.pixels, 100) << what;
  const double largest = std::max({r.mean.x, r.mean.y, r.mean.z});
  const double smallest = std::min({r.mean.x, r.mean.y, r.mean.z});
  EXPECT_GT(smallest, 0.05) << what;
  EXPECT_LT((largest - smallest) / largest, 1e-3) << what;
}

void expectReddish(const Region& r, const std::string& what)
{
  ASSERT_GT(r.pixels, 100) << what;
  EXPECT_GT(r.mean.x, r.mean.y) << what;
  EXPECT_GT(r.mean.y, r.mean.z) << what;
  EXPECT_GT(r.mean.x, 1.5 * r.mean.z) << what;
}

// The largest |a - b| over the RGBA of columns [x0, x1).
double largestDifference(const aniso::Image& a, const aniso::Image& b, int x0, int x1)
{
  double largest = 0.0;
  for (int y = 0; y < a.height; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      for (int c = 0; c < 4; ++c)
      {
        largest = std::max(largest, double(std::abs(a.at(x, y, c) - b.at(x, y, c))));
      }
    }
  }
  return largest;
}

int coveredPixels(const aniso::Image& image)
{
  int n = 0;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      n += image.at(x, y, 3) > 0.0f ? 1 : 0;
    }
  }
  return n;
}

int coveredOnBorder(const aniso::Image& image)
{
  int n = 0;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      const bool border = x == 0 || y == 0 || x == image.width - 1 || y == image.height - 1;
      n += border && image.at(x, y, 3) > 0.0f ? 1 : 0;
    }
  }
  return n;
}

void expectOneLineError(const Outcome& r, int exitCode, const std::string& subject,
                        const std::string& named)
{
  EXPECT_EQ(r.exitCode, exitCode) << r.err;
  EXPECT_EQ(r.err.rfind("aniso: " + subject + ":", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

std::vector<std::string> lines(const std::string& text)
{
  std::vector<std::string> out;
  std::string::size_type start = 0;
  while (start < text.size())
  {
    const auto end = text.find('\n', start);
    out.push_back(text.substr(start, end - start));
    start = end == std::string::npos ? text.size() : end + 1;
  }
  return out;
}

TEST_F(RenderPartsCli, HelpListsThePartOptions)
{
  const Outcome r = run({"render", "--help"});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("aniso render [MESH...]"), std::string::npos);
  for (const char* option :
       {"--materials FILE", "--part PATTERN=MATERIAL", "--hide PATTERN", "--list-parts "})
  {
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
}

TEST_F(RenderPartsCli, ListPartsPrintsNamesTrianglesAndMaterials)
{
  std::filesystem::create_directory(path("sub"));
  const std::string again = writeSphere("sub/left.ply", 0.0, 32, 16);
  const auto before = files();
  const Outcome r = run({"render", left_, right_, again, "--part", "right=satin gold", "--hide",
                         "left 2", "--list-parts"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(lines(r.out), (std::vector<std::string>{
                              "left\t896 triangles\t(command line)",
                              "right\t480 triangles\tsatin gold",
                              "left 2\t896 triangles\t(command line)\thidden",
                          }));
  EXPECT_EQ(files(), before); // nothing written

  // The built-in mesh is one part named by it; a later --part wins.
  const Outcome builtin = run({"render", "--builtin", "torus", "--part", "*=brushed steel",
                               "--part", "to?us=satin gold", "--list-parts"});
  ASSERT_EQ(builtin.exitCode, 0) << builtin.err;
  EXPECT_EQ(builtin.out.rfind("torus\t", 0), 0u) << builtin.out;
  EXPECT_NE(builtin.out.find("\tsatin gold\n"), std::string::npos) << builtin.out;
}

// --list-arrays: a VTP (vtkXMLPolyDataWriter) of one quad split in two triangles with a point
// vector "flow" (one NaN component), a point scalar "heat" and a cell scalar "id" prints one
// line per array under the part's name: point or cell, components, the finite range (of the
// lengths for a vector), the NaN/Inf count; a part without arrays says so. --tangents
// array:NAME of an array the part lacks ends with one line naming the vector arrays it has.
TEST_F(RenderPartsCli, ListArraysPrintsEachPartsFields)
{
  vtkNew<vtkPoints> points;
  const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  vtkNew<vtkFloatArray> flow;
  flow->SetName("flow");
  flow->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> heat;
  heat->SetName("heat");
  for (int i = 0; i < 4; ++i)
  {
    points->InsertNextPoint(corners[i][0], corners[i][1], 0.0);
    flow->InsertNextTuple3(3.0 * (i + 1), 4.0 * (i + 1), 0.0); // lengths 5, 10, 15, 20
    heat->InsertNextValue(-2.5 + i);
  }
  flow->SetComponent(3, 1, std::nan(""));
  vtkNew<vtkCellArray> triangles;
  const vtkIdType first[3] = {0, 1, 2};
  const vtkIdType second[3] = {0, 2, 3};
  triangles->InsertNextCell(3, first);
  triangles->InsertNextCell(3, second);
  vtkNew<vtkIntArray> id;
  id->SetName("id");
  id->InsertNextValue(7);
  id->InsertNextValue(9);
  vtkNew<vtkPolyData> quad;
  quad->SetPoints(points);
  quad->SetPolys(triangles);
  quad->GetPointData()->AddArray(flow);
  quad->GetPointData()->AddArray(heat);
  quad->GetCellData()->AddArray(id);
  const std::string file = path("quad.vtp").string();
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(quad);
  writer->SetFileName(file.c_str());
  ASSERT_EQ(writer->Write(), 1);

  const auto before = files();
  const Outcome r = run({"render", file, right_, "--list-arrays"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(lines(r.out), (std::vector<std::string>{
                              "quad",
                              "  flow\tpoint\t3 components\t5..15 (length)\t1 NaN/Inf",
                              "  heat\tpoint\t1 component\t-2.5..0.5\t0 NaN/Inf",
                              "  id\tcell\t1 component\t7..9\t0 NaN/Inf",
                              "right\t(no arrays)",
                          }));
  EXPECT_EQ(files(), before); // nothing written

  const Outcome missing =
      run({"render", file, "--tangents", "array:velocity", "-o", path("quad.png").string()});
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE(missing.err.find("tangents 'array:velocity': the mesh has no point or cell array "
                             "'velocity' (its vector arrays: flow)"),
            std::string::npos)
      << missing.err;
}

TEST_F(RenderPartsCli, AFileOfSeveralBlocksIsSeveralParts)
{
  // An OBJ of two groups (loadMeshBlocks: a part per g statement, named by it), one of a single
  // group (one part: the file's stem) and a PLY whose stem repeats a group's name.
  const std::string box = path("box.obj").string();
  std::ofstream(box) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                        "g base\nf 1 3 2\nf 1 4 3\n"
                        "g lid\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n";
  const std::string single = path("single.obj").string();
  std::ofstream(single) << "v 0 0 0\nv 1 0 0\nv 0 1 0\ng only\nf 1 2 3\n";
  const std::string base = writeSphere("base.ply", 3.0, 24, 12);
  const Outcome r =
      run({"render", box, single, base, "--part", "lid=brushed copper", "--list-parts"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(lines(r.out), (std::vector<std::string>{
                              "base\t2 triangles\t(command line)",
                              "lid\t4 triangles\tbrushed copper",
                              "single\t1 triangle\t(command line)",
                              "base 2\t480 triangles\t(command line)",
                          }));
}

TEST_F(RenderPartsCli, PartTakesALibraryMaterial)
{
  ANISO_REQUIRE_DISPLAY();
  const aniso::Image plain = render({left_, right_}, "plain");
  const aniso::Image gold = render({left_, right_, "--part", "left=satin gold"}, "gold");
  ASSERT_FALSE(plain.empty());
  ASSERT_FALSE(gold.empty());
  expectGrey(region(plain, 0, kWidth / 2), "left, no --part");
  expectGrey(region(plain, kWidth / 2, kWidth), "right, no --part");
  expectReddish(region(gold, 0, kWidth / 2), "left, satin gold");
  expectGrey(region(gold, kWidth / 2, kWidth), "right, the command line's material");
  EXPECT_GT(largestDifference(gold, plain, 0, kWidth / 2), 0.05);
  EXPECT_LE(largestDifference(gold, plain, kWidth / 2, kWidth), 1e-6);

  // A library file's material of a built-in name wins over the built-in one.
  const std::string library = path("shop.json").string();
  std::ofstream(library) << R"({"format": "aniso-materials", "version": 1, "materials": {
      "satin gold": {"nu": 200, "nv": 200, "f0": [0.2, 0.3, 0.9]}}})";
  const aniso::Image blue =
      render({left_, right_, "--materials", library, "--part", "left=satin gold"}, "blue");
  ASSERT_FALSE(blue.empty());
  const Region left = region(blue, 0, kWidth / 2);
  EXPECT_GT(left.mean.z, 1.5 * left.mean.x);
  expectGrey(region(blue, kWidth / 2, kWidth), "right, beside the file's satin gold");
}

TEST_F(RenderPartsCli, HideRemovesAPartAndTheCameraFitsTheRest)
{
  ANISO_REQUIRE_DISPLAY();
  const aniso::Image both = render({left_, right_}, "both");
  const aniso::Image hidden = render({left_, right_, "--hide", "r*"}, "hidden");
  const aniso::Image alone = render({left_}, "alone");
  ASSERT_FALSE(both.empty());
  ASSERT_FALSE(hidden.empty());
  ASSERT_FALSE(alone.empty());
  EXPECT_EQ(coveredPixels(hidden), coveredPixels(alone));
  EXPECT_LE(largestDifference(hidden, alone, 0, kWidth), 1e-6);
  EXPECT_EQ(coveredOnBorder(hidden), 0);
  EXPECT_EQ(coveredOnBorder(both), 0);
  // The camera fits the left sphere alone: it is larger than in the pair's image.
  EXPECT_GT(coveredPixels(hidden), coveredPixels(both) / 2);
}

TEST_F(RenderPartsCli, BadPartInputIsNamed)
{
  const std::string out = path("a.png").string();
  expectOneLineError(run({"render", left_, "--part", "left=unobtainium", "-o", out}), 2, "--part",
                     "'unobtainium'");
  expectOneLineError(run({"render", left_, right_, "--part", "lft=satin gold", "-o", out}), 2,
                     "--part", "'lft'");
  expectOneLineError(run({"render", left_, right_, "--hide", "middle", "-o", out}), 2, "--hide",
                     "'middle'");
  expectOneLineError(run({"render", left_, right_, "--hide", "*", "-o", out}), 2, "--hide",
                     "every part");
  expectOneLineError(run({"render", left_, "--part", "left", "-o", out}), 2, "--part",
                     "PATTERN=MATERIAL");
  expectOneLineError(
      run({"render", left_, "--model", "ward", "--part", "left=satin gold", "-o", out}), 2,
      "--part", "as-env");

  const std::string notJson = path("bad.json").string();
  std::ofstream(notJson) << "materials: [brushed]\n";
  expectOneLineError(run({"render", left_, "--materials", notJson, "-o", out}), 1, notJson,
                     "not JSON");

  const std::string library = path("maps.json").string();
  const std::string map = path("grooves.png").string();
  std::ofstream(library) << R"({"format": "aniso-materials", "version": 1, "materials": {
      "grooved": {"bump": "normal", "normal-map": "grooves.png"}}})";
  expectOneLineError(
      run({"render", left_, "--materials", library, "--part", "left=grooved", "-o", out}), 1, map,
      map);

  const std::string missing1 = path("gone.ply").string();
  const std::string missing2 = path("lost.obj").string();
  expectOneLineError(run({"render", missing1, missing2, "-o", out}), 1, missing1 + ", " + missing2,
                     "no mesh could be loaded");
  EXPECT_EQ(files(), (std::set<std::string>{"left.ply", "right.ply", "bad.json", "maps.json"}));
}

TEST_F(RenderPartsCli, AMissingSecondFileIsSkippedWithAWarning)
{
  ANISO_REQUIRE_DISPLAY();
  const std::string missing = path("missing.ply").string();
  Outcome r;
  const aniso::Image rendered = render({left_, missing}, "skipped", &r);
  ASSERT_FALSE(rendered.empty());
  EXPECT_EQ(r.err.rfind("aniso: warning: " + missing + ":", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("(skipped)"), std::string::npos) << r.err;
  const aniso::Image alone = render({left_}, "alone");
  ASSERT_FALSE(alone.empty());
  EXPECT_LE(largestDifference(rendered, alone, 0, kWidth), 1e-6);
  EXPECT_GT(coveredPixels(rendered), 100);
}
// A file's polylines: a part of their own, listed with their segments, drawn at their width.
TEST_F(RenderPartsCli, PolylinesOfAVtpFileAreALinePartDrawnAtTheirWidth)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-1.5, 0.0, 0.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  sphere->Update();
  vtkNew<vtkPolyData> poly;
  poly->DeepCopy(sphere->GetOutput());
  poly->GetPointData()->RemoveArray("Normals"); // one a point: the circle's points have none
  // A circle of 64 segments (65 points, the last the first again) around x = +1.5.
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(65);
  for (int i = 0; i <= 64; ++i)
  {
    const double a = 2.0 * M_PI * (i % 64) / 64.0;
    lines->InsertCellPoint(poly->GetPoints()->InsertNextPoint(1.5 + std::cos(a), 0.0, std::sin(a)));
  }
  poly->SetLines(lines);
  const std::string file = path("strands.vtp").string();
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->SetFileName(file.c_str());
  ASSERT_EQ(writer->Write(), 1);

  const Outcome listed = run({"render", file, "--list-parts"});
  EXPECT_EQ(listed.exitCode, 0) << listed.err;
  EXPECT_EQ(listed.out, "strands\t896 triangles\t(command line)\n"
                        "strands lines\t64 line segments\t(command line)\n");

  const aniso::Image thin = render({file, "--hide", "strands", "--line-width", "1"}, "thin");
  const aniso::Image wide = render({file, "--hide", "strands", "--line-width", "4"}, "wide");
  const Region thinLines = region(thin, 0, kWidth);
  const Region wideLines = region(wide, 0, kWidth);
  EXPECT_GT(thinLines.pixels, 20);
  EXPECT_GT(wideLines.pixels, 2.5 * thinLines.pixels);
  expectGrey(wideLines, "lines under the white environment");
}
} // namespace
