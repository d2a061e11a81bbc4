#pragma once
// VTK's error output text (vtkOutputWindow's Display*Text): "ERROR: In FILE, line N\nvtkClass
// (0x...): what\n\n" for errors, "Warning: In ..." and "Generic Warning: In FILE, line N\nwhat"
// likewise, told apart into the class that printed it and its words; and what VTK prints while
// a reader runs, captured as such messages instead of reaching stderr. No GL.
#include <memory>
#include <string>
#include <vector>

class vtkAlgorithm;

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

// VTK's message as a user reads it: parseVtkErrorText's words in one line of printable text
// (readers quote raw file bytes in their messages): cut at the first unprintable byte and at 160
// characters, "..." where cut.
VtkErrorText readableVtkMessage(const char* raw);

// For its lifetime, what VTK would print (vtkOutputWindow) is collected as readable messages and
// vtkLogger's stderr copy of the same messages is silenced; both are restored afterwards. Both
// are process-wide: one capture at a time (loadMesh serialises its loads).
class VtkMessageCapture
{
public:
  VtkMessageCapture();
  ~VtkMessageCapture();
  VtkMessageCapture(const VtkMessageCapture&) = delete;
  VtkMessageCapture& operator=(const VtkMessageCapture&) = delete;

  const std::vector<VtkErrorText>& errors() const;
  const std::vector<VtkErrorText>& warnings() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Throws aniso::Error "PATH: reason" when the reader failed: the reason is its first own message
// captured (the most specific one; the pipeline's "returned failure" and the readers' follow-up
// "failed to load" messages add nothing a user can act on), else a generic one when any error
// was captured, else READER's error code when it has one. READER may be null.
void throwIfReaderFailed(const std::string& path, vtkAlgorithm* reader,
                         const VtkMessageCapture& capture);
} // namespace aniso
