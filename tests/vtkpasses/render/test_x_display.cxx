// The process's X connection (requireXDisplay) and an X server that resets.
//
// An X server started without -noreset (xvfb-run's default) resets when its last client leaves
// and refuses connections for that moment. A process that renders with one window after another,
// each opening and closing its own connection, then failed at random ("cannot open the X
// display"; `aniso bench` between two of its render sessions). requireXDisplay keeps one
// connection for the life of the process, so the server never loses its last client.
//
// The test starts its own Xvfb (with resets, display number chosen by the server) so that the
// suite's own server, started with -noreset, does not hide the failure.
#include "core/env/environment.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <gtest/gtest.h>
#include <iostream>
#include <poll.h>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vtkPolyData.h>

// Last: Xlib defines macros (None, Bool, Status) that clash with googletest's names.
#include <X11/Xlib.h>

extern char** environ;

namespace aniso
{
namespace
{
// An Xvfb of this test's own, stopped at the end.
class PrivateXServer
{
public:
  PrivateXServer()
  {
    int fds[2];
    if (pipe(fds) != 0)
    {
      return;
    }
    const std::string fd = std::to_string(fds[1]);
    const char* argv[] = {"Xvfb",     "-displayfd", fd.c_str(), "-screen", "0",
                          "64x64x24", "-nolisten",  "tcp",      nullptr};
    if (posix_spawnp(&pid_, "Xvfb", nullptr, nullptr, const_cast<char**>(argv), environ) != 0)
    {
      pid_ = -1;
    }
    close(fds[1]);
    // Xvfb writes its display number to the descriptor once it accepts connections.
    std::string number;
    pollfd p{fds[0], POLLIN, 0};
    char c = 0;
    while (pid_ > 0 && poll(&p, 1, 10000) > 0 && read(fds[0], &c, 1) == 1 && c != '\n')
    {
      number += c;
    }
    close(fds[0]);
    if (!number.empty())
    {
      display_ = ":" + number;
    }
  }
  ~PrivateXServer()
  {
    if (pid_ > 0)
    {
      kill(pid_, SIGTERM);
      int status = 0;
      waitpid(pid_, &status, 0);
    }
  }
  const std::string& display() const { return display_; }

private:
  pid_t pid_ = -1;
  std::string display_;
};

// Connections opened and closed one after another; how many the server refused.
int refusedConnections(int attempts)
{
  int refused = 0;
  for (int i = 0; i < attempts; ++i)
  {
    Display* d = XOpenDisplay(nullptr);
    if (!d)
    {
      ++refused;
      continue;
    }
    XSync(d, False);
    XCloseDisplay(d);
  }
  return refused;
}

TEST(XDisplay, TheProcessConnectionKeepsAResettingServerFromRefusingWindows)
{
  PrivateXServer server;
  if (server.display().empty())
  {
    GTEST_SKIP() << "Xvfb could not be started (scripts/setup.sh installs it)";
  }
  ASSERT_EQ(setenv("DISPLAY", server.display().c_str(), 1), 0);

  // Without a held connection every close is the server's last client: some reconnections fail
  // (from 1 in 50 to a quarter of them on the development machine), which shows that this
  // server resets and the checks below can fail. Printed, not checked: how many is a matter of
  // timing. 50 attempts: each reset takes the server most of 0.1 s (200 took 18 s).
  const int refusedBefore = refusedConnections(50);
  std::cout << "connections refused before the process held one: " << refusedBefore << " of 50\n";

  // Renders one after another, each in a window of its own, then bare connections: none refused
  // once the process holds its connection.
  RenderSettings s;
  s.surface = makeSphere(16, 8);
  s.environment = std::make_shared<StudioEnvironment>();
  s.cubeSize = 16;
  s.material.samples = 1;
  s.width = 16;
  s.height = 16;
  s.frames = 1;
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NO_THROW(renderOffscreen(s)) << "render " << i;
  }
  EXPECT_EQ(refusedConnections(200), 0);
}

TEST(XDisplay, NamesTheDisplayWhenThereIsNone)
{
  // Checked before the held connection: an unset DISPLAY is named even when one is held.
  ASSERT_EQ(setenv("DISPLAY", "", 1), 0);
  try
  {
    requireXDisplay();
    ADD_FAILURE() << "no error without a display";
  }
  catch (const std::exception& e)
  {
    EXPECT_NE(std::string(e.what()).find("DISPLAY is not set"), std::string::npos) << e.what();
  }
}
} // namespace
} // namespace aniso
