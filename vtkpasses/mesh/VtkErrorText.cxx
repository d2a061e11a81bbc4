#include "vtkpasses/mesh/VtkErrorText.h"

#include <cctype>
#include <utility>

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
} // namespace aniso
