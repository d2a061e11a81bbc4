// Lookup tables follow the material off the UI thread: a slider drag gives exactly one bake
// once it settles, returning to earlier values is a memory hit of the LutCache (its stats are
// the reference), the latest of two quick requests wins, and the previews show the LUT texels
// where the stated layout puts them (checked against core's sampler directly).
#include "core/lut/lut_cache.h"
#include "scene/LutScheduler.h"
#include "scene/SceneEditor.h"
#include "widgets/LutView.h"
#include "widgets/MaterialDock.h"
#include "widgets/ParameterControls.h"
#include "widgets/SliderMapping.h"

#include <QSignalSpy>
#include <QSlider>
#include <QtTest>
#include <cmath>

using aniso::numberValue;

namespace
{
// Small tables keep each bake to milliseconds.
void smallTables(aniso::SceneModel& model)
{
  model.setValues({{"lut-size", numberValue(16.0)}, {"lut-samples", numberValue(32.0)}});
}
} // namespace

class TestLutScheduler : public QObject
{
  Q_OBJECT

private slots:
  // Ten slider steps 20 ms apart under a 200 ms debounce: the model follows every step, and
  // one bake starts, for the final values, after the drag ends.
  void aDragGivesExactlyOneBake()
  {
    aniso::SceneModel model;
    smallTables(model);
    aniso::SceneEditor editor(&model);
    aniso::MaterialDock dock(&editor);
    aniso::LutCache cache("none");
    aniso::LutScheduler scheduler(&model, &cache);
    scheduler.setDebounceMs(200);
    QSignalSpy started(&scheduler, &aniso::LutScheduler::bakeStarted);
    QSignalSpy ready(&scheduler, &aniso::LutScheduler::lutsReady);

    QSlider* slider = dock.findChild<aniso::NumberControl*>("nu")->slider();
    slider->setSliderDown(true);
    for (int p = 600; p <= 690; p += 10)
    {
      slider->setValue(p);
      QCOMPARE(model.real("nu"), aniso::sliderValue(aniso::parameterSpec("nu"), p));
      QTest::qWait(20);
    }
    slider->setSliderDown(false);
    QCOMPARE(started.count(), 0);
    QVERIFY(scheduler.busy());
    QVERIFY(ready.wait(10000));
    QTest::qWait(400);
    QCOMPARE(started.count(), 1);
    QCOMPARE(ready.count(), 1);
    QCOMPARE(cache.stats().bakes, uint64_t(2)); // one half-vector and one BRDF table
    const auto result = ready.at(0).at(0).value<aniso::LutResult>();
    QCOMPARE(result.request.lobe.nu, model.real("nu"));
    QCOMPARE(result.request.lobe.nv, model.real("nv"));
    QCOMPARE(result.halfVector->size, 16);
    QCOMPARE(result.brdf->samples, 32);
    QVERIFY(!scheduler.busy());
  }

  // A, B, then A again: the third request bakes nothing (LutCache stats) and hands back the
  // very tables of the first.
  void returningToEarlierValuesHitsTheCache()
  {
    aniso::SceneModel model;
    smallTables(model);
    aniso::LutCache cache("none");
    aniso::LutScheduler scheduler(&model, &cache);
    scheduler.setDebounceMs(10);
    QSignalSpy ready(&scheduler, &aniso::LutScheduler::lutsReady);
    const auto settle = [&](double nu)
    {
      const int before = ready.count();
      model.setValue("nu", numberValue(nu));
      QVERIFY(ready.wait(10000));
      QCOMPARE(ready.count(), before + 1);
    };
    settle(20000.0);
    const aniso::LutResult first = scheduler.current();
    QVERIFY(first.baked);
    settle(70.0);
    const aniso::LutCacheStats afterTwo = cache.stats();
    QCOMPARE(afterTwo.bakes, uint64_t(4));
    settle(20000.0);
    const aniso::LutCacheStats afterThree = cache.stats();
    QCOMPARE(afterThree.bakes, afterTwo.bakes);
    QCOMPARE(afterThree.memoryHits, afterTwo.memoryHits + 2);
    QVERIFY(!scheduler.current().baked);
    QCOMPARE(scheduler.current().halfVector.get(), first.halfVector.get());
    QCOMPARE(scheduler.current().brdf.get(), first.brdf.get());
  }

  // Two requests in a row: only the latest is delivered.
  void latestRequestWins()
  {
    aniso::SceneModel model;
    smallTables(model);
    aniso::LutCache cache("none");
    aniso::LutScheduler scheduler(&model, &cache);
    QSignalSpy ready(&scheduler, &aniso::LutScheduler::lutsReady);
    model.setValue("nu", numberValue(500.0));
    scheduler.requestNow();
    model.setValue("nu", numberValue(900.0));
    scheduler.requestNow();
    QVERIFY(ready.wait(10000));
    scheduler.waitForIdle();
    QTest::qWait(50);
    QCOMPARE(ready.count(), 1);
    QCOMPARE(scheduler.current().request.lobe.nu, 900.0);
  }

  // Preview layout: texel (i, j) of the half-vector LUT is pixel (i, size - 1 - j) with colour
  // (h + 1) / 2, h = sampleHalfVector at the texel centre (core's sampler, not the LUT).
  void previewsShowTexelsWhereStated()
  {
    const aniso::AsLobe lobe{300.0, 30.0};
    const aniso::HalfVectorLut lut = aniso::bakeHalfVectorLut(lobe, 8);
    const QImage image = aniso::halfVectorPreview(lut);
    QCOMPARE(image.size(), QSize(8, 8));
    for (int j = 0; j < 8; ++j)
    {
      for (int i = 0; i < 8; ++i)
      {
        const glm::dvec3 h = aniso::sampleHalfVector(lobe, {(i + 0.5) / 8.0, (j + 0.5) / 8.0});
        const QRgb pixel = image.pixel(i, 7 - j);
        QVERIFY(std::abs(qRed(pixel) - (h.x + 1.0) / 2.0 * 255.0) <= 1.0);
        QVERIFY(std::abs(qGreen(pixel) - (h.y + 1.0) / 2.0 * 255.0) <= 1.0);
        QVERIFY(std::abs(qBlue(pixel) - (h.z + 1.0) / 2.0 * 255.0) <= 1.0);
      }
    }
    double range[2];
    aniso::pdfPreview(lut, range);
    const double peak = std::log2(aniso::pdfHalfVector(lobe, {0.0, 0.0, 1.0}));
    QVERIFY(range[1] <= peak + 1e-3);
    QVERIFY(range[0] < range[1]);
  }

  // The view shows what was baked.
  void viewShowsParameters()
  {
    aniso::SceneModel model;
    smallTables(model);
    aniso::LutCache cache("none");
    aniso::LutScheduler scheduler(&model, &cache);
    aniso::LutView view(&scheduler);
    QSignalSpy ready(&scheduler, &aniso::LutScheduler::lutsReady);
    scheduler.requestNow();
    QVERIFY(ready.wait(10000));
    QVERIFY2(view.infoText().contains("n_u = 10000, n_v = 20; 16 × 16 texels, 32 samples"),
             qPrintable(view.infoText()));
  }
};

QTEST_MAIN(TestLutScheduler)
#include "test_lut_scheduler.moc"
