// Writes the STEP assembly of the README's STEP gallery image (docs/gallery-step.png): turned
// parts (a shaft, a cone, a revolved knob with a curved profile, a ring) standing on a plate,
// built with OpenCASCADE's primitives and written by its STEP writer, without colours (the
// render assigns library metals by part name). Each turned part is made about its own Z axis,
// so its faces' u runs around it: `face-u` brushing (auto on a CAD part) turns it round.
//   cmake --build build --target make_gallery_step
//   build/tests/vtkpasses/mesh/make_gallery_step turned-set.step
#include "tests/vtkpasses/mesh/cad_test_documents.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TDataStd_Name.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Shape.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <cstdio>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>

namespace
{
const gp_Ax2 kUp(gp_Pnt(0.0, 0.0, 0.0), gp_Dir(0.0, 0.0, 1.0));

// A knob: a smooth profile (radius by height, a B-spline through the points) revolved about Z.
TopoDS_Shape knob()
{
  const double profile[][2] = {{9.0, 0.0},  {10.0, 3.0}, {7.0, 9.0},  {5.0, 14.0},
                               {6.5, 19.0}, {9.5, 23.0}, {8.0, 27.0}, {3.0, 30.0}};
  const int n = int(sizeof(profile) / sizeof(profile[0]));
  TColgp_Array1OfPnt points(1, n);
  for (int i = 0; i < n; ++i)
  {
    points.SetValue(i + 1, gp_Pnt(profile[i][0], 0.0, profile[i][1]));
  }
  const Handle(Geom_BSplineCurve) side = GeomAPI_PointsToBSpline(points).Curve();
  const gp_Pnt bottom(0.0, 0.0, 0.0);
  const gp_Pnt top(0.0, 0.0, profile[n - 1][1]);
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(bottom, points.Value(1)).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(side).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(points.Value(n), top).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(top, bottom).Edge());
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), true).Face();
  return BRepPrimAPI_MakeRevol(face, gp_Ax1(bottom, gp_Dir(0.0, 0.0, 1.0))).Shape();
}

TopLoc_Location at(double x, double y, double z)
{
  gp_Trsf t;
  t.SetTranslation(gp_Vec(x, y, z));
  return TopLoc_Location(t);
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: make_gallery_step OUT.step\n");
    return 2;
  }
  Handle(TDocStd_Document) document;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  const TDF_Label set = shapes->NewShape();
  TDataStd_Name::Set(set, "turned-set");
  const auto add = [&](const char* name, const TopoDS_Shape& shape, const TopLoc_Location& placement)
  {
    const TDF_Label product = shapes->AddShape(shape, false);
    TDataStd_Name::Set(product, name);
    TDataStd_Name::Set(shapes->AddComponent(set, product, placement), name);
  };
  add("plate", BRepPrimAPI_MakeBox(gp_Pnt(-46.0, -30.0, -5.0), 92.0, 60.0, 5.0).Shape(),
      TopLoc_Location());
  add("shaft", BRepPrimAPI_MakeCylinder(kUp, 8.0, 52.0).Shape(), at(-28.0, 12.0, 0.0));
  add("cone", BRepPrimAPI_MakeCone(kUp, 14.0, 3.0, 30.0).Shape(), at(-18.0, -14.0, 0.0));
  add("knob", knob(), at(12.0, 12.0, 0.0));
  add("ring", BRepPrimAPI_MakeTorus(kUp, 10.0, 3.5).Shape(), at(26.0, -14.0, 3.5));
  shapes->UpdateAssemblies();
  if (!aniso::cadtest::writeStepFile(document, argv[1]))
  {
    std::fprintf(stderr, "%s: the STEP writer failed\n", argv[1]);
    return 1;
  }
  return 0;
}
