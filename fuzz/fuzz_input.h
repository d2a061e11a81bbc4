#pragma once
// What every harness shares: the readers under test take a path, so each input is written to a
// file of this process's own (in TMPDIR) and read back from there; and the one outcome a
// harness accepts besides success, aniso::Error (the file's name and a reason).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace aniso::fuzz
{
// Writes DATA to a per-process file ending in SUFFIX and returns its path.
inline std::string writeInput(const uint8_t* data, size_t size, const std::string& suffix)
{
  const char* dir = std::getenv("TMPDIR");
  const std::string path = std::string(dir && *dir ? dir : "/tmp") + "/aniso-fuzz-" +
                           std::to_string(static_cast<long>(getpid())) + suffix;
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    std::perror(path.c_str());
    std::abort();
  }
  if (size > 0 && std::fwrite(data, 1, size, file) != size)
  {
    std::perror(path.c_str());
    std::abort();
  }
  std::fclose(file);
  return path;
}
} // namespace aniso::fuzz
