#pragma once
// CAD documents the tests build and write with OpenCASCADE's own XCAF writers
// (STEPCAFControl_Writer, IGESCAFControl_Writer): an independent writer, whose document's names,
// colours and placements are what a test expects back (test_cad_reader, and the window's
// test_cad_window). Library aniso_cad_test_documents (tests/vtkpasses/mesh/CMakeLists.txt).
#include "core/placement.h"

#include <Standard_Handle.hxx>
#include <TDocStd_Document.hxx>
#include <gp_Trsf.hxx>
#include <string>

namespace aniso::cadtest
{
// The pin's cylinder: radius and height (along its Z), millimetres.
inline constexpr double kPinRadius = 3.0;
inline constexpr double kPinHeight = 12.0;

struct Rgb
{
  double r, g, b;
};
inline constexpr Rgb kPlateColour{0.8, 0.1, 0.05};
inline constexpr Rgb kPinColour{0.1, 0.25, 0.7};

// The row-major affine matrix of TRSF (ScenePart's and MeshBlock's placement).
PartMatrix matrixOf(const gp_Trsf& trsf);

// The reference assembly: "rig" holds a plate (a 20 x 10 x 2 box, kPlateColour) as "base" and a
// sub-assembly "pin-pair" placed as "pins", which holds one pin product (a cylinder of
// kPinRadius and kPinHeight along Z, kPinColour) twice, as "pin-a" and "pin-b", at two
// placements. Its leaf instances read back as "rig/base", "rig/pins/pin-a", "rig/pins/pin-b".
struct Reference
{
  gp_Trsf pins; // the sub-assembly in the rig
  gp_Trsf pinA; // the pins in the sub-assembly
  gp_Trsf pinB;
};
Reference reference();
Handle(TDocStd_Document) referenceDocument();

// A single cylinder (kPinRadius, kPinHeight, along Z) named "pin", without colour.
Handle(TDocStd_Document) cylinderDocument();

// Writes DOCUMENT to PATH with names and colours; false when the writer fails. Quiet: the
// writers' messages to standard output are switched off.
bool writeStepFile(const Handle(TDocStd_Document) & document, const std::string& path);
bool writeIgesFile(const Handle(TDocStd_Document) & document, const std::string& path);
} // namespace aniso::cadtest
