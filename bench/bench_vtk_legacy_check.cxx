// What the checks of a VTK legacy file (core/formats/vtk_legacy_sizes.h: the declared sizes, the
// walk of its dataset section) cost against loading the same file (loadMesh: VTK's legacy reader
// in the reader program, then the mesh's preparation: the baseline), measured side by side in
// one run for a sphere written by vtkPolyDataWriter as ASCII and binary, median of N runs each
// (default 5). bench_vtk_legacy_check [N] [SEGMENTS_AROUND]
#include "bench/median_time.h"
#include "core/formats/vtk_legacy_sizes.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/MeshLoader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <unistd.h>
#include <vector>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>

using aniso::bench::medianMs;

int main(int argc, char** argv)
{
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const int around = argc > 2 ? std::max(8, std::atoi(argv[2])) : 512;
  vtkSmartPointer<vtkPolyData> sphere = aniso::makeSphere(around, around / 2);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("aniso-bench-legacy-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::printf("| file | points | bytes | check (ms) | loadMesh (ms) | check / load |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (bool binary : {false, true})
  {
    const std::string path = (dir / (binary ? "sphere-binary.vtk" : "sphere-ascii.vtk")).string();
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetInputData(sphere);
    writer->SetFileName(path.c_str());
    binary ? writer->SetFileTypeToBinary() : writer->SetFileTypeToASCII();
    writer->Write();
    if (aniso::vtkLegacySizeProblem(path))
    {
      std::fprintf(stderr, "bench_vtk_legacy_check: %s refused\n", path.c_str());
      return 1;
    }
    aniso::loadMesh(path); // warm: the page cache, the reader program's libraries
    const double checkMs = medianMs([&] { aniso::vtkLegacySizeProblem(path); }, runs);
    const double loadMs = medianMs([&] { aniso::loadMesh(path); }, runs);
    std::printf("| %s | %lld | %ju | %.1f | %.1f | %.3f |\n", binary ? "binary" : "ASCII",
                static_cast<long long>(sphere->GetNumberOfPoints()),
                static_cast<std::uintmax_t>(std::filesystem::file_size(path)), checkMs, loadMs,
                checkMs / loadMs);
  }
  std::filesystem::remove_all(dir);
  return 0;
}
