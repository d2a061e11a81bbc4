// Scenes of many parts (scene/SceneModel, SceneEditor, Session): the part list with references
// into the material library, edits reaching exactly the materials of the edited parts (checked
// against the library's values set here), make unique, undo restoring the library whatever is
// selected by then, and the session round trip of a multi-part scene (exact) and of a session of
// the single-material version (one part).
#include "core/error.h"
#include "scene/SceneEditor.h"
#include "scene/SceneModel.h"
#include "scene/Session.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>
#include <string>
#include <vector>

using aniso::MaterialLibrary;
using aniso::numberValue;
using aniso::SceneModel;
using aniso::ScenePart;

namespace
{
ScenePart part(const std::string& name, const std::string& material)
{
  ScenePart p;
  p.name = name;
  p.mesh = "/data/gearbox.obj";
  p.block = name;
  p.group = "gearbox.obj";
  p.material = material;
  return p;
}

// Housing and cover share brushed steel; the shaft is turned brass.
void gearbox(SceneModel& model)
{
  model.setParts({part("housing", "brushed steel"), part("shaft", "turned brass"),
                  part("cover", "brushed steel")},
                 aniso::builtinMaterials());
}

double nuOf(const SceneModel& model, const std::string& material)
{
  return model.materials().at(material).value("nu").number[0];
}
} // namespace

class TestSceneParts : public QObject
{
  Q_OBJECT

private slots:
  // A new scene is one part of the default mesh with the start-up material, and the material
  // keys are that material's.
  void aNewSceneIsOnePart()
  {
    SceneModel model;
    QCOMPARE(model.parts().size(), std::size_t(1));
    QCOMPARE(model.parts()[0].name, std::string("sphere"));
    QCOMPARE(model.parts()[0].material, std::string(aniso::kStartMaterialName));
    QCOMPARE(model.real("nu"), nuOf(model, std::string(aniso::kStartMaterialName)));
  }

  // With nothing selected an edit reaches every part's material; with a part selected, only
  // its material (so also the parts sharing it) and no other.
  void editsReachTheEditedPartsMaterials()
  {
    SceneModel model;
    gearbox(model);
    const double brass = nuOf(model, "turned brass");
    QSignalSpy materials(&model, &SceneModel::materialsChanged);
    model.setSelection({0});
    QCOMPARE(model.real("nu"), nuOf(model, "brushed steel"));
    model.setValue("nu", numberValue(123.0));
    QCOMPARE(nuOf(model, "brushed steel"), 123.0);
    QCOMPARE(nuOf(model, "turned brass"), brass);
    QCOMPARE(materials.count(), 1);
    QCOMPARE(materials.at(0).at(0).toStringList(), QStringList{"brushed steel"});

    model.setSelection({1});
    QCOMPARE(model.real("nu"), brass); // the docks now show the shaft's material
    model.setSelection({});
    QVERIFY(model.mixed("nu"));
    model.setValue("nu", numberValue(77.0));
    QCOMPARE(nuOf(model, "brushed steel"), 77.0);
    QCOMPARE(nuOf(model, "turned brass"), 77.0);
    QVERIFY(!model.mixed("nu"));
    QVERIFY(!model.mixed("exposure")); // a scene key is never mixed
  }

  // Make unique gives the part a copy; editing it leaves the part it shared with as it was;
  // undo brings the shared material back.
  void makeUniqueSplitsAPartsMaterialOff()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    gearbox(model);
    editor.makeUnique({2});
    const std::string copy = model.parts()[2].material;
    QCOMPARE(copy, std::string("brushed steel (cover)"));
    QCOMPARE(model.materials().at(copy).values, model.materials().at("brushed steel").values);
    model.setSelection({2});
    editor.edit("nu", numberValue(5.0));
    QCOMPARE(nuOf(model, copy), 5.0);
    QCOMPARE(nuOf(model, "brushed steel"), 800.0);
    editor.undoStack()->undo(); // the edit
    editor.undoStack()->undo(); // make unique
    QCOMPARE(model.parts()[2].material, std::string("brushed steel"));
    QVERIFY(!model.materials().contains(copy));
    // A part that is alone with its material stays as it is.
    editor.makeUnique({1});
    QCOMPARE(model.parts()[1].material, std::string("turned brass"));
  }

  // Undo of a material edit restores the materials it changed even after the selection moved
  // to a part of another material; redo sets them again.
  void undoRestoresTheLibraryWhateverIsSelected()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    gearbox(model);
    model.setSelection({1});
    const int drag = editor.beginDrag();
    editor.edit("nu", numberValue(300.0), drag);
    editor.edit("nu", numberValue(400.0), drag);
    QCOMPARE(editor.undoStack()->count(), 1); // a drag is one step
    model.setSelection({0});
    editor.undoStack()->undo();
    QCOMPARE(nuOf(model, "turned brass"), 2000.0);
    QCOMPARE(nuOf(model, "brushed steel"), 800.0);
    QCOMPARE(model.real("nu"), 800.0); // the selected housing's
    editor.undoStack()->redo();
    QCOMPARE(nuOf(model, "turned brass"), 400.0);
    QCOMPARE(nuOf(model, "brushed steel"), 800.0);
  }

  void assignAndHideAreUndoable()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    MaterialLibrary small;
    small.put(aniso::defaultMaterial("plain"));
    model.setParts({part("a", "plain"), part("b", "plain")}, small);
    editor.assignMaterial({1}, "satin gold"); // a built-in metal joins the library
    QCOMPARE(model.parts()[1].material, std::string("satin gold"));
    QVERIFY(model.materials().contains("satin gold"));
    editor.setPartsVisible({0}, false);
    QVERIFY(!model.parts()[0].visible);
    editor.undoStack()->undo();
    editor.undoStack()->undo();
    QCOMPARE(model.parts()[1].material, std::string("plain"));
    QVERIFY(model.parts()[0].visible);
    QVERIFY(!model.materials().contains("satin gold"));
    bool threw = false;
    try
    {
      editor.assignMaterial({0}, "unobtainium");
    }
    catch (const aniso::Error& e)
    {
      threw = QString(e.what()).startsWith("unobtainium: no such material");
    }
    QVERIFY(threw);
  }

  // Bad part lists are refused with the reason, and the scene stays as it was.
  void badPartListsChangeNothing()
  {
    SceneModel model;
    gearbox(model);
    const auto before = model.parts();
    const auto expectError = [&](std::vector<ScenePart> parts, const char* reason)
    {
      try
      {
        model.setParts(std::move(parts), aniso::builtinMaterials());
        QFAIL("no error");
      }
      catch (const aniso::Error& e)
      {
        QVERIFY2(QString(e.what()).contains(reason), e.what());
      }
      QCOMPARE(model.parts(), before);
    };
    expectError({}, "at least one part");
    expectError({part("a", "brushed steel"), part("a", "turned brass")}, "two parts are named");
    expectError({part("a", "unobtainium")}, "is not in the library");
  }

  // Opening another mesh makes the scene one part of it, with the edited material.
  void aNewMeshIsOnePart()
  {
    SceneModel model;
    gearbox(model);
    model.setSelection({1});
    QSignalSpy parts(&model, &SceneModel::partsChanged);
    model.setValue("mesh", aniso::textValue("builtin:torus"));
    QCOMPARE(parts.count(), 1);
    QCOMPARE(model.parts().size(), std::size_t(1));
    QCOMPARE(model.parts()[0].name, std::string("torus"));
    QCOMPARE(model.parts()[0].material, std::string("turned brass"));
    QVERIFY(model.selection().empty());
  }

  // A multi-part scene survives a session exactly; opening it is one undoable step.
  void sessionRoundTripIsExact()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    gearbox(model);
    editor.makeUnique({2});
    model.setSelection({2});
    editor.edit("f0", aniso::colorValue(0.25, 0.5, 0.125));
    editor.setPartsVisible({1}, false);
    std::vector<ScenePart> placed = model.parts();
    placed[1].placement = {0, -1, 0, 0.25, 1, 0, 0, -3.5, 0, 0, 1, 1e-3, 0, 0, 0, 1};
    editor.editParts(placed, model.materials(), "Place");
    const QJsonObject json = aniso::sessionToJson(model, {}, "/data");
    QVERIFY(!json["parts"].toArray()[0].toObject().contains("placement")); // the identity
    QCOMPARE(json["parts"].toArray()[1].toObject()["placement"].toArray().size(), 16);
    QCOMPARE(json["version"].toInt(), aniso::kSessionVersion);
    QCOMPARE(json["parts"].toArray()[0].toObject()["mesh"].toString(), QString("gearbox.obj"));

    const aniso::SessionContent content = aniso::sessionFromJson(json, "/data", "s.json");
    QCOMPARE(content.parts, model.parts());
    QVERIFY(content.library == model.materials());

    SceneModel other;
    aniso::SceneEditor otherEditor(&other);
    otherEditor.replaceScene(content.values, content.camera, content.parts, content.library,
                             "Open");
    QCOMPARE(other.parts(), model.parts());
    QVERIFY(other.materials() == model.materials());
    QCOMPARE(other.text("mesh"), model.text("mesh"));
    otherEditor.undoStack()->undo();
    QCOMPARE(other.parts().size(), std::size_t(1));
    QCOMPARE(other.parts()[0].name, std::string("sphere"));
  }

  // A session of the single-material version (no parts) opens as one part of its mesh with a
  // material of its parameters.
  void versionOneSessionsOpenAsOnePart()
  {
    const QByteArray v1 = R"({"format": "aniso-session", "version": 1,
      "parameters": {"nu": 321, "f0": [0.5, 0.5, 0.5]},
      "assets": {"mesh": "builtin:sphere"}})";
    const aniso::SessionContent content =
        aniso::sessionFromJson(QJsonDocument::fromJson(v1).object(), {}, "old.json");
    QCOMPARE(content.parts.size(), std::size_t(1));
    QCOMPARE(content.parts[0].name, std::string("sphere"));
    const aniso::Material& m = content.library.at(content.parts[0].material);
    QCOMPARE(m.value("nu").number[0], 321.0);
    QCOMPARE(m.value("f0").number[1], 0.5);
    QCOMPARE(content.parts[0].material, std::string("material"));

    // Defaults only: the default material itself, nothing added.
    const QByteArray plain = R"({"format": "aniso-session", "version": 1})";
    const aniso::SessionContent d =
        aniso::sessionFromJson(QJsonDocument::fromJson(plain).object(), {}, "old.json");
    QCOMPARE(d.parts[0].material, std::string(aniso::kDefaultMaterialName));
    QVERIFY(d.library == aniso::builtinMaterials());
  }

  void badPartsSectionsNameTheEntry()
  {
    const auto errorOf = [](const QByteArray& text)
    {
      try
      {
        aniso::sessionFromJson(QJsonDocument::fromJson(text).object(), {}, "s.json");
      }
      catch (const aniso::Error& e)
      {
        return QString(e.what());
      }
      return QString();
    };
    QString e = errorOf(R"({"format": "aniso-session", "version": 2, "materials": {},
      "parts": [{"name": "a", "mesh": "builtin:sphere", "material": "missing"}]})");
    QVERIFY2(e.startsWith("s.json: parts: ") && e.contains("missing"), qPrintable(e));
    e = errorOf(R"({"format": "aniso-session", "version": 2, "materials": {},
      "parts": [{"mesh": "builtin:sphere", "material": "x"}]})");
    QVERIFY2(e.startsWith("s.json: parts/1/name: expected a text"), qPrintable(e));
    e = errorOf(R"({"format": "aniso-session", "version": 2, "materials": {"m": {}},
      "parts": [{"name": "a", "mesh": "builtin:sphere", "material": "m",
                 "placement": [1,0,0,0, 0,1,0,0, 0,0,0,0, 0,0,0,1]}]})");
    QVERIFY2(e.startsWith("s.json: parts/1/placement: ") && e.contains("singular"),
             qPrintable(e));
    e = errorOf(R"({"format": "aniso-session", "version": 2, "materials": {"m": {}},
      "parts": [{"name": "a", "mesh": "builtin:sphere", "material": "m", "placement": [1, 2]}]})");
    QVERIFY2(e.startsWith("s.json: parts/1/placement: expected an array of 16"), qPrintable(e));
    e = errorOf(R"({"format": "aniso-session", "version": 2,
      "materials": {"m": {"nu": "high"}}, "parts": []})");
    QVERIFY2(e.startsWith("s.json: materials: material \"m\": nu: expected a number"),
             qPrintable(e));
  }
};

QTEST_MAIN(TestSceneParts)
#include "test_scene_parts.moc"
