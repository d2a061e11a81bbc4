// `aniso thumbnail IN OUT SIZE` end to end: the PNG it writes has the requested size, its part
// covers the centre and leaves the corners transparent, it is written as PNG whatever OUT's name
// ends in (thumbnailers pass temporary names), within the time docs/BENCHMARKS.md states, and
// bad input fails with the file's name and nothing left behind. The mesh is a sphere written by
// VTK's STL writer (an independent writer), read back by the reader program.
#include "core/image/image.h"
#include "tests/app/cli_runner.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <vtkNew.h>
#include <vtkSTLWriter.h>
#include <vtkSphereSource.h>
#include <vtkTriangleFilter.h>

namespace
{
using aniso_test::CliTest;

class ThumbnailCli : public CliTest
{
protected:
  std::string writeSphereStl()
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(24);
    sphere->SetRadius(3.0);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(sphere->GetOutputPort());
    const std::string file = path("sphere.stl").string();
    vtkNew<vtkSTLWriter> writer;
    writer->SetInputConnection(triangles->GetOutputPort());
    writer->SetFileName(file.c_str());
    writer->SetFileTypeToBinary();
    EXPECT_EQ(writer->Write(), 1);
    return file;
  }
};

double alphaAt(const aniso::Image& image, int x, int y)
{
  return image.data[(std::size_t(y) * image.width + x) * image.channels + 3];
}

TEST_F(ThumbnailCli, WritesAPngOfTheRequestedSizeWithThePartInTheMiddle)
{
  const std::string stl = writeSphereStl();
  // A thumbnailer's temporary output name has no extension.
  const std::string out = path("thumbnail-tmp").string();
  // The first run may bake the thumbnail's small lookup tables into the test's cache.
  ASSERT_EQ(run({"thumbnail", stl, out, "96"}).exitCode, 0);
  const auto start = std::chrono::steady_clock::now();
  const aniso_test::Outcome r = run({"thumbnail", stl, out, "256"});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "") << "a thumbnailer prints nothing unless asked to";
  // Its time is a benchmark's (docs/BENCHMARKS.md, "Thumbnails"), not a pass/fail criterion.
  RecordProperty("thumbnail_seconds", std::to_string(seconds));

  EXPECT_EQ(aniso_test::slurp(out).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  aniso::ImageInfo info;
  const aniso::Image image = aniso::readImage(out, &info);
  EXPECT_TRUE(info.integerFormat);
  EXPECT_EQ(image.width, 256);
  EXPECT_EQ(image.height, 256);
  ASSERT_EQ(image.channels, 4);
  EXPECT_GT(alphaAt(image, 128, 128), 0.99) << "the sphere covers the centre";
  for (const auto& [x, y] : {std::pair{0, 0}, {255, 0}, {0, 255}, {255, 255}})
  {
    EXPECT_LT(alphaAt(image, x, y), 0.01) << "a corner at " << x << "," << y;
  }
  // Lit, not black: the centre has some brightness.
  const std::size_t centre = (std::size_t(128) * 256 + 128) * 4;
  EXPECT_GT(image.data[centre] + image.data[centre + 1] + image.data[centre + 2], 0.1);
  // Nothing but the thumbnail is left (the temporary file was renamed).
  EXPECT_EQ(files(), (std::set<std::string>{"sphere.stl", "thumbnail-tmp"}));
}

TEST_F(ThumbnailCli, BadInputFailsWithItsNameAndLeavesNothing)
{
  const std::string out = path("t.png").string();
  aniso_test::Outcome r = run({"thumbnail", path("missing.stl").string(), out, "64"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("missing.stl: no such file"), std::string::npos) << r.err;

  std::ofstream(path("broken.stl")) << "solid x\n  facet normal 0 0 1\n    outer loop\n";
  r = run({"thumbnail", path("broken.stl").string(), out, "64"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("broken.stl"), std::string::npos) << r.err;

  r = run({"thumbnail", "builtin:torus", out, "64x32"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("SIZE"), std::string::npos) << r.err;
  r = run({"thumbnail", "builtin:torus", out, "0"});
  EXPECT_EQ(r.exitCode, 2);
  r = run({"thumbnail", "builtin:torus", path("no-such-dir/t.png").string(), "64"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_EQ(files(), (std::set<std::string>{"broken.stl"}));
}
} // namespace
