#include "app/gui/run_gui.h"

#include "app/cli.h"
#include "app/gui/MainWindow.h"
#include "app/gui/OpenGlCheck.h"
#include "app/gui/ReferenceDock.h"
#include "app/gui/ReferenceView.h"
#include "app/gui/SceneView.h"
#include "core/error.h"
#include "scene/LutScheduler.h"

#include <QApplication>
#include <QMessageBox>
#include <QStringList>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>

namespace aniso::gui
{
namespace
{
struct GuiArguments
{
  std::string mesh;               // the first MESH: it opens
  std::vector<std::string> added; // the others: added as parts
  std::string session;
  std::string screenshot;
  std::string windowScreenshot;
  std::string referenceView; // "wipe" or "error": View > Reference on, the dock showing that
  bool quit = false;
};

bool isWindowOption(const std::string& arg)
{
  return arg == "--session" || arg == "--screenshot" || arg == "--window-screenshot" ||
         arg == "--reference-view" || arg == "--quit";
}

// Session files are JSON (scene/Session.h); no mesh format the window reads is.
bool isSessionPath(const std::string& arg)
{
  std::string ext = std::filesystem::path(arg).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext == ".json";
}

GuiArguments parse(const std::vector<std::string>& args)
{
  GuiArguments a;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& arg = args[i];
    const auto value = [&]() -> std::string
    {
      if (i + 1 >= args.size())
      {
        throw cli::usageError(arg, "missing value");
      }
      return args[++i];
    };
    if (arg == "--session")
    {
      a.session = value();
    }
    else if (arg == "--screenshot")
    {
      a.screenshot = value();
    }
    else if (arg == "--window-screenshot")
    {
      a.windowScreenshot = value();
    }
    else if (arg == "--reference-view")
    {
      a.referenceView = value();
      if (a.referenceView != "wipe" && a.referenceView != "error")
      {
        throw cli::usageError(arg, "'" + a.referenceView + "' is not one of wipe, error");
      }
    }
    else if (arg == "--quit")
    {
      a.quit = true;
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      throw cli::usageError(arg, "unknown option (see aniso --help)");
    }
    else if (a.session.empty() && isSessionPath(arg))
    {
      // A session file opened from a file manager (the desktop entry's `aniso %F`).
      a.session = arg;
    }
    else if (a.mesh.empty())
    {
      a.mesh = arg;
    }
    else
    {
      a.added.push_back(arg);
    }
  }
  if (a.quit && a.screenshot.empty() && a.windowScreenshot.empty())
  {
    throw cli::usageError("--quit", "only applies with --screenshot or --window-screenshot");
  }
  return a;
}

// Qt aborts the process when it cannot reach a display: say it in words instead.
void requireDisplay()
{
  const char* platform = std::getenv("QT_QPA_PLATFORM");
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!platform || !*platform) && (!display || !*display) && (!wayland || !*wayland))
  {
    throw errorAbout("aniso", "no display to open the window on (DISPLAY is not set); use "
                              "'aniso render' for images without one, or run under xvfb-run");
  }
}
} // namespace

bool isGuiCommandLine(const std::vector<std::string>& args)
{
  if (args.empty() || isWindowOption(args[0]))
  {
    return true;
  }
  const std::string& first = args[0];
  if (first.rfind("builtin:", 0) == 0)
  {
    return true;
  }
  // A path (it has a directory or an extension) is a mesh, even a missing one: the window
  // then says the file does not exist, rather than calling it an unknown command.
  std::error_code ec;
  return first[0] != '-' && (first.find_first_of("./") != std::string::npos ||
                             std::filesystem::is_regular_file(first, ec));
}

std::string guiUsage()
{
  return "aniso [MESH...] [SESSION.json | --session FILE] [--reference-view wipe|error] "
         "[--screenshot FILE | --window-screenshot FILE [--quit]]";
}

int runGui(const std::vector<std::string>& args)
{
  const GuiArguments a = parse(args);
  requireDisplay();
  // The VTK widget needs its OpenGL format before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  static int argc = 1;
  static char name[] = "aniso";
  static char* argv[] = {name, nullptr};
  QApplication app(argc, argv);
  QApplication::setOrganizationName("aniso");
  QApplication::setApplicationName("aniso");
  // One clear message, before any VTK window, where OpenGL lacks what the renderer needs.
  if (const std::string missing = openGlShortcoming(); !missing.empty())
  {
    if (a.screenshot.empty() && a.windowScreenshot.empty())
    {
      QMessageBox::critical(nullptr, QStringLiteral("aniso"), QString::fromStdString(missing));
    }
    throw errorAbout("OpenGL", missing);
  }

  MainWindow window;
  const bool scripted = !a.screenshot.empty() || !a.windowScreenshot.empty();
  window.setErrorDialogs(!scripted);
  std::string failure;
  QObject::connect(&window, &MainWindow::errorReported,
                   [&](const QString& message)
                   {
                     if (scripted && failure.empty())
                     {
                       failure = message.toStdString();
                     }
                   });
  window.show();
  if (!scripted)
  {
    // Nothing of the user's tuning is lost if this run dies; a start that opens a file of its
    // own leaves an earlier run's autosave for a later plain start.
    window.enableAutosave(QString(), a.mesh.empty() && a.session.empty() ? AutosaveRestore::Ask
                                                                         : AutosaveRestore::Keep);
  }
  QStringList added;
  for (const std::string& path : a.added)
  {
    added << QString::fromStdString(path);
  }
  if (!a.mesh.empty() && !scripted && a.session.empty())
  {
    // The window answers while the meshes load (the default scene until then); the others
    // join the first as parts.
    if (added.isEmpty())
    {
      window.openMeshInBackground(QString::fromStdString(a.mesh));
    }
    else
    {
      window.openMeshesInBackground(QStringList{QString::fromStdString(a.mesh)} + added);
    }
  }
  else if (!a.mesh.empty())
  {
    if (!window.openMesh(QString::fromStdString(a.mesh)) && scripted)
    {
      throw Error(failure);
    }
    if (!added.isEmpty() && !window.addMeshes(added) && scripted)
    {
      throw Error(failure);
    }
  }
  if (!a.session.empty() && !window.openSession(QString::fromStdString(a.session)) && scripted)
  {
    throw Error(failure);
  }

  if (!a.referenceView.empty())
  {
    window.referenceDock()->setMode(a.referenceView == "error" ? ReferenceCanvas::Mode::Error
                                                               : ReferenceCanvas::Mode::Wipe);
    window.showReference(true);
  }

  int code = 0;
  if (!a.screenshot.empty())
  {
    QTimer::singleShot(0, &window,
                       [&]
                       {
                         try
                         {
                           window.exportScreenshot(QString::fromStdString(a.screenshot),
                                                   ScreenshotOptions{});
                           std::cout << "aniso: wrote " << a.screenshot << "\n";
                         }
                         catch (const Error& e)
                         {
                           std::cerr << "aniso: " << e.what() << "\n";
                           code = 1;
                         }
                         if (a.quit && a.windowScreenshot.empty())
                         {
                           QApplication::exit(code);
                         }
                       });
  }
  if (!a.windowScreenshot.empty())
  {
    // The whole window, once the view has refined to its quality (and with --reference-view,
    // once the reference is complete and compared with it).
    auto grabbed = std::make_shared<bool>(false);
    const auto grab = [&, grabbed]
    {
      if (*grabbed)
      {
        return;
      }
      ReferenceView* reference = window.referenceView();
      const bool uncompared = reference->complete() && reference->pixelsTotal() == 0;
      if (!a.referenceView.empty() && (!reference->unsupported().isEmpty() || uncompared))
      {
        *grabbed = true;
        std::cerr << "aniso: --reference-view: "
                  << (uncompared ? reference->progressText()
                                 : "the view has no reference: " + reference->unsupported())
                         .toStdString()
                  << "\n";
        code = 1;
        QApplication::exit(code);
        return;
      }
      if (!window.view()->converged() || window.lutScheduler()->busy() ||
          (!a.referenceView.empty() && (!reference->complete() || !reference->error())))
      {
        return;
      }
      *grabbed = true;
      // Let the status bar and docks lay themselves out with the final texts first.
      QTimer::singleShot(300, &window,
                         [&]
                         {
                           window.referenceDock()->refresh();
                           const QString path = QString::fromStdString(a.windowScreenshot);
                           if (window.grab().save(path))
                           {
                             std::cout << "aniso: wrote " << a.windowScreenshot << "\n";
                           }
                           else
                           {
                             std::cerr << "aniso: " << a.windowScreenshot << ": cannot write\n";
                             code = 1;
                           }
                           if (a.quit)
                           {
                             QApplication::exit(code);
                           }
                         });
    };
    QObject::connect(window.view(), &SceneView::frameRendered, &window, grab);
    QObject::connect(window.referenceView(), &ReferenceView::changed, &window, grab);
  }
  const int result = QApplication::exec();
  return code ? code : result;
}
} // namespace aniso::gui
