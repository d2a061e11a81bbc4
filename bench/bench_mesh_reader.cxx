// What reading a file with VTK's readers in a process of its own costs per load: loadMesh of the
// same small mesh as OBJ (vtkOBJReader, in the reader process) and as PLY (the project's own
// reader, in this process: the baseline), measured side by side in one run, N loads each
// (default 40), median per load and the ratio. bench_mesh_reader [N] [TRIANGLES_PER_SIDE]
#include "bench/median_time.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/MeshLoader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>

using aniso::bench::medianMs;

int main(int argc, char** argv)
{
  const int loads = argc > 1 ? std::max(1, std::atoi(argv[1])) : 40;
  const int side = argc > 2 ? std::max(2, std::atoi(argv[2])) : 16;
  vtkSmartPointer<vtkPolyData> plate = aniso::makePlate(side);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("aniso-bench-reader-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string obj = (dir / "plate.obj").string();
  const std::string ply = (dir / "plate.ply").string();
  vtkNew<vtkOBJWriter> objWriter;
  objWriter->SetInputData(plate);
  objWriter->SetFileName(obj.c_str());
  objWriter->Write();
  vtkNew<vtkPLYWriter> plyWriter;
  plyWriter->SetInputData(plate);
  plyWriter->SetFileName(ply.c_str());
  plyWriter->Write();
  medianMs([&] { aniso::loadMesh(obj); },
           2); // warm: the page cache, the reader program's libraries
  medianMs([&] { aniso::loadMesh(ply); }, 2);
  const double objMs = medianMs([&] { aniso::loadMesh(obj); }, loads);
  const double plyMs = medianMs([&] { aniso::loadMesh(ply); }, loads);
  std::printf("| mesh | loads | OBJ, reader process (ms) | PLY, in process (ms) | ratio |\n");
  std::printf("|---|---|---|---|---|\n");
  std::printf("| plate, %lld triangles | %d | %.2f | %.2f | %.2f |\n",
              static_cast<long long>(plate->GetNumberOfPolys()), loads, objMs, plyMs,
              objMs / plyMs);
  std::filesystem::remove_all(dir);
  return 0;
}
