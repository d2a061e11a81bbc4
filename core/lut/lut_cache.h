#pragma once
// Memory + disk cache of baked LUTs keyed by their inputs. Disk: $XDG_CACHE_HOME/aniso
// (or ~/.cache/aniso), EXR files written atomically; a corrupt or foreign file is ignored and
// re-baked. Thread-safe. Asking twice for the same inputs costs a map lookup.
#include <cstdint>
#include <memory>
#include <string>

#include "lut/lut.h"

namespace aniso
{
struct LutCacheStats
{
  uint64_t memoryHits = 0;
  uint64_t diskHits = 0;
  uint64_t bakes = 0;
};

class LutCache
{
public:
  // directory empty: the XDG default; "none": memory only.
  explicit LutCache(std::string directory = {});
  ~LutCache();
  LutCache(const LutCache&) = delete;
  LutCache& operator=(const LutCache&) = delete;

  std::shared_ptr<const HalfVectorLut> halfVector(const AsLobe& lobe, int size);
  std::shared_ptr<const BrdfLut> brdf(const AsLobe& lobe, int size, int samples);

  LutCacheStats stats() const;
  const std::string& directory() const;
  void clearMemory();

  static LutCache& shared(); // process-wide instance on the default directory

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace aniso
