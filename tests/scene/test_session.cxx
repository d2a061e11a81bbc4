// Sessions: every key and the camera round-trip exactly (against the values set here), paths
// under the session's folder are stored relative to it, keys from a newer version are kept and
// written back, and a bad or missing session is reported naming the file while the scene and
// its undo history stay as they were.
#include "core/error.h"
#include "scene/SceneEditor.h"
#include "scene/Session.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using aniso::SceneModel;

namespace
{
// A value of KEY that differs from the default and is awkward to print: thirds, sevenths.
aniso::ParameterValue unusualValue(const aniso::SceneKey& key, const QDir& dir)
{
  const aniso::ParameterSpec& s = key.spec;
  const std::string name(s.name);
  switch (s.type)
  {
  case aniso::ParameterType::Real:
    return aniso::numberValue(s.minimum + (s.maximum - s.minimum) / 3.0);
  case aniso::ParameterType::Integer:
    return aniso::numberValue(s.powerOfTwo ? 512.0
                                           : std::round(s.minimum + (s.maximum - s.minimum) / 3.0));
  case aniso::ParameterType::Color:
    return aniso::colorValue(1.0 / 3.0, 1.0 / 7.0, 0.9);
  case aniso::ParameterType::Text:
    break;
  }
  if (!s.choices.empty())
  {
    // The last choice that is not the default, whichever the declaration's default is.
    for (auto c = s.choices.rbegin(); c != s.choices.rend(); ++c)
    {
      if (!(aniso::textValue(std::string(*c)) == aniso::defaultParameterValue(s)))
      {
        return aniso::textValue(std::string(*c));
      }
    }
  }
  if (name == "env")
  {
    return aniso::textValue(dir.filePath("sky.exr").toStdString());
  }
  if (name == "tangents")
  {
    return aniso::textValue("around:0,0,1@0.5,0,0");
  }
  if (name == "field")
  {
    return aniso::textValue("velocity:2");
  }
  if (name == "field-range")
  {
    return aniso::textValue("-1.5,2.25");
  }
  if (name == "mesh")
  {
    return aniso::textValue("builtin:plate");
  }
  if (name == "tpr")
  {
    return aniso::textValue("spiral:0.25,0.75:30");
  }
  if (name == "albedo-map")
  {
    return aniso::textValue("/elsewhere/albedo.png"); // outside the session's folder
  }
  return aniso::textValue(
      dir.filePath("maps/" + QString::fromStdString(name) + ".png").toStdString());
}

QJsonObject readJson(const QString& path)
{
  QFile f(path);
  f.open(QIODevice::ReadOnly);
  return QJsonDocument::fromJson(f.readAll()).object();
}

void writeText(const QString& path, const QByteArray& text)
{
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write(text);
}
} // namespace

class TestSession : public QObject
{
  Q_OBJECT

private slots:
  // Every key set to an unusual value and an awkward camera come back identical.
  void roundTripsEveryKeyExactly()
  {
    QTemporaryDir tmp;
    const QDir dir(tmp.path());
    SceneModel model;
    SceneModel::Values expected;
    for (const aniso::SceneKey& key : aniso::sceneKeys())
    {
      const aniso::ParameterValue v = unusualValue(key, dir);
      QVERIFY2(!(v == aniso::defaultParameterValue(key.spec)), key.spec.name.data());
      expected[std::string(key.spec.name)] = v;
    }
    model.setValues(expected);
    aniso::CameraState camera;
    camera.set = true;
    camera.position = {0.1, -3.0 / 7.0, 1e-17};
    camera.focalPoint = {1.0 / 3.0, 0.0, -2.5};
    camera.viewUp = {0.0, 0.2, 0.9};
    camera.viewAngle = 100.0 / 3.0;
    camera.parallel = true;
    camera.parallelScale = 0.7;
    model.setCamera(camera);

    const QString path = dir.filePath("scene.json");
    aniso::SessionFile().save(model, path);
    SceneModel loaded;
    aniso::SceneEditor editor(&loaded);
    aniso::SessionFile session;
    QVERIFY(session.open(editor, path).isEmpty());
    for (const auto& [key, value] : expected)
    {
      QVERIFY2(loaded.value(key) == value, key.c_str());
    }
    QCOMPARE(loaded.camera(), camera);
    QCOMPARE(editor.undoStack()->count(), 1);

    // On disk: paths inside the folder are relative, others absolute, patterns untouched.
    const QJsonObject json = readJson(path);
    QCOMPARE(json["version"].toInt(), aniso::kSessionVersion);
    QCOMPARE(json["assets"].toObject()["normal-map"].toString(), QString("maps/normal-map.png"));
    QCOMPARE(json["assets"].toObject()["albedo-map"].toString(), QString("/elsewhere/albedo.png"));
    QCOMPARE(json["assets"].toObject()["tpr"].toString(), QString("spiral:0.25,0.75:30"));
    QCOMPARE(json["parameters"].toObject()["env"].toString(), QString("sky.exr"));
  }

  // A session of a newer version: known keys load, unknown ones are reported and written back
  // unchanged on save; missing keys take their defaults.
  void unknownKeysAreKeptAndReported()
  {
    QTemporaryDir tmp;
    const QDir dir(tmp.path());
    const QString path = dir.filePath("newer.json");
    writeText(path, R"({
      "format": "aniso-session", "version": 2,
      "parameters": {"nu": 20000, "nv": 70, "sheen": 0.5},
      "assets": {"mesh": "builtin:sphere", "clearcoat-map": "cc.png"},
      "view": {"position": [0, -4, 0], "focal-point": [0, 0, 0], "view-up": [0, 0, 1],
               "view-angle": 30, "parallel": false, "parallel-scale": 1, "roll-lock": true},
      "lights": [{"kind": "point", "power": 10}]
    })");
    SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::SessionFile session;
    QStringList unknown = session.open(editor, path);
    unknown.sort();
    QCOMPARE(unknown,
             QStringList({"assets/clearcoat-map", "lights", "parameters/sheen", "view/roll-lock"}));
    QCOMPARE(model.real("nu"), 20000.0);
    QCOMPARE(model.text("mesh"), std::string("builtin:sphere"));
    QCOMPARE(model.text("method"), std::string("exact")); // missing: the default

    model.setValue("nv", aniso::numberValue(80.0));
    const QString saved = dir.filePath("saved.json");
    session.save(model, saved);
    const QJsonObject json = readJson(saved);
    QCOMPARE(json["parameters"].toObject()["sheen"].toDouble(), 0.5);
    QCOMPARE(json["parameters"].toObject()["nv"].toDouble(), 80.0);
    QCOMPARE(json["assets"].toObject()["clearcoat-map"].toString(), QString("cc.png"));
    QCOMPARE(json["view"].toObject()["roll-lock"].toBool(), true);
    QCOMPARE(json["lights"].toArray()[0].toObject()["power"].toDouble(), 10.0);
  }

  // Each bad session is refused with "PATH: reason"; the scene, its undo history and the kept
  // keys are untouched.
  void badSessionsChangeNothing()
  {
    QTemporaryDir tmp;
    const QDir dir(tmp.path());
    struct Case
    {
      const char* file;
      QByteArray text; // empty: the file is not written
      const char* reason;
    };
    const QByteArray head = R"("format": "aniso-session", "version": 1)";
    const Case cases[] = {
        {"missing.json", {}, "no such file"},
        {"garbage.json", "\x89PNG\r\n not json at all", "not valid JSON"},
        {"array.json", "[1, 2, 3]", "not a JSON object"},
        {"other.json", R"({"format": "something-else", "version": 1})", "not an aniso session"},
        {"version.json", R"({"format": "aniso-session", "version": "one"})", "version: expected"},
        {"range.json", "{" + head + R"(, "parameters": {"nu": -5}})", "nu: -5 is out of range"},
        {"type.json", "{" + head + R"(, "parameters": {"f0": "red"}})",
         "f0: expected an array of three numbers"},
        {"choice.json", "{" + head + R"(, "parameters": {"method": "magic"}})",
         "method: 'magic' is not one of"},
        {"view.json", "{" + head + R"(, "view": {"position": [0,0,0], "focal-point": [0,0,0],
           "view-up": [0,0,1], "view-angle": 30, "parallel": false, "parallel-scale": 1}})",
         "view: camera position and focal point coincide"},
        {"mesh.json", "{" + head + R"(, "assets": {"mesh": "broken.stl"}})",
         "mesh: cannot load broken.stl"},
    };
    SceneModel model;
    model.setValidator(
        "mesh",
        [](const std::string& text, const std::string& subject)
        {
          if (text.rfind("builtin:", 0) != 0)
          {
            throw aniso::errorAbout(
                subject,
                "cannot load " + QFileInfo(QString::fromStdString(text)).fileName().toStdString());
          }
        });
    aniso::SceneEditor editor(&model);
    editor.edit("nu", aniso::numberValue(123.0));
    const SceneModel::Values before = model.values();
    QSignalSpy changes(&model, &SceneModel::valueChanged);
    aniso::SessionFile session;
    for (const Case& c : cases)
    {
      const QString path = dir.filePath(c.file);
      if (!c.text.isEmpty())
      {
        writeText(path, c.text);
      }
      try
      {
        session.open(editor, path);
        QFAIL(qPrintable(QString(c.file) + " was accepted"));
      }
      catch (const aniso::Error& e)
      {
        const QString message = e.what();
        QVERIFY2(message.startsWith(path + ": "), e.what());
        QVERIFY2(message.contains(c.reason), e.what());
      }
    }
    QCOMPARE(changes.count(), 0);
    QVERIFY(model.values() == before);
    QCOMPARE(editor.undoStack()->count(), 1);
    QVERIFY(session.unknown().isEmpty());
  }
};

QTEST_MAIN(TestSession)
#include "test_session.moc"
