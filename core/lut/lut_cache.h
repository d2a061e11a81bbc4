#pragma once
// Memory + disk cache of baked LUTs keyed by their inputs. Disk: $XDG_CACHE_HOME/aniso
// (or ~/.cache/aniso), EXR files written atomically; a corrupt or foreign file is ignored and
// re-baked. Thread-safe. Asking twice for the same inputs costs a map lookup.
#include "core/cache_directory.h"
#include "core/lut/lut.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace aniso
{
// Part of every cache key and file: a change of what a LUT holds (encoding, definition,
// layout) bumps it, so files written by older builds are never mistaken for current ones.
constexpr int kLutFormatVersion = 1;

struct LutCacheStats
{
  uint64_t memoryHits = 0;        // served from memory (or from a bake another caller started)
  uint64_t diskHits = 0;          // read from a valid cache file
  uint64_t bakes = 0;             // computed
  uint64_t diskRejected = 0;      // cache files ignored: unreadable, truncated, foreign, corrupt
  uint64_t diskWriteFailures = 0; // bakes that could not be stored (the cache keeps working)
  uint64_t diskEvictions = 0;     // cache files removed to keep the directory within its budget
};

// Key: kind, kLutFormatVersion, the exact bits of n_u and n_v, size and (BRDF) samples.
// File names carry the key (e.g. brdf_v1_nu<16 hex digits>_nv<...>_s64_n1024.exr) and the EXR
// header repeats it with a checksum of the pixels, so a renamed, foreign or damaged file is
// detected. Disk problems never fail a request: the cache falls back to memory.
// The directory is kept within a disk budget: after each write, the cache's own LUT files
// (never anything else in the directory) are removed least recently used first, where a disk hit
// counts as a use (it renews the file's modification time), until the budget holds; the file
// just written always stays. Temporary files left by a writer that died are removed after an
// hour.
class LutCache
{
public:
  // directory empty: the XDG default ($XDG_CACHE_HOME/aniso if XDG_CACHE_HOME is an absolute
  // path, else $HOME/.cache/aniso, else memory only); "none": memory only; else that directory
  // (created on first write).
  explicit LutCache(std::string directory = {});
  ~LutCache();
  LutCache(const LutCache&) = delete;
  LutCache& operator=(const LutCache&) = delete;

  // Invalid inputs throw aniso::Error as the bakers do (checkLutInputs).
  // cancel: as for the bakers; a set flag makes the call throw BakeCancelled and stores
  // nothing. A caller waiting for the same LUT from a bake that was cancelled makes it itself
  // (unless its own flag is set too).
  std::shared_ptr<const HalfVectorLut> halfVector(const AsLobe& lobe, int size,
                                                  const std::atomic<bool>* cancel = nullptr);
  std::shared_ptr<const BrdfLut> brdf(const AsLobe& lobe, int size, int samples,
                                      const std::atomic<bool>* cancel = nullptr);

  LutCacheStats stats() const;
  // The directory in use; empty when the cache is memory only.
  const std::string& directory() const;
  void clearMemory();

  // LUTs kept in memory beyond this many bytes are dropped, least recently used first (callers
  // holding one keep it alive). A LUT just made is kept even if it alone exceeds the budget.
  static constexpr std::size_t kDefaultMemoryBudget = std::size_t(256) << 20;
  void setMemoryBudget(std::size_t bytes);
  std::size_t memoryBytes() const;

  // Bytes of LUT files the directory may hold (see above); applied at once and after each write.
  static constexpr std::uintmax_t kDefaultDiskBudget = std::uintmax_t(512) << 20;
  void setDiskBudget(std::uintmax_t bytes);

  static LutCache& shared(); // process-wide instance on the default directory

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace aniso
