// A GL context without what the renderer needs gives one clear message at start and no crash.
// Mesa's MESA_GL_VERSION_OVERRIDE=3.1 makes llvmpipe offer OpenGL 3.1 (below VTK 9.1's 3.2):
//  - `aniso render` fails with exit code 1 and one line "aniso: OpenGL: ..." on stderr naming the
//    version found and the one needed, writes no image, and prints none of VTK's errors;
//  - the window (`aniso --screenshot FILE --quit`) fails the same way before any VTK window is
//    made (no screenshot written);
//  - without the override the render succeeds (the control: the message comes from the check,
//    not from a broken display; the window's own tests show it opening).
#include "tests/app/cli_runner.h"

#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

namespace
{
using aniso_test::Outcome;

class OpenGlCheckCli : public aniso_test::CliTest
{
protected:
  void TearDown() override
  {
    ::unsetenv("MESA_GL_VERSION_OVERRIDE");
    CliTest::TearDown();
  }

  static int lines(const std::string& text)
  {
    int n = 0;
    for (char c : text)
    {
      n += c == '\n' ? 1 : 0;
    }
    return n;
  }
};

TEST_F(OpenGlCheckCli, ContextBelowThreePointTwoIsOneClearMessage)
{
  const std::vector<std::string> render = {"render", "--builtin", "sphere",
                                           "--size", "32",        "--frames",
                                           "1",      "-o",        path("r.png").string()};
  const std::vector<std::string> window = {"--screenshot", path("w.png").string(), "--quit"};
  ASSERT_EQ(run(render).exitCode, 0);
  std::filesystem::remove(path("r.png"));

  ::setenv("MESA_GL_VERSION_OVERRIDE", "3.1", 1);
  for (const auto& args : {render, window})
  {
    const Outcome o = run(args);
    EXPECT_EQ(o.exitCode, 1) << o.err;
    EXPECT_NE(o.err.find("aniso: OpenGL: this display offers OpenGL 3.1"), std::string::npos)
        << o.err;
    EXPECT_NE(o.err.find("needs OpenGL 3.2 or later"), std::string::npos) << o.err;
    // Qt may note its runtime directory; nothing of VTK's.
    EXPECT_EQ(o.err.find("ERROR"), std::string::npos) << o.err;
    EXPECT_LE(lines(o.err.substr(o.err.find("aniso: OpenGL"))), 1) << o.err;
  }
  EXPECT_FALSE(std::filesystem::exists(path("r.png")));
  EXPECT_FALSE(std::filesystem::exists(path("w.png")));
}
} // namespace
