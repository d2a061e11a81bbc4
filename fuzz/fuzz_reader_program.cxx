// libFuzzer harness of the readers that only the mesh reader program (aniso-mesh-reader) runs:
// VTK's (OBJ, legacy VTK, VTP, VTM), tinygltf's (.gltf, .glb) and OpenCASCADE's (STEP, IGES),
// each through the project's function the program calls (ANISO_FUZZ_FORMAT picks the format at
// build time): readBlocksWithVtk / readWithVtk, readCadBlocks / readCadSurface with the
// program's default options (parseCadArguments({})). An even-sized input is read as parts, an
// odd-sized one as the merged surface, as the program does with and without "blocks"; each part
// then goes through sanitizeSurface, as the application does with what the program sends.
// Accepted outcomes: parts (never a null surface) or a surface, whose sanitised points are all
// finite, or an aniso::Error naming the file, or std::bad_alloc (an allocation past the memory
// limit, which the program reports by the file's name). Anything else (a crash, a sanitizer report, a hang,
// another exception) is a finding. The program runs these readers in a process of their own
// because they are not hardened (docs/RELIABILITY.md): a crash found here inside VTK,
// tinygltf or OpenCASCADE is contained in the application, and is recorded there.
//
// .vtm: the harness writes, once, a composite tree through vtkXMLMultiBlockDataWriter
// (vtm_fixture.h) in a directory of its own and reads each input from there, so the seeds'
// references reach real pieces; pieces a fuzzed file names that are not there must give
// aniso::Error. .gltf/.glb: texture images are copied to the cache directory, here a directory
// of the harness's own (XDG_CACHE_HOME) that is emptied after each input.
// Known crashes inside VTK and OpenCASCADE that the project does not guard against (they end the
// reader program's process, which the application reports as an error; docs/RELIABILITY.md)
// are kept out, so that the harnesses look past them:
//   .vtk: only files of the current legacy format (first line "# vtk DataFile Version 5.1",
//     OFFSETS and CONNECTIVITY) are read. An older format's cell lists are walked before VTK
//     reads them (core/formats/vtk_legacy_sizes.h), but VTK 9.1 still crashes on other damage in
//     such files: a campaign with older files let through found, within 3 000 inputs for most
//     seeds, ASCII points holding a value that does not read ("0.02^451"), after which VTK's
//     polygonal reader goes on (SEGV in vtkPolyDataReader::ReadMeshSimple); a 5.1 file with the
//     same value is refused by VTK.
//   STEP: a file where a LINE, VECTOR, CIRCLE, PLANE, CYLINDRICAL_SURFACE, VERTEX_POINT or
//     AXIS2_PLACEMENT_3D refers to an instance of another type than its schema asks for is
//     skipped: OpenCASCADE 7.6 dereferences the empty handle it makes of such a reference
//     (StepToGeom::MakeCartesianPoint and the like). Names given twice and references to names
//     not given are refused by the project (CadReader.cxx) and do reach it.
// STEP/IGES: inputs over kCadMaxBytes (32 KiB, twice the largest seed) are skipped:
// OpenCASCADE's reading and BRepMesh's tessellation grow fast with the file, and libFuzzer's
// inputs stay below the largest seed anyway (scripts/fuzz.sh sets no -max_len).
#include "core/error.h"
#include "fuzz/fuzz_input.h"
#include "fuzz/fuzz_surface.h"
#include "fuzz/vtm_fixture.h"
#include "vtkpasses/mesh/CadReader.h"
#include "vtkpasses/mesh/MeshValidation.h"
#include "vtkpasses/mesh/VtkErrorText.h"
#include "vtkpasses/mesh/VtkReaders.h"

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <new>
#include <regex>
#include <string>
#include <system_error>
#include <unistd.h>
#include <utility>
#include <vector>
#include <vtkObject.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace
{
#define ANISO_STRINGIFY2(x) #x
#define ANISO_STRINGIFY(x) ANISO_STRINGIFY2(x)
const std::string kFormat = ANISO_STRINGIFY(ANISO_FUZZ_FORMAT);
const std::string kExt = "." + kFormat;
const bool kCad = aniso::isCadExtension(kExt);
constexpr size_t kCadMaxBytes = 32 * 1024;

std::string gltfCache;

// What the application does with each surface the program sends: an empty part is the
// loader's to report (sanitizeSurface's aniso::Error), not the reader's.
void sanitize(vtkPolyData* surface, const std::string& path)
{
  try
  {
    aniso::MeshReport report;
    aniso::fuzz::checkFinite(aniso::sanitizeSurface(surface, path, report));
  }
  catch (const aniso::Error&)
  {
  }
}

// The types the references of the geometric entities above must have, in order (STEP AP214;
// "A|B": either).
bool stepReferencesFit(const std::string& text)
{
  static const std::map<std::string, std::vector<std::string>> kExpected = {
      {"LINE", {"CARTESIAN_POINT", "VECTOR"}},
      {"VECTOR", {"DIRECTION"}},
      {"CIRCLE", {"AXIS2_PLACEMENT_3D|AXIS2_PLACEMENT_2D"}},
      {"PLANE", {"AXIS2_PLACEMENT_3D"}},
      {"CYLINDRICAL_SURFACE", {"AXIS2_PLACEMENT_3D"}},
      {"VERTEX_POINT", {"CARTESIAN_POINT"}},
      {"AXIS2_PLACEMENT_3D", {"CARTESIAN_POINT", "DIRECTION", "DIRECTION"}},
  };
  static const std::regex kInstance(R"(#(\d+)\s*=\s*([A-Z_0-9]+)\s*\(([^;]*))");
  static const std::regex kReference(R"(#(\d+))");
  std::map<std::string, std::string> types;
  std::vector<std::pair<std::string, std::string>> instances; // type, parameters
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kInstance);
       it != std::sregex_iterator(); ++it)
  {
    if (!types.emplace((*it)[1].str(), (*it)[2].str()).second)
    {
      return true; // a name given twice: CadReader refuses the file before OpenCASCADE reads it
    }
    instances.emplace_back((*it)[2].str(), (*it)[3].str());
  }
  for (const auto& [type, parameters] : instances)
  {
    const auto expected = kExpected.find(type);
    if (expected == kExpected.end())
    {
      continue;
    }
    size_t k = 0;
    for (auto it = std::sregex_iterator(parameters.begin(), parameters.end(), kReference);
         it != std::sregex_iterator(); ++it, ++k)
    {
      const auto target = types.find((*it)[1].str());
      if (target == types.end())
      {
        continue; // a name not given (or a complex instance): CadReader refuses the former
      }
      if (k >= expected->second.size() ||
          ("|" + expected->second[k] + "|").find("|" + target->second + "|") == std::string::npos)
      {
        return false;
      }
    }
    if (k < expected->second.size())
    {
      return false;
    }
  }
  return true;
}

bool knownThirdPartyCrash(const uint8_t* data, size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (kFormat == "vtk")
  {
    return text.rfind("# vtk DataFile Version 5.1\n", 0) != 0;
  }
  if (kFormat == "step")
  {
    return !stepReferencesFit(text);
  }
  return false;
}

void readInput(const std::string& path, bool blocks)
{
  std::vector<std::string> warnings;
  if (kCad)
  {
    const aniso::CadReadOptions options = aniso::parseCadArguments({});
    if (blocks)
    {
      for (const aniso::ReaderBlock& block : aniso::readCadBlocks(path, kExt, options, warnings))
      {
        if (!block.polyData)
        {
          std::abort(); // ReaderBlock promises a surface
        }
        sanitize(block.polyData, path);
      }
      return;
    }
    sanitize(aniso::readCadSurface(path, kExt, options, warnings), path);
    return;
  }
  aniso::VtkMessageCapture capture;
  if (blocks)
  {
    const std::vector<aniso::ReaderBlock> parts =
        aniso::readBlocksWithVtk(path, kExt, capture, warnings);
    if (parts.empty())
    {
      std::abort(); // the program sends at least one part
    }
    for (const aniso::ReaderBlock& block : parts)
    {
      if (!block.polyData)
      {
        std::abort();
      }
      sanitize(block.polyData, path);
    }
    return;
  }
  sanitize(aniso::readWithVtk(path, kExt, capture), path);
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vtkObject::GlobalWarningDisplayOff();
  // OpenCASCADE's messages go to standard output; the program sends its output to /dev/null.
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  const char* tmp = std::getenv("TMPDIR");
  const std::string base = std::string(tmp && *tmp ? tmp : "/tmp") + "/aniso-fuzz-" + kFormat +
                           "-" + std::to_string(static_cast<long>(getpid()));
  if (kFormat == "vtm")
  {
    // The inputs are written beside the fixture's pieces (writeInput writes into TMPDIR).
    std::filesystem::create_directories(base);
    if (!aniso::fuzz::writeVtmFixture(base, false))
    {
      std::abort();
    }
    setenv("TMPDIR", base.c_str(), 1);
  }
  if (kFormat == "gltf" || kFormat == "glb")
  {
    setenv("XDG_CACHE_HOME", base.c_str(), 1);
    gltfCache = base + "/aniso/gltf";
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if ((kCad && size > kCadMaxBytes) || knownThirdPartyCrash(data, size))
  {
    return 0;
  }
  const std::string path = aniso::fuzz::writeInput(data, size, kExt);
  try
  {
    readInput(path, size % 2 == 0);
  }
  catch (const aniso::Error&)
  {
  }
  catch (const std::bad_alloc&)
  {
    // An allocation past the memory limit (scripts/fuzz.sh: ASan's max_allocation_size_mb, the
    // reader program's address-space limit in the application): the program sends "PATH: the
    // reader ran out of memory" (MeshReaderProcess.cxx), a refusal by name.
  }
  if (!gltfCache.empty())
  {
    std::error_code ignored;
    std::filesystem::remove_all(gltfCache, ignored);
  }
  return 0;
}
