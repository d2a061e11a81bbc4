// A long session in one process: the real main window, shown, takes 10 000 scripted edits and
// 1 000 mesh loads, and the benchmark watches its resident memory, the textures it uploads, the
// GL errors and what VTK writes to its output window. A cycle is 50 edits, then 5 loads; every
// fourth cycle is a heavy one:
// - drags (one undo step each, as a slider's): n_u (6 edits; 15 in a light cycle), n_v (6; 14),
//   F0 (4), albedo (4), exposure (4), the environment's rotation (1);
// - choices: samples, method, filtered, env-sampling (one edit each);
// - heavy cycles only: maps, through the path the Maps dock takes (read on a worker, then set):
//   bump normal, a normal map (a PNG written once with core/image's writeImage), a TPR map (the
//   pattern "circular", or a PNG of one, alternately), both cleared, bump none (6 edits);
// - heavy cycles only: the environment, through the path the Environment dock takes:
//   builtin:studio, builtin:white, builtin:sunsky and one of Blender's HDRIs when installed, in
//   turn (1 edit);
// - heavy cycles only: parts: a second mesh added (a PLY plate with a point property
//   "temperature", read on a worker as File > Add Mesh reads), hidden, shown, given part 0's
//   material, made unique, its field set to "temperature" (selected, as the Maps dock edits it),
//   the field's target changed, the field cleared, a library material assigned, the part
//   removed (with the copy made unique for it) (10 edits);
// - undo twice, redo twice;
// - loads, through the window's background open (File > Open), each until it is the scene's:
//   every twentieth an OBJ (read by the reader program), every fifth else a PLY (both written
//   once by VTK's writers), the others builtin:torus, builtin:plate, builtin:sphere.
// The values repeat every kPeriod cycles, so caches keyed by them (lookup tables, environments,
// shader variants) are full after the first period and what grows later is not their filling.
// Between steps (an edit or a load) the event loop runs one pass, which draws a frame when one
// is due; every --frame-every steps the benchmark waits for the view to show a frame (or to have
// nothing to draw); after an edit read on a worker (maps, environments, parts) it waits for the
// read, and for an environment for its lighting to be on screen. Every 100 steps it samples
// VmRSS (/proc/self/status), the texture upload counter (TextureUpload.h), the LUT cache's
// memory, the undo stack's commands, the GL errors (glGetError at the sample, and the view's
// own reports of GL errors after its frames) and VTK's error and warning output; at step 500,
// every 1 000 steps and at the end it counts the GL object names alive (glIsTexture and
// friends).
// Prints the samples as CSV and a summary; writes the RSS curve as SVG.
// Run (X server needed):
//   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" bench_soak [--edits N] [--loads N]
//     [--frame-every N] [--size WxH] [--target-samples N] [--undo-limit N] [--csv FILE]
//     [--svg FILE]
// --undo-limit caps the window's undo stack lower than its own limit (SceneEditor::kUndoLimit).
// The run's caches, settings and state go to a temporary directory (XDG_CACHE_HOME,
// XDG_CONFIG_HOME, XDG_STATE_HOME), so it starts cold and leaves the user's alone.
// clang-format off
#include <vtk_glew.h> // before any other GL header (QtTest and QVTKOpenGLNativeWidget bring Qt's)
// clang-format on

#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "bench/plot.h"
#include "core/error.h"
#include "core/image/image.h"
#include "core/lut/lut_cache.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/render/TextureUpload.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDebug.h> // VTK_DEBUG_LEAKS, when VTK was built with it
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPLYWriter.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkSuperquadricSource.h>
#include <vtkTriangleFilter.h>
#ifdef VTK_DEBUG_LEAKS
#include <vtkDebugLeaks.h>
#endif

using aniso::colorValue;
using aniso::numberValue;
using aniso::textValue;

namespace
{
constexpr int kEditsPerCycle = 50;
constexpr int kPeriod = 16;               // cycles after which every value repeats
constexpr int kHeavyEvery = 4;            // cycles: maps, environment and parts every fourth
constexpr int kSampleEvery = 100;         // steps
constexpr int kCensusEvery = 1000;        // steps
constexpr GLuint kCensusNames = 1u << 18; // GL names scanned per kind

double residentMiB()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind("VmRSS:", 0) == 0)
    {
      return std::atof(line.c_str() + 6) / 1024.0; // kB
    }
  }
  return 0.0;
}

// Counts VTK's errors and warnings (all of them: the view reports each distinct one once), and
// passes the first few distinct ones on.
class CountingOutput : public vtkOutputWindow
{
public:
  static CountingOutput* New();

  vtkSmartPointer<vtkOutputWindow> previous;
  long errors = 0;
  long warnings = 0;
  std::set<std::string> seen;

  void DisplayText(const char* text) override { previous->DisplayText(text); }
  void DisplayErrorText(const char* text) override
  {
    ++errors;
    if (firstTime(text))
    {
      previous->DisplayErrorText(text);
    }
  }
  void DisplayWarningText(const char* text) override
  {
    ++warnings;
    if (firstTime(text))
    {
      previous->DisplayWarningText(text);
    }
  }
  void DisplayGenericWarningText(const char* text) override
  {
    ++warnings;
    if (firstTime(text))
    {
      previous->DisplayGenericWarningText(text);
    }
  }
  void DisplayDebugText(const char* text) override { previous->DisplayDebugText(text); }

private:
  bool firstTime(const char* text) { return seen.size() < 50 && seen.insert(text).second; }

public:
  vtkTypeMacro(CountingOutput, vtkOutputWindow)
};
vtkStandardNewMacro(CountingOutput);

// GL object names alive in the window's context.
struct GlCensus
{
  long textures = 0;
  long buffers = 0;
  long framebuffers = 0;
  long vertexArrays = 0;
  long programs = 0;
  long shaders = 0;
};

GlCensus census(vtkRenderWindow* window)
{
  window->MakeCurrent();
  GlCensus c;
  for (GLuint name = 1; name < kCensusNames; ++name)
  {
    c.textures += glIsTexture(name) ? 1 : 0;
    c.buffers += glIsBuffer(name) ? 1 : 0;
    c.framebuffers += glIsFramebuffer(name) ? 1 : 0;
    c.vertexArrays += glIsVertexArray(name) ? 1 : 0;
    c.programs += glIsProgram(name) ? 1 : 0;
    c.shaders += glIsShader(name) ? 1 : 0;
  }
  return c;
}

struct Sample
{
  long step = 0;
  std::string kind;
  double rssMiB = 0.0;
  unsigned long long uploads = 0;
  long glErrors = 0;
  long vtkErrors = 0;
  long vtkWarnings = 0;
  long reported = 0;
  double lutMiB = 0.0;
  int undoCommands = 0;
  double seconds = 0.0;
};

struct CensusRow
{
  long step = 0;
  GlCensus gl;
};

// Runs the event loop for MS milliseconds.
void pump(int ms)
{
  QEventLoop loop;
  QTimer::singleShot(ms, Qt::PreciseTimer, &loop, &QEventLoop::quit);
  loop.exec();
}

// Runs the event loop until DONE, or LIMIT_MS; false on the limit.
bool pumpUntil(const std::function<bool()>& done, int limitMs)
{
  QElapsedTimer t;
  t.start();
  while (!done())
  {
    if (t.elapsed() > limitMs)
    {
      return false;
    }
    pump(2);
  }
  return true;
}

// Least-squares slope of Y against X.
double slope(const std::vector<double>& x, const std::vector<double>& y)
{
  const double n = double(x.size());
  if (x.size() < 2)
  {
    return 0.0;
  }
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double d = n * sxx - sx * sx;
  return d != 0.0 ? (n * sxy - sx * sy) / d : 0.0;
}

// A normal map of ripples, encoded as PNG stores signed vectors: (n + 1) / 2.
aniso::Image normalMapImage()
{
  const int side = 64;
  aniso::Image image(side, side, 3);
  for (int y = 0; y < side; ++y)
  {
    for (int x = 0; x < side; ++x)
    {
      const double dx = 0.4 * std::cos(2.0 * M_PI * 4.0 * x / side);
      const double dy = 0.4 * std::cos(2.0 * M_PI * 3.0 * y / side);
      const double length = std::sqrt(dx * dx + dy * dy + 1.0);
      image.at(x, y, 0) = float(0.5 * (-dx / length + 1.0));
      image.at(x, y, 1) = float(0.5 * (-dy / length + 1.0));
      image.at(x, y, 2) = float(0.5 * (1.0 / length + 1.0));
    }
  }
  return image;
}

// A TPR map of circles about the centre, (x, y) encoded as (v + 1) / 2.
aniso::Image tprImage()
{
  const int side = 64;
  aniso::Image image(side, side, 3);
  for (int y = 0; y < side; ++y)
  {
    for (int x = 0; x < side; ++x)
    {
      const double u = (x + 0.5) / side - 0.5;
      const double v = 0.5 - (y + 0.5) / side;
      const double r = std::max(1e-6, std::hypot(u, v));
      image.at(x, y, 0) = float(0.5 * (-v / r + 1.0));
      image.at(x, y, 1) = float(0.5 * (u / r + 1.0));
      image.at(x, y, 2) = 0.5f;
    }
  }
  return image;
}

bool writeMeshes(const QString& ply, const QString& obj)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPLYWriter> plyWriter;
  plyWriter->SetFileName(ply.toStdString().c_str());
  plyWriter->SetInputConnection(sphere->GetOutputPort());
  plyWriter->SetFileTypeToBinary();
  vtkNew<vtkSuperquadricSource> torusSource;
  torusSource->ToroidalOn();
  torusSource->SetThickness(0.35);
  torusSource->SetThetaResolution(96);
  torusSource->SetPhiResolution(48);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(torusSource->GetOutputPort());
  vtkNew<vtkOBJWriter> objWriter;
  objWriter->SetFileName(obj.toStdString().c_str());
  objWriter->SetInputConnection(triangles->GetOutputPort());
  return plyWriter->Write() == 1 && objWriter->Write() == 1;
}

// The part of the field: a plate of N x N quads beside the unit meshes, with texture coordinates
// and the point property "temperature" = x, as ASCII PLY (which the project's reader reads in
// the application's process; VTK's PLY writer writes no such property).
bool writeFieldPlate(const QString& path)
{
  const int n = 16;
  std::ofstream ply(path.toStdString());
  ply << "ply\nformat ascii 1.0\nelement vertex " << (n + 1) * (n + 1)
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty float u\n"
         "property float v\nproperty float temperature\nelement face "
      << n * n << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double u = double(i) / n;
      const double v = double(j) / n;
      const double x = 1.0 + u;
      ply << x << " " << v - 0.5 << " 0 " << u << " " << v << " " << x << "\n";
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int a = j * (n + 1) + i;
      ply << "4 " << a << " " << a + 1 << " " << a + n + 2 << " " << a + n + 1 << "\n";
    }
  }
  return bool(ply);
}

// The first HDRI of Blender's world studio lights, if installed.
std::string blenderHdri()
{
  for (const char* name : {"city.exr", "forest.exr", "courtyard.exr"})
  {
    for (const char* dir : {"/usr/share/blender/datafiles/studiolights/world/"})
    {
      const std::string path = std::string(dir) + name;
      if (QFile::exists(QString::fromStdString(path)))
      {
        return path;
      }
    }
  }
  // Versioned layouts: /usr/share/blender/X.Y/datafiles/...
  const QDir root("/usr/share/blender");
  for (const QString& version : root.entryList(QDir::Dirs | QDir::NoDotAndDotDot))
  {
    const QDir world(root.filePath(version + "/datafiles/studiolights/world"));
    const QStringList exrs = world.entryList({"*.exr"}, QDir::Files, QDir::Name);
    if (!exrs.isEmpty())
    {
      return world.filePath(exrs.front()).toStdString();
    }
  }
  return {};
}

// Position K of a slider of N positions from LO to HI on a log scale.
double logPosition(int k, int n, double lo, double hi)
{
  return lo * std::pow(hi / lo, double(k % n) / double(n - 1));
}

void usage()
{
  std::fprintf(stderr, "usage: bench_soak [--edits N] [--loads N] [--frame-every N] [--size WxH] "
                       "[--target-samples N] [--undo-limit N] [--csv FILE] [--svg FILE]\n");
}
} // namespace

int main(int argc, char** argv)
{
  int edits = 10000;
  int loads = 1000;
  int frameEvery = 25;
  int targetSamples = 0; // the scene's default
  int undoLimit = 0;     // 0: the window's (none)
  int width = 1280;
  int height = 800;
  std::string csvPath;
  std::string svgPath;
  for (int i = 1; i < argc; ++i)
  {
    const auto next = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    const char* value = nullptr;
    if (std::strcmp(argv[i], "--edits") == 0 && (value = next()))
    {
      edits = std::max(kEditsPerCycle, std::atoi(value));
    }
    else if (std::strcmp(argv[i], "--loads") == 0 && (value = next()))
    {
      loads = std::max(0, std::atoi(value));
    }
    else if (std::strcmp(argv[i], "--frame-every") == 0 && (value = next()))
    {
      frameEvery = std::max(1, std::atoi(value));
    }
    else if (std::strcmp(argv[i], "--size") == 0 && (value = next()) &&
             std::sscanf(value, "%dx%d", &width, &height) == 2)
    {
    }
    else if (std::strcmp(argv[i], "--target-samples") == 0 && (value = next()))
    {
      targetSamples = std::max(1, std::atoi(value));
    }
    else if (std::strcmp(argv[i], "--undo-limit") == 0 && (value = next()))
    {
      undoLimit = std::max(1, std::atoi(value));
    }
    else if (std::strcmp(argv[i], "--csv") == 0 && (value = next()))
    {
      csvPath = value;
    }
    else if (std::strcmp(argv[i], "--svg") == 0 && (value = next()))
    {
      svgPath = value;
    }
    else
    {
      usage();
      return 2;
    }
  }
  const int cycles = edits / kEditsPerCycle;
  edits = cycles * kEditsPerCycle;
  const int loadsPerCycle = int(std::lround(double(loads) / cycles));
  loads = loadsPerCycle * cycles;

  // Caches, settings and state of this run only (before anything reads them).
  QTemporaryDir home;
  for (const char* variable : {"XDG_CACHE_HOME", "XDG_CONFIG_HOME", "XDG_STATE_HOME"})
  {
    const QString dir = home.filePath(QString(variable).toLower());
    QDir().mkpath(dir);
    setenv(variable, dir.toLocal8Bit().constData(), 1);
  }

  vtkNew<CountingOutput> output;
  output->previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(output);

  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);

  QTemporaryDir files;
  const QString ply = files.filePath("sphere.ply");
  const QString obj = files.filePath("torus.obj");
  const QString plate = files.filePath("plate.ply");
  const std::string normalPng = files.filePath("ripples-normal.png").toStdString();
  const std::string tprPng = files.filePath("circles-tpr.png").toStdString();
  try
  {
    if (!writeMeshes(ply, obj) || !writeFieldPlate(plate))
    {
      std::fprintf(stderr, "bench_soak: cannot write the meshes in %s\n", qPrintable(files.path()));
      return 1;
    }
    aniso::writeImage(normalPng, normalMapImage());
    aniso::writeImage(tprPng, tprImage());
  }
  catch (const aniso::Error& e)
  {
    std::fprintf(stderr, "bench_soak: %s\n", e.what());
    return 1;
  }
  std::vector<std::string> environments = {"builtin:studio", "builtin:white", "builtin:sunsky"};
  const std::string hdri = blenderHdri();
  if (!hdri.empty())
  {
    environments.push_back(hdri);
  }
  const std::vector<QString> builtins = {"builtin:torus", "builtin:plate", "builtin:sphere",
                                         "builtin:torus"};

  std::vector<Sample> samples;
  std::vector<CensusRow> censuses;
  std::vector<std::string> reports; // every errorReported message, in order
  long glErrors = 0;                // glGetError codes seen at samples
  long reportedGl = 0;              // the view's "OpenGL: ..." reports
  long waitsTimedOut = 0;
  long editFailures = 0;
  long loadFailures = 0;
  long partStepsSkipped = 0;
  std::map<std::string, double> phaseSeconds;
  long renders = 0;
  double renderSeconds = 0.0;
  std::string hdriName = hdri.empty() ? "none installed" : hdri;
  double seconds = 0.0;
  int viewWidth = 0;
  int viewHeight = 0;
  {
    aniso::MainWindow window;
    window.setErrorDialogs(false);
    QObject::connect(&window, &aniso::MainWindow::errorReported,
                     [&](const QString& message)
                     {
                       reports.push_back(message.toStdString());
                       if (message.startsWith("OpenGL"))
                       {
                         ++reportedGl;
                       }
                       if (reports.size() <= 20)
                       {
                         std::fprintf(stderr, "bench_soak: reported: %s\n", qPrintable(message));
                       }
                     });
    if (targetSamples > 0)
    {
      window.model()->setValue("target-samples", numberValue(targetSamples));
    }
    window.resize(width, height);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
    {
      std::fprintf(stderr, "bench_soak: the window was not shown\n");
      return 1;
    }
    aniso::SceneView* view = window.view();
    aniso::SceneModel* model = window.model();
    aniso::SceneEditor* editor = window.editor();
    vtkRenderWindow* renderWindow = window.vtkWidget()->renderWindow();
    const char* phase = "set-up";
    long frames = 0;
    QObject::connect(view, &aniso::SceneView::frameRendered, [&frames] { ++frames; });
    // Every render of the window, and the time spent in them.
    QElapsedTimer renderClock;
    std::function<void(unsigned long)> onRender = [&](unsigned long event)
    {
      if (event == vtkCommand::StartEvent)
      {
        renderClock.start();
      }
      else if (renderClock.isValid())
      {
        ++renders;
        renderSeconds += double(renderClock.nsecsElapsed()) * 1e-9;
      }
    };
    vtkNew<vtkCallbackCommand> renderTiming;
    renderTiming->SetClientData(&onRender);
    renderTiming->SetCallback([](vtkObject*, unsigned long event, void* f, void*)
                              { (*static_cast<std::function<void(unsigned long)>*>(f))(event); });
    renderWindow->AddObserver(vtkCommand::StartEvent, renderTiming);
    renderWindow->AddObserver(vtkCommand::EndEvent, renderTiming);
    const auto idle = [&]
    {
      return view->converged() && !window.lutScheduler()->busy() && !view->lightingBusy() &&
             !window.meshLoading() && !window.environmentLoading();
    };
    pumpUntil(idle, 120000);
    if (undoLimit > 0)
    {
      // The undo history capped lower than the window does, to tell its growth from the rest's.
      editor->undoStack()->clear();
      editor->undoStack()->setUndoLimit(undoLimit);
    }
    viewWidth = renderWindow->GetSize()[0];
    viewHeight = renderWindow->GetSize()[1];

    // A frame drawn since the call, or nothing left to draw.
    const auto waitFrame = [&](int limitMs)
    {
      const long before = frames;
      if (!pumpUntil([&] { return frames > before || idle(); }, limitMs))
      {
        ++waitsTimedOut;
      }
    };
    const auto waitFor = [&](const std::function<bool()>& done, int limitMs)
    {
      if (!pumpUntil(done, limitMs))
      {
        ++waitsTimedOut;
      }
    };
    const auto attempt = [&](const std::function<void()>& edit)
    {
      try
      {
        edit();
      }
      catch (const aniso::Error& e)
      {
        ++editFailures;
        if (editFailures <= 20)
        {
          std::fprintf(stderr, "bench_soak: edit failed: %s\n", e.what());
        }
      }
    };

    QElapsedTimer clock;
    clock.start();
    // Where the time goes: seconds by the kind of step, the sampling apart.
    phase = "start";
    qint64 lastStepNs = clock.nsecsElapsed();
    long step = 0;
    int editsDone = 0;
    const auto sampleNow = [&](const char* kind)
    {
      renderWindow->MakeCurrent();
      for (int i = 0; i < 8; ++i)
      {
        if (glGetError() == GL_NO_ERROR)
        {
          break;
        }
        ++glErrors;
      }
      Sample s;
      s.step = step;
      s.kind = kind;
      s.rssMiB = residentMiB();
      s.uploads = aniso::textureUploadCount();
      s.glErrors = glErrors + reportedGl;
      s.vtkErrors = output->errors;
      s.vtkWarnings = output->warnings;
      s.reported = long(reports.size());
      s.lutMiB = double(aniso::LutCache::shared().memoryBytes()) / double(1 << 20);
      s.undoCommands = editor->undoStack()->count();
      s.seconds = double(clock.elapsed()) * 1e-3;
      samples.push_back(s);
      if (step == 500 || step % kCensusEvery == 0)
      {
        censuses.push_back({step, census(renderWindow)});
      }
      if (step % 1000 == 0)
      {
        std::fprintf(stderr, "bench_soak: step %ld (%d edits), %.0f s, RSS %.1f MiB\n", step,
                     editsDone, s.seconds, s.rssMiB);
      }
    };
    // After each step: one pass of the event loop, a frame every FRAME_EVERY steps, a sample
    // every kSampleEvery steps.
    const auto stepDone = [&](const char* kind)
    {
      ++step;
      const auto account = [&]
      {
        const qint64 now = clock.nsecsElapsed();
        phaseSeconds[phase] += double(now - lastStepNs) * 1e-9;
        lastStepNs = now;
      };
      QCoreApplication::processEvents();
      editsDone += std::strcmp(kind, "edit") == 0 ? 1 : 0;
      if (step % frameEvery == 0)
      {
        waitFrame(3000);
      }
      account();
      if (step % kSampleEvery == 0)
      {
        const char* stepPhase = phase;
        phase = "sampling";
        sampleNow(kind);
        account();
        phase = stepPhase;
      }
    };
    const auto edit =
        [&](const std::string& key, const aniso::ParameterValue& value, int dragId = 0)
    {
      attempt([&] { editor->edit(key, value, dragId); });
      stepDone("edit");
    };
    const auto drag = [&](const std::string& key, int count,
                          const std::function<aniso::ParameterValue(int)>& valueAt)
    {
      const int id = editor->beginDrag();
      for (int i = 0; i < count; ++i)
      {
        edit(key, valueAt(i), id);
      }
    };
    // An edit read on a worker first (the Maps dock's path), until set.
    const auto mapEdit = [&](const std::string& key, const std::string& text)
    {
      window.editInBackground(key, QString::fromStdString(text));
      waitFor([&] { return !window.assetLoading(key); }, 30000);
      stepDone("edit");
    };
    const auto partStep = [&](const std::function<void()>& action)
    {
      if (model->parts().size() == 2)
      {
        attempt(action);
      }
      else
      {
        ++partStepsSkipped;
      }
      stepDone("edit");
    };

    sampleNow("start");
    for (int cycle = 0; cycle < cycles; ++cycle)
    {
      const int c = cycle % kPeriod;
      const bool heavy = cycle % kHeavyEvery == 0;
      const int h = c / kHeavyEvery; // which heavy cycle of the period
      // Drags: each a run of slider positions, the runs' ends moving over the period. A cycle
      // without maps, environment and parts drags n_u and n_v longer instead (the same count).
      phase = "drags";
      const int nuSteps = heavy ? 6 : 15;
      const int nvSteps = heavy ? 6 : 14;
      drag("nu", nuSteps,
           [&](int i) { return numberValue(logPosition(7 * c + i, 97, 20.0, 20000.0)); });
      drag("nv", nvSteps,
           [&](int i) { return numberValue(logPosition(5 * c + i, 89, 10.0, 5000.0)); });
      drag("f0", 4,
           [&](int i)
           {
             const double t = 0.025 * ((3 * c + i) % 17);
             return colorValue(0.55 + t, 0.56 + 0.8 * t, 0.58 + 0.5 * t);
           });
      drag("albedo", 4,
           [&](int i)
           {
             const double t = 0.02 * ((2 * c + i) % 11);
             return colorValue(t, 0.5 * t, 0.25 * t);
           });
      drag("exposure", 4, [&](int i) { return numberValue(-2.0 + 0.25 * ((c + i) % 13)); });
      drag("env-rotation", 1, [&](int) { return numberValue(-180.0 + 360.0 * c / kPeriod); });
      phase = "choices";
      edit("samples", numberValue(std::vector<double>{16.0, 8.0, 32.0, 16.0}[std::size_t(c % 4)]));
      // Split sum on odd cycles: the field's roughness and anisotropy targets need exact.
      edit("method", textValue(c % 2 ? "split-sum" : "exact"));
      edit("filtered", textValue(c % 3 == 1 ? "off" : "on"));
      edit("env-sampling", textValue(std::vector<std::string>{"auto", "off", "mis",
                                                              "sources"}[std::size_t(c % 4)]));
      if (heavy)
      {
        phase = "maps";
        edit("bump", textValue("normal"));
        mapEdit("normal-map", normalPng);
        mapEdit("tpr", h % 2 ? tprPng : std::string("circular"));
        mapEdit("normal-map", "");
        mapEdit("tpr", "");
        edit("bump", textValue("none"));
        phase = "environment";
        window.openEnvironmentInBackground(
            QString::fromStdString(environments[std::size_t(h) % environments.size()]), false);
        waitFor([&] { return !window.environmentLoading(); }, 60000);
        waitFor([&] { return !view->lightingBusy(); }, 60000);
        stepDone("edit");
        phase = "parts";
        window.addMeshesInBackground({plate});
        waitFor([&] { return !window.assetLoading("add mesh") && model->parts().size() == 2; },
                30000);
        stepDone("edit");
        partStep([&] { editor->setPartsVisible({1}, false); });
        partStep([&] { editor->setPartsVisible({1}, true); });
        partStep([&] { editor->assignMaterial({1}, model->parts()[0].material); });
        std::string madeUnique;
        partStep(
            [&]
            {
              editor->makeUnique({1});
              madeUnique = model->parts()[1].material;
            });
        partStep(
            [&]
            {
              model->setSelection({1});
              editor->edit("field", textValue("temperature"));
            });
        partStep(
            [&]
            {
              // The method is exact on even cycles (heavy ones are).
              editor->edit("field-target",
                           textValue(std::vector<std::string>{"albedo", "roughness", "f0",
                                                              "anisotropy"}[std::size_t(h % 4)]));
            });
        partStep(
            [&]
            {
              editor->edit("field", textValue("none"));
              model->setSelection({});
            });
        partStep([&] { editor->assignMaterial({1}, "satin gold"); });
        partStep(
            [&]
            {
              std::vector<aniso::ScenePart> parts = model->parts();
              aniso::MaterialLibrary library = model->materials();
              parts.erase(parts.begin() + 1);
              if (!madeUnique.empty() &&
                  std::none_of(parts.begin(), parts.end(),
                               [&](const aniso::ScenePart& p) { return p.material == madeUnique; }))
              {
                library.remove(madeUnique);
              }
              editor->editParts(parts, library, "Remove part");
            });
      }
      phase = "undo, redo";
      for (int i = 0; i < 2; ++i)
      {
        editor->undoStack()->undo();
        stepDone("edit");
      }
      for (int i = 0; i < 2; ++i)
      {
        editor->undoStack()->redo();
        stepDone("edit");
      }
      // Loads: a file every fifth (the OBJ every twentieth, through the reader program), else
      // a built-in mesh, each until it is the scene's.
      phase = "loads";
      for (int i = 0; i < loadsPerCycle; ++i)
      {
        const long k = long(cycle) * loadsPerCycle + i;
        const QString mesh = k % 20 == 0  ? obj
                             : k % 5 == 0 ? ply
                                          : builtins[std::size_t(k % 5 - 1) % builtins.size()];
        window.openMeshInBackground(mesh);
        waitFor([&] { return !window.meshLoading(); }, 60000);
        if (model->text("mesh") != mesh.toStdString())
        {
          ++loadFailures;
        }
        stepDone("load");
      }
    }
    if (step % kSampleEvery != 0)
    {
      sampleNow("end");
    }
    if (censuses.empty() || censuses.back().step != step)
    {
      censuses.push_back({step, census(renderWindow)});
    }
    seconds = double(clock.elapsed()) * 1e-3;
  }
  // The window is gone: what VTK said while it went (a texture released without its context,
  // say) is in the counts now.
  const long errorsAtExit = output->errors;
  const long warningsAtExit = output->warnings;

  std::FILE* csv = stdout;
  if (!csvPath.empty())
  {
    csv = std::fopen(csvPath.c_str(), "w");
    if (!csv)
    {
      std::fprintf(stderr, "bench_soak: cannot write %s\n", csvPath.c_str());
      return 1;
    }
  }
  std::fprintf(csv, "step,kind,rss_mib,texture_uploads,gl_errors,vtk_errors,vtk_warnings,"
                    "reported,lut_cache_mib,undo_commands,seconds\n");
  for (const Sample& s : samples)
  {
    std::fprintf(csv, "%ld,%s,%.1f,%llu,%ld,%ld,%ld,%ld,%.1f,%d,%.1f\n", s.step, s.kind.c_str(),
                 s.rssMiB, s.uploads, s.glErrors, s.vtkErrors, s.vtkWarnings, s.reported, s.lutMiB,
                 s.undoCommands, s.seconds);
  }
  if (csv != stdout)
  {
    std::fclose(csv);
  }

  // RSS after warm-up, at the end, and its slope over the second half.
  const long lastStep = samples.back().step;
  const auto at = [&](long step) -> const Sample&
  {
    for (const Sample& s : samples)
    {
      if (s.step >= step)
      {
        return s;
      }
    }
    return samples.back();
  };
  std::vector<double> xs, ys, ysLessLut;
  for (const Sample& s : samples)
  {
    if (2 * s.step >= lastStep)
    {
      xs.push_back(double(s.step));
      ys.push_back(s.rssMiB);
      ysLessLut.push_back(s.rssMiB - s.lutMiB);
    }
  }
  const double stepsPerEdit = double(lastStep) / double(edits);
  const double perThousandEdits = slope(xs, ys) * 1000.0 * stepsPerEdit;
  const double perThousandEditsLessLut = slope(xs, ysLessLut) * 1000.0 * stepsPerEdit;

  std::printf("\nsoak: %d edits and %d loads (%d cycles of %d edits and %d loads), window "
              "%dx%d (view %dx%d), a frame waited for every %d steps; "
              "%.0f s\n",
              edits, loads, cycles, kEditsPerCycle, loadsPerCycle, width, height, viewWidth,
              viewHeight, frameEvery, seconds);
  std::printf("window renders: %ld, %.0f s in them (%.1f ms each)\n", renders, renderSeconds,
              renders ? 1e3 * renderSeconds / double(renders) : 0.0);
  std::printf("time by kind of step (s):");
  for (const auto& [name, t] : phaseSeconds)
  {
    std::printf(" %s %.1f;", name.c_str(), t);
  }
  std::printf("\n");
  std::printf("environments: builtin:studio, builtin:white, builtin:sunsky, HDRI %s\n",
              hdriName.c_str());
  std::printf("RSS: start %.1f MiB, step 500 %.1f MiB, end %.1f MiB (peak sample %.1f MiB)\n",
              samples.front().rssMiB, at(500).rssMiB, samples.back().rssMiB,
              std::max_element(samples.begin(), samples.end(),
                               [](const Sample& a, const Sample& b) { return a.rssMiB < b.rssMiB; })
                  ->rssMiB);
  std::printf("RSS slope over steps %ld-%ld: %+.2f MiB per 1000 edits (with the loads between "
              "them); without the LUT cache's memory %+.2f MiB (LUT cache %.1f MiB at the end)\n",
              lastStep / 2, lastStep, perThousandEdits, perThousandEditsLessLut,
              samples.back().lutMiB);
  std::printf("texture uploads: %llu at step 500, %llu at the end\n", at(500).uploads,
              samples.back().uploads);
  std::printf("undo stack: %d commands at the end (%s)\n", samples.back().undoCommands,
              undoLimit > 0 ? ("limit " + std::to_string(undoLimit)).c_str() : "no limit");
  std::printf("GL errors: %ld (glGetError at samples: %ld; the view's OpenGL reports: %ld)\n",
              glErrors + reportedGl, glErrors, reportedGl);
  std::printf("VTK output: %ld errors, %ld warnings during the run; %ld errors, %ld warnings "
              "including the window's destruction\n",
              samples.back().vtkErrors, samples.back().vtkWarnings, errorsAtExit, warningsAtExit);
  std::printf("errors reported by the window: %zu; edits refused: %ld; loads that did not "
              "arrive: %ld; part steps skipped: %ld; waits past their limit: %ld\n",
              reports.size(), editFailures, loadFailures, partStepsSkipped, waitsTimedOut);
  std::set<std::string> distinctReports(reports.begin(), reports.end());
  for (const std::string& r : distinctReports)
  {
    std::printf("  reported: %s\n", r.c_str());
  }
  std::printf("GL names alive (of 1..%u per kind): step, textures, buffers, framebuffers, vertex "
              "arrays, programs, shaders\n",
              kCensusNames - 1);
  for (const CensusRow& row : censuses)
  {
    std::printf("  %6ld %6ld %6ld %6ld %6ld %6ld %6ld\n", row.step, row.gl.textures, row.gl.buffers,
                row.gl.framebuffers, row.gl.vertexArrays, row.gl.programs, row.gl.shaders);
  }
#ifdef VTK_DEBUG_LEAKS
  std::printf("VTK leak report (VTK_DEBUG_LEAKS on):\n");
  vtkDebugLeaks::PrintCurrentLeaks();
#else
  std::printf("VTK leak report: none, this VTK is built without VTK_DEBUG_LEAKS (vtkDebug.h)\n");
#endif

  if (!svgPath.empty())
  {
    aniso::bench::Figure figure;
    figure.title = "Resident memory over a long session (bench_soak)";
    figure.columns = 1;
    figure.panelWidth = 760;
    figure.panelHeight = 380;
    aniso::bench::PlotPanel panel;
    panel.title =
        std::to_string(edits) + " edits and " + std::to_string(loads) + " loads in one process";
    panel.xLabel = "step (edits and loads)";
    panel.yLabel = "RSS (MiB)";
    panel.logX = false;
    panel.logY = false;
    aniso::bench::PlotSeries rss;
    rss.label = "VmRSS, every 100 steps";
    rss.color = {0.12, 0.35, 0.75};
    rss.connect = true;
    rss.markerSize = 2.0;
    for (const Sample& s : samples)
    {
      rss.points.push_back({double(s.step), s.rssMiB});
    }
    panel.series = {rss};
    if (xs.size() >= 2)
    {
      // The fitted line over the second half, whose slope the summary gives.
      aniso::bench::PlotSeries fit;
      char label[96];
      std::snprintf(label, sizeof label,
                    "least squares over the second half: %+.1f MiB per 1000 edits",
                    perThousandEdits);
      fit.label = label;
      fit.color = {0.85, 0.3, 0.1};
      fit.connect = true;
      fit.marker = aniso::bench::Marker::None;
      const double meanX = std::accumulate(xs.begin(), xs.end(), 0.0) / double(xs.size());
      const double meanY = std::accumulate(ys.begin(), ys.end(), 0.0) / double(ys.size());
      for (double x : {xs.front(), xs.back()})
      {
        fit.points.push_back({x, meanY + slope(xs, ys) * (x - meanX)});
      }
      panel.series.push_back(fit);
    }
    figure.panels.push_back(panel);
    std::ofstream svg(svgPath);
    svg << aniso::bench::figureToSvg(figure);
    if (!svg)
    {
      std::fprintf(stderr, "bench_soak: cannot write %s\n", svgPath.c_str());
      return 1;
    }
  }
  return 0;
}
