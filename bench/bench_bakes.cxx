// LUT bake and cache timings, and the BRDF LUT's error against the reference integrator for
// each sample count (time against error). Goals: the default pair (64x64 each, 1024 samples)
// under 50 ms on a 2-core machine, a cache hit under 1 ms.
#include "core/env/environment.h"
#include "core/frame.h"
#include "core/lut/lut.h"
#include "core/lut/lut_cache.h"
#include "core/reference/reference_integrator.h"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using aniso::AsLobe;

constexpr int kSize = 64;
constexpr int kSamples = 1024;

// Arg 0 of the lobe-indexed benchmarks: the default material and the source's example.
const AsLobe kLobes[] = {{1000, 50}, {20000, 70}};

const AsLobe& lobeOf(const benchmark::State& state)
{
  return kLobes[state.range(0)];
}

void labelLobe(benchmark::State& state)
{
  const AsLobe& lobe = lobeOf(state);
  state.SetLabel("nu=" + std::to_string(int(lobe.nu)) + " nv=" + std::to_string(int(lobe.nv)));
}

fs::path benchDirectory()
{
  static const fs::path dir =
      fs::temp_directory_path() / ("aniso-bench-bakes-" + std::to_string(::getpid()));
  return dir;
}

// ---- Bakes ---------------------------------------------------------------------------------

// The default pair, as a material change costs on a cache miss. Args: lobe, threads (0: all).
void BM_BakeDefaultPair(benchmark::State& state)
{
  const AsLobe& lobe = lobeOf(state);
  const int threads = static_cast<int>(state.range(1));
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(aniso::bakeHalfVectorLut(lobe, kSize, threads));
    benchmark::DoNotOptimize(aniso::bakeBrdfLut(lobe, kSize, kSamples, threads));
  }
  labelLobe(state);
}
BENCHMARK(BM_BakeDefaultPair)
    ->ArgNames({"lobe", "threads"})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_BakeHalfVectorLut(benchmark::State& state)
{
  const int size = static_cast<int>(state.range(1));
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(aniso::bakeHalfVectorLut(lobeOf(state), size));
  }
  state.counters["texels/s"] =
      benchmark::Counter(double(size) * size, benchmark::Counter::kIsIterationInvariantRate);
  labelLobe(state);
}
BENCHMARK(BM_BakeHalfVectorLut)
    ->ArgNames({"lobe", "size"})
    ->Args({1, 64})
    ->Args({1, 256})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Time against error: the BRDF LUT for each sample count, with the largest |s - s_ref| or
// |b - b_ref| over an 8x8 grid of its texels, the reference from the reference integrator
// (deterministic quadrature, no sampling) under a uniform white environment: F0 = 1 gives
// s + b, F0 = 0 gives b. "err_nv>=0.05" leaves out the grazing rows (beyond ~87 degrees).
struct ReferenceTexel
{
  int i = 0;
  int j = 0;
  glm::dvec2 sizeBias{0.0};
};

const std::vector<ReferenceTexel>& referenceTexels(int lobeIndex)
{
  static std::map<int, std::vector<ReferenceTexel>> cache;
  auto found = cache.find(lobeIndex);
  if (found != cache.end())
  {
    return found->second;
  }
  const aniso::UniformEnvironment white(glm::dvec3(1.0));
  aniso::ReferenceOptions options;
  options.relativeTolerance = 1e-5;
  options.absoluteTolerance = 1e-6;
  std::vector<ReferenceTexel> texels;
  for (int j = 0; j < kSize; j += 9)
  {
    for (int i = 0; i < kSize; i += 9)
    {
      const glm::dvec3 view = aniso::brdfLutView({(i + 0.5) / kSize, (j + 0.5) / kSize});
      const aniso::ReferenceResult r = aniso::integrateSpecular(
          kLobes[lobeIndex], glm::dvec3(1.0, 0.0, 0.0), aniso::Frame{}, view, white, options);
      texels.push_back({i, j, {r.value.x - r.value.y, r.value.y}});
    }
  }
  return cache.emplace(lobeIndex, std::move(texels)).first->second;
}

void BM_BakeBrdfLut(benchmark::State& state)
{
  const AsLobe& lobe = lobeOf(state);
  const int samples = static_cast<int>(state.range(1));
  const std::vector<ReferenceTexel>& reference = referenceTexels(static_cast<int>(state.range(0)));
  aniso::BrdfLut lut;
  for (auto _ : state)
  {
    lut = aniso::bakeBrdfLut(lobe, kSize, samples);
    benchmark::DoNotOptimize(lut.rg.data());
  }
  double worst = 0.0;
  double worstAbove = 0.0;
  for (const ReferenceTexel& t : reference)
  {
    const std::size_t k = (std::size_t(t.j) * kSize + t.i) * 2;
    const double error =
        std::max(std::abs(lut.rg[k] - t.sizeBias.x), std::abs(lut.rg[k + 1] - t.sizeBias.y));
    worst = std::max(worst, error);
    const double nv = std::pow((t.j + 0.5) / kSize, 2.0);
    worstAbove = nv >= 0.05 ? std::max(worstAbove, error) : worstAbove;
  }
  state.counters["err_max"] = worst;
  state.counters["err_nv>=0.05"] = worstAbove;
  labelLobe(state);
}
BENCHMARK(BM_BakeBrdfLut)
    ->ArgNames({"lobe", "samples"})
    ->ArgsProduct({{0, 1}, {256, 1024, 4096, 16384}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// ---- Cache -----------------------------------------------------------------------------------

// The pair from memory: what a repeated request (same material) costs.
void BM_CacheMemoryHit(benchmark::State& state)
{
  aniso::LutCache cache("none");
  const AsLobe& lobe = lobeOf(state);
  cache.halfVector(lobe, kSize);
  cache.brdf(lobe, kSize, kSamples);
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(cache.halfVector(lobe, kSize));
    benchmark::DoNotOptimize(cache.brdf(lobe, kSize, kSamples));
  }
  labelLobe(state);
}
BENCHMARK(BM_CacheMemoryHit)->Arg(1)->Unit(benchmark::kMicrosecond)->UseRealTime();

// The pair read from the EXR files (first request after a restart).
void BM_CacheDiskHit(benchmark::State& state)
{
  aniso::LutCache cache(benchDirectory().string());
  const AsLobe& lobe = lobeOf(state);
  cache.halfVector(lobe, kSize);
  cache.brdf(lobe, kSize, kSamples);
  for (auto _ : state)
  {
    cache.clearMemory();
    benchmark::DoNotOptimize(cache.halfVector(lobe, kSize));
    benchmark::DoNotOptimize(cache.brdf(lobe, kSize, kSamples));
  }
  if (cache.stats().diskHits < 2u * static_cast<uint64_t>(state.iterations()))
  {
    state.SkipWithError("the cache did not read its files");
  }
  labelLobe(state);
}
BENCHMARK(BM_CacheDiskHit)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// A miss: bake the pair and store both files (the cost over BM_BakeDefaultPair is the write).
void BM_CacheMissBakeAndStore(benchmark::State& state)
{
  const fs::path dir = benchDirectory() / "miss";
  aniso::LutCache cache(dir.string());
  const AsLobe& lobe = lobeOf(state);
  for (auto _ : state)
  {
    state.PauseTiming();
    cache.clearMemory();
    fs::remove_all(dir);
    state.ResumeTiming();
    benchmark::DoNotOptimize(cache.halfVector(lobe, kSize));
    benchmark::DoNotOptimize(cache.brdf(lobe, kSize, kSamples));
  }
  labelLobe(state);
}
BENCHMARK(BM_CacheMissBakeAndStore)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::error_code ec;
  fs::remove_all(benchDirectory(), ec);
  return 0;
}
