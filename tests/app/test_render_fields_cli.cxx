// `aniso render --field ...` end to end, running the built executable on a VTP written by VTK's
// XML writer (an independent writer): the plate [-1, 1]^2 of the built-in meshes with a point
// array "temperature" = x (NaN at x >= 0.75) and a cell array "side".
//  - --list-arrays names both arrays with the NaN count.
//  - Seen from above (--view +z; F0 0 and a sharp lobe: no specular; the uniform white
//    environment; tone mapping clamp) the albedo field shows the colour map: the middle row holds
//    the map's colour at t = 0 (the plate's left edge) and the preset's NaN red (the NaN strip).
//  - The legend: a colour bar in the right part of the image that is absent with --legend off
//    (the rest of the image unchanged there: an identity) and absent from EXR output.
//  - The run reports the NaN values it draws in the NaN colour.
//  - Bad input: a field no part has fails naming the file; a malformed --field or --field-range
//    is a command-line error (exit 2); roughness with the split-sum method fails naming the key.
#include "core/fields/color_map.h"
#include "core/image/image.h"
#include "tests/app/cli_runner.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

namespace
{
using aniso_test::Outcome;

class RenderFieldsCli : public aniso_test::CliTest
{
protected:
  void SetUp() override
  {
    CliTest::SetUp();
    vtkSmartPointer<vtkPolyData> plate = aniso::makePlate(8);
    vtkNew<vtkDoubleArray> temperature;
    temperature->SetName("temperature");
    temperature->SetNumberOfTuples(plate->GetNumberOfPoints());
    for (vtkIdType i = 0; i < plate->GetNumberOfPoints(); ++i)
    {
      const double x = plate->GetPoint(i)[0];
      temperature->SetValue(i, x >= 0.75 - 1e-9 ? std::numeric_limits<double>::quiet_NaN() : x);
    }
    plate->GetPointData()->AddArray(temperature);
    vtkNew<vtkDoubleArray> side;
    side->SetName("side");
    side->SetNumberOfTuples(plate->GetNumberOfCells());
    side->Fill(1.0);
    plate->GetCellData()->AddArray(side);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(plate);
    writer->SetFileName(path("plate.vtp").c_str());
    ASSERT_EQ(writer->Write(), 1);
  }

  std::vector<std::string> args(const std::string& output) const
  {
    return {"render",
            path("plate.vtp").string(),
            "--field",
            "temperature",
            "--f0",
            "0",
            "--nu",
            "10000",
            "--nv",
            "10000",
            "--env",
            "builtin:white",
            "--tone-mapping",
            "clamp",
            "--view",
            "+z",
            "--frames",
            "1",
            "--size",
            "128",
            "-o",
            path(output).string()};
  }
};

TEST_F(RenderFieldsCli, ListsTheArrays)
{
  const Outcome o = run({"render", path("plate.vtp").string(), "--list-arrays"});
  ASSERT_EQ(o.exitCode, 0) << o.err;
  EXPECT_NE(o.out.find("temperature\tpoint\t1 component\t-1..0.5\t18 NaN/Inf"), std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find("side\tcell"), std::string::npos) << o.out;
}

TEST_F(RenderFieldsCli, ColoursTheAlbedoWithALegend)
{
  const Outcome with = run(args("with.png"));
  ASSERT_EQ(with.exitCode, 0) << with.err;
  EXPECT_NE(with.out.find("render: field temperature of plate: 18 of 81 point values NaN or "
                          "infinite"),
            std::string::npos)
      << with.out;
  std::vector<std::string> plain = args("plain.png");
  plain.insert(plain.end(), {"--legend", "off"});
  const Outcome without = run(plain);
  ASSERT_EQ(without.exitCode, 0) << without.err;
  const aniso::Image a = aniso::readImage(path("with.png").string());
  const aniso::Image b = aniso::readImage(path("plain.png").string());
  ASSERT_EQ(a.width, 128);

  // Along the middle row: the colour map's colour at t = 0 (the plate's left edge, range
  // -1 .. 0.5) and the NaN colour (the right strip) are both there.
  const int y = 64;
  const glm::dvec3 first = aniso::colorMapColor(aniso::ColorMap::Viridis, 0.0);
  bool foundStart = false;
  bool foundNan = false;
  for (int x = 0; x < b.width; ++x)
  {
    const glm::dvec3 c(b.at(x, y, 0), b.at(x, y, 1), b.at(x, y, 2));
    foundStart =
        foundStart || (std::abs(c.x - first.x) < 2.0 / 255 && std::abs(c.y - first.y) < 2.0 / 255 &&
                       std::abs(c.z - first.z) < 2.0 / 255);
    foundNan = foundNan || (c.x > 254.0 / 255 && c.y < 1.0 / 255 && c.z < 1.0 / 255);
  }
  EXPECT_TRUE(foundStart) << "no pixel of the colour map's first colour on the middle row";
  EXPECT_TRUE(foundNan) << "no pixel of viridis' NaN colour (red) on the middle row";

  // The legend changes pixels in the right fifth of the image only.
  int changedRight = 0;
  int changedElsewhere = 0;
  for (int yy = 0; yy < a.height; ++yy)
  {
    for (int x = 0; x < a.width; ++x)
    {
      bool differs = false;
      for (int c = 0; c < 3; ++c)
      {
        differs = differs || std::abs(a.at(x, yy, c) - b.at(x, yy, c)) > 0.5f / 255;
      }
      (x >= a.width * 4 / 5 ? changedRight : changedElsewhere) += differs ? 1 : 0;
    }
  }
  std::cout << "legend: " << changedRight << " pixels changed at the right, " << changedElsewhere
            << " elsewhere\n";
  EXPECT_GT(changedRight, 200);
  EXPECT_EQ(changedElsewhere, 0);
}

TEST_F(RenderFieldsCli, ExrHasNoLegend)
{
  const Outcome with = run(args("with.exr"));
  ASSERT_EQ(with.exitCode, 0) << with.err;
  std::vector<std::string> plain = args("plain.exr");
  plain.insert(plain.end(), {"--legend", "off"});
  ASSERT_EQ(run(plain).exitCode, 0);
  const aniso::Image a = aniso::readImage(path("with.exr").string());
  const aniso::Image b = aniso::readImage(path("plain.exr").string());
  ASSERT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(a.data, b.data);
}

TEST_F(RenderFieldsCli, BadInputNamesItsCause)
{
  std::vector<std::string> missing = args("x.png");
  missing[3] = "pressure";
  Outcome o = run(missing);
  EXPECT_EQ(o.exitCode, 1);
  EXPECT_NE(o.err.find("plate.vtp: has no point or cell array 'pressure'"), std::string::npos)
      << o.err;

  std::vector<std::string> malformed = args("x.png");
  malformed[3] = "temperature:w";
  o = run(malformed);
  EXPECT_EQ(o.exitCode, 2);
  EXPECT_NE(o.err.find("'w' is not a component"), std::string::npos) << o.err;

  std::vector<std::string> range = args("x.png");
  range.insert(range.end(), {"--field-range", "2,1"});
  o = run(range);
  EXPECT_EQ(o.exitCode, 2);
  EXPECT_NE(o.err.find("--field-range"), std::string::npos) << o.err;

  std::vector<std::string> splitSum = args("x.png");
  splitSum.insert(splitSum.end(), {"--field-target", "roughness", "--method", "split-sum"});
  o = run(splitSum);
  EXPECT_EQ(o.exitCode, 1);
  EXPECT_NE(o.err.find("field-target: roughness and anisotropy need the exact method"),
            std::string::npos)
      << o.err;
}
} // namespace
