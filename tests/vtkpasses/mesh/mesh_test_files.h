#pragma once
// The files a mesh test writes: each test's own folder (made fresh, named by its suite, the
// process and the test; removed after it unless ANISO_KEEP_TEST_FILES is set), text files in
// it and small images (core/image's writer), and reading a file back whole.
#include "core/image/image.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace aniso::test
{
class MeshFilesTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const ::testing::UnitTest* unit = ::testing::UnitTest::GetInstance();
    std::string suite = unit->current_test_info()->test_suite_name();
    std::replace(suite.begin(), suite.end(), '/', '-');
    this->Dir = std::filesystem::temp_directory_path() /
                ("aniso-test-" + suite + "-" + std::to_string(unit->random_seed()) + "-" +
                 std::to_string(::getpid()) + "-" + unit->current_test_info()->name());
    std::filesystem::remove_all(this->Dir);
    std::filesystem::create_directories(this->Dir);
  }
  void TearDown() override
  {
    if (!std::getenv("ANISO_KEEP_TEST_FILES"))
    {
      std::filesystem::remove_all(this->Dir);
    }
  }

  std::string path(const std::string& name) const { return (this->Dir / name).string(); }

  // Writes CONTENT as the file NAME of the folder; returns its path.
  std::string write(const std::string& name, const std::string& content) const
  {
    std::ofstream(this->Dir / name, std::ios::binary) << content;
    return this->path(name);
  }

  // Writes a WIDTH x HEIGHT image of CHANNELS from TEXELS (row by row) as NAME (its extension
  // picks the format); returns its path.
  std::string writeTexture(const std::string& name, int width, int height, int channels,
                           std::vector<float> texels) const
  {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.data = std::move(texels);
    writeImage(this->path(name), image);
    return this->path(name);
  }

  std::filesystem::path Dir;
};

inline std::string readText(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
} // namespace aniso::test
