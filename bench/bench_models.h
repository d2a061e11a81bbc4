#pragma once
// The shading models of issue 6 in `aniso bench`: the lit models (Banks, anisotropic
// Blinn-Phong, Ward, Heidrich-Seidel, Ashikhmin-Shirley) under 1, 2 and 4 point and directional
// lights on the sphere and the flange; LEADR (with plain normal mapping, the baseline it
// replaces) against a supersampled reference over its slope-grid size and the distance (mip
// level); the microstructure over K x K sample grids (full and jittered) against its converged
// CPU evaluation, per structure and masking mode. Each scene also times the Ashikhmin-Shirley
// environment frame (exact, filtered, LUT, 16 samples), so every row carries its frame time as a
// ratio to that baseline measured in the same run.
#include "bench/bench_run.h"

#include <ostream>
#include <string>
#include <vector>

namespace aniso::bench
{
struct ModelBenchOptions
{
  bool quick = false;
  int size = 128;  // sphere and flange; the plate of LEADR and microstructure: half
  bool lit = true; // which families run
  bool leadr = true;
  bool microstructure = true;
  std::string cacheDirectory; // the baselines' reference cache (reference_image.h); "" = none
};

// Appends the rows of the families asked for to ROWS; progress lines go to LOG. Returns the
// OpenGL renderer's name. Throws aniso::Error on a failed render.
std::string runModelBenches(const ModelBenchOptions& options, std::ostream& log,
                            std::vector<BenchRow>& rows);
} // namespace aniso::bench
