// The lights dock and the scene's shading keys: the selectors list exactly the registry's models
// and sample materials; adding, editing and removing a light changes the scene's lights once per
// change, to the lights stated here; the lights text reads back to the same lights (and bad
// texts are refused naming the key); the list names each light in words (lightText), its stored
// text the tip; a session brings back the model, sample material and
// lights written into it.
#include "core/error.h"
#include "core/models/models.h"
#include "scene/SceneEditor.h"
#include "scene/SceneShading.h"
#include "scene/Session.h"
#include "widgets/LightsDock.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <cmath>

using aniso::Light;
using aniso::LightType;
using aniso::SceneModel;

namespace
{
Light light(LightType type, double x, double y, double z, double r, double g, double b)
{
  Light l;
  l.type = type;
  l.vector = {x, y, z};
  l.intensity = {r, g, b};
  return l;
}

bool sameLight(const Light& a, const Light& b, double tolerance)
{
  return a.type == b.type && std::abs(a.vector.x - b.vector.x) <= tolerance &&
         std::abs(a.vector.y - b.vector.y) <= tolerance &&
         std::abs(a.vector.z - b.vector.z) <= tolerance && a.intensity == b.intensity;
}

// How many valueChanged signals named KEY the spy caught.
int changesOf(const QSignalSpy& spy, const QString& key)
{
  int n = 0;
  for (const QList<QVariant>& args : spy)
  {
    n += args.at(0).toString() == key ? 1 : 0;
  }
  return n;
}

QString message(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch (const aniso::Error& e)
  {
    return QString::fromUtf8(e.what());
  }
  return {};
}
} // namespace

class TestLightsDock : public QObject
{
  Q_OBJECT

private slots:
  // The model box holds the registry's names in its order, the sample box "uniform" then the
  // sample materials' names; the scene keys accept exactly those.
  void selectorsListTheRegistry()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::LightsDock dock(&editor);
    QCOMPARE(dock.modelBox()->count(), int(aniso::shadingModels().size()));
    for (int i = 0; i < dock.modelBox()->count(); ++i)
    {
      QCOMPARE(dock.modelBox()->itemData(i).toString().toStdString(),
               std::string(aniso::shadingModels()[std::size_t(i)].name));
    }
    QCOMPARE(dock.sampleBox()->count(), int(aniso::sampleMaterials().size()) + 1);
    QCOMPARE(dock.sampleBox()->itemData(0).toString(), QString("uniform"));
    for (int i = 1; i < dock.sampleBox()->count(); ++i)
    {
      QCOMPARE(dock.sampleBox()->itemData(i).toString().toStdString(),
               std::string(aniso::sampleMaterials()[std::size_t(i - 1)].name));
    }
    QCOMPARE(model.text("model"), std::string("as-env"));
    QCOMPARE(dock.modelBox()->currentData().toString(), QString("as-env"));
    QVERIFY(
        message([&] { model.setValue("model", aniso::textValue("phong")); }).startsWith("model:"));
    QVERIFY(message([&] { model.setValue("sample-material", aniso::textValue("wood")); })
                .startsWith("sample-material:"));

    // Choosing in the box is one change of the scene's model, and the box follows the scene.
    QSignalSpy spy(&model, &SceneModel::valueChanged);
    const int ward = dock.modelBox()->findData("ward");
    QVERIFY(ward > 0);
    QMetaObject::invokeMethod(dock.modelBox(), "activated", Q_ARG(int, ward));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(model.text("model"), std::string("ward"));
    model.setValue("sample-material", aniso::textValue("marble"));
    QCOMPARE(dock.sampleBox()->currentData().toString(), QString("marble"));
  }

  // Add, edit and remove: each is one change of "lights", leaving the lights stated here.
  void editsChangeTheLightsOnce()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::installShadingValidators(model);
    const Light first = light(LightType::Point, 1.0, -2.0, 3.0, 2.0, 1.0, 0.5);
    model.setValue("lights", aniso::textValue("point:1,-2,3:2,1,0.5"));
    aniso::LightsDock dock(&editor);
    QCOMPARE(dock.lightList()->count(), 1);
    QCOMPARE(dock.lightList()->currentRow(), 0);
    // The list reads in words (azimuth atan2(1, 2) = 26.57, elevation asin(3 / sqrt(14)) = 53.30,
    // distance sqrt(14) = 3.742); the stored text is its tip.
    QCOMPARE(dock.lightList()->item(0)->text(),
             QString("point at azimuth 26.6, elevation 53.3, distance 3.74, intensity 2, 1, 0.5"));
    QCOMPARE(dock.lightList()->item(0)->toolTip(), QString("point:1,-2,3:2,1,0.5"));
    QCOMPARE(dock.vectorBox(1)->value(), -2.0);
    QCOMPARE(dock.intensityBox(2)->value(), 0.5);

    QSignalSpy spy(&model, &SceneModel::valueChanged);
    dock.addButton()->click(); // a copy of the selected light, selected
    QCOMPARE(spy.count(), 1);
    QCOMPARE(changesOf(spy, "lights"), 1);
    std::vector<Light> lights = dock.lights();
    QCOMPARE(lights.size(), std::size_t(2));
    QVERIFY(sameLight(lights[1], first, 0.0));
    QCOMPARE(dock.lightList()->currentRow(), 1);

    spy.clear();
    dock.intensityBox(0)->setValue(4.0);
    QCOMPARE(spy.count(), 1);
    lights = dock.lights();
    QVERIFY(sameLight(lights[0], first, 0.0));
    QVERIFY(sameLight(lights[1], light(LightType::Point, 1.0, -2.0, 3.0, 4.0, 1.0, 0.5), 0.0));

    // A directional light is stored unit: (3, 0, 4) / 5.
    spy.clear();
    dock.typeBox()->setCurrentIndex(0);
    QCOMPARE(spy.count(), 1);
    QVERIFY(sameLight(dock.lights()[1],
                      light(LightType::Directional, 1.0 / std::sqrt(14.0), -2.0 / std::sqrt(14.0),
                            3.0 / std::sqrt(14.0), 4.0, 1.0, 0.5),
                      1e-15));
    spy.clear();
    dock.vectorBox(0)->setValue(3.0);
    dock.vectorBox(1)->setValue(0.0);
    dock.vectorBox(2)->setValue(4.0);
    QCOMPARE(spy.count(), 3);
    QVERIFY(sameLight(dock.lights()[1], light(LightType::Directional, 0.6, 0.0, 0.8, 4.0, 1.0, 0.5),
                      1e-15));
    // The editors keep what was typed, not the normalised vector.
    QCOMPARE(dock.vectorBox(0)->value(), 3.0);

    // A zero direction is refused: reported, nothing changes.
    spy.clear();
    QSignalSpy errors(&dock, &aniso::LightsDock::errorOccurred);
    dock.vectorBox(0)->setValue(0.0);
    dock.vectorBox(2)->setValue(0.0);
    QCOMPARE(errors.count(), 1);
    QCOMPARE(spy.count(), 1); // only the first edit, (0, 0, 4), was a valid direction
    QVERIFY(sameLight(dock.lights()[1], light(LightType::Directional, 0.0, 0.0, 1.0, 4.0, 1.0, 0.5),
                      0.0));

    spy.clear();
    dock.lightList()->setCurrentRow(0);
    dock.removeButton()->click();
    QCOMPARE(spy.count(), 1);
    lights = dock.lights();
    QCOMPARE(lights.size(), std::size_t(1));
    QVERIFY(lights[0].type == LightType::Directional);
    QCOMPARE(dock.lightList()->count(), 1);

    // Removing the last light leaves a scene without lights (a valid value).
    dock.removeButton()->click();
    QVERIFY(dock.lights().empty());
    QCOMPARE(model.text("lights"), std::string("none"));
    QVERIFY(!dock.removeButton()->isEnabled());
    editor.undoStack()->undo();

    // Undo brings back the removed light.
    editor.undoStack()->undo();
    QCOMPARE(dock.lights().size(), std::size_t(2));
    QVERIFY(sameLight(dock.lights()[0], first, 0.0));
  }

  // formatLightList / parseLightList read back the same lights, awkward numbers included; bad
  // texts are refused with the subject first.
  void lightsTextRoundTrips()
  {
    const std::vector<Light> lights = {
        light(LightType::Point, 1.0 / 3.0, -2.0 / 7.0, 1e-17, 0.1, 1.0 / 9.0, 5e3),
        light(LightType::Directional, 0.0, 0.0, 1.0, 3.0, 3.0, 3.0),
        light(LightType::Directional, -1.0, 0.0, 0.0, 0.0, 0.25, 1.5)};
    const std::vector<Light> back = aniso::parseLightList(aniso::formatLightList(lights), "lights");
    QCOMPARE(back.size(), lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
      QVERIFY(sameLight(back[i], lights[i], 0.0));
    }
    QVERIFY(aniso::parseLightList("", "lights").empty());
    QCOMPARE(aniso::formatLightList({}), std::string("none"));
    QVERIFY(aniso::parseLightList(" none ", "lights").empty());
    QVERIFY(aniso::parseLightList("  ", "lights").empty());
    const std::vector<Light> spaced = aniso::parseLightList(" dir:0,0,2:1 ; point:1,2,3:4 ", "x");
    QCOMPARE(spaced.size(), std::size_t(2));
    QVERIFY(sameLight(spaced[0], light(LightType::Directional, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0), 0.0));
    QVERIFY(sameLight(spaced[1], light(LightType::Point, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0), 0.0));

    QVERIFY(message([] { aniso::parseLightList("dir:0,0,1:1;;dir:0,0,1:1", "lights"); })
                .startsWith("lights: "));
    QVERIFY(
        message([] { aniso::parseLightList("spot:0,0,1:1", "lights"); }).startsWith("lights: "));
    std::string nine;
    for (int i = 0; i < 9; ++i)
    {
      nine += (i ? ";" : "") + std::string("dir:0,0,1:1");
    }
    QVERIFY(message([&] { aniso::parseLightList(nine, "lights"); }).contains("at most 8"));
    QVERIFY(message([&] { aniso::parseLightList(nine.substr(12), "lights"); }).isEmpty());

    // With the validator the scene refuses a bad text and keeps its lights.
    SceneModel model;
    aniso::installShadingValidators(model);
    const std::string before = model.text("lights");
    QVERIFY(!aniso::parseLightList(before, "lights").empty());
    QVERIFY(message([&] { model.setValue("lights", aniso::textValue("dir:0,0,0:1")); })
                .startsWith("lights: "));
    QCOMPARE(model.text("lights"), before);
  }

  // A session written with a model, a sample material and lights opens to the same three.
  void sessionRoundTripsShading()
  {
    QTemporaryDir tmp;
    const QString path = QDir(tmp.path()).filePath("lit.json");
    const std::vector<Light> lights = {
        light(LightType::Point, 0.5, 1.0 / 3.0, 2.0, 7.0, 0.0, 1.0 / 7.0),
        light(LightType::Directional, 0.0, -1.0, 0.0, 2.0, 2.0, 2.0)};
    {
      SceneModel model;
      model.setValues({{"model", aniso::textValue("heidrich-seidel")},
                       {"sample-material", aniso::textValue("brushed-latitudinal")},
                       {"lights", aniso::textValue(aniso::formatLightList(lights))}});
      aniso::SessionFile().save(model, path);
    }
    SceneModel loaded;
    aniso::installShadingValidators(loaded);
    aniso::SceneEditor editor(&loaded);
    aniso::SessionFile session;
    QVERIFY(session.open(editor, path).isEmpty());
    QCOMPARE(loaded.text("model"), std::string("heidrich-seidel"));
    QCOMPARE(loaded.text("sample-material"), std::string("brushed-latitudinal"));
    const std::vector<Light> back = aniso::parseLightList(loaded.text("lights"), "lights");
    QCOMPARE(back.size(), lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
      QVERIFY(sameLight(back[i], lights[i], 0.0));
    }
  }
};

QTEST_MAIN(TestLightsDock)
#include "test_lights_dock.moc"
