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
  using aniso::cli::wrapText;
  const std::size_t width = aniso::cli::terminalWidth();
  const auto row = [&](const std::string& left, const std::string& text)
  { return "  " + left + std::string(12 - left.size(), ' ') + wrapText(text, 14, width) + "\n"; };
  return "Usage: aniso [--help | --version] COMMAND [ARGS...]\n       " +
         wrapText(aniso::gui::guiUsage(), 7, width) +
         "\n\n" +
         wrapText("aniso renders meshes with anisotropic Ashikhmin-Shirley materials under "
                  "image-based lighting. Without a command it opens the window.",
                  0, width) +
         "\n\nCommands:\n" +
         row("bake KIND", "bake lookup tables, maps and environment data; KIND one of:") +
         aniso::cli::bakeKindsSummary(6) + row("render", aniso::cli::renderSummary()) +
         row("thumbnail", aniso::cli::thumbnailSummary()) +
         row("bench", aniso::cli::benchSummary()) +
         "\nOptions:\n"
         "  -h, --help  show this help and exit\n"
         "  --version   print the version and exit\n\n" +
         wrapText("Run 'aniso bake --help' or 'aniso bake KIND --help' for details.", 0, width) +
         "\n";
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
