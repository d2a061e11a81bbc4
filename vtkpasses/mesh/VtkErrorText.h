#pragma once
// VTK's error output text (vtkOutputWindow's Display*Text): "ERROR: In FILE, line N\nvtkClass
// (0x...): what\n\n" for errors, "Warning: In ..." and "Generic Warning: In FILE, line N\nwhat"
// likewise, told apart into the class that printed it and its words. No GL.
#include <string>

namespace aniso
{
struct VtkErrorText
{
  std::string origin; // the VTK class that printed it ("vtkXReader"), empty when none is named
  std::string text;   // the rest: without the "In FILE, line N" line, the class and its address,
                      // and trailing white space
};

// "ERROR: In ./IO/x.cxx, line 12\nvtkXReader (0x55d...): reason\n\n" -> {vtkXReader, reason}. A
// text with the "In FILE" line and nothing after it is empty; one without that line is taken
// as the words (with their class, if they start with one). Null reads as empty.
VtkErrorText parseVtkErrorText(const char* raw);
} // namespace aniso
