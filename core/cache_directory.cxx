#include "core/cache_directory.h"

#include <cstdlib>
#include <filesystem>

namespace aniso
{
std::string defaultCacheDirectory()
{
  namespace fs = std::filesystem;
  // XDG: a relative XDG_CACHE_HOME is invalid and must be ignored.
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && xdg[0] == '/')
  {
    return (fs::path(xdg) / "aniso").string();
  }
  const char* home = std::getenv("HOME");
  if (home && home[0] == '/')
  {
    return (fs::path(home) / ".cache" / "aniso").string();
  }
  return {};
}
} // namespace aniso
