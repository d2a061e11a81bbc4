#include "tests/vtkpasses/mesh/cad_test_documents.h"

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TopLoc_Location.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>

namespace aniso::cadtest
{
namespace
{
void quiet()
{
  // The writers report on standard output; a test's output stays readable without them.
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
}

Quantity_Color colourOf(const Rgb& c)
{
  return Quantity_Color(c.r, c.g, c.b, Quantity_TOC_RGB);
}

TDF_Label addPin(const Handle(XCAFDoc_ShapeTool) & shapes)
{
  const TDF_Label pin = shapes->AddShape(
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0.0, 0.0, 0.0), gp_Dir(0.0, 0.0, 1.0)), kPinRadius,
                               kPinHeight)
          .Shape(),
      false);
  TDataStd_Name::Set(pin, "pin");
  return pin;
}
} // namespace

PartMatrix matrixOf(const gp_Trsf& trsf)
{
  PartMatrix m = kIdentityPlacement;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      m[static_cast<size_t>(r * 4 + c)] = trsf.Value(r + 1, c + 1);
    }
  }
  return m;
}

Reference reference()
{
  Reference r;
  r.pins.SetTranslation(gp_Vec(0.0, 0.0, 2.0));
  r.pinA.SetTranslation(gp_Vec(4.0, 5.0, 0.0));
  r.pinB.SetRotation(gp_Ax1(gp_Pnt(0.0, 0.0, 0.0), gp_Dir(1.0, 0.0, 0.0)), 0.5);
  r.pinB.SetTranslationPart(gp_Vec(16.0, 5.0, 1.0));
  return r;
}

Handle(TDocStd_Document) referenceDocument()
{
  Handle(TDocStd_Document) document;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  const Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(document->Main());
  const Reference r = reference();

  const TDF_Label plate = shapes->AddShape(BRepPrimAPI_MakeBox(20.0, 10.0, 2.0).Shape(), false);
  TDataStd_Name::Set(plate, "plate");
  colours->SetColor(plate, colourOf(kPlateColour), XCAFDoc_ColorSurf);
  const TDF_Label pin = addPin(shapes);
  colours->SetColor(pin, colourOf(kPinColour), XCAFDoc_ColorSurf);

  const TDF_Label pair = shapes->NewShape();
  TDataStd_Name::Set(pair, "pin-pair");
  TDataStd_Name::Set(shapes->AddComponent(pair, pin, TopLoc_Location(r.pinA)), "pin-a");
  TDataStd_Name::Set(shapes->AddComponent(pair, pin, TopLoc_Location(r.pinB)), "pin-b");

  const TDF_Label rig = shapes->NewShape();
  TDataStd_Name::Set(rig, "rig");
  TDataStd_Name::Set(shapes->AddComponent(rig, plate, TopLoc_Location()), "base");
  TDataStd_Name::Set(shapes->AddComponent(rig, pair, TopLoc_Location(r.pins)), "pins");
  shapes->UpdateAssemblies();
  return document;
}

Handle(TDocStd_Document) cylinderDocument()
{
  Handle(TDocStd_Document) document;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
  addPin(XCAFDoc_DocumentTool::ShapeTool(document->Main()));
  return document;
}

bool writeStepFile(const Handle(TDocStd_Document) & document, const std::string& path)
{
  quiet();
  STEPCAFControl_Writer writer;
  writer.SetColorMode(true);
  writer.SetNameMode(true);
  return writer.Transfer(document, STEPControl_AsIs) &&
         writer.Write(path.c_str()) == IFSelect_RetDone;
}

bool writeIgesFile(const Handle(TDocStd_Document) & document, const std::string& path)
{
  quiet();
  IGESCAFControl_Writer writer;
  writer.SetColorMode(true);
  writer.SetNameMode(true);
  return writer.Transfer(document) && writer.Write(path.c_str());
}
} // namespace aniso::cadtest
