#include "scene/SceneModel.h"

#include "core/error.h"
#include "scene/SceneShading.h"

#include <cmath>
#include <utility>

namespace aniso
{
namespace
{
SceneKey asset(std::string_view name, std::string_view label, std::string_view defaultText,
               std::string_view help, Affects roles)
{
  SceneKey key;
  key.spec.name = name;
  key.spec.label = label;
  key.spec.type = ParameterType::Text;
  key.spec.defaultText = defaultText;
  key.spec.help = help;
  key.spec.roles = roles;
  key.asset = true;
  return key;
}

std::vector<SceneKey> makeKeys()
{
  std::vector<SceneKey> keys;
  for (const ParameterSpec& spec : parameterSpecs())
  {
    keys.push_back({spec, false});
  }
  // The shading model and its lights are scene settings of the application, not material
  // parameters of the command line (which has --model and --light of its own).
  for (const SceneKey& key : shadingSceneKeys())
  {
    keys.push_back(key);
  }
  // Assets are paths (or the names of built-in ones), not tunable values, so the declaration of
  // tunable parameters does not hold them. Maps are features of the material's shader variant.
  using A = Affects;
  const Affects map = A::Variant | A::FrameCost;
  keys.push_back(
      asset("mesh", "Mesh", "builtin:torus",
            "the mesh: a file path or builtin:sphere, builtin:torus, builtin:plate, builtin:disk",
            A::FrameCost | A::LitModels | A::SurfaceModels));
  keys.push_back(asset("normal-map", "Normal map", {}, "tangent-space normal map", map));
  keys.push_back(asset("quaternion-map", "Quaternion map", {},
                       "quaternion map (a, b, c); baked from the normal map when absent", map));
  keys.push_back(asset("tpr", "TPR map", {},
                       "tangent-plane rotation: a pattern (linear:ANGLE, circular:U,V, "
                       "radial:U,V, spiral:U,V:PITCH, wave) or an image file",
                       map | A::SurfaceModels));
  keys.push_back(asset("height-map", "Height map", {}, "height map for parallax occlusion", map));
  keys.push_back(asset("albedo-map", "Albedo map", {}, "diffuse albedo map, linear RGB", map));
  keys.push_back(asset("ao-map", "AO map", {}, "ambient occlusion map", map));
  keys.push_back(asset("metallic-map", "Metallic map", {}, "metalness map", map));
  return keys;
}

const SceneKey* findSceneKey(std::string_view key)
{
  for (const SceneKey& k : sceneKeys())
  {
    if (k.spec.name == key)
    {
      return &k;
    }
  }
  return nullptr;
}

std::size_t indexOf(std::string_view key)
{
  if (const SceneKey* k = findSceneKey(key))
  {
    return static_cast<std::size_t>(k - sceneKeys().data());
  }
  throw errorAbout(std::string(key), "unknown parameter");
}

ParameterValue defaultValue(const SceneKey& key)
{
  return defaultParameterValue(key.spec);
}

bool finite3(const std::array<double, 3>& v)
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}
} // namespace

const std::vector<SceneKey>& sceneKeys()
{
  static const std::vector<SceneKey> keys = makeKeys();
  return keys;
}

const SceneKey& sceneKey(std::string_view key)
{
  return sceneKeys()[indexOf(key)];
}

bool isSceneKey(std::string_view key)
{
  return findSceneKey(key) != nullptr;
}

bool sceneKeyAffects(std::string_view key, Affects what)
{
  const SceneKey* k = findSceneKey(key);
  return k && k->spec.affects(what);
}

ParameterValue numberValue(double value)
{
  ParameterValue v;
  v.number.fill(value);
  return v;
}

ParameterValue colorValue(double r, double g, double b)
{
  ParameterValue v;
  v.number = {r, g, b};
  return v;
}

ParameterValue textValue(std::string text)
{
  ParameterValue v;
  v.text = std::move(text);
  return v;
}

void checkCameraState(const CameraState& c)
{
  if (!finite3(c.position) || !finite3(c.focalPoint) || !finite3(c.viewUp) ||
      !std::isfinite(c.viewAngle) || !std::isfinite(c.parallelScale))
  {
    throw errorAbout("view", "a camera value is not a finite number");
  }
  if (!(c.viewAngle > 0.0 && c.viewAngle < 180.0))
  {
    throw errorAbout("view",
                     "view angle " + formatNumber(c.viewAngle) + " is out of range (0, 180)");
  }
  if (!(c.parallelScale > 0.0))
  {
    throw errorAbout("view",
                     "parallel scale " + formatNumber(c.parallelScale) + " is not positive");
  }
  const double d[3] = {c.focalPoint[0] - c.position[0], c.focalPoint[1] - c.position[1],
                       c.focalPoint[2] - c.position[2]};
  const double distance = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(distance > 0.0))
  {
    throw errorAbout("view", "camera position and focal point coincide");
  }
  const auto& u = c.viewUp;
  const double up = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  const double cross[3] = {d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2],
                           d[0] * u[1] - d[1] * u[0]};
  const double sine =
      std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]) / (distance * up);
  // Up along the view direction leaves the roll undefined.
  if (!(up > 0.0) || !(sine > 1e-9))
  {
    throw errorAbout("view", "view up is zero or along the view direction");
  }
}

SceneModel::SceneModel(QObject* parent) : QObject(parent), validators_(sceneKeys().size())
{
  for (const SceneKey& key : sceneKeys())
  {
    values_.push_back(defaultValue(key));
  }
}

SceneModel::~SceneModel() = default;

const ParameterValue& SceneModel::value(std::string_view key) const
{
  return values_[indexOf(key)];
}

double SceneModel::real(std::string_view key) const
{
  return value(key).number[0];
}

int SceneModel::integer(std::string_view key) const
{
  return static_cast<int>(value(key).number[0]);
}

std::array<double, 3> SceneModel::color(std::string_view key) const
{
  return value(key).number;
}

const std::string& SceneModel::text(std::string_view key) const
{
  return value(key).text;
}

ParameterSet SceneModel::parameters() const
{
  ParameterSet set;
  for (const ParameterSpec& spec : parameterSpecs())
  {
    set.setValue(spec.name, value(spec.name));
  }
  return set;
}

void SceneModel::check(std::string_view key, const ParameterValue& v) const
{
  const std::size_t i = indexOf(key);
  const SceneKey& k = sceneKeys()[i];
  const std::string subject(key);
  if (k.spec.type == ParameterType::Text)
  {
    // Only the text counts: stray numbers would make equal texts compare unequal.
    if (v.number != std::array<double, 3>{0.0, 0.0, 0.0})
    {
      throw errorAbout(subject, "a text value carries numbers");
    }
    if (k.asset && v.text.empty())
    {
      return;
    }
  }
  else if (!v.text.empty())
  {
    throw errorAbout(subject, "a number carries text");
  }
  checkParameterValue(k.spec, v, subject);
  // Integer and Real keep the value in every component (numberValue), so equal values compare
  // equal whichever way they were made.
  if ((k.spec.type == ParameterType::Integer || k.spec.type == ParameterType::Real) &&
      (v.number[1] != v.number[0] || v.number[2] != v.number[0]))
  {
    throw errorAbout(subject, "a single number was expected");
  }
  if (validators_[i] && k.spec.type == ParameterType::Text)
  {
    validators_[i](v.text, subject);
  }
}

void SceneModel::setValue(std::string_view key, const ParameterValue& v)
{
  Values one;
  one.emplace(std::string(key), v);
  setValues(one);
}

void SceneModel::setValues(const Values& values)
{
  for (const auto& [key, v] : values)
  {
    if (!(v == value(key)))
    {
      check(key, v);
    }
  }
  std::vector<QString> changed;
  for (const auto& [key, v] : values)
  {
    ParameterValue& current = values_[indexOf(key)];
    if (!(current == v))
    {
      current = v;
      changed.push_back(QString::fromStdString(key));
    }
  }
  // Signals go out once every value is in place, so a listener sees a consistent scene.
  for (const QString& key : changed)
  {
    emit valueChanged(key);
  }
}

SceneModel::Values SceneModel::values() const
{
  Values all;
  const auto& keys = sceneKeys();
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    all.emplace(std::string(keys[i].spec.name), values_[i]);
  }
  return all;
}

void SceneModel::reset()
{
  std::vector<QString> changed;
  const auto& keys = sceneKeys();
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    const ParameterValue v = defaultValue(keys[i]);
    if (!(values_[i] == v))
    {
      values_[i] = v;
      changed.push_back(QString::fromStdString(std::string(keys[i].spec.name)));
    }
  }
  for (const QString& key : changed)
  {
    emit valueChanged(key);
  }
  if (camera_ != CameraState{})
  {
    camera_ = CameraState{};
    emit cameraChanged();
  }
}

void SceneModel::setValidator(std::string_view key, Validator validator)
{
  validators_[indexOf(key)] = std::move(validator);
}

void SceneModel::setCamera(const CameraState& camera)
{
  if (camera.set)
  {
    checkCameraState(camera);
  }
  if (camera != camera_)
  {
    camera_ = camera.set ? camera : CameraState{};
    emit cameraChanged();
  }
}
} // namespace aniso
