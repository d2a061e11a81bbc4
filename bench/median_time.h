#pragma once
// The median wall time of a few runs of something, in milliseconds (the benchmarks of file
// loading and checking).
#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace aniso::bench
{
inline double medianMs(const std::function<void()>& run, int runs)
{
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    run();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}
} // namespace aniso::bench
