#include "vtkpasses/mesh/VtkErrorText.h"

#include "core/error.h"

#include <cctype>
#include <utility>
#include <vtkAlgorithm.h>
#include <vtkErrorCode.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

namespace aniso
{
VtkErrorText parseVtkErrorText(const char* raw)
{
  std::string text = raw ? raw : "";
  if (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0 ||
      text.rfind("Generic Warning: In ", 0) == 0)
  {
    const std::size_t newline = text.find('\n');
    text = newline == std::string::npos ? std::string() : text.substr(newline + 1);
  }
  VtkErrorText message;
  // "vtkClass (0x...): ": the class is the first word.
  const std::size_t open = text.find(" (");
  const std::size_t close = text.find("): ");
  if (open != std::string::npos && close != std::string::npos && open < close &&
      text.find_first_of(" \n") == open)
  {
    message.origin = text.substr(0, open);
    text = text.substr(close + 3);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
  {
    text.pop_back();
  }
  message.text = std::move(text);
  return message;
}

VtkErrorText readableVtkMessage(const char* raw)
{
  VtkErrorText message = parseVtkErrorText(raw);
  const std::string& text = message.text;
  // One line of printable text: readers quote raw file bytes in their messages, and a user
  // message must carry neither binary junk nor a whole line of a corrupt file, so it stops at
  // the first unprintable byte.
  constexpr size_t kMaxLength = 160;
  std::string clean;
  bool cut = false;
  for (char c : text)
  {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x7f || (u < 0x20 && !std::isspace(u)))
    {
      cut = true;
      break;
    }
    if (std::isspace(u) && (clean.empty() || clean.back() == ' '))
    {
      continue;
    }
    clean += std::isspace(u) ? ' ' : c;
  }
  while (!clean.empty() && clean.back() == ' ')
  {
    clean.pop_back();
  }
  if (clean.rfind("* ", 0) == 0)
  {
    clean.erase(0, 2); // jsoncpp's bullet before "Line N, Column M"
  }
  if (clean.size() > kMaxLength)
  {
    clean.resize(kMaxLength);
    cut = true;
  }
  if (cut)
  {
    clean += "...";
  }
  message.text = clean;
  return message;
}

namespace
{
// Collects what VTK would print, so that it becomes the error message instead of stderr noise.
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow)

      void DisplayText(const char*) override
  {
  }
  void DisplayDebugText(const char*) override {}
  void DisplayErrorText(const char* text) override
  {
    this->Errors.push_back(readableVtkMessage(text));
  }
  void DisplayWarningText(const char* text) override
  {
    this->Warnings.push_back(readableVtkMessage(text));
  }
  void DisplayGenericWarningText(const char* text) override
  {
    this->Warnings.push_back(readableVtkMessage(text));
  }

  std::vector<VtkErrorText> Errors;
  std::vector<VtkErrorText> Warnings;

protected:
  CapturingOutputWindow() = default;
};
vtkStandardNewMacro(CapturingOutputWindow);

bool isPipelineClass(const std::string& origin)
{
  return origin == "vtkExecutive" || origin == "vtkStreamingDemandDrivenPipeline" ||
         origin == "vtkCompositeDataPipeline" || origin == "vtkDemandDrivenPipeline";
}
} // namespace

struct VtkMessageCapture::Impl
{
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkLogger::Verbosity previousVerbosity = vtkLogger::GetCurrentVerbosityCutoff();
  vtkNew<CapturingOutputWindow> window;
};

VtkMessageCapture::VtkMessageCapture() : impl_(std::make_unique<Impl>())
{
  vtkOutputWindow::SetInstance(impl_->window);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkMessageCapture::~VtkMessageCapture()
{
  vtkOutputWindow::SetInstance(impl_->previous);
  vtkLogger::SetStderrVerbosity(impl_->previousVerbosity);
}

const std::vector<VtkErrorText>& VtkMessageCapture::errors() const
{
  return impl_->window->Errors;
}

const std::vector<VtkErrorText>& VtkMessageCapture::warnings() const
{
  return impl_->window->Warnings;
}

void throwIfReaderFailed(const std::string& path, vtkAlgorithm* reader,
                         const VtkMessageCapture& capture)
{
  const auto& errors = capture.errors();
  std::string reason;
  for (const VtkErrorText& message : errors)
  {
    if (!isPipelineClass(message.origin) && !message.text.empty())
    {
      reason = message.text;
      break;
    }
  }
  if (reason.empty() && !errors.empty())
  {
    reason = "the reader failed (corrupt file, or not in this format)";
  }
  const unsigned long code =
      reader ? reader->GetErrorCode() : static_cast<unsigned long>(vtkErrorCode::NoError);
  if (reason.empty() && code != vtkErrorCode::NoError)
  {
    reason = std::string("read error (") + vtkErrorCode::GetStringFromErrorCode(code) + ")";
  }
  if (!reason.empty())
  {
    throw errorAbout(path, reason);
  }
}
} // namespace aniso
