#pragma once
// The errors of a view's renderer, each distinct message reported once (a failure repeats with
// every frame): VTK's error output while the view draws (a shader that does not compile, a
// failed GL call) and its generic warnings (the material's failures), and after a frame the GL's
// own error codes (glGetError: VTK checks only in debug builds). Installed as VTK's output window
// while it lives; everything still goes where it went before too.
#include <functional>
#include <set>
#include <string>
#include <vtkSmartPointer.h>

namespace aniso
{
class ErrorForwardingWindow;

class RenderErrorOutput
{
public:
  // REPORT hears each distinct message once, in words: "OpenGL: what", or the material's own.
  explicit RenderErrorOutput(std::function<void(const std::string&)> report);
  ~RenderErrorOutput();
  RenderErrorOutput(const RenderErrorOutput&) = delete;
  RenderErrorOutput& operator=(const RenderErrorOutput&) = delete;

  // VTK's output is reported between beginDrawing and endDrawing.
  void beginDrawing();
  void endDrawing();
  // After a frame, its GL context current: the GL's errors (a few at most, as glGetError
  // returns one per call), unless VTK or the material said what failed while it drew (the GL's
  // code for the same failure adds nothing).
  void checkGlErrors();
  // MESSAGE to REPORT, unless it was reported before.
  void report(const std::string& message);

private:
  std::function<void(const std::string&)> report_;
  std::set<std::string> reported_;
  vtkSmartPointer<ErrorForwardingWindow> window_;
};
} // namespace aniso
