// aniso-mesh-reader PATH EXT FILE_SIZE [blocks] [KEY=VALUE...]: reads one mesh file (its parts,
// with "blocks") with VTK's readers, or OpenCASCADE's for STEP and IGES (CadReader.h, which takes
// the KEY=VALUE arguments), for the application (MeshReaderProcess.h), the result on standard
// output in the records it expects.
#include "core/error.h"
#include "core/image/image_module.h"
#include "vtkpasses/mesh/CadReader.h"
#include "vtkpasses/mesh/MeshReaderProcess.h"
#include "vtkpasses/mesh/VtkReaders.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>
#include <vector>

int main(int argc, char** argv)
{
  const bool blocks = argc >= 5 && std::strcmp(argv[4], aniso::kReaderBlocksArgument) == 0;
  if (argc < 4 || ::isatty(STDOUT_FILENO))
  {
    std::fprintf(stderr, "usage: aniso-mesh-reader PATH EXT FILE_SIZE [blocks] [KEY=VALUE...] "
                         "(run by aniso, which reads its output)\n");
    return 2;
  }
  const std::vector<std::string> readArguments(argv + (blocks ? 5 : 4), argv + argc);
  // The records go to the pipe that is standard output now; runMeshReader then points standard
  // output at /dev/null, so nothing a reader prints can mix with them.
  const int fd = ::dup(STDOUT_FILENO);
  if (fd < 0)
  {
    return 3;
  }
  const uintmax_t fileSize = std::strtoull(argv[3], nullptr, 10);
  const std::string path = argv[1];
  const std::string ext = argv[2];
  if (ext == ".gltf" || ext == ".glb")
  {
    // glTF textures are decoded through the image module: loaded before runMeshReader bounds
    // the address space, as its libraries were when the program linked them.
    aniso::loadImageModule();
  }
  if (aniso::isCadExtension(ext))
  {
    auto options = [&readArguments] { return aniso::parseCadArguments(readArguments); };
    if (blocks)
    {
      return aniso::runMeshReaderBlocks(
          fd, path, ext, fileSize,
          [&](const std::string& p, const std::string& e, const aniso::VtkMessageCapture&,
              std::vector<std::string>& warnings)
          { return aniso::readCadBlocks(p, e, options(), warnings); });
    }
    return aniso::runMeshReader(
        fd, path, ext, fileSize,
        [&](const std::string& p, const std::string& e, const aniso::VtkMessageCapture&)
        {
          std::vector<std::string> warnings; // a merged surface has no part to tell them of
          return aniso::readCadSurface(p, e, options(), warnings);
        });
  }
  if (blocks)
  {
    return aniso::runMeshReaderBlocks(fd, path, ext, fileSize, aniso::readBlocksWithVtk);
  }
  return aniso::runMeshReader(fd, path, ext, fileSize, aniso::readWithVtk);
}
