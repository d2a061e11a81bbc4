#include "scene/Session.h"

#include "core/error.h"
#include "core/maps/tpr_map.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>
#include <tuple>

namespace aniso
{
namespace
{
const char* const kFormat = "aniso-session";
constexpr qint64 kMaxSessionBytes = 16 << 20; // far beyond any real session

QString qstr(std::string_view s)
{
  return QString::fromUtf8(s.data(), static_cast<int>(s.size()));
}

// Whether the value of KEY is a file path (as opposed to a built-in name or a pattern).
bool isPath(const SceneKey& key, const std::string& text)
{
  if (text.empty() || text.rfind("builtin:", 0) == 0)
  {
    return false;
  }
  if (key.spec.name == "tpr")
  {
    try
    {
      parseTprPattern(text);
      return false;
    }
    catch (const Error&)
    {
      return true;
    }
  }
  return key.asset || key.spec.name == "env";
}

QString relativeTo(const QString& base, const QString& path)
{
  if (base.isEmpty())
  {
    return path;
  }
  const QString absolute = QFileInfo(path).absoluteFilePath();
  const QString dir = QDir(base).absolutePath();
  return absolute.startsWith(dir + "/") ? QDir(dir).relativeFilePath(absolute) : path;
}

QString resolvedAgainst(const QString& base, const QString& path)
{
  if (base.isEmpty() || !QFileInfo(path).isRelative())
  {
    return path;
  }
  return QDir::cleanPath(QDir(base).absoluteFilePath(path));
}

QJsonArray triple(const std::array<double, 3>& v)
{
  return QJsonArray{v[0], v[1], v[2]};
}

std::array<double, 3> readTriple(const QJsonValue& value, const std::string& subject)
{
  const QJsonArray a = value.toArray();
  if (!value.isArray() || a.size() != 3 || !a[0].isDouble() || !a[1].isDouble() || !a[2].isDouble())
  {
    throw errorAbout(subject, "expected an array of three numbers");
  }
  return {a[0].toDouble(), a[1].toDouble(), a[2].toDouble()};
}

QJsonValue toJson(const SceneKey& key, const ParameterValue& value, const QString& base)
{
  switch (key.spec.type)
  {
  case ParameterType::Integer:
  case ParameterType::Real:
    return value.number[0];
  case ParameterType::Color:
    return triple(value.number);
  case ParameterType::Text:
    break;
  }
  const QString text = QString::fromStdString(value.text);
  return isPath(key, value.text) ? relativeTo(base, text) : text;
}

ParameterValue fromJson(const SceneKey& key, const QJsonValue& json, const QString& base,
                        const std::string& subject)
{
  ParameterValue v;
  switch (key.spec.type)
  {
  case ParameterType::Integer:
  case ParameterType::Real:
    if (!json.isDouble())
    {
      throw errorAbout(subject, "expected a number");
    }
    v.number.fill(json.toDouble());
    return v;
  case ParameterType::Color:
    v.number = readTriple(json, subject);
    return v;
  case ParameterType::Text:
    break;
  }
  if (!json.isString())
  {
    throw errorAbout(subject, "expected a text");
  }
  v.text = json.toString().toStdString();
  if (isPath(key, v.text))
  {
    v.text = resolvedAgainst(base, QString::fromStdString(v.text)).toStdString();
  }
  return v;
}

QJsonObject viewToJson(const CameraState& c)
{
  QJsonObject view;
  view["position"] = triple(c.position);
  view["focal-point"] = triple(c.focalPoint);
  view["view-up"] = triple(c.viewUp);
  view["view-angle"] = c.viewAngle;
  view["parallel"] = c.parallel;
  view["parallel-scale"] = c.parallelScale;
  return view;
}

CameraState viewFromJson(const QJsonObject& view, QJsonObject& unknown, QStringList& unknownKeys)
{
  CameraState c;
  c.set = true;
  c.position = readTriple(view["position"], "view/position");
  c.focalPoint = readTriple(view["focal-point"], "view/focal-point");
  c.viewUp = readTriple(view["view-up"], "view/view-up");
  for (const char* number : {"view-angle", "parallel-scale"})
  {
    if (!view[number].isDouble())
    {
      throw errorAbout(std::string("view/") + number, "expected a number");
    }
  }
  c.viewAngle = view["view-angle"].toDouble();
  c.parallelScale = view["parallel-scale"].toDouble();
  if (!view["parallel"].isBool())
  {
    throw errorAbout("view/parallel", "expected true or false");
  }
  c.parallel = view["parallel"].toBool();
  checkCameraState(c);
  QJsonObject extra;
  for (auto it = view.begin(); it != view.end(); ++it)
  {
    if (!QStringList{"position", "focal-point", "view-up", "view-angle", "parallel",
                     "parallel-scale"}
             .contains(it.key()))
    {
      extra[it.key()] = it.value();
      unknownKeys << "view/" + it.key();
    }
  }
  if (!extra.isEmpty())
  {
    unknown["view"] = extra;
  }
  return c;
}
std::string readString(const QJsonObject& object, const char* key, const std::string& subject,
                       bool required)
{
  const QJsonValue value = object[key];
  if (value.isUndefined() && !required)
  {
    return {};
  }
  if (!value.isString())
  {
    throw errorAbout(subject + "/" + key, "expected a text");
  }
  return value.toString().toStdString();
}

// The "parts" and "materials" sections into CONTENT, checked as SceneModel::setParts checks.
void readParts(const QJsonObject& json, const QString& base, SessionContent& content)
{
  if (!json["materials"].isObject())
  {
    throw errorAbout("materials", "expected an object");
  }
  QJsonObject libraryDocument;
  libraryDocument["format"] = "aniso-materials";
  libraryDocument["version"] = 1;
  libraryDocument["materials"] = json["materials"];
  content.library = materialLibraryFromJson(
      QJsonDocument(libraryDocument).toJson().toStdString(), base.toStdString(), "materials");
  if (!json["parts"].isArray())
  {
    throw errorAbout("parts", "expected an array");
  }
  const QJsonArray parts = json["parts"].toArray();
  for (int i = 0; i < parts.size(); ++i)
  {
    const std::string subject = "parts/" + std::to_string(i + 1);
    if (!parts[i].isObject())
    {
      throw errorAbout(subject, "expected an object");
    }
    const QJsonObject p = parts[i].toObject();
    ScenePart part;
    part.name = readString(p, "name", subject, true);
    part.mesh = fromJson(sceneKey("mesh"), p["mesh"], base, subject + "/mesh").text;
    part.block = readString(p, "block", subject, false);
    part.group = readString(p, "group", subject, false);
    part.material = readString(p, "material", subject, true);
    if (!p["visible"].isUndefined() && !p["visible"].isBool())
    {
      throw errorAbout(subject + "/visible", "expected true or false");
    }
    part.visible = p["visible"].toBool(true);
    if (!p["placement"].isUndefined())
    {
      const QJsonArray matrix = p["placement"].toArray();
      if (!p["placement"].isArray() || matrix.size() != 16)
      {
        throw errorAbout(subject + "/placement", "expected an array of 16 numbers (row-major)");
      }
      for (int k = 0; k < 16; ++k)
      {
        if (!matrix[k].isDouble())
        {
          throw errorAbout(subject + "/placement", "expected an array of 16 numbers (row-major)");
        }
        part.placement[std::size_t(k)] = matrix[k].toDouble();
      }
      checkPlacement(part.placement, subject + "/placement");
    }
    content.parts.push_back(std::move(part));
  }
  SceneModel probe; // the checks of setParts, with messages naming the section
  try
  {
    probe.setParts(content.parts, content.library);
  }
  catch (const Error& e)
  {
    throw errorAbout("parts", e.what());
  }
}
} // namespace

QJsonObject sessionToJson(const SceneModel& model, const QJsonObject& unknown,
                          const QString& baseDirectory)
{
  QJsonObject sections[2]; // parameters, assets
  for (const SceneKey& key : sceneKeys())
  {
    sections[key.asset ? 1 : 0][qstr(key.spec.name)] =
        toJson(key, model.value(key.spec.name), baseDirectory);
  }
  QJsonObject json;
  json["format"] = kFormat;
  json["version"] = kSessionVersion;
  json["parameters"] = sections[0];
  json["assets"] = sections[1];
  if (model.camera().set)
  {
    json["view"] = viewToJson(model.camera());
  }
  QJsonArray parts;
  for (const ScenePart& part : model.parts())
  {
    QJsonObject p;
    p["name"] = QString::fromStdString(part.name);
    p["mesh"] = toJson(sceneKey("mesh"), textValue(part.mesh), baseDirectory);
    p["block"] = QString::fromStdString(part.block);
    p["group"] = QString::fromStdString(part.group);
    p["material"] = QString::fromStdString(part.material);
    p["visible"] = part.visible;
    if (part.placement != kIdentityPlacement)
    {
      QJsonArray matrix;
      for (double v : part.placement)
      {
        matrix.append(v);
      }
      p["placement"] = matrix;
    }
    parts.append(p);
  }
  json["parts"] = parts;
  const QJsonDocument library = QJsonDocument::fromJson(
      QByteArray::fromStdString(materialLibraryToJson(model.materials(), baseDirectory.toStdString())));
  json["materials"] = library.object()["materials"];
  // Keys kept from a newer session go back where they were; known keys are never overridden.
  for (auto it = unknown.begin(); it != unknown.end(); ++it)
  {
    if (json.contains(it.key()) && json[it.key()].isObject() && it.value().isObject())
    {
      QJsonObject merged = json[it.key()].toObject();
      const QJsonObject extra = it.value().toObject();
      for (auto e = extra.begin(); e != extra.end(); ++e)
      {
        if (!merged.contains(e.key()))
        {
          merged[e.key()] = e.value();
        }
      }
      json[it.key()] = merged;
    }
    else if (!json.contains(it.key()))
    {
      json[it.key()] = it.value();
    }
  }
  return json;
}

SessionContent sessionFromJson(const QJsonObject& json, const QString& baseDirectory,
                               const QString& subject)
{
  try
  {
    if (json["format"].toString() != kFormat)
    {
      throw Error("not an aniso session (no \"format\": \"aniso-session\")");
    }
    const QJsonValue version = json["version"];
    if (!version.isDouble() || version.toDouble() < 1.0 ||
        version.toDouble() != static_cast<double>(version.toInt()))
    {
      throw errorAbout("version", "expected a whole number from 1");
    }
    SessionContent content;
    for (const SceneKey& key : sceneKeys())
    {
      content.values.emplace(std::string(key.spec.name), defaultParameterValue(key.spec));
    }
    const char* const sections[2] = {"parameters", "assets"};
    for (int s = 0; s < 2; ++s)
    {
      const QJsonValue section = json[sections[s]];
      if (section.isUndefined())
      {
        continue;
      }
      if (!section.isObject())
      {
        throw errorAbout(sections[s], "expected an object");
      }
      const QJsonObject object = section.toObject();
      QJsonObject extra;
      for (auto it = object.begin(); it != object.end(); ++it)
      {
        const std::string name = it.key().toStdString();
        if (!isSceneKey(name) || sceneKey(name).asset != (s == 1))
        {
          extra[it.key()] = it.value();
          content.unknownKeys << QString(sections[s]) + "/" + it.key();
          continue;
        }
        const SceneKey& key = sceneKey(name);
        ParameterValue v = fromJson(key, it.value(), baseDirectory, name);
        if (!(key.asset && v.text.empty()))
        {
          checkParameterValue(key.spec, v, name);
        }
        content.values[name] = std::move(v);
      }
      if (!extra.isEmpty())
      {
        content.unknown[sections[s]] = extra;
      }
    }
    if (json.contains("view"))
    {
      if (!json["view"].isObject())
      {
        throw errorAbout("view", "expected an object");
      }
      content.camera = viewFromJson(json["view"].toObject(), content.unknown, content.unknownKeys);
    }
    if (json.contains("parts") || json.contains("materials"))
    {
      readParts(json, baseDirectory, content);
    }
    else
    {
      std::tie(content.parts, content.library) = onePartScene(content.values, builtinMaterials());
    }
    for (auto it = json.begin(); it != json.end(); ++it)
    {
      if (!QStringList{"format", "version", "parameters", "assets", "view", "parts", "materials"}
               .contains(it.key()))
      {
        content.unknown[it.key()] = it.value();
        content.unknownKeys << it.key();
      }
    }
    return content;
  }
  catch (const Error& e)
  {
    throw errorAbout(subject.toStdString(), e.what());
  }
}

SessionContent readSessionFile(const QString& path)
{
  const std::string subject = path.toStdString();
  QFile file(path);
  if (!QFileInfo(path).isFile())
  {
    throw errorAbout(subject, QFileInfo::exists(path) ? "not a regular file" : "no such file");
  }
  if (!file.open(QIODevice::ReadOnly))
  {
    throw errorAbout(subject, "cannot open (" + file.errorString().toStdString() + ")");
  }
  if (file.size() > kMaxSessionBytes)
  {
    throw errorAbout(subject, "too large for a session");
  }
  QJsonParseError parseError;
  const QJsonDocument document = QJsonDocument::fromJson(file.readAll(), &parseError);
  if (parseError.error != QJsonParseError::NoError)
  {
    throw errorAbout(subject, "not valid JSON (" + parseError.errorString().toStdString() +
                                  " at offset " + std::to_string(parseError.offset) + ")");
  }
  if (!document.isObject())
  {
    throw errorAbout(subject, "not an aniso session (not a JSON object)");
  }
  return sessionFromJson(document.object(), QFileInfo(path).absolutePath(), path);
}

QStringList SessionFile::open(SceneEditor& editor, const QString& path)
{
  const std::string subject = path.toStdString();
  SessionContent content = readSessionFile(path);
  try
  {
    editor.replaceScene(content.values, content.camera, content.parts, content.library,
                        QObject::tr("Open session %1").arg(QFileInfo(path).fileName()));
  }
  catch (const Error& e)
  {
    throw errorAbout(subject, e.what());
  }
  unknown_ = content.unknown;
  return content.unknownKeys;
}

void SessionFile::save(const SceneModel& model, const QString& path) const
{
  const std::string subject = path.toStdString();
  const QString base = QFileInfo(path).absolutePath();
  const QByteArray bytes = QJsonDocument(sessionToJson(model, unknown_, base)).toJson();
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
  {
    throw errorAbout(subject, "cannot write (" + file.errorString().toStdString() + ")");
  }
}
} // namespace aniso
