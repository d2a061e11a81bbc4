// The environment dock's sources: under the built-in sun-sky the dock lists one source, of kind
// sun, at the azimuth and elevation of the environment's own sun direction (computed here from
// SunSkyEnvironment::sun(), in the convention the dock states: 0 towards -Y, 90 towards +X),
// and its preview is the environment's thumbnail with a ring drawn around the sun's pixel
// (directionToEquirect's (u, v) at x = u W, y = (1 - v) H) and nothing changed elsewhere; under
// the uniform white environment it lists none and marks nothing; quick switches show only the
// latest environment; a file that cannot be analysed is reported with its name.
#include "core/env/environment.h"
#include "core/env/sun_sky.h"
#include "scene/SceneEditor.h"
#include "widgets/EnvironmentDock.h"
#include "widgets/EnvironmentThumbnails.h"

#include <QFile>
#include <QLabel>
#include <QPixmap>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <memory>

using aniso::textValue;

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kWait = 120000; // ms: the analysis samples the sun densely

// "26.6°" -> 26.6
double degreesIn(const QTableWidget* table, int row, int column)
{
  QString text = table->item(row, column)->text();
  text.remove(QChar(0x00B0));
  bool ok = false;
  const double value = text.toDouble(&ok);
  return ok ? value : std::nan("");
}

QImage previewOf(const aniso::EnvironmentDock& dock)
{
  const QPixmap pixmap = dock.sourcesPreview()->pixmap(Qt::ReturnByValue);
  return pixmap.isNull() ? QImage() : pixmap.toImage().convertToFormat(QImage::Format_RGB32);
}

QImage thumbnailOf(const aniso::Environment& env, int width)
{
  return aniso::environmentThumbnail(env, width).convertToFormat(QImage::Format_RGB32);
}

bool samePixel(const QImage& a, const QImage& b, int x, int y)
{
  return (a.pixel(x, y) & 0xFFFFFF) == (b.pixel(x, y) & 0xFFFFFF);
}
} // namespace

class TestEnvironmentDockSources : public QObject
{
  Q_OBJECT

private slots:
  void sunSkyListsItsSun()
  {
    QTemporaryDir dir;
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    // Set before the dock is made, so it analyses the sun-sky first (the studio's analysis
    // samples it at 1024 x 512, over a second).
    model.setValue("env", textValue("builtin:sunsky"));
    aniso::EnvironmentDock dock(&editor, dir.path());
    QSignalSpy errors(&dock, &aniso::EnvironmentDock::errorOccurred);
    QTRY_VERIFY_WITH_TIMEOUT(!dock.analysing(), kWait);
    QCOMPARE(dock.analysedSpec(), QString("builtin:sunsky"));
    QCOMPARE(errors.count(), 0);

    const auto env = std::dynamic_pointer_cast<aniso::SunSkyEnvironment>(
        aniso::openEnvironment("builtin:sunsky"));
    QVERIFY(env);
    const glm::dvec3 sun = env->sun().direction;
    const double azimuth = std::fmod(std::atan2(sun.x, -sun.y) * 180.0 / kPi + 360.0, 360.0);
    const double elevation =
        std::asin(sun.z / std::sqrt(sun.x * sun.x + sun.y * sun.y + sun.z * sun.z)) * 180.0 / kPi;
    // Within the sun's own radius (0.27 degrees), and the table's rounding to 0.1.
    const double tolerance = env->sun().angularRadius * 180.0 / kPi + 0.05;

    const QTableWidget* table = dock.sourcesTable();
    QCOMPARE(table->rowCount(), 1);
    QCOMPARE(table->item(0, 0)->text(), QString("sun"));
    QVERIFY2(std::abs(degreesIn(table, 0, 1) - azimuth) < tolerance,
             qPrintable(table->item(0, 1)->text() + " vs " + QString::number(azimuth)));
    QVERIFY2(std::abs(degreesIn(table, 0, 2) - elevation) < tolerance,
             qPrintable(table->item(0, 2)->text() + " vs " + QString::number(elevation)));
    QVERIFY2(dock.sourcesSummary()->text().startsWith("1 source carries "),
             qPrintable(dock.sourcesSummary()->text()));
    // The environment turned by 30 degrees counter-clockwise about Z: the world's azimuth
    // grows by 30, the elevation stays.
    model.setValue("env-rotation", aniso::numberValue(30.0));
    QVERIFY2(std::abs(degreesIn(table, 0, 1) - std::fmod(azimuth + 30.0, 360.0)) < tolerance,
             qPrintable(table->item(0, 1)->text()));
    QVERIFY(std::abs(degreesIn(table, 0, 2) - elevation) < tolerance);
    model.setValue("env-rotation", aniso::numberValue(0.0));

    // The preview is the thumbnail, with a ring of kMinimumMarkRadius (the sun is far smaller
    // than a texel) around the sun's pixel, and unchanged beyond it.
    const QImage preview = previewOf(dock);
    QVERIFY(!preview.isNull());
    const QImage plain = thumbnailOf(*env, preview.width());
    QCOMPARE(plain.size(), preview.size());
    const glm::dvec2 uv = aniso::directionToEquirect(sun);
    const double cx = uv.x * preview.width();
    const double cy = (1.0 - uv.y) * preview.height();
    const int r = aniso::kMinimumMarkRadius;
    for (const QPointF offset : {QPointF(r, 0), QPointF(-r, 0), QPointF(0, r), QPointF(0, -r)})
    {
      const int x = int(std::floor(cx + offset.x()));
      const int y = int(std::floor(cy + offset.y()));
      QVERIFY2(!samePixel(preview, plain, x, y), qPrintable(QString("%1 %2").arg(x).arg(y)));
    }
    int changedFar = 0;
    for (int y = 0; y < preview.height(); ++y)
    {
      for (int x = 0; x < preview.width(); ++x)
      {
        if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) > r + 3.0 && !samePixel(preview, plain, x, y))
        {
          ++changedFar;
        }
      }
    }
    QCOMPARE(changedFar, 0);
  }

  void whiteShowsNoSources()
  {
    QTemporaryDir dir;
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    model.setValue("env", textValue("builtin:white"));
    aniso::EnvironmentDock dock(&editor, dir.path());
    QTRY_VERIFY_WITH_TIMEOUT(!dock.analysing(), kWait);
    QCOMPARE(dock.analysedSpec(), QString("builtin:white"));
    QCOMPARE(dock.sourcesTable()->rowCount(), 0);
    QVERIFY2(dock.sourcesSummary()->text().startsWith("no concentrated sources"),
             qPrintable(dock.sourcesSummary()->text()));
    const QImage preview = previewOf(dock);
    QVERIFY(!preview.isNull());
    QCOMPARE(preview, thumbnailOf(*aniso::openEnvironment("builtin:white"), preview.width()));
  }

  // Three environments chosen while the first one's analysis runs: only the last one is shown
  // (the sun-sky's result, which came back while others were asked for, is not).
  void latestRequestWins()
  {
    QTemporaryDir dir;
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    model.setValue("env", textValue("builtin:sunsky"));
    aniso::EnvironmentDock dock(&editor, dir.path());
    QSignalSpy shown(&dock, &aniso::EnvironmentDock::sourcesShown);
    QVERIFY(dock.analysing());
    model.setValue("env", textValue("builtin:studio"));
    model.setValue("env", textValue("builtin:sunsky"));
    model.setValue("env", textValue("builtin:white"));
    QTRY_VERIFY_WITH_TIMEOUT(!dock.analysing(), kWait);
    QCOMPARE(dock.analysedSpec(), QString("builtin:white"));
    QCOMPARE(dock.sourcesTable()->rowCount(), 0);
    QCOMPARE(shown.count(), 1);
  }

  void failureNamesTheEnvironment()
  {
    QTemporaryDir dir;
    const QString broken = dir.filePath("broken.exr");
    {
      QFile f(broken);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("this is not an image");
    }
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    model.setValue("env", textValue("builtin:white"));
    const QTemporaryDir empty;
    aniso::EnvironmentDock dock(&editor, empty.path());
    QSignalSpy errors(&dock, &aniso::EnvironmentDock::errorOccurred);
    QTRY_VERIFY_WITH_TIMEOUT(!dock.analysing(), kWait);
    QCOMPARE(dock.analysedSpec(), QString("builtin:white"));
    model.setValue("env", textValue(broken.toStdString()));
    QTRY_VERIFY_WITH_TIMEOUT(!dock.analysing(), kWait);
    QCOMPARE(errors.count(), 1);
    QVERIFY2(errors.at(0).at(0).toString().startsWith("broken.exr: "),
             qPrintable(errors.at(0).at(0).toString()));
    QVERIFY(dock.analysedSpec().isEmpty());
    QVERIFY(!dock.analysis());
    QCOMPARE(dock.sourcesTable()->rowCount(), 0);
  }
};

QTEST_MAIN(TestEnvironmentDockSources)
#include "test_environment_dock_sources.moc"
