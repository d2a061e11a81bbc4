#pragma once
// What failed, in words, of work whose failure is reported rather than thrown on (a load on a
// worker thread, an upload to the GL).
#include "core/error.h"

#include <QString>
#include <functional>
#include <new>

namespace aniso
{
// Runs WORK: empty when it succeeded, else the message of the aniso::Error it threw, or
// OUT_OF_MEMORY when memory ran out.
inline QString failureOf(const std::function<void()>& work, const QString& outOfMemory)
{
  try
  {
    work();
  }
  catch (const Error& e)
  {
    return QString::fromStdString(e.what());
  }
  catch (const std::bad_alloc&)
  {
    return outOfMemory;
  }
  return QString();
}
} // namespace aniso
