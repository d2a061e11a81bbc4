// SceneModel and SceneEditor: the model holds exactly the declared parameters with their
// declared defaults, validates by the declared range and choices, signals each change once, and
// the editor's undo stack steps back through changes, a drag being one step.
#include "core/error.h"
#include "scene/SceneEditor.h"
#include "scene/SceneModel.h"

#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>
#include <map>
#include <string>
#include <vector>

using aniso::colorValue;
using aniso::numberValue;
using aniso::SceneModel;
using aniso::textValue;

class TestSceneModel : public QObject
{
  Q_OBJECT

private slots:
  // Every declared parameter is a key, with the declared default (the declaration in
  // core/parameters/parameters.cxx is the reference) but for the start-up scene's: the material
  // keys are the start-up material's (the library's "spun aluminium") and the exposure is one
  // stop under the declared one; the mesh is the built-in sphere; the assets default to "none".
  void defaultsAreTheDeclaredOnes()
  {
    SceneModel model;
    const aniso::Material& start = aniso::builtinMaterials().at(aniso::kStartMaterialName);
    for (const aniso::ParameterSpec& spec : aniso::parameterSpecs())
    {
      QVERIFY(aniso::isSceneKey(spec.name));
      if (aniso::isMaterialKey(spec.name))
      {
        QCOMPARE(model.value(spec.name), start.value(spec.name));
      }
      else if (spec.name != "exposure")
      {
        QCOMPARE(model.value(spec.name), aniso::defaultParameterValue(spec));
      }
    }
    QCOMPARE(model.real("exposure"), aniso::parameterSpec("exposure").defaultValue[0] - 1.0);
    QCOMPARE(model.real("nu"), 10000.0);
    QCOMPARE(model.real("nv"), 20.0);
    QCOMPARE(model.text("tangents"), std::string("auto"));
    QCOMPARE(model.text("method"), std::string("exact"));
    QCOMPARE(model.text("normal-map"), std::string());
    QCOMPARE(model.text("mesh"), std::string("builtin:sphere"));
    QCOMPARE(model.parts().size(), std::size_t(1));
    QCOMPARE(model.parts()[0].material, std::string("spun aluminium"));
    QVERIFY(!model.camera().set);
    // reset() comes back to the same scene after edits.
    model.setValue("nu", aniso::numberValue(30.0));
    model.setValue("exposure", aniso::numberValue(2.0));
    model.reset();
    QCOMPARE(model.real("nu"), 10000.0);
    QCOMPARE(model.real("exposure"), -1.0);
    QCOMPARE(model.parts()[0].material, std::string("spun aluminium"));
  }

  // What the keys beside the declared parameters affect (the parameters' roles: test_parameters):
  // maps are features of the material's shader variant; the mesh, the shading model and the
  // lights are what the lit and surface models draw; each forgets the learnt frame costs. A key
  // that is no scene key affects nothing.
  void sceneKeysSayWhatTheyAffect()
  {
    using A = aniso::Affects;
    const A map = A::Variant | A::FrameCost;
    const std::map<std::string, A> expected = {
        {"model", A::FrameCost | A::LitModels | A::SurfaceModels},
        {"sample-material", A::FrameCost | A::LitModels},
        {"lights", A::FrameCost | A::LitModels | A::SurfaceModels},
        {"mesh", A::FrameCost | A::LitModels | A::SurfaceModels},
        {"normal-map", map},
        {"quaternion-map", map},
        {"tpr", map | A::SurfaceModels},
        {"height-map", map},
        {"albedo-map", map},
        {"ao-map", map},
        {"metallic-map", map}};
    // The declared parameters first, in their order (sceneKeys), then the others.
    const std::vector<aniso::SceneKey>& keys = aniso::sceneKeys();
    const std::size_t declared = aniso::parameterSpecs().size();
    QCOMPARE(keys.size(), declared + expected.size());
    for (std::size_t i = 0; i < keys.size(); ++i)
    {
      const std::string name(keys[i].spec.name);
      QVERIFY2(i < declared || expected.count(name) == 1, name.c_str());
      const A roles = i < declared ? aniso::parameterSpecs()[i].roles : expected.at(name);
      QVERIFY2(keys[i].spec.roles == roles, name.c_str());
      QVERIFY2(aniso::sceneKeyAffects(name, roles) == (roles != A::None), name.c_str());
    }
    QVERIFY(aniso::sceneKeyAffects("normal-map", A::Uniforms | A::Variant));
    QVERIFY(!aniso::sceneKeyAffects("normal-map", A::Uniforms | A::Display));
    QVERIFY(!aniso::sceneKeyAffects("nope", A::Uniforms | A::Variant | A::Luts | A::Display |
                                                A::FrameCost | A::LitModels | A::SurfaceModels));
  }

  // Out-of-range numbers, unknown choices, wrong types and unknown keys are refused with a
  // message naming the key; the model keeps its value and emits nothing.
  void invalidValuesAreRefusedAndChangeNothing()
  {
    SceneModel model;
    QSignalSpy spy(&model, &SceneModel::valueChanged);
    const auto refuses = [&](const char* key, const aniso::ParameterValue& v, const char* reason)
    {
      const aniso::ParameterValue before = model.value(key);
      try
      {
        model.setValue(key, v);
        QFAIL(qPrintable(QString("%1 accepted").arg(key)));
      }
      catch (const aniso::Error& e)
      {
        const std::string message = e.what();
        QVERIFY2(message.rfind(std::string(key) + ": ", 0) == 0, e.what());
        QVERIFY2(message.find(reason) != std::string::npos, e.what());
      }
      QCOMPARE(model.value(key), before);
    };
    refuses("nu", numberValue(-1.0), "out of range [0, 1e6]");
    refuses("nv", numberValue(1e6 + 1.0), "out of range [0, 1e6]");
    refuses("samples", numberValue(2.5), "is not an integer");
    refuses("f0", colorValue(0.5, 1.5, 0.5), "out of range [0, 1]");
    refuses("method", textValue("fast"), "'fast' is not one of exact, split-sum");
    refuses("env", textValue(""), "empty value");
    refuses("nu", textValue("5"), "a number carries text");
    refuses("nu", colorValue(1.0, 2.0, 3.0), "a single number was expected");
    refuses("cube-size", numberValue(100.0), "is not a power of two");
    QCOMPARE(spy.count(), 0);
    QVERIFY_EXCEPTION_THROWN(model.setValue("nope", numberValue(1.0)), aniso::Error);
  }

  // One signal per key that really changes; setting the same value again emits nothing.
  void eachChangeIsSignalledOnce()
  {
    SceneModel model;
    QSignalSpy spy(&model, &SceneModel::valueChanged);
    model.setValue("nu", numberValue(20000.0));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).toString(), QString("nu"));
    model.setValue("nu", numberValue(20000.0));
    QCOMPARE(spy.count(), 1);
    model.setValues({{"nu", numberValue(20000.0)},
                     {"nv", numberValue(70.0)},
                     {"f0", colorValue(1.0, 0.766, 0.336)}});
    QCOMPARE(spy.count(), 3);
    QCOMPARE(model.real("nv"), 70.0);
    QCOMPARE(model.color("f0"), (std::array<double, 3>{1.0, 0.766, 0.336}));
    QCOMPARE(model.integer("samples"), 16);
  }

  // setValues is all or nothing: one bad value leaves every other key as it was.
  void setValuesIsAllOrNothing()
  {
    SceneModel model;
    QSignalSpy spy(&model, &SceneModel::valueChanged);
    QVERIFY_EXCEPTION_THROWN(
        model.setValues({{"nu", numberValue(5.0)}, {"exposure", numberValue(100.0)}}),
        aniso::Error);
    QCOMPARE(model.real("nu"), 10000.0);
    QCOMPARE(spy.count(), 0);
  }

  // Assets accept empty text (no map) and go through their validator, whose error is passed on.
  void assetValidatorsDecide()
  {
    SceneModel model;
    model.setValidator("normal-map",
                       [](const std::string& text, const std::string& subject)
                       {
                         if (text != "good.png")
                         {
                           throw aniso::errorAbout(subject, "cannot read " + text);
                         }
                       });
    model.setValue("normal-map", textValue("good.png"));
    QVERIFY_EXCEPTION_THROWN(model.setValue("normal-map", textValue("bad.png")), aniso::Error);
    QCOMPARE(model.text("normal-map"), std::string("good.png"));
    model.setValue("normal-map", textValue(""));
    QCOMPARE(model.text("normal-map"), std::string());
  }

  // The camera needs a proper frame; reset brings back every default.
  void cameraIsValidatedAndResetRestoresDefaults()
  {
    SceneModel model;
    aniso::CameraState camera;
    camera.set = true;
    camera.position = {0.0, -4.0, 1.0};
    camera.viewUp = {0.0, 0.0, 1.0};
    model.setCamera(camera);
    QCOMPARE(model.camera(), camera);
    aniso::CameraState bad = camera;
    bad.viewUp = {0.0, 4.0, -1.0}; // along the view direction
    QVERIFY_EXCEPTION_THROWN(model.setCamera(bad), aniso::Error);
    bad = camera;
    bad.viewAngle = 180.0;
    QVERIFY_EXCEPTION_THROWN(model.setCamera(bad), aniso::Error);
    QCOMPARE(model.camera(), camera);
    model.setValue("nu", numberValue(3.0));
    model.reset();
    QCOMPARE(model.real("nu"), 10000.0);
    QVERIFY(!model.camera().set);
  }

  // Undo and redo walk back and forth through edits; a linked edit of two keys is one step.
  void undoRedoWalksThroughEdits()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    editor.edit("nu", numberValue(2000.0));
    editor.edit({{"nu", numberValue(4000.0)}, {"nv", numberValue(200.0)}});
    QCOMPARE(editor.undoStack()->count(), 2);
    editor.undoStack()->undo();
    QCOMPARE(model.real("nu"), 2000.0);
    QCOMPARE(model.real("nv"), 20.0);
    editor.undoStack()->undo();
    QCOMPARE(model.real("nu"), 10000.0);
    editor.undoStack()->redo();
    editor.undoStack()->redo();
    QCOMPARE(model.real("nu"), 4000.0);
    QCOMPARE(model.real("nv"), 200.0);
    // An invalid edit pushes nothing.
    QVERIFY_EXCEPTION_THROWN(editor.edit("nu", numberValue(-3.0)), aniso::Error);
    QCOMPARE(editor.undoStack()->count(), 2);
  }

  // The edits of one drag merge into a single command; the next drag is a new one; a drag that
  // returns to its start leaves no command.
  void aDragIsOneUndoStep()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    const int drag = editor.beginDrag();
    for (double nu : {1100.0, 1300.0, 1700.0, 2500.0})
    {
      editor.edit("nu", numberValue(nu), drag);
    }
    QCOMPARE(editor.undoStack()->count(), 1);
    const int second = editor.beginDrag();
    QVERIFY(second != drag && second != 0);
    editor.edit("nu", numberValue(3000.0), second);
    editor.edit("nu", numberValue(2500.0), second);
    QCOMPARE(editor.undoStack()->count(), 1);
    editor.undoStack()->undo();
    QCOMPARE(model.real("nu"), 10000.0);
  }

  // The history keeps the last kUndoLimit steps: after kUndoLimit + 5 edits, undoing all it
  // holds leaves the value of the fifth edit, the first five steps being gone.
  void historyKeepsTheLastSteps()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    const int limit = aniso::SceneEditor::kUndoLimit;
    QVERIFY(limit >= 100);
    for (int i = 1; i <= limit + 5; ++i)
    {
      editor.edit("nu", numberValue(1000.0 + i));
    }
    QCOMPARE(editor.undoStack()->count(), limit);
    while (editor.undoStack()->canUndo())
    {
      editor.undoStack()->undo();
    }
    QCOMPARE(model.real("nu"), 1005.0);
    editor.undoStack()->setIndex(limit);
    QCOMPARE(model.real("nu"), 1000.0 + limit + 5);
  }

  // Replacing the whole scene (opening a session) is one step; undo restores values and camera.
  void replaceSceneIsOneStep()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    SceneModel::Values values = model.values();
    values["nu"] = numberValue(20000.0);
    values["tone-mapping"] = textValue("clamp");
    aniso::CameraState camera;
    camera.set = true;
    camera.position = {3.0, 0.0, 0.0};
    camera.viewUp = {0.0, 0.0, 1.0};
    editor.replaceScene(values, camera, "Open session");
    QCOMPARE(model.real("nu"), 20000.0);
    QCOMPARE(model.camera(), camera);
    editor.undoStack()->undo();
    QCOMPARE(model.real("nu"), 10000.0);
    QCOMPARE(model.text("tone-mapping"), std::string("aces"));
    QVERIFY(!model.camera().set);
  }
};

QTEST_MAIN(TestSceneModel)
#include "test_scene_model.moc"
