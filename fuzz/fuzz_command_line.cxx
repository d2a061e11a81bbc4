// libFuzzer harness of `aniso render`'s command line: the input is the arguments after "render",
// separated by NUL bytes, parsed and range-checked as the program does before any work
// (renderViewSettings: the render command's whole option table, then the view it places the
// camera by). Accepted outcomes: a view, or aniso::Error (UsageError among them) naming the
// argument at fault. Anything else (a crash, a sanitizer report, another exception) is a finding.
#include "app/render_command.h"
#include "core/error.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  std::vector<std::string> args;
  std::string current;
  for (size_t i = 0; i < size; ++i)
  {
    if (data[i] == 0)
    {
      args.push_back(current);
      current.clear();
    }
    else
    {
      current.push_back(static_cast<char>(data[i]));
    }
  }
  if (!current.empty())
  {
    args.push_back(current);
  }
  try
  {
    const aniso::ViewSettings view = aniso::cli::renderViewSettings(args);
    const double length = std::sqrt(view.direction.x * view.direction.x +
                                    view.direction.y * view.direction.y +
                                    view.direction.z * view.direction.z);
    if (!(std::abs(length - 1.0) < 1e-9))
    {
      std::abort(); // a view direction is a unit vector whatever the angles given
    }
  }
  catch (const aniso::Error& e)
  {
    if (std::string(e.what()).empty())
    {
      std::abort(); // an error says what is wrong
    }
  }
  return 0;
}
