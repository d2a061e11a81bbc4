#pragma once
// Runs the built aniso executable from a fresh temporary directory and captures what it printed.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#ifndef ANISO_EXECUTABLE
#error "ANISO_EXECUTABLE must name the aniso executable under test"
#endif

namespace aniso_test
{
namespace fs = std::filesystem;

struct Outcome
{
  int exitCode = -1;
  std::string out;
  std::string err;
};

inline std::string shellQuoted(const std::string& s)
{
  std::string q = "'";
  for (char c : s)
  {
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return q + "'";
}

inline std::string slurp(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::set<std::string> listing(const fs::path& dir)
{
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
  {
    names.insert(fs::relative(entry.path(), dir).string());
  }
  return names;
}

class CliTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::string pattern = (fs::temp_directory_path() / "aniso-cli-test-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    io_ = dir_ / ".io";
    fs::create_directory(io_);
  }
  void TearDown() override
  {
    if (!std::getenv("ANISO_KEEP_TEST_FILES"))
      fs::remove_all(dir_);
  }

  fs::path path(const std::string& name) const { return dir_ / name; }

  // Runs aniso with ARGS, each passed as one argument (quoted for the shell), capturing both
  // streams in files.
  Outcome run(const std::vector<std::string>& args) const
  {
    std::string command = shellQuoted(ANISO_EXECUTABLE);
    for (const auto& a : args)
    {
      command += " " + shellQuoted(a);
    }
    command +=
        " >" + shellQuoted((io_ / "out").string()) + " 2>" + shellQuoted((io_ / "err").string());
    const int status = std::system(command.c_str());
    Outcome r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(io_ / "out");
    r.err = slurp(io_ / "err");
    return r;
  }

  // Files in the test directory (relative paths), without the captured streams.
  std::set<std::string> files() const
  {
    std::set<std::string> names = listing(dir_);
    names.erase(".io");
    names.erase(".io/out");
    names.erase(".io/err");
    return names;
  }

  fs::path dir_;
  fs::path io_;
};
} // namespace aniso_test
