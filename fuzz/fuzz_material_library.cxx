// libFuzzer harness of material library files (core/parameters/material_library): the bytes go
// through materialLibraryFromJson (nlohmann's parser, then every material's keys, types and
// ranges). Accepted outcomes: a library, which written back and read again is the same library
// (the round trip every library file must make), or an aniso::Error naming the file.
#include "core/error.h"
#include "core/parameters/material_library.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  aniso::MaterialLibrary library;
  try
  {
    library = aniso::materialLibraryFromJson(text, "/nonexistent", "fuzz.json");
  }
  catch (const aniso::Error&)
  {
    return 0;
  }
  const aniso::MaterialLibrary back = aniso::materialLibraryFromJson(
      aniso::materialLibraryToJson(library, "/nonexistent"), "/nonexistent", "written.json");
  if (!(back == library))
  {
    std::abort(); // a library that does not survive its own file
  }
  return 0;
}
