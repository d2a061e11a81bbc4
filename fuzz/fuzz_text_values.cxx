// libFuzzer harness of the text every option and session value goes through: the first byte
// picks a declared parameter (or the brushing-model spelling), the rest is the text. Besides
// an aniso::Error, the only accepted outcome is a value that its own range check accepts and
// that formats to a text parsing back to the same value (what sessions rely on).
#include "core/error.h"
#include "core/parameters/parameters.h"
#include "vtkpasses/mesh/BrushingModel.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  const auto& specs = aniso::parameterSpecs();
  const size_t pick = data[0] % (specs.size() + 1);
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  if (pick == specs.size())
  {
    try
    {
      const aniso::BrushingModel model = aniso::parseBrushingModel(text);
      const std::string spelled = aniso::toString(model);
      if (aniso::toString(aniso::parseBrushingModel(spelled)) != spelled)
      {
        std::abort(); // toString promises a spelling that parses back to the same model
      }
    }
    catch (const aniso::Error&)
    {
    }
    return 0;
  }
  const aniso::ParameterSpec& spec = specs[pick];
  aniso::ParameterValue value;
  try
  {
    value = aniso::parseParameterValue(spec, text, "--" + std::string(spec.name));
  }
  catch (const aniso::Error&)
  {
    return 0;
  }
  try
  {
    aniso::checkParameterValue(spec, value, "check");
    const std::string formatted = aniso::formatParameterValue(spec, value);
    if (!(aniso::parseParameterValue(spec, formatted, "round trip") == value))
    {
      std::abort(); // a session would not read back what it wrote
    }
  }
  catch (const aniso::Error&)
  {
    std::abort(); // a parsed value must pass its own check and read back
  }
  return 0;
}
