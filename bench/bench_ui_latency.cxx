// How long the UI thread stalls while the real main window draws: a 5 ms timer on the UI thread
// records the gaps between its ticks while (a) a camera orbit is dragged for 2 s, (b) the n_u
// slider is dragged, (c) the view refines to its target once still, (d) environment sampling
// is switched to mis, (e) a large mesh is opened in the background as the File menu opens it,
// (f) the same opened synchronously, for comparison, (g) the orbit of (a) around that mesh and its
// refinement once still, (h) a scene of 200 parts opened in the background, (i) one part
// selected by a click, (j) its n_u edited, (k) a library material assigned to it. Prints, per
// phase, the largest and the 99th-percentile gap, the frames drawn (window renders: a frame drawn
// in bands counts once per band), the samples per pixel accumulated and the samples per pixel and
// second.
// Run (X server needed): xvfb-run -a -s "-screen 0 1920x1080x24" bench_ui_latency [WxH]
//   [--frame-budget MS] (0: one frame per model sample count, the behaviour without the
//   frame-time budget) [--trace MS] (prints every event whose handling on the UI thread took
//   longer than MS, with its phase, type and receiver: where a long gap comes from)
#include "app/gui/MainWindow.h"
#include "app/gui/SceneView.h"
#include "scene/LutScheduler.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"
#include "widgets/ParameterControls.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QMouseEvent>
#include <QPointer>
#include <QSlider>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkCompositeDataSet.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkSphereSource.h>
#include <vtkXMLMultiBlockDataWriter.h>

namespace
{
struct Phase
{
  std::string name;
  std::vector<double> gapsMs;
  int frames = 0;
  long long samples = 0; // per pixel, summed over the frames
  double seconds = 0.0;
  double rendererMs = 0.0; // summed: the renderer's passes (scene, accumulation, display)
  double windowMs = 0.0;   // summed: the whole window render (also the copy to the widget)
};

// Runs the event loop for MS milliseconds (QTest::qWait sleeps between its passes, which would
// hide the timer's ticks).
void pump(int ms)
{
  QEventLoop loop;
  QTimer::singleShot(ms, Qt::PreciseTimer, &loop, &QEventLoop::quit);
  loop.exec();
}

// The application whose event deliveries can be timed (--trace).
class TracingApplication : public QApplication
{
public:
  using QApplication::QApplication;
  double traceMs = 0.0; // 0: off
  const char* phase = "set-up";

  bool notify(QObject* receiver, QEvent* event) override
  {
    if (traceMs <= 0.0 || depth_ > 0)
    {
      return QApplication::notify(receiver, event);
    }
    const int type = event->type();
    // A delivery may delete its receiver (a single-shot timer's own object): it is described
    // only if it still exists.
    const QPointer<QObject> alive(receiver);
    QElapsedTimer t;
    t.start();
    ++depth_;
    const bool result = QApplication::notify(receiver, event);
    --depth_;
    const double ms = double(t.nsecsElapsed()) * 1e-6;
    if (ms > traceMs)
    {
      const QObject* object = alive.data();
      const QObject* parent = object ? object->parent() : nullptr;
      std::fprintf(stderr, "trace: %-16s %7.1f ms  event %d  receiver %s \"%s\" (parent %s)\n",
                   phase, ms, type, object ? object->metaObject()->className() : "(deleted)",
                   object ? qPrintable(object->objectName()) : "",
                   parent ? parent->metaObject()->className() : "-");
    }
    return result;
  }

private:
  int depth_ = 0; // only the outermost delivery of nested ones is timed
};

double percentile(std::vector<double> v, double q)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  return v[std::min(i, v.size() - 1)];
}
} // namespace

int main(int argc, char** argv)
{
  bool partsOnly = false; // phases (h) to (k) alone
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  TracingApplication app(argc, argv);
  int width = 0;
  int height = 0;
  int budgetMs = -1; // the view's default
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--frame-budget") == 0 && i + 1 < argc)
    {
      budgetMs = std::atoi(argv[++i]);
    }
    else if (std::strcmp(argv[i], "--parts-only") == 0)
    {
      partsOnly = true;
    }
    else if (std::strcmp(argv[i], "--trace") == 0 && i + 1 < argc)
    {
      app.traceMs = std::atof(argv[++i]);
    }
    else if (std::sscanf(argv[i], "%dx%d", &width, &height) != 2)
    {
      std::fprintf(
          stderr,
          "usage: bench_ui_latency [WxH] [--frame-budget MS] [--trace MS] [--parts-only]\n");
      return 2;
    }
  }

  aniso::MainWindow window;
  window.setErrorDialogs(false);
  // The scene these phases were first measured on (docs/BENCHMARKS.md, "UI latency"): the torus
  // in aluminium n_u = 1000, n_v = 50 at the declared exposure, not the window's start-up scene.
  window.model()->setValues({{"mesh", aniso::textValue("builtin:torus")},
                             {"nu", aniso::numberValue(1000.0)},
                             {"nv", aniso::numberValue(50.0)},
                             {"exposure", aniso::numberValue(0.0)}});
  if (width > 0)
  {
    window.resize(width, height);
  }
  window.show();
  if (!QTest::qWaitForWindowExposed(&window))
  {
    std::fprintf(stderr, "bench_ui_latency: the window was not shown\n");
    return 1;
  }
  aniso::SceneView* view = window.view();
  if (budgetMs >= 0)
  {
    view->setFrameBudgetMs(budgetMs);
  }
  QTest::qWait(200);
  // The first image, compiled shaders and baked tables are not what is measured.
  QElapsedTimer wait;
  wait.start();
  while (!(view->converged() && !window.lutScheduler()->busy()) && wait.elapsed() < 120000)
  {
    QTest::qWait(50);
  }

  Phase* current = nullptr;
  QElapsedTimer clock;
  clock.start();
  qint64 last = 0;
  QTimer tick;
  tick.setTimerType(Qt::PreciseTimer);
  tick.setInterval(5);
  QObject::connect(&tick, &QTimer::timeout,
                   [&]
                   {
                     const qint64 now = clock.nsecsElapsed();
                     if (current && last)
                     {
                       current->gapsMs.push_back(double(now - last) * 1e-6);
                     }
                     last = now;
                   });
  // Every frame the window draws (the view's progressive frames and the interactor's own),
  // counted at the renderer's end.
  int lastSamples = 0;
  int lastFrames = 0;
  auto* pass = vtkAnisoAccumulationPass::SafeDownCast(view->renderer()->GetPass());
  vtkNew<vtkCallbackCommand> frameEnd;
  std::function<void()> onFrame = [&]
  {
    const int samples = view->accumulatedSamples();
    const int frames = pass->GetAccumulatedFrames();
    if (current)
    {
      ++current->frames;
      // A band that does not complete a frame adds nothing; a frame that continues the mean
      // adds its samples, one that starts it over counts whole.
      if (pass->GetNextBand() == 0)
      {
        current->samples += frames == lastFrames + 1 ? samples - lastSamples : samples;
      }
    }
    if (pass->GetNextBand() == 0)
    {
      lastSamples = samples;
      lastFrames = frames;
    }
  };
  frameEnd->SetClientData(&onFrame);
  frameEnd->SetCallback([](vtkObject*, unsigned long, void* f, void*)
                        { (*static_cast<std::function<void()>*>(f))(); });
  view->renderer()->AddObserver(vtkCommand::EndEvent, frameEnd);
  // Where a frame's time goes: the renderer's part and the whole window's.
  QElapsedTimer rendererClock;
  QElapsedTimer windowClock;
  std::function<void(unsigned long, bool)> onTiming = [&](unsigned long event, bool renderer)
  {
    QElapsedTimer& c = renderer ? rendererClock : windowClock;
    if (event == vtkCommand::StartEvent)
    {
      c.start();
    }
    else if (current && c.isValid())
    {
      (renderer ? current->rendererMs : current->windowMs) += double(c.nsecsElapsed()) * 1e-6;
    }
  };
  vtkNew<vtkCallbackCommand> rendererTiming;
  vtkNew<vtkCallbackCommand> windowTiming;
  for (vtkCallbackCommand* command : {rendererTiming.Get(), windowTiming.Get()})
  {
    command->SetClientData(&onTiming);
  }
  rendererTiming->SetCallback(
      [](vtkObject*, unsigned long event, void* f, void*)
      { (*static_cast<std::function<void(unsigned long, bool)>*>(f))(event, true); });
  windowTiming->SetCallback(
      [](vtkObject*, unsigned long event, void* f, void*)
      { (*static_cast<std::function<void(unsigned long, bool)>*>(f))(event, false); });
  view->renderer()->AddObserver(vtkCommand::StartEvent, rendererTiming);
  view->renderer()->AddObserver(vtkCommand::EndEvent, rendererTiming);
  vtkRenderWindow* renderWindow = window.vtkWidget()->renderWindow();
  renderWindow->AddObserver(vtkCommand::StartEvent, windowTiming);
  renderWindow->AddObserver(vtkCommand::EndEvent, windowTiming);
  tick.start();

  std::vector<Phase> phases;
  phases.reserve(16);
  const auto run = [&](const char* name, const std::function<void()>& body)
  {
    phases.push_back(Phase{name, {}, 0, 0, 0.0});
    current = &phases.back();
    app.phase = name;
    // The first gap counts from the phase's start (a stall right at the start is the phase's).
    last = clock.nsecsElapsed();
    QElapsedTimer t;
    t.start();
    body();
    current->seconds = double(t.nsecsElapsed()) * 1e-9;
    current = nullptr;
    app.phase = "between phases";
  };
  const auto waitConverged = [&](int limitMs)
  {
    QElapsedTimer t;
    t.start();
    while (!view->converged() && t.elapsed() < limitMs)
    {
      pump(5);
    }
  };

  // (a) A 2 s orbit: the pointer moves 4 px every 16 ms with the left button down, as a hand
  // would; events the UI thread could not take in time pile up as they would for a user.
  QWidget* widget = window.vtkWidget();
  const auto orbit = [&]
  {
    const QPoint start(widget->width() / 3, widget->height() / 2);
    QApplication::postEvent(widget, new QMouseEvent(QEvent::MouseButtonPress, start, Qt::LeftButton,
                                                    Qt::LeftButton, Qt::NoModifier));
    QElapsedTimer t;
    t.start();
    int step = 0;
    while (t.elapsed() < 2000)
    {
      ++step;
      const QPoint p = start + QPoint((4 * step) % (widget->width() / 3), 0);
      QApplication::postEvent(widget, new QMouseEvent(QEvent::MouseMove, p, Qt::NoButton,
                                                      Qt::LeftButton, Qt::NoModifier));
      pump(16);
    }
    QApplication::postEvent(widget, new QMouseEvent(QEvent::MouseButtonRelease, start,
                                                    Qt::LeftButton, Qt::NoButton, Qt::NoModifier));
    pump(20);
  };
  QTemporaryDir meshDir;
  if (!partsOnly)
  {
    run("orbit 2 s", orbit);
    waitConverged(120000);

    // (b) The n_u slider dragged over two decades in 1.5 s (one step every 30 ms).
    auto* nu = window.findChild<aniso::NumberControl*>("nu");
    run("n_u drag 1.5 s",
        [&]
        {
          QSlider* slider = nu->slider();
          const int from = slider->value();
          slider->setSliderDown(true);
          for (int i = 0; i < 50; ++i)
          {
            slider->setValue(from - 4 * i);
            pump(30);
          }
          slider->setSliderDown(false);
        });

    // (c) Still: refinement to the target (the LUT bake of the new exponent included).
    run("refine to target", [&] { waitConverged(120000); });

    // (d) Environment sampling switched on, then refinement with it.
    run("env-sampling mis",
        [&]
        {
          window.editor()->edit("env-sampling", aniso::textValue("mis"));
          pump(50);
          QElapsedTimer t;
          t.start();
          while ((view->lightingBusy() || !view->converged()) && t.elapsed() < 120000)
          {
            pump(5);
          }
        });

    // (e) A large mesh (a 400 x 400 torus grid, 320 000 triangles, written to a temporary OBJ)
    // opened as the File menu and drops open it (read and prepared on a worker), until its first
    // frame is drawn; then (f) the same opened synchronously (openMesh: the model's validation
    // reads it on the UI thread), for comparison.
    const QString bigMesh = meshDir.filePath("big.obj");
    const QString bigMeshAgain = meshDir.filePath("big-again.obj");
    {
      const int n = 400;
      std::string obj;
      obj.reserve(std::size_t(n) * n * 60);
      char line[96];
      for (int i = 0; i < n; ++i)
      {
        for (int j = 0; j < n; ++j)
        {
          const double u = 2.0 * M_PI * i / n;
          const double v = 2.0 * M_PI * j / n;
          std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n",
                        (1.0 + 0.3 * std::cos(v)) * std::cos(u),
                        (1.0 + 0.3 * std::cos(v)) * std::sin(u), 0.3 * std::sin(v));
          obj += line;
        }
      }
      for (int i = 0; i < n; ++i)
      {
        for (int j = 0; j < n; ++j)
        {
          const int a = i * n + j + 1;
          const int b = ((i + 1) % n) * n + j + 1;
          const int c = ((i + 1) % n) * n + (j + 1) % n + 1;
          const int d = i * n + (j + 1) % n + 1;
          std::snprintf(line, sizeof line, "f %d %d %d\nf %d %d %d\n", a, b, c, a, c, d);
          obj += line;
        }
      }
      for (const QString& path : {bigMesh, bigMeshAgain})
      {
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) ||
            file.write(obj.data(), qint64(obj.size())) != qint64(obj.size()))
        {
          std::fprintf(stderr, "bench_ui_latency: cannot write %s\n", qPrintable(path));
          return 1;
        }
      }
    }
    const auto waitMesh = [&](const QString& path)
    {
      QElapsedTimer t;
      t.start();
      while ((window.meshLoading() || window.model()->text("mesh") != path.toStdString() ||
              !view->converged()) &&
             t.elapsed() < 120000)
      {
        pump(5);
      }
    };
    run("open mesh (bg)",
        [&]
        {
          window.openMeshInBackground(bigMesh);
          waitMesh(bigMesh);
        });
    run("open mesh (sync)",
        [&]
        {
          // Posted, so the call runs inside the event loop as a menu action would.
          QTimer::singleShot(0, &window, [&] { window.openMesh(bigMeshAgain); });
          waitMesh(bigMeshAgain);
        });
    // (g) The orbit of (a) around the large mesh (drawn as its stand-in while it moves), then its
    // refinement once still.
    run("orbit large mesh", orbit);
    run("refine large mesh", [&] { waitConverged(120000); });
  }

  // (h) A scene of 200 parts (a VTM of 20 x 10 spheres of 960 triangles, written by VTK's
  // multiblock writer) opened in the background; (i) one part selected by a click;
  // (j) that part's n_u edited; (k) a library material assigned to it. Each until refined.
  const QString partsFile = meshDir.filePath("parts.vtm");
  {
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(200);
    for (unsigned i = 0; i < 200; ++i)
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(double(i % 20), 0.0, double(i / 20));
      sphere->SetRadius(0.4);
      sphere->SetThetaResolution(24);
      sphere->SetPhiResolution(22);
      sphere->Update();
      blocks->SetBlock(i, sphere->GetOutput());
      blocks->GetMetaData(i)->Set(vtkCompositeDataSet::NAME(),
                                  ("sphere " + std::to_string(i)).c_str());
    }
    vtkNew<vtkXMLMultiBlockDataWriter> writer;
    writer->SetFileName(partsFile.toStdString().c_str());
    writer->SetInputData(blocks);
    writer->Write();
  }
  const auto waitSettled = [&]
  {
    QElapsedTimer t;
    t.start();
    while ((window.meshLoading() || window.lutScheduler()->busy() || !view->converged()) &&
           t.elapsed() < 120000)
    {
      pump(5);
    }
  };
  run("open 200 parts (bg)",
      [&]
      {
        window.openMeshInBackground(partsFile);
        QElapsedTimer t;
        t.start();
        while (window.model()->parts().size() != 200 && t.elapsed() < 120000)
        {
          pump(5);
        }
        waitSettled();
      });
  run("select a part",
      [&]
      {
        // A click on the part's centre: VTK's hardware selector names it (SceneView::partAt).
        double bounds[6];
        view->partDrawnSurface(57)->GetBounds(bounds);
        vtkRenderer* renderer = view->renderer();
        renderer->SetWorldPoint(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                                0.5 * (bounds[4] + bounds[5]), 1.0);
        renderer->WorldToDisplay();
        const double* at = renderer->GetDisplayPoint();
        view->clickedAt(int(at[0] + 0.5), int(at[1] + 0.5), false);
        if (window.model()->selection() != std::vector<int>{57})
        {
          std::fprintf(stderr, "the click did not pick part 57\n");
          window.model()->setSelection({57});
        }
        pump(400); // the LUT scheduler's debounce, its bake (a cache hit) and what follows
        waitSettled();
      });
  run("edit its n_u",
      [&]
      {
        window.editor()->edit("nu", aniso::numberValue(321.0));
        pump(400);
        waitSettled();
      });
  run("assign a material",
      [&]
      {
        window.editor()->assignMaterial({57}, "satin gold");
        pump(400);
        waitSettled();
      });
  tick.stop();

  const int* size = window.vtkWidget()->renderWindow()->GetSize();
  std::printf("view %dx%d, window %dx%d, frame budget %s\n", size[0], size[1], window.width(),
              window.height(),
              budgetMs == 0 ? "off" : std::to_string(view->frameBudgetMs()).append(" ms").c_str());
  std::printf("%-18s %9s %9s %9s %7s %9s %10s %8s %18s %16s\n", "phase", "max ms", "p99 ms",
              "p50 ms", "frames", "samples", "samples/s", "time s", "renderer ms/frame",
              "window ms/frame");
  for (const Phase& p : phases)
  {
    const double maxGap =
        p.gapsMs.empty() ? 0.0 : *std::max_element(p.gapsMs.begin(), p.gapsMs.end());
    std::printf("%-18s %9.1f %9.1f %9.1f %7d %9lld %10.1f %8.2f %18.1f %16.1f\n", p.name.c_str(),
                maxGap, percentile(p.gapsMs, 0.99), percentile(p.gapsMs, 0.5), p.frames, p.samples,
                p.seconds > 0.0 ? double(p.samples) / p.seconds : 0.0, p.seconds,
                p.frames ? p.rendererMs / p.frames : 0.0, p.frames ? p.windowMs / p.frames : 0.0);
  }
  return 0;
}
