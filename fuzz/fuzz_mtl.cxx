// libFuzzer harness of MTL material libraries (core/formats/mtl, mtl_material): the bytes go
// through parseMtl, which must never throw, and each material it gives through materialFromMtl
// (its textures looked for in a folder that does not exist). Accepted outcome: materials that
// the material library takes as they are (every value within its declared range) and that
// survive the library's JSON round trip; anything else aborts.
#include "core/error.h"
#include "core/formats/mtl.h"
#include "core/formats/mtl_material.h"
#include "core/parameters/material_library.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const aniso::MtlLibrary mtl = aniso::parseMtl(text, "/nonexistent/fuzz.mtl");
  if (mtl.warnings.size() > aniso::kMaxMtlWarnings + 1 ||
      mtl.materials.size() > aniso::kMaxMtlMaterials)
  {
    std::abort(); // past the parser's own limits
  }
  aniso::MaterialLibrary library;
  std::vector<std::string> warnings;
  for (const aniso::MtlMaterial& m : mtl.materials)
  {
    try
    {
      library.put(aniso::materialFromMtl(m, "/nonexistent/fuzz.mtl", warnings));
    }
    catch (const aniso::Error&)
    {
      std::abort(); // the mapping made a value the material library refuses
    }
  }
  const aniso::MaterialLibrary back = aniso::materialLibraryFromJson(
      aniso::materialLibraryToJson(library), "/nonexistent", "written.json");
  if (!(back == library))
  {
    std::abort();
  }
  return 0;
}
