// parseVtkErrorText: the forms vtkOutputWindow receives (vtkErrorMacro, vtkWarningMacro,
// vtkGenericWarningMacro), written out here as VTK 9.1's macros compose them, split into the
// printing class and the words; text in no such form passes through as the words.
#include "vtkpasses/mesh/VtkErrorText.h"

#include <gtest/gtest.h>

namespace aniso
{
namespace
{
TEST(VtkErrorText, AnErrorGivesItsClassAndWords)
{
  const VtkErrorText e = parseVtkErrorText(
      "ERROR: In /build/IO/XML/vtkXMLReader.cxx, line 12\nvtkXMLPolyDataReader (0x55d0c0): Error "
      "parsing XML in stream at line 1\n\n");
  EXPECT_EQ(e.origin, "vtkXMLPolyDataReader");
  EXPECT_EQ(e.text, "Error parsing XML in stream at line 1");
}

TEST(VtkErrorText, WarningsAndGenericWarnings)
{
  const VtkErrorText w =
      parseVtkErrorText("Warning: In x.cxx, line 3\nvtkOBJReader (0x1): no faces\n\n");
  EXPECT_EQ(w.origin, "vtkOBJReader");
  EXPECT_EQ(w.text, "no faces");
  // A generic warning names no class; the words keep what looks like one later on.
  const VtkErrorText g = parseVtkErrorText(
      "Generic Warning: In m.cxx, line 9\nanisotropic material: normal-map (2x2): too large\n\n");
  EXPECT_EQ(g.origin, "");
  EXPECT_EQ(g.text, "anisotropic material: normal-map (2x2): too large");
}

TEST(VtkErrorText, OtherTextIsTheWords)
{
  EXPECT_EQ(parseVtkErrorText("plain words \n").text, "plain words");
  EXPECT_EQ(parseVtkErrorText("vtkShaderProgram (0x2): 1: #version 150\n").text, "1: #version 150");
  // The "In FILE" line and nothing after it, or nothing at all: empty.
  EXPECT_EQ(parseVtkErrorText("ERROR: In a.cxx, line 1").text, "");
  EXPECT_EQ(parseVtkErrorText(nullptr).text, "");
  EXPECT_EQ(parseVtkErrorText(nullptr).origin, "");
}
} // namespace
} // namespace aniso
