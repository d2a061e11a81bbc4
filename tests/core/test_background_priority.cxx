// Background work yields the cores (background_priority.h): on Linux the calling thread's nice
// value becomes kBackgroundNice, read back by getpriority for that thread id; a thread it starts
// afterwards inherits it; another thread (the test's own) keeps its value; calling it twice
// leaves it so.
#include "core/background_priority.h"

#include <gtest/gtest.h>
#include <thread>
#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace aniso
{
namespace
{
#if defined(__linux__)
int niceOfThisThread()
{
  return getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
}

TEST(BackgroundPriority, LowersTheCallingThreadAndWhatItStarts)
{
  const int mine = niceOfThisThread();
  ASSERT_LT(mine, kBackgroundNice) << "the test must start at a nice value below the background's";
  int lowered = -100;
  int loweredAgain = -100;
  int child = -100;
  std::thread worker(
      [&]
      {
        lowerThreadPriority();
        lowered = niceOfThisThread();
        lowerThreadPriority();
        loweredAgain = niceOfThisThread();
        std::thread started([&] { child = niceOfThisThread(); });
        started.join();
      });
  worker.join();
  EXPECT_EQ(lowered, kBackgroundNice);
  EXPECT_EQ(loweredAgain, kBackgroundNice);
  EXPECT_EQ(child, kBackgroundNice);
  EXPECT_EQ(niceOfThisThread(), mine);
}
#endif
} // namespace
} // namespace aniso
