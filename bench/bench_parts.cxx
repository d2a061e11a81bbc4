// What a scene of many parts costs against the same triangles drawn as one part: a grid of
// COLUMNS x ROWS small spheres (radius 0.4, one unit apart, in the XZ plane facing the front
// camera) under the studio, each sphere a part of its own (its own actor, AnisoMaterial and
// uniforms, the same material values) or all of them merged into one surface, drawn through
// renderOffscreen at 1 sample per frame and at the declared default samples (the material's
// samples per frame of a progressive refinement).
//
// Per configuration and round: renderOffscreen with F frames in a fresh window, the first frame
// (shaders, LUT and map textures, the environment's upload) and the median of the others. The
// rounds alternate merged and parts; the table prints the median over the rounds of each, and
// parts / merged. Also the texture uploads of one render (every part's material uploads its own
// half-vector table; the environment's textures are uploaded once) and what the LUT cache did.
//
// Needs an X display. Usage: bench_parts [--columns C] [--rows R] [--size S] [--frames F]
//                                       [--rounds N]
#include "core/env/environment.h"
#include "core/lut/lut_cache.h"
#include "core/parameters/parameters.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "vtkpasses/render/TextureUpload.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>
#include <vtkAppendPolyData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace
{
using namespace aniso;

struct Options
{
  int columns = 20;
  int rows = 10;
  int size = 512;
  int frames = 6;
  int rounds = 3;
};

// A sphere of radius 0.4 at (x, 0, z): the built-in one scaled (normals and tangents unchanged).
vtkSmartPointer<vtkPolyData> smallSphere(double x, double z)
{
  auto sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->DeepCopy(makeSphere(32, 16));
  vtkPoints* points = sphere->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, 0.4 * p[0] + x, 0.4 * p[1], 0.4 * p[2] + z);
  }
  return sphere;
}

struct Timing
{
  double firstMs = 0.0;
  double frameMs = 0.0;
  uint64_t uploads = 0;
  int64_t covered = 0;
};

Timing measure(const RenderSettings& s)
{
  const uint64_t uploads = textureUploadCount();
  const RenderResult r = renderOffscreen(s);
  Timing t;
  t.uploads = textureUploadCount() - uploads;
  t.firstMs = r.frameSeconds.front() * 1e3;
  t.frameMs =
      medianSeconds(std::vector<double>(r.frameSeconds.begin() + 1, r.frameSeconds.end())) * 1e3;
  t.covered = r.coveredPixels;
  return t;
}

double median(std::vector<double> v)
{
  return medianSeconds(std::move(v));
}

int parse(int argc, char** argv, Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const auto value = [&](int& target, int minimum)
    {
      if (i + 1 >= argc || (target = std::atoi(argv[++i])) < minimum)
      {
        std::fprintf(stderr, "bench_parts: %s needs a number >= %d\n", argv[i - 1], minimum);
        std::exit(2);
      }
    };
    if (!std::strcmp(argv[i], "--columns"))
      value(o.columns, 1);
    else if (!std::strcmp(argv[i], "--rows"))
      value(o.rows, 1);
    else if (!std::strcmp(argv[i], "--size"))
      value(o.size, 16);
    else if (!std::strcmp(argv[i], "--frames"))
      value(o.frames, 2);
    else if (!std::strcmp(argv[i], "--rounds"))
      value(o.rounds, 1);
    else
    {
      std::fprintf(stderr, "usage: bench_parts [--columns C] [--rows R] [--size S] [--frames F] "
                           "[--rounds N]\n");
      return 2;
    }
  }
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  Options o;
  if (const int code = parse(argc, argv, o))
  {
    return code;
  }
  std::vector<RenderPart> parts;
  vtkNew<vtkAppendPolyData> append;
  for (int r = 0; r < o.rows; ++r)
  {
    for (int c = 0; c < o.columns; ++c)
    {
      RenderPart part;
      part.name = "sphere " + std::to_string(r * o.columns + c + 1);
      part.surface = smallSphere(c - 0.5 * (o.columns - 1), r - 0.5 * (o.rows - 1));
      append->AddInputData(part.surface);
      parts.push_back(part);
    }
  }
  append->Update();
  vtkSmartPointer<vtkPolyData> merged = append->GetOutput();

  RenderSettings base;
  base.environment = std::make_shared<StudioEnvironment>();
  base.width = o.size;
  base.height = o.size;
  base.frames = o.frames;
  base.material.lobe = {1000.0, 50.0};
  const int defaultSamples = static_cast<int>(parameterSpec("samples").defaultValue[0]);

  std::printf("%d parts (%d x %d spheres of %lld triangles, %lld in all), %dx%d, %d frames a "
              "render (the first apart), %d rounds, n_u = 1000, n_v = 50, the studio\n",
              o.columns * o.rows, o.columns, o.rows,
              static_cast<long long>(parts.front().surface->GetNumberOfCells()),
              static_cast<long long>(merged->GetNumberOfCells()), o.size, o.size, o.frames,
              o.rounds);
  std::printf("%-8s %-7s %10s %10s %9s %8s %8s\n", "samples", "scene", "frame ms", "first ms",
              "uploads", "covered", "ratio");
  for (const int samples : {1, defaultSamples})
  {
    RenderSettings one = base;
    one.material.samples = samples;
    one.surface = merged;
    RenderSettings many = base;
    many.material.samples = samples;
    many.parts = parts;
    for (RenderPart& part : many.parts)
    {
      part.material = one.material;
    }
    std::vector<double> oneFrame, oneFirst, manyFrame, manyFirst;
    Timing oneLast, manyLast;
    const LutCacheStats lutsBefore = LutCache::shared().stats();
    for (int round = 0; round < o.rounds; ++round)
    {
      oneLast = measure(one);
      manyLast = measure(many);
      oneFrame.push_back(oneLast.frameMs);
      oneFirst.push_back(oneLast.firstMs);
      manyFrame.push_back(manyLast.frameMs);
      manyFirst.push_back(manyLast.firstMs);
    }
    const LutCacheStats luts = LutCache::shared().stats();
    const double frameRatio = median(manyFrame) / median(oneFrame);
    const double firstRatio = median(manyFirst) / median(oneFirst);
    std::printf("%-8d %-7s %10.1f %10.1f %9llu %8lld %8s\n", samples, "merged", median(oneFrame),
                median(oneFirst), static_cast<unsigned long long>(oneLast.uploads),
                static_cast<long long>(oneLast.covered), "");
    std::printf("%-8d %-7s %10.1f %10.1f %9llu %8lld %8.2f\n", samples, "parts", median(manyFrame),
                median(manyFirst), static_cast<unsigned long long>(manyLast.uploads),
                static_cast<long long>(manyLast.covered), frameRatio);
    std::printf("  parts / merged: frame %.2f, first frame %.2f; LUT cache over these renders: "
                "%llu bakes, %llu disk reads, %llu memory hits\n",
                frameRatio, firstRatio,
                static_cast<unsigned long long>(luts.bakes - lutsBefore.bakes),
                static_cast<unsigned long long>(luts.diskHits - lutsBefore.diskHits),
                static_cast<unsigned long long>(luts.memoryHits - lutsBefore.memoryHits));
  }
  return 0;
}
