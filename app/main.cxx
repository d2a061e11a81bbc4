// The aniso executable: dispatches to its subcommands.
#include "app/bake_command.h"
#include "app/cli.h"
#include "app/gui/run_gui.h"
#include "app/render_command.h"
#include "app/thumbnail_command.h"
#include "bench/bench_command.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
std::string mainHelp()
{
  return "Usage: aniso [--help | --version] COMMAND [ARGS...]\n       " + aniso::gui::guiUsage() +
         "  (opens the window)\n\n"
         "aniso renders meshes with anisotropic Ashikhmin-Shirley materials under image-based\n"
         "lighting.\n\n"
         "Commands:\n"
         "  bake KIND   bake lookup tables, maps and environment data to files, KIND one of:\n" +
         aniso::cli::bakeKindsSummary(6) + "  render      " + aniso::cli::renderSummary() + "\n" +
         "  thumbnail   " + aniso::cli::thumbnailSummary() + "\n" + "  bench       " +
         aniso::cli::benchSummary() + "\n" +
         "\nOptions:\n"
         "  -h, --help  show this help and exit\n"
         "  --version   print the version and exit\n\n"
         "Run 'aniso bake --help' or 'aniso bake KIND --help' for details.\n";
}

int run(const std::vector<std::string>& args)
{
  using aniso::cli::usageError;
  if (aniso::gui::isGuiCommandLine(args))
  {
    return aniso::gui::runGui(args);
  }
  const std::string& command = args[0];
  if (command == "-h" || command == "--help")
  {
    std::cout << mainHelp();
    return 0;
  }
  if (command == "--version")
  {
    std::cout << "aniso " << ANISO_VERSION << "\n";
    return 0;
  }
  if (command == "bake")
  {
    return aniso::cli::runBake(std::vector<std::string>(args.begin() + 1, args.end()), std::cout);
  }
  if (command == "bench")
  {
    return aniso::cli::runBenchCommand(std::vector<std::string>(args.begin() + 1, args.end()),
                                       std::cout);
  }
  if (command == "render")
  {
    return aniso::cli::runRender(std::vector<std::string>(args.begin() + 1, args.end()), std::cout,
                                 std::cerr);
  }
  if (command == "thumbnail")
  {
    return aniso::cli::runThumbnail(std::vector<std::string>(args.begin() + 1, args.end()),
                                    std::cout);
  }
  if (command.size() > 1 && command[0] == '-')
  {
    throw usageError(command, "unknown option (see aniso --help)");
  }
  throw usageError(command, "unknown command (see aniso --help)");
}
} // namespace

int main(int argc, char** argv)
{
  const std::vector<std::string> args(argv + 1, argv + argc);
  return aniso::cli::runReportingErrors([&] { return run(args); }, std::cerr);
}
