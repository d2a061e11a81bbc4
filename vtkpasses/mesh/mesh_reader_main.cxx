// aniso-mesh-reader PATH EXT FILE_SIZE [blocks]: reads one mesh file (its parts, with "blocks")
// with VTK's readers for the application (MeshReaderProcess.h), the result on standard output in
// the records it expects.
#include "vtkpasses/mesh/MeshReaderProcess.h"
#include "vtkpasses/mesh/VtkReaders.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>

int main(int argc, char** argv)
{
  const bool blocks = argc == 5 && std::strcmp(argv[4], aniso::kReaderBlocksArgument) == 0;
  if ((argc != 4 && !blocks) || ::isatty(STDOUT_FILENO))
  {
    std::fprintf(stderr, "usage: aniso-mesh-reader PATH EXT FILE_SIZE [blocks] (run by aniso, "
                         "which reads its output)\n");
    return 2;
  }
  // The records go to the pipe that is standard output now; runMeshReader then points standard
  // output at /dev/null, so nothing a reader prints can mix with them.
  const int fd = ::dup(STDOUT_FILENO);
  if (fd < 0)
  {
    return 3;
  }
  const uintmax_t fileSize = std::strtoull(argv[3], nullptr, 10);
  if (blocks)
  {
    return aniso::runMeshReaderBlocks(fd, argv[1], argv[2], fileSize, aniso::readBlocksWithVtk);
  }
  return aniso::runMeshReader(fd, argv[1], argv[2], fileSize, aniso::readWithVtk);
}
