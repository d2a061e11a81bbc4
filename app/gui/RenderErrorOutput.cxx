#include "app/gui/RenderErrorOutput.h"

#include "vtkpasses/mesh/VtkErrorText.h"

#include <sstream>
#include <utility>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtk_glew.h> // before any other GL header

namespace aniso
{
// VTK's error text and generic warnings go to SINK while drawing; everything goes where it went
// before too.
class ErrorForwardingWindow : public vtkOutputWindow
{
public:
  static ErrorForwardingWindow* New();
  vtkSmartPointer<vtkOutputWindow> previous;
  std::function<void(const std::string&)> sink;
  bool drawing = false;
  bool spoke = false; // something went to SINK since the flag was cleared

  void DisplayText(const char* text) override { previous->DisplayText(text); }
  void DisplayErrorText(const char* text) override
  {
    previous->DisplayErrorText(text);
    forward(text);
  }
  void DisplayWarningText(const char* text) override { previous->DisplayWarningText(text); }
  void DisplayGenericWarningText(const char* text) override
  {
    previous->DisplayGenericWarningText(text);
    // The material reports what failed while drawing (a texture that could not be made) so.
    forward(text);
  }
  void DisplayDebugText(const char* text) override { previous->DisplayDebugText(text); }
  void forward(const char* text)
  {
    if (drawing && sink && text)
    {
      spoke = true;
      sink(text);
    }
  }

  vtkTypeMacro(ErrorForwardingWindow, vtkOutputWindow)
};
vtkStandardNewMacro(ErrorForwardingWindow);

RenderErrorOutput::RenderErrorOutput(std::function<void(const std::string&)> report)
    : report_(std::move(report)), window_(vtkSmartPointer<ErrorForwardingWindow>::New())
{
  window_->previous = vtkOutputWindow::GetInstance();
  window_->sink = [this](const std::string& text)
  {
    // The words, not the source.
    const std::string plain = parseVtkErrorText(text.c_str()).text;
    const std::string material = "anisotropic material: ";
    // The material's messages name their subject already.
    this->report(plain.rfind(material, 0) == 0 ? plain.substr(material.size())
                                               : "OpenGL: " + plain);
  };
  vtkOutputWindow::SetInstance(window_);
}

RenderErrorOutput::~RenderErrorOutput()
{
  vtkOutputWindow::SetInstance(window_->previous);
}

void RenderErrorOutput::beginDrawing()
{
  window_->drawing = true;
  window_->spoke = false;
}

void RenderErrorOutput::endDrawing()
{
  window_->drawing = false;
}

void RenderErrorOutput::checkGlErrors()
{
  for (int i = 0; i < 4; ++i)
  {
    const GLenum code = glGetError();
    if (code == GL_NO_ERROR)
    {
      break;
    }
    if (window_->spoke)
    {
      continue;
    }
    std::ostringstream message;
    message << "OpenGL: error 0x" << std::hex << code
            << " while drawing the view (the image may be wrong)";
    report(message.str());
  }
}

void RenderErrorOutput::report(const std::string& message)
{
  if (reported_.insert(message).second)
  {
    report_(message);
  }
}
} // namespace aniso
