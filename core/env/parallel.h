#pragma once
// A minimal parallel loop for the environment bakes and the reference integrator: indices are
// handed out one at a time to the hardware threads, each index runs exactly once, so callers
// that write one result per index stay deterministic whatever the thread count.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace aniso
{
// Calls fn(i) for i in [0, count). Runs serially when count < 2 * minPerThread or only one
// hardware thread exists. The first exception thrown by fn is rethrown after all threads stop.
template <class Fn>
void parallelFor(int count, const Fn& fn, int minPerThread = 1)
{
  if (count <= 0)
    return;
  const int hardware = int(std::max(1u, std::thread::hardware_concurrency()));
  const int wanted = std::min(hardware, count / std::max(1, minPerThread));
  if (wanted <= 1)
  {
    for (int i = 0; i < count; ++i)
      fn(i);
    return;
  }
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto worker = [&]()
  {
    try
    {
      for (int i = next.fetch_add(1); i < count; i = next.fetch_add(1))
        fn(i);
    }
    catch (...)
    {
      next.store(count); // stop handing out work
      std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure)
        failure = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(std::size_t(wanted - 1));
  for (int t = 1; t < wanted; ++t)
  {
    try
    {
      pool.emplace_back(worker);
    }
    catch (const std::system_error&)
    {
      break; // fewer threads than hoped: the remaining ones (and this one) finish the work
    }
  }
  worker();
  for (std::thread& thread : pool)
    thread.join();
  if (failure)
    std::rethrow_exception(failure);
}
} // namespace aniso
