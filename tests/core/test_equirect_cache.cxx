// cachedEquirectRefined: a built-in environment's image read back from the cache directory is
// bitwise the image renderEquirectRefined computes, and reading it evaluates the radiance only
// for the fingerprint (64 directions, against the 130 000-odd of the sampling); a damaged,
// truncated or foreign file is sampled anew and replaced; a changed radiance under the same key
// is not served the old image; environments that are not built in, an empty directory and one
// that cannot be written are sampled every time, with the same result.
#include "core/env/env_sampling.h"
#include "core/env/environment.h"
#include "core/env/equirect_cache.h"
#include "core/image/image.h"

#include <atomic>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;
using aniso::Image;

// The built-in studio's radiance under a key of the caller's, counting its evaluations; `tint`
// changes the function without changing the key.
class CountingEnvironment : public aniso::Environment
{
public:
  explicit CountingEnvironment(std::string key, double tint = 1.0)
      : key_(std::move(key)), tint_(tint)
  {
  }
  glm::dvec3 radiance(const glm::dvec3& d) const override
  {
    ++calls;
    return tint_ * studio_.radiance(d);
  }
  std::string key() const override { return key_; }
  mutable std::atomic<long> calls{0};

private:
  aniso::StudioEnvironment studio_;
  std::string key_;
  double tint_;
};

constexpr int kWidth = 128;
constexpr int kHeight = 64;
constexpr int kSupersample = 4;

class EquirectCache : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("aniso-equirect-cache-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Image cached(const aniso::Environment& env) const
  {
    return aniso::cachedEquirectRefined(env, kWidth, kHeight, kSupersample, dir_.string());
  }
  // The one file the cache holds.
  fs::path onlyFile() const
  {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir_ / "env"))
    {
      files.push_back(entry.path());
    }
    EXPECT_EQ(files.size(), 1u);
    return files.empty() ? fs::path() : files.front();
  }

  fs::path dir_;
};

void expectSameImage(const Image& a, const Image& b)
{
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.channels, b.channels);
  EXPECT_EQ(a.data, b.data); // bitwise: the file holds the computed floats
}

TEST_F(EquirectCache, ReadsBackTheComputedImageWithoutSamplingAgain)
{
  CountingEnvironment env("builtin:counting");
  const Image reference = aniso::renderEquirectRefined(env, kWidth, kHeight, kSupersample);
  const long sampling = env.calls.exchange(0);
  ASSERT_GT(sampling, 100000);

  const Image first = cached(env);
  expectSameImage(first, reference);
  EXPECT_GT(env.calls.exchange(0), sampling); // sampled (and fingerprinted), then written
  ASSERT_TRUE(fs::is_regular_file(onlyFile()));

  const Image second = cached(env);
  expectSameImage(second, reference);
  EXPECT_EQ(env.calls.load(), 64); // the fingerprint only
}

TEST_F(EquirectCache, DamagedTruncatedAndForeignFilesAreSampledAnewAndReplaced)
{
  CountingEnvironment env("builtin:counting");
  const Image reference = cached(env);
  const fs::path file = onlyFile();
  const auto intact = fs::file_size(file);

  // One float's bytes changed: the checksum refuses it.
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(intact - 8));
    const char garbage[4] = {1, 2, 3, 4};
    f.write(garbage, 4);
  }
  env.calls = 0;
  expectSameImage(cached(env), reference);
  EXPECT_GT(env.calls.load(), 100000);
  EXPECT_EQ(fs::file_size(file), intact);

  // Cut short.
  fs::resize_file(file, intact / 2);
  env.calls = 0;
  expectSameImage(cached(env), reference);
  EXPECT_GT(env.calls.load(), 100000);
  EXPECT_EQ(fs::file_size(file), intact);

  // Not a cache file at all.
  {
    std::ofstream f(file, std::ios::binary | std::ios::trunc);
    f << "P6\n2 2\n255\n";
  }
  env.calls = 0;
  expectSameImage(cached(env), reference);
  EXPECT_GT(env.calls.load(), 100000);
  EXPECT_EQ(fs::file_size(file), intact);
}

TEST_F(EquirectCache, AChangedRadianceUnderTheSameKeyIsSampledAnew)
{
  CountingEnvironment before("builtin:counting");
  CountingEnvironment after("builtin:counting", 2.0);
  const Image old = cached(before);
  const Image changed = cached(after);
  expectSameImage(changed, aniso::renderEquirectRefined(after, kWidth, kHeight, kSupersample));
  EXPECT_NE(old.data, changed.data);
  // Each is kept under its own name; both read back.
  before.calls = 0;
  expectSameImage(cached(before), old);
  EXPECT_EQ(before.calls.load(), 64);
}

TEST_F(EquirectCache, OtherEnvironmentsAndUnusableDirectoriesAreSampledEveryTime)
{
  CountingEnvironment file("/data/sky.exr 1024x512 1700000000");
  const Image reference = aniso::renderEquirectRefined(file, kWidth, kHeight, kSupersample);
  file.calls = 0;
  expectSameImage(cached(file), reference);
  expectSameImage(cached(file), reference);
  EXPECT_GT(file.calls.load(), 200000);
  EXPECT_FALSE(fs::exists(dir_ / "env"));

  CountingEnvironment builtin("builtin:counting");
  expectSameImage(aniso::cachedEquirectRefined(builtin, kWidth, kHeight, kSupersample, ""),
                  reference);
  // A regular file where the directory should be: nothing can be written, the image is right.
  fs::create_directories(dir_);
  std::ofstream(dir_ / "env") << "in the way";
  expectSameImage(cached(builtin), reference);
  expectSameImage(cached(builtin), reference);
}
} // namespace
