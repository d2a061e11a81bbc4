// LutCache: memory hits return the same object, a new cache on the same directory reads the EXR
// files (checked independently through readImage) with values identical to a fresh bake,
// damaged, truncated, foreign or renamed files are re-baked and overwritten, an unusable
// directory degrades to memory, and concurrent requests for one key bake once.
#include "core/error.h"
#include "core/image/image.h"
#include "core/lut/lut_cache.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using aniso::AsLobe;
using aniso::LutCache;

// A fresh directory per test, removed afterwards.
class LutCacheTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("aniso-lut-cache-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir_, ec);
  }
  std::string dir() const { return dir_.string(); }

  // The one cache file whose name starts with `kind`.
  fs::path fileOf(const std::string& kind) const
  {
    std::vector<fs::path> found;
    for (const auto& entry : fs::directory_iterator(dir_))
    {
      if (entry.path().filename().string().rfind(kind + "_", 0) == 0)
      {
        found.push_back(entry.path());
      }
    }
    EXPECT_EQ(found.size(), 1u) << kind;
    return found.empty() ? fs::path() : found.front();
  }

  fs::path dir_;
};

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

const AsLobe kLobe{20000, 70};

// Second request: the same object from memory; memoryHits counts it, bakes does not.
TEST_F(LutCacheTest, SecondRequestIsAMemoryHit)
{
  LutCache cache(dir());
  EXPECT_EQ(cache.directory(), dir());
  const auto first = cache.brdf(kLobe, 16, 64);
  const auto half = cache.halfVector(kLobe, 16);
  EXPECT_EQ(cache.stats().bakes, 2u);
  EXPECT_EQ(cache.stats().memoryHits, 0u);
  EXPECT_EQ(cache.brdf(kLobe, 16, 64).get(), first.get());
  EXPECT_EQ(cache.halfVector(kLobe, 16).get(), half.get());
  EXPECT_EQ(cache.stats().memoryHits, 2u);
  EXPECT_EQ(cache.stats().bakes, 2u);
  // What the cache hands out is the baker's result.
  EXPECT_TRUE(sameBits(first->rg, aniso::bakeBrdfLut(kLobe, 16, 64).rg));
  EXPECT_TRUE(sameBits(half->rgba, aniso::bakeHalfVectorLut(kLobe, 16).rgba));
  // Every part of the key counts: another size, sample count or exponent is another LUT;
  // -0 and +0 are one exponent.
  cache.brdf(kLobe, 17, 64);
  cache.brdf(kLobe, 16, 65);
  cache.brdf({20000, 70.000000001}, 16, 64);
  EXPECT_EQ(cache.stats().bakes, 5u);
  const auto zero = cache.halfVector({0.0, 5.0}, 8);
  EXPECT_EQ(cache.halfVector({-0.0, 5.0}, 8).get(), zero.get());
}

// A new cache on the same directory reads the files (disk hits, no bake), bit-identical to a
// bake; the files are float EXRs with the LUT layout, read here through readImage.
TEST_F(LutCacheTest, NewCacheReadsFromDisk)
{
  {
    LutCache writer(dir());
    writer.brdf(kLobe, 32, 128);
    writer.halfVector(kLobe, 32);
  }
  LutCache reader(dir());
  const auto brdf = reader.brdf(kLobe, 32, 128);
  const auto half = reader.halfVector(kLobe, 32);
  EXPECT_EQ(reader.stats().diskHits, 2u);
  EXPECT_EQ(reader.stats().bakes, 0u);
  EXPECT_EQ(reader.stats().diskRejected, 0u);
  const aniso::BrdfLut bakedBrdf = aniso::bakeBrdfLut(kLobe, 32, 128);
  const aniso::HalfVectorLut bakedHalf = aniso::bakeHalfVectorLut(kLobe, 32);
  EXPECT_TRUE(sameBits(brdf->rg, bakedBrdf.rg));
  EXPECT_TRUE(sameBits(half->rgba, bakedHalf.rgba));
  EXPECT_EQ(brdf->size, 32);
  EXPECT_EQ(brdf->samples, 128);
  EXPECT_EQ(brdf->lobe.nu, kLobe.nu);
  EXPECT_EQ(half->lobe.nv, kLobe.nv);

  const aniso::Image brdfImage = aniso::readImage(fileOf("brdf").string());
  EXPECT_EQ(brdfImage.width, 32);
  EXPECT_EQ(brdfImage.height, 32);
  ASSERT_EQ(brdfImage.channels, 2);
  EXPECT_TRUE(sameBits(brdfImage.data, bakedBrdf.rg));
  const aniso::Image halfImage = aniso::readImage(fileOf("halfvector").string());
  ASSERT_EQ(halfImage.channels, 4);
  EXPECT_TRUE(sameBits(halfImage.data, bakedHalf.rgba));
  // No temporary file is left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_))
  {
    ++files;
  }
  EXPECT_EQ(files, 2);
}

// clearMemory drops the LUTs from memory; the next request is served from disk.
TEST_F(LutCacheTest, ClearMemoryFallsBackToDisk)
{
  LutCache cache(dir());
  const auto before = cache.brdf(kLobe, 16, 64);
  cache.clearMemory();
  EXPECT_EQ(cache.memoryBytes(), 0u);
  const auto after = cache.brdf(kLobe, 16, 64);
  EXPECT_NE(after.get(), before.get());
  EXPECT_EQ(cache.stats().diskHits, 1u);
  EXPECT_EQ(cache.stats().bakes, 1u);
  EXPECT_TRUE(sameBits(after->rg, before->rg));
}

// Damaged files are ignored, re-baked and overwritten: garbage, a truncated EXR, a valid EXR
// without the cache's metadata, and the file of another lobe renamed to this key.
TEST_F(LutCacheTest, DamagedOrForeignFilesAreRebaked)
{
  const aniso::BrdfLut expected = aniso::bakeBrdfLut(kLobe, 16, 64);
  {
    LutCache writer(dir());
    writer.brdf(kLobe, 16, 64);
    writer.brdf({10, 10}, 16, 64);
  }
  // The documented name: kind, format version, exponent bits in hex, size, samples.
  const fs::path target = dir_ / ("brdf_v" + std::to_string(aniso::kLutFormatVersion) +
                                  "_nu40d3880000000000_nv4051800000000000_s16_n64.exr");
  ASSERT_TRUE(fs::is_regular_file(target));
  const auto otherFile = [&]
  {
    for (const auto& entry : fs::directory_iterator(dir_))
    {
      if (entry.path() != target)
      {
        return entry.path();
      }
    }
    return fs::path();
  }();
  std::string intact;
  {
    std::ifstream in(target, std::ios::binary);
    intact.assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_GT(intact.size(), 100u);

  const auto damage = [&](const std::string& how)
  {
    if (how == "garbage")
    {
      std::ofstream(target, std::ios::binary | std::ios::trunc) << "not an EXR at all";
    }
    else if (how == "truncated")
    {
      std::ofstream(target, std::ios::binary | std::ios::trunc)
          << intact.substr(0, intact.size() / 2);
    }
    else if (how == "flipped")
    {
      // One byte changed inside the compressed pixels, past the header.
      std::string bytes = intact;
      bytes[bytes.size() - 40] = static_cast<char>(bytes[bytes.size() - 40] ^ 0x5a);
      std::ofstream(target, std::ios::binary | std::ios::trunc) << bytes;
    }
    else if (how == "foreign")
    {
      aniso::Image image(16, 16, 2);
      aniso::writeImage(target.string(), image);
    }
    else if (how == "renamed")
    {
      fs::copy_file(otherFile, target, fs::copy_options::overwrite_existing);
    }
  };
  for (const std::string how : {"garbage", "truncated", "flipped", "foreign", "renamed"})
  {
    damage(how);
    LutCache cache(dir());
    const auto lut = cache.brdf(kLobe, 16, 64);
    EXPECT_EQ(cache.stats().diskRejected, 1u) << how;
    EXPECT_EQ(cache.stats().diskHits, 0u) << how;
    EXPECT_EQ(cache.stats().bakes, 1u) << how;
    EXPECT_TRUE(sameBits(lut->rg, expected.rg)) << how;
    // The re-bake replaced the file: the next cache reads it.
    LutCache next(dir());
    EXPECT_TRUE(sameBits(next.brdf(kLobe, 16, 64)->rg, expected.rg)) << how;
    EXPECT_EQ(next.stats().diskHits, 1u) << how;
  }
}

// A cache directory that cannot be created or written still serves every request from memory.
TEST_F(LutCacheTest, UnwritableDirectoryWorksFromMemory)
{
  fs::create_directories(dir_);
  // A regular file where a directory should be: no user, root included, can create under it.
  const fs::path blocker = dir_ / "blocker";
  std::ofstream(blocker) << "x";
  LutCache cache((blocker / "aniso").string());
  const auto first = cache.brdf(kLobe, 16, 64);
  EXPECT_TRUE(sameBits(first->rg, aniso::bakeBrdfLut(kLobe, 16, 64).rg));
  EXPECT_EQ(cache.brdf(kLobe, 16, 64).get(), first.get());
  cache.halfVector(kLobe, 16);
  const aniso::LutCacheStats stats = cache.stats();
  EXPECT_EQ(stats.bakes, 2u);
  EXPECT_EQ(stats.memoryHits, 1u);
  EXPECT_EQ(stats.diskWriteFailures, 2u);
}

// A directory without write permission (for users the permission applies to) behaves the same:
// requests succeed, nothing is written.
TEST_F(LutCacheTest, ReadOnlyDirectoryWorksFromMemory)
{
  fs::create_directories(dir_);
  fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
  LutCache cache(dir());
  const auto lut = cache.halfVector(kLobe, 16);
  EXPECT_TRUE(sameBits(lut->rgba, aniso::bakeHalfVectorLut(kLobe, 16).rgba));
  EXPECT_EQ(cache.halfVector(kLobe, 16).get(), lut.get());
  EXPECT_EQ(cache.stats().bakes, 1u);
  if (::geteuid() != 0) // permissions do not bind root
  {
    EXPECT_EQ(cache.stats().diskWriteFailures, 1u);
  }
}

// "none": memory only, nothing on disk, directory() empty.
TEST_F(LutCacheTest, NoneKeepsEverythingInMemory)
{
  LutCache cache("none");
  EXPECT_TRUE(cache.directory().empty());
  cache.brdf(kLobe, 8, 16);
  cache.brdf(kLobe, 8, 16);
  EXPECT_EQ(cache.stats().bakes, 1u);
  EXPECT_EQ(cache.stats().memoryHits, 1u);
  EXPECT_EQ(cache.stats().diskWriteFailures, 0u);
  EXPECT_FALSE(fs::exists(dir_));
}

// Default directory per the XDG base directory specification: $XDG_CACHE_HOME/aniso when it is
// absolute, else $HOME/.cache/aniso.
TEST_F(LutCacheTest, DefaultDirectoryFollowsXdg)
{
  const char* savedXdg = std::getenv("XDG_CACHE_HOME");
  const std::string saved = savedXdg ? savedXdg : "";
  const char* home = std::getenv("HOME");
  ::setenv("XDG_CACHE_HOME", dir().c_str(), 1);
  EXPECT_EQ(LutCache().directory(), (dir_ / "aniso").string());
  ::setenv("XDG_CACHE_HOME", "relative/path", 1);
  if (home && home[0] == '/')
  {
    EXPECT_EQ(LutCache().directory(), (fs::path(home) / ".cache" / "aniso").string());
  }
  if (savedXdg)
  {
    ::setenv("XDG_CACHE_HOME", saved.c_str(), 1);
  }
  else
  {
    ::unsetenv("XDG_CACHE_HOME");
  }
}

// Eight threads asking for one key at the same moment: one bake, seven memory hits, one
// object. Holds for any schedule: a thread arriving after the bake finished is a memory hit too.
TEST_F(LutCacheTest, ConcurrentRequestsBakeOnce)
{
  LutCache cache(dir());
  constexpr int kThreads = 8;
  std::vector<std::shared_ptr<const aniso::BrdfLut>> results(kThreads);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int k = 0; k < kThreads; ++k)
  {
    threads.emplace_back(
        [&, k]
        {
          ++ready;
          while (ready.load() < kThreads)
          {
            std::this_thread::yield();
          }
          results[k] = cache.brdf(kLobe, 64, 2048);
        });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  EXPECT_EQ(cache.stats().bakes, 1u);
  EXPECT_EQ(cache.stats().memoryHits, unsigned(kThreads - 1));
  for (const auto& r : results)
  {
    EXPECT_EQ(r.get(), results.front().get());
  }
}

// Past the memory budget the least recently used LUT is dropped (holders keep theirs alive);
// the one just made stays even alone over budget.
TEST_F(LutCacheTest, MemoryBudgetDropsLeastRecentlyUsed)
{
  LutCache cache("none");
  const auto a = cache.brdf(kLobe, 32, 16); // 8 KiB of pixels
  const std::size_t one = cache.memoryBytes();
  EXPECT_GE(one, 32u * 32u * 2u * sizeof(float));
  cache.setMemoryBudget(2 * one + one / 2);
  cache.brdf({10, 10}, 32, 16);
  cache.brdf(kLobe, 32, 16); // a used again: (10, 10) is now the oldest
  cache.brdf({100, 100}, 32, 16);
  EXPECT_EQ(cache.memoryBytes(), 2 * one);
  EXPECT_EQ(cache.stats().bakes, 3u);
  EXPECT_EQ(cache.brdf(kLobe, 32, 16).get(), a.get()); // kept
  cache.brdf({10, 10}, 32, 16);                        // dropped: baked again
  EXPECT_EQ(cache.stats().bakes, 4u);
  cache.setMemoryBudget(0);
  EXPECT_EQ(cache.memoryBytes(), 0u);
  EXPECT_EQ(a->size, 32); // still alive in its holder
  cache.brdf(kLobe, 32, 16);
  EXPECT_EQ(cache.memoryBytes(), one); // the newest is kept although over budget
}

// The disk budget: files are removed least recently used first (a disk hit is a use), only the
// cache's own LUT files count and go (older format versions included), a stale temporary file of
// a dead writer goes while a fresh one stays, other files are never touched, and the file just
// written stays even when it alone exceeds the budget.
TEST_F(LutCacheTest, DiskBudgetRemovesLeastRecentlyUsedFiles)
{
  const auto now = fs::file_time_type::clock::now();
  auto age = [&](const fs::path& path, int hours)
  { fs::last_write_time(path, now - std::chrono::hours(hours)); };
  auto write = [&](const std::string& name, int hours)
  {
    std::ofstream(dir_ / name) << "not a cache file of this version";
    age(dir_ / name, hours);
    return dir_ / name;
  };
  {
    LutCache writer(dir());
    writer.brdf({10, 10}, 32, 16);
    writer.brdf({20, 20}, 32, 16);
  }
  const fs::path a = fileOf("brdf_v1_nu4024000000000000"); // n_u = 10
  const fs::path b = fileOf("brdf_v1_nu4034000000000000"); // n_u = 20
  age(a, 3);
  age(b, 2);
  const fs::path old = write("brdf_v0_old.exr", 5);
  const fs::path foreign = write("notes.txt", 6);
  const fs::path staleTemp = write(".brdf_v1_x.exr.99.0.tmp.exr", 2);
  const fs::path freshTemp = write(".brdf_v1_y.exr.99.1.tmp.exr", 0);

  LutCache cache(dir());
  cache.brdf({10, 10}, 32, 16); // a disk hit: a is now the most recently used
  EXPECT_EQ(cache.stats().diskHits, 1u);
  cache.brdf({30, 30}, 32, 16); // c, written now
  const fs::path c = fileOf("brdf_v1_nu403e000000000000");
  EXPECT_EQ(cache.stats().diskEvictions, 0u); // the default budget holds all of them
  const std::uintmax_t budget = fs::file_size(a) + fs::file_size(c) + fs::file_size(b) / 2;
  cache.setDiskBudget(budget);
  // Oldest first: the old-version file, then b; a (used) and c (newest) fit the budget.
  EXPECT_FALSE(fs::exists(old));
  EXPECT_FALSE(fs::exists(b));
  EXPECT_TRUE(fs::exists(a));
  EXPECT_TRUE(fs::exists(c));
  EXPECT_EQ(cache.stats().diskEvictions, 2u);
  EXPECT_TRUE(fs::exists(foreign));
  EXPECT_FALSE(fs::exists(staleTemp));
  EXPECT_TRUE(fs::exists(freshTemp));

  // Nothing fits: every LUT file goes, but a file just written stays.
  cache.setDiskBudget(0);
  EXPECT_FALSE(fs::exists(a));
  EXPECT_FALSE(fs::exists(c));
  cache.halfVector({40, 40}, 16);
  EXPECT_TRUE(fs::exists(fileOf("halfvector")));
  EXPECT_EQ(cache.stats().diskEvictions, 4u);
  EXPECT_TRUE(fs::exists(foreign));
}

// Invalid inputs throw the bakers' errors and leave the cache usable and unchanged.
TEST_F(LutCacheTest, InvalidInputsThrowAndLeaveTheCacheUsable)
{
  LutCache cache(dir());
  EXPECT_THROW(cache.brdf(kLobe, 1, 64), aniso::Error);
  EXPECT_THROW(cache.brdf(kLobe, 16, 0), aniso::Error);
  EXPECT_THROW(cache.halfVector({-3.0, 1.0}, 16), aniso::Error);
  EXPECT_THROW(cache.halfVector({1.0, std::nan("")}, 16), aniso::Error);
  const aniso::LutCacheStats stats = cache.stats();
  EXPECT_EQ(stats.bakes + stats.memoryHits + stats.diskHits, 0u);
  EXPECT_FALSE(fs::exists(dir_));
  EXPECT_NO_THROW(cache.brdf(kLobe, 16, 64));
  EXPECT_EQ(cache.stats().bakes, 1u);
}
} // namespace
