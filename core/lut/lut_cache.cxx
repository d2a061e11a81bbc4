#include "core/lut/lut_cache.h"

#include "core/hash.h"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <future>
#include <limits>
#include <map>
#include <mutex>
#include <tuple>
#include <type_traits>
#include <unistd.h>
#include <utility>
#include <vector>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

enum class Kind
{
  HalfVector,
  Brdf
};

struct Key
{
  Kind kind = Kind::HalfVector;
  uint64_t nu = 0;
  uint64_t nv = 0;
  int size = 0;
  int samples = 0;

  bool operator<(const Key& o) const
  {
    return std::tie(kind, nu, nv, size, samples) < std::tie(o.kind, o.nu, o.nv, o.size, o.samples);
  }
};

// -0 and +0 bake the same LUT, so they share a key.
uint64_t exactBits(double x)
{
  const double normalised = x + 0.0;
  uint64_t bits = 0;
  std::memcpy(&bits, &normalised, sizeof bits);
  return bits;
}

Key keyOf(Kind kind, const AsLobe& lobe, int size, int samples)
{
  return {kind, exactBits(lobe.nu), exactBits(lobe.nv), size, samples};
}

const char* kindName(Kind kind)
{
  return kind == Kind::HalfVector ? "halfvector" : "brdf";
}

std::string fileName(const Key& key)
{
  std::string name = std::string(kindName(key.kind)) + "_v" + std::to_string(kLutFormatVersion) +
                     "_nu" + hex16(key.nu) + "_nv" + hex16(key.nv) + "_s" +
                     std::to_string(key.size);
  if (key.kind == Kind::Brdf)
  {
    name += "_n" + std::to_string(key.samples);
  }
  return name + ".exr";
}

// FNV-1a over the pixel bytes: detects damaged files that still decode.
uint64_t checksum(const std::vector<float>& pixels)
{
  return fnv1a(pixels.data(), pixels.size() * sizeof(float));
}

// What each LUT type stores and how its file names its channels.
int channelsOf(Kind kind)
{
  return kind == Kind::HalfVector ? 4 : 2;
}
std::vector<float>& pixelsOf(HalfVectorLut& lut)
{
  return lut.rgba;
}
std::vector<float>& pixelsOf(BrdfLut& lut)
{
  return lut.rg;
}
const std::vector<float>& pixelsOf(const HalfVectorLut& lut)
{
  return lut.rgba;
}
const std::vector<float>& pixelsOf(const BrdfLut& lut)
{
  return lut.rg;
}

enum class DiskResult
{
  Absent,
  Rejected,
  Loaded
};

// Reads the file of `key` into `pixels` if it is a complete, intact LUT of exactly that key.
DiskResult readLutFile(const std::string& path, const Key& key, std::vector<float>& pixels)
{
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
  {
    return fs::exists(path, ec) ? DiskResult::Rejected : DiskResult::Absent;
  }
  auto input = OIIO::ImageInput::open(path);
  if (!input)
  {
    OIIO::geterror(); // clear this thread's pending message: the failure is handled here
    return DiskResult::Rejected;
  }
  const OIIO::ImageSpec& spec = input->spec();
  const int channels = channelsOf(key.kind);
  const bool shapeMatches = spec.width == key.size && spec.height == key.size && spec.depth == 1 &&
                            spec.nchannels == channels && spec.format == OIIO::TypeDesc::FLOAT &&
                            spec.channelformats.empty();
  const bool keyMatches = spec.get_string_attribute("aniso:kind") == kindName(key.kind) &&
                          spec.get_int_attribute("aniso:formatVersion", -1) == kLutFormatVersion &&
                          spec.get_string_attribute("aniso:nu") == hex16(key.nu) &&
                          spec.get_string_attribute("aniso:nv") == hex16(key.nv) &&
                          spec.get_int_attribute("aniso:size", -1) == key.size &&
                          spec.get_int_attribute("aniso:samples", -1) == key.samples;
  if (!shapeMatches || !keyMatches)
  {
    return DiskResult::Rejected;
  }
  std::vector<float> data(std::size_t(key.size) * key.size * channels);
  const bool read = input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data());
  input->geterror();
  input->close();
  if (!read || spec.get_string_attribute("aniso:checksum") != hex16(checksum(data)))
  {
    return DiskResult::Rejected;
  }
  for (float x : data)
  {
    if (!std::isfinite(x))
    {
      return DiskResult::Rejected;
    }
  }
  pixels = std::move(data);
  return DiskResult::Loaded;
}

// Writes to a temporary file in the same directory and renames it over the final name, so a
// reader (this process or another) never sees a partial file.
bool writeLutFile(const std::string& directory, const Key& key, const AsLobe& lobe,
                  const std::vector<float>& pixels)
{
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec && !fs::is_directory(directory))
  {
    return false;
  }
  static std::atomic<uint64_t> counter{0};
  const std::string name = fileName(key);
  const fs::path finalPath = fs::path(directory) / name;
  const fs::path tempPath = fs::path(directory) / ("." + name + "." + std::to_string(::getpid()) +
                                                   "." + std::to_string(counter++) + ".tmp.exr");
  const int channels = channelsOf(key.kind);
  OIIO::ImageSpec spec(key.size, key.size, channels, OIIO::TypeDesc::FLOAT);
  spec.channelnames = channels == 4 ? std::vector<std::string>{"R", "G", "B", "A"}
                                    : std::vector<std::string>{"R", "G"};
  spec.attribute("compression", "zip");
  spec.attribute("aniso:kind", kindName(key.kind));
  spec.attribute("aniso:formatVersion", kLutFormatVersion);
  spec.attribute("aniso:nu", hex16(key.nu));
  spec.attribute("aniso:nv", hex16(key.nv));
  spec.attribute("aniso:size", key.size);
  spec.attribute("aniso:samples", key.samples);
  spec.attribute("aniso:lobe", "nu=" + std::to_string(lobe.nu) + " nv=" + std::to_string(lobe.nv));
  spec.attribute("aniso:checksum", hex16(checksum(pixels)));

  auto output = OIIO::ImageOutput::create("openexr");
  bool ok = output && output->open(tempPath.string(), spec) &&
            output->write_image(OIIO::TypeDesc::FLOAT, pixels.data());
  if (output)
  {
    ok = output->close() && ok;
    output->geterror();
  }
  OIIO::geterror();
  if (ok)
  {
    fs::rename(tempPath, finalPath, ec);
    ok = !ec;
  }
  if (!ok)
  {
    fs::remove(tempPath, ec);
  }
  return ok;
}

// Disk trouble of any kind, exceptions from the file system or the EXR library included, only
// costs a bake: it never reaches the caller.
DiskResult readLutFileSafely(const std::string& path, const Key& key, std::vector<float>& pixels)
{
  try
  {
    return readLutFile(path, key, pixels);
  }
  catch (const std::exception&)
  {
    return DiskResult::Rejected;
  }
}

bool writeLutFileSafely(const std::string& directory, const Key& key, const AsLobe& lobe,
                        const std::vector<float>& pixels)
{
  try
  {
    return writeLutFile(directory, key, lobe, pixels);
  }
  catch (const std::exception&)
  {
    return false;
  }
}

bool startsWith(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0;
}

bool endsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The cache's own files: LUTs of any format version, and temporary files of their writers
// ("." + LUT file name + ".PID.COUNTER.tmp.exr").
bool hasLutPrefix(const std::string& name)
{
  return startsWith(name, "halfvector_v") || startsWith(name, "brdf_v");
}

bool isLutFile(const std::string& name)
{
  return hasLutPrefix(name) && endsWith(name, ".exr") && !endsWith(name, ".tmp.exr");
}

bool isTemporaryFile(const std::string& name)
{
  return name.size() > 1 && name[0] == '.' && hasLutPrefix(name.substr(1)) &&
         endsWith(name, ".tmp.exr");
}

// Removes LUT files of DIRECTORY, least recently used first, until they take at most BUDGET
// bytes, never KEEP; and temporary files older than an hour (their writer died: a live one
// renames or removes its file within seconds). Returns how many LUT files it removed. Every
// file system error only skips the file concerned.
uint64_t pruneDirectory(const std::string& directory, std::uintmax_t budget,
                        const std::string& keep)
{
  struct File
  {
    fs::path path;
    std::uintmax_t size = 0;
    fs::file_time_type time;
  };
  std::vector<File> files;
  std::uintmax_t total = 0;
  const auto now = fs::file_time_type::clock::now();
  std::error_code ec;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec))
  {
    const std::string name = it->path().filename().string();
    std::error_code fileError;
    if (!it->is_regular_file(fileError) || fileError)
    {
      continue;
    }
    const fs::file_time_type time = fs::last_write_time(it->path(), fileError);
    if (fileError)
    {
      continue;
    }
    if (isTemporaryFile(name))
    {
      if (now - time > std::chrono::hours(1))
      {
        fs::remove(it->path(), fileError);
      }
      continue;
    }
    if (!isLutFile(name))
    {
      continue;
    }
    const std::uintmax_t size = fs::file_size(it->path(), fileError);
    if (fileError)
    {
      continue;
    }
    total += size;
    if (name != keep)
    {
      files.push_back({it->path(), size, time});
    }
  }
  std::sort(files.begin(), files.end(),
            [](const File& a, const File& b) { return a.time < b.time; });
  uint64_t removed = 0;
  for (const File& file : files)
  {
    if (total <= budget)
    {
      break;
    }
    std::error_code removeError;
    if (fs::remove(file.path, removeError))
    {
      total -= file.size;
      ++removed;
    }
  }
  return removed;
}

uint64_t pruneDirectorySafely(const std::string& directory, std::uintmax_t budget,
                              const std::string& keep)
{
  try
  {
    return pruneDirectory(directory, budget, keep);
  }
  catch (const std::exception&)
  {
    return 0;
  }
}

// A disk hit is a use: the file moves to the back of the eviction order.
void touch(const std::string& path)
{
  std::error_code ec;
  fs::last_write_time(path, fs::file_time_type::clock::now(), ec);
}

template <class Lut>
struct Entry
{
  std::shared_future<std::shared_ptr<const Lut>> future;
  std::size_t bytes = 0; // 0 while the LUT is being made
  uint64_t lastUse = 0;
};

template <class Lut>
using EntryMap = std::map<Key, std::shared_ptr<Entry<Lut>>>;

enum class Source
{
  Disk,
  Bake
};
} // namespace

struct LutCache::Impl
{
  std::string directory;
  mutable std::mutex mutex;
  EntryMap<HalfVectorLut> halfVectors;
  EntryMap<BrdfLut> brdfs;
  LutCacheStats stats;
  uint64_t tick = 0;
  std::size_t bytes = 0;
  std::size_t budget = kDefaultMemoryBudget;
  std::atomic<std::uintmax_t> diskBudget{kDefaultDiskBudget};

  // One caller makes a missing LUT (disk or bake) outside the lock; callers asking for the same
  // key meanwhile wait for its result instead of baking it again.
  template <class Lut, class Make>
  std::shared_ptr<const Lut> get(EntryMap<Lut>& map, const Key& key, const AsLobe& lobe,
                                 const Make& make, const std::atomic<bool>* cancel)
  {
    std::unique_lock<std::mutex> lock(mutex);
    auto found = map.find(key);
    while (found != map.end())
    {
      std::shared_ptr<Entry<Lut>> entry = found->second;
      entry->lastUse = ++tick;
      lock.unlock();
      try
      {
        std::shared_ptr<const Lut> lut = entry->future.get();
        lock.lock();
        ++stats.memoryHits;
        return lut;
      }
      catch (const BakeCancelled&)
      {
        // The caller making it gave up (its entry is gone already); this one did not.
        if (cancel && cancel->load())
        {
          throw;
        }
        lock.lock();
        found = map.find(key);
      }
    }
    std::promise<std::shared_ptr<const Lut>> promise;
    auto entry = std::make_shared<Entry<Lut>>();
    entry->future = promise.get_future().share();
    entry->lastUse = ++tick;
    map.emplace(key, entry);
    lock.unlock();

    std::shared_ptr<const Lut> lut;
    Source source = Source::Bake;
    bool rejected = false;
    bool writeFailed = false;
    uint64_t evicted = 0;
    try
    {
      auto made = std::make_shared<Lut>();
      if (!directory.empty())
      {
        const std::string path = (fs::path(directory) / fileName(key)).string();
        const DiskResult result = readLutFileSafely(path, key, pixelsOf(*made));
        rejected = result == DiskResult::Rejected;
        if (result == DiskResult::Loaded)
        {
          source = Source::Disk;
          describe(*made, key, lobe);
          touch(path);
        }
      }
      if (source == Source::Bake)
      {
        *made = make();
        writeFailed =
            !directory.empty() && !writeLutFileSafely(directory, key, made->lobe, pixelsOf(*made));
        if (!directory.empty() && !writeFailed)
        {
          evicted = pruneDirectorySafely(directory, diskBudget.load(), fileName(key));
        }
      }
      lut = std::move(made);
    }
    catch (...)
    {
      // Erased before waiters wake, so a waiter that retries never finds this entry again.
      lock.lock();
      auto current = map.find(key);
      if (current != map.end() && current->second == entry)
      {
        map.erase(current);
      }
      lock.unlock();
      promise.set_exception(std::current_exception());
      throw;
    }
    promise.set_value(lut);

    lock.lock();
    ++(source == Source::Disk ? stats.diskHits : stats.bakes);
    stats.diskRejected += rejected ? 1 : 0;
    stats.diskWriteFailures += writeFailed ? 1 : 0;
    stats.diskEvictions += evicted;
    auto current = map.find(key);
    if (current != map.end() && current->second == entry)
    {
      entry->bytes = sizeof(Lut) + pixelsOf(*lut).size() * sizeof(float);
      bytes += entry->bytes;
      evict(entry.get());
    }
    return lut;
  }

  // A LUT read from disk carries the inputs its file was validated against.
  template <class Lut>
  static void describe(Lut& lut, const Key& key, const AsLobe& lobe)
  {
    lut.size = key.size;
    lut.lobe = lobe;
    if constexpr (std::is_same_v<Lut, BrdfLut>)
    {
      lut.samples = key.samples;
    }
  }

  // Drops least recently used ready LUTs until the budget holds, never `keep`.
  void evict(const void* keep)
  {
    while (bytes > budget)
    {
      uint64_t oldest = std::numeric_limits<uint64_t>::max();
      auto pick = [&](auto& map, auto& victim)
      {
        for (auto it = map.begin(); it != map.end(); ++it)
        {
          if (it->second.get() != keep && it->second->bytes > 0 && it->second->lastUse < oldest)
          {
            oldest = it->second->lastUse;
            victim = it;
          }
        }
      };
      auto halfVictim = halfVectors.end();
      auto brdfVictim = brdfs.end();
      pick(halfVectors, halfVictim);
      pick(brdfs, brdfVictim);
      if (brdfVictim != brdfs.end() && brdfVictim->second->lastUse == oldest)
      {
        bytes -= brdfVictim->second->bytes;
        brdfs.erase(brdfVictim);
      }
      else if (halfVictim != halfVectors.end())
      {
        bytes -= halfVictim->second->bytes;
        halfVectors.erase(halfVictim);
      }
      else
      {
        return;
      }
    }
  }

  template <class Lut>
  void dropReady(EntryMap<Lut>& map)
  {
    for (auto it = map.begin(); it != map.end();)
    {
      if (it->second->bytes > 0)
      {
        bytes -= it->second->bytes;
        it = map.erase(it);
      }
      else
      {
        ++it;
      }
    }
  }
};

LutCache::LutCache(std::string directory) : impl_(std::make_unique<Impl>())
{
  if (directory == "none")
  {
    directory.clear();
  }
  else if (directory.empty())
  {
    directory = defaultCacheDirectory();
  }
  impl_->directory = std::move(directory);
}

LutCache::~LutCache() = default;

std::shared_ptr<const HalfVectorLut> LutCache::halfVector(const AsLobe& lobe, int size,
                                                          const std::atomic<bool>* cancel)
{
  checkLutInputs(lobe, size);
  return impl_->get(
      impl_->halfVectors, keyOf(Kind::HalfVector, lobe, size, 0), lobe,
      [&] { return bakeHalfVectorLut(lobe, size, 0, cancel); }, cancel);
}

std::shared_ptr<const BrdfLut> LutCache::brdf(const AsLobe& lobe, int size, int samples,
                                              const std::atomic<bool>* cancel)
{
  checkLutInputs(lobe, size, samples);
  return impl_->get(
      impl_->brdfs, keyOf(Kind::Brdf, lobe, size, samples), lobe,
      [&] { return bakeBrdfLut(lobe, size, samples, 0, cancel); }, cancel);
}

LutCacheStats LutCache::stats() const
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->stats;
}

const std::string& LutCache::directory() const
{
  return impl_->directory;
}

void LutCache::clearMemory()
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->dropReady(impl_->halfVectors);
  impl_->dropReady(impl_->brdfs);
}

void LutCache::setMemoryBudget(std::size_t bytes)
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->budget = bytes;
  impl_->evict(nullptr);
}

void LutCache::setDiskBudget(std::uintmax_t bytes)
{
  impl_->diskBudget = bytes;
  if (!impl_->directory.empty())
  {
    const uint64_t evicted = pruneDirectorySafely(impl_->directory, bytes, {});
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->stats.diskEvictions += evicted;
  }
}

std::size_t LutCache::memoryBytes() const
{
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->bytes;
}

LutCache& LutCache::shared()
{
  static LutCache cache;
  return cache;
}
} // namespace aniso
