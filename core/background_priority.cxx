#include "core/background_priority.h"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace aniso
{
void lowerThreadPriority()
{
#if defined(__linux__)
  // On Linux a thread's nice value is its own (setpriority with its thread id), unlike POSIX's
  // per-process value. A failure leaves the priority as it was: nothing to report.
  const auto tid = static_cast<id_t>(syscall(SYS_gettid));
  const int current = getpriority(PRIO_PROCESS, tid);
  if (current < kBackgroundNice)
  {
    (void)setpriority(PRIO_PROCESS, tid, kBackgroundNice);
  }
#endif
}
} // namespace aniso
