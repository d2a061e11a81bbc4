// How long the UI thread stalls while the material dock's sliders move and the lookup tables
// are rebaked (LutScheduler: debounced, off the UI thread, stale bakes cancelled). Prints the
// largest gap between ticks of a 5 ms timer on the UI thread, and the bake and cache-hit
// times. Run: QT_QPA_PLATFORM=offscreen bench_lut_latency [LUT_SIZE LUT_SAMPLES]
#include "core/lut/lut_cache.h"
#include "scene/LutScheduler.h"
#include "scene/SceneEditor.h"
#include "widgets/MaterialDock.h"
#include "widgets/ParameterControls.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QSlider>
#include <QTimer>
#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv)
{
  QApplication app(argc, argv);
  const int size = argc > 1 ? std::atoi(argv[1]) : 128;
  const int samples = argc > 2 ? std::atoi(argv[2]) : 4096;
  aniso::SceneModel model;
  // The lobe of the declared default material (brushed aluminium), as first measured, not the
  // start-up scene's.
  model.setValues({{"lut-size", aniso::numberValue(size)},
                   {"lut-samples", aniso::numberValue(samples)},
                   {"nu", aniso::numberValue(1000.0)},
                   {"nv", aniso::numberValue(50.0)}});
  aniso::SceneEditor editor(&model);
  aniso::MaterialDock dock(&editor);
  aniso::LutCache cache("none");
  aniso::LutScheduler scheduler(&model, &cache);

  // The UI thread's responsiveness: the largest gap between 5 ms ticks.
  QElapsedTimer clock;
  clock.start();
  qint64 last = 0;
  qint64 worst = 0;
  QTimer tick;
  tick.setInterval(5);
  QObject::connect(&tick, &QTimer::timeout,
                   [&]
                   {
                     const qint64 now = clock.nsecsElapsed();
                     if (last)
                     {
                       worst = std::max(worst, now - last);
                     }
                     last = now;
                   });
  tick.start();

  int started = 0;
  QObject::connect(&scheduler, &aniso::LutScheduler::bakeStarted, [&] { ++started; });
  QSignalSpy ready(&scheduler, &aniso::LutScheduler::lutsReady);
  QSlider* slider = dock.findChild<aniso::NumberControl*>("nu")->slider();
  const auto drag = [&](int from, int to, int pauseMs)
  {
    slider->setSliderDown(true);
    const int step = from < to ? 10 : -10;
    for (int p = from; p != to + step; p += step)
    {
      slider->setValue(p);
      QElapsedTimer wait;
      wait.start();
      while (wait.elapsed() < pauseMs)
      {
        app.processEvents(QEventLoop::AllEvents, 5);
      }
    }
    slider->setSliderDown(false);
  };
  const auto settle = [&]
  {
    while (scheduler.busy())
    {
      app.processEvents(QEventLoop::AllEvents, 5);
    }
  };

  // 1. A drag, then its single bake.
  drag(500, 700, 30);
  settle();
  const double first = scheduler.current().seconds;
  // 2. A drag that pauses past the debounce halfway, so a bake starts and is overtaken.
  drag(700, 600, 30);
  QElapsedTimer pause;
  pause.start();
  while (pause.elapsed() < 300)
  {
    app.processEvents(QEventLoop::AllEvents, 5);
  }
  drag(600, 550, 30);
  settle();
  // 3. Back to the first drag's end: a cache hit.
  slider->setValue(700);
  settle();
  const double hit = scheduler.current().seconds;
  std::printf("LUT %dx%d, %d samples per BRDF texel\n", size, size, samples);
  std::printf("bakes started: %d, delivered: %d, baked by the cache: %llu\n", started,
              static_cast<int>(ready.count()),
              static_cast<unsigned long long>(cache.stats().bakes));
  std::printf("first bake: %.1f ms; back to earlier values (cache hit): %.2f ms\n", first * 1e3,
              hit * 1e3);
  std::printf("largest UI-thread gap between 5 ms ticks: %.1f ms\n",
              static_cast<double>(worst) / 1e6);
  return 0;
}
