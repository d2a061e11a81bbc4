// aniso-mesh-reader PATH EXT FILE_SIZE: reads one mesh file with VTK's readers for the
// application (MeshReaderProcess.h), the result on standard output in the records it expects.
#include "vtkpasses/mesh/MeshReaderProcess.h"
#include "vtkpasses/mesh/VtkReaders.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

int main(int argc, char** argv)
{
  if (argc != 4 || ::isatty(STDOUT_FILENO))
  {
    std::fprintf(stderr, "usage: aniso-mesh-reader PATH EXT FILE_SIZE (run by aniso, which reads "
                         "its output)\n");
    return 2;
  }
  // The records go to the pipe that is standard output now; runMeshReader then points standard
  // output at /dev/null, so nothing a reader prints can mix with them.
  const int fd = ::dup(STDOUT_FILENO);
  if (fd < 0)
  {
    return 3;
  }
  return aniso::runMeshReader(fd, argv[1], argv[2], std::strtoull(argv[3], nullptr, 10),
                              aniso::readWithVtk);
}
