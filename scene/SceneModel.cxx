#include "scene/SceneModel.h"

#include "core/error.h"
#include "scene/SceneShading.h"

#include <algorithm>
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
      asset("mesh", "Mesh", kStartMesh,
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

// KEY's value in the start-up scene: its default, but the exposure.
ParameterValue startValue(const SceneKey& key)
{
  if (key.spec.name == "exposure")
  {
    return numberValue(kStartExposure);
  }
  return defaultValue(key);
}

bool finite3(const std::array<double, 3>& v)
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}
} // namespace

ScenePart partOfMesh(const std::string& mesh, const std::string& material)
{
  ScenePart part;
  part.mesh = mesh;
  part.material = material;
  std::string name = mesh;
  if (name.rfind("builtin:", 0) == 0)
  {
    name = name.substr(8);
  }
  else
  {
    const auto slash = name.find_last_of('/');
    if (slash != std::string::npos)
    {
      name = name.substr(slash + 1);
    }
    const auto dot = name.find_last_of('.');
    if (dot != std::string::npos && dot > 0)
    {
      name = name.substr(0, dot);
    }
  }
  part.name = name.empty() ? std::string("part") : name;
  return part;
}

std::pair<std::vector<ScenePart>, MaterialLibrary> onePartScene(const SceneModel::Values& values,
                                                                MaterialLibrary library)
{
  Material material = defaultMaterial({});
  for (std::string_view key : materialKeys())
  {
    const auto it = values.find(key);
    if (it != values.end())
    {
      material.values[std::string(key)] = it->second;
    }
  }
  std::string name;
  for (const Material& m : library.materials())
  {
    if (m.values == material.values)
    {
      name = m.name;
      break;
    }
  }
  if (name.empty())
  {
    material.name = library.uniqueName("material");
    name = material.name;
    library.put(material);
  }
  const auto mesh = values.find("mesh");
  const std::string meshText =
      mesh != values.end() ? mesh->second.text : std::string(sceneKey("mesh").spec.defaultText);
  return {{partOfMesh(meshText, name)}, std::move(library)};
}

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

SceneModel::SceneModel(QObject* parent)
    : QObject(parent), library_(builtinMaterials()), validators_(sceneKeys().size())
{
  for (const SceneKey& key : sceneKeys())
  {
    values_.push_back(startValue(key));
  }
  parts_.push_back(partOfMesh(text("mesh"), std::string(kStartMaterialName)));
  projectMaterial();
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
  QStringList changedMaterials;
  const std::vector<std::string> edited = editedMaterials();
  bool meshChanged = false;
  for (const auto& [key, v] : values)
  {
    ParameterValue& current = values_[indexOf(key)];
    if (isMaterialKey(key))
    {
      // Every edited material takes the value, also those that already held another one.
      for (const std::string& name : edited)
      {
        if (!(library_.at(name).value(key) == v))
        {
          library_.setValue(name, key, v);
          if (!changedMaterials.contains(QString::fromStdString(name)))
          {
            changedMaterials.push_back(QString::fromStdString(name));
          }
        }
      }
    }
    if (!(current == v))
    {
      current = v;
      changed.push_back(QString::fromStdString(key));
      meshChanged = meshChanged || key == "mesh";
    }
  }
  const bool hadSelection = !selection_.empty();
  if (meshChanged)
  {
    // A new mesh is a scene of one part, with the material edits went to.
    parts_ = {partOfMesh(text("mesh"), edited.front())};
    selection_.clear();
  }
  // Signals go out once every value is in place, so a listener sees a consistent scene.
  for (const QString& key : changed)
  {
    emit valueChanged(key);
  }
  if (!changedMaterials.isEmpty())
  {
    emit materialsChanged(changedMaterials);
  }
  if (meshChanged)
  {
    emit partsChanged();
    if (hadSelection)
    {
      emit selectionChanged();
    }
  }
}

std::vector<QString> SceneModel::projectMaterial()
{
  std::vector<QString> changed;
  const Material& material = library_.at(editedMaterials().front());
  for (std::string_view key : materialKeys())
  {
    ParameterValue& current = values_[indexOf(key)];
    const ParameterValue& v = material.value(key);
    if (!(current == v))
    {
      current = v;
      changed.push_back(QString::fromUtf8(key.data(), int(key.size())));
    }
  }
  return changed;
}

void SceneModel::setParts(std::vector<ScenePart> parts, MaterialLibrary library)
{
  if (parts.empty())
  {
    throw errorAbout("scene", "a scene needs at least one part");
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    const ScenePart& p = parts[i];
    if (p.name.empty())
    {
      throw errorAbout("scene", "part " + std::to_string(i + 1) + " has no name");
    }
    for (std::size_t j = 0; j < i; ++j)
    {
      if (parts[j].name == p.name)
      {
        throw errorAbout("scene", "two parts are named \"" + p.name + "\"");
      }
    }
    if (p.mesh.empty())
    {
      throw errorAbout("scene", "part \"" + p.name + "\" has no mesh");
    }
    checkPlacement(p.placement, "scene: part \"" + p.name + "\"");
    if (!library.contains(p.material))
    {
      throw errorAbout("scene", "part \"" + p.name + "\": material \"" + p.material +
                                    "\" is not in the library");
    }
  }
  QStringList changedMaterials;
  for (const Material& m : library.materials())
  {
    const Material* before = library_.find(m.name);
    if (!before || *before != m)
    {
      changedMaterials.push_back(QString::fromStdString(m.name));
    }
  }
  for (const Material& m : library_.materials())
  {
    if (!library.contains(m.name))
    {
      changedMaterials.push_back(QString::fromStdString(m.name));
    }
  }
  const bool partsDiffer = parts != parts_;
  // The selection keeps the parts still there, by name.
  std::vector<int> selection;
  for (int i : selection_)
  {
    for (std::size_t j = 0; j < parts.size(); ++j)
    {
      if (parts[j].name == parts_[i].name)
      {
        selection.push_back(int(j));
      }
    }
  }
  const bool selectionDiffers = selection != selection_;
  parts_ = std::move(parts);
  library_ = std::move(library);
  selection_ = std::move(selection);
  const std::vector<QString> changed = projectMaterial();
  for (const QString& key : changed)
  {
    emit valueChanged(key);
  }
  if (!changedMaterials.isEmpty())
  {
    emit materialsChanged(changedMaterials);
  }
  if (partsDiffer)
  {
    emit partsChanged();
  }
  if (selectionDiffers)
  {
    emit selectionChanged();
  }
}

const Material& SceneModel::partMaterial(int part) const
{
  return library_.at(parts_.at(std::size_t(part)).material);
}

ParameterSet SceneModel::partParameters(int part) const
{
  ParameterSet set = parameters();
  const Material& material = partMaterial(part);
  for (const ParameterSpec& spec : parameterSpecs())
  {
    if (spec.scope == ParameterScope::Material)
    {
      set.setValue(spec.name, material.value(spec.name));
    }
  }
  return set;
}

void SceneModel::setPartArrays(const std::string& part, std::vector<std::string> names)
{
  const auto it = partArrays_.find(part);
  if (it != partArrays_.end() ? it->second == names : names.empty())
  {
    return;
  }
  partArrays_[part] = std::move(names);
  emit partArraysChanged();
}

const std::vector<std::string>& SceneModel::partArrays(const std::string& part) const
{
  static const std::vector<std::string> none;
  const auto it = partArrays_.find(part);
  return it == partArrays_.end() ? none : it->second;
}

std::vector<std::string> SceneModel::editedPartArrays() const
{
  std::vector<std::string> names;
  for (int i : editedParts())
  {
    for (const std::string& name : partArrays(parts_[size_t(i)].name))
    {
      if (std::find(names.begin(), names.end(), name) == names.end())
      {
        names.push_back(name);
      }
    }
  }
  return names;
}

void SceneModel::setPartFields(const std::string& part, std::vector<std::string> names)
{
  const auto it = partFields_.find(part);
  if (it != partFields_.end() ? it->second == names : names.empty())
  {
    return;
  }
  partFields_[part] = std::move(names);
  emit partArraysChanged();
}

const std::vector<std::string>& SceneModel::partFields(const std::string& part) const
{
  static const std::vector<std::string> none;
  const auto it = partFields_.find(part);
  return it == partFields_.end() ? none : it->second;
}

std::vector<std::string> SceneModel::editedPartFields() const
{
  std::vector<std::string> names;
  for (int i : editedParts())
  {
    for (const std::string& name : partFields(parts_[size_t(i)].name))
    {
      if (std::find(names.begin(), names.end(), name) == names.end())
      {
        names.push_back(name);
      }
    }
  }
  return names;
}

void SceneModel::setSelection(std::vector<int> parts)
{
  std::vector<int> kept;
  for (int i : parts)
  {
    if (i >= 0 && i < int(parts_.size()) && std::find(kept.begin(), kept.end(), i) == kept.end())
    {
      kept.push_back(i);
    }
  }
  if (kept == selection_)
  {
    return;
  }
  selection_ = std::move(kept);
  const std::vector<QString> changed = projectMaterial();
  emit selectionChanged();
  for (const QString& key : changed)
  {
    emit valueChanged(key);
  }
}

std::vector<int> SceneModel::editedParts() const
{
  if (!selection_.empty())
  {
    return selection_;
  }
  std::vector<int> all(parts_.size());
  for (std::size_t i = 0; i < all.size(); ++i)
  {
    all[i] = int(i);
  }
  return all;
}

std::vector<std::string> SceneModel::editedMaterials() const
{
  std::vector<std::string> names;
  for (int i : editedParts())
  {
    const std::string& name = parts_[std::size_t(i)].material;
    if (std::find(names.begin(), names.end(), name) == names.end())
    {
      names.push_back(name);
    }
  }
  return names;
}

bool SceneModel::mixed(std::string_view key) const
{
  if (!isMaterialKey(key))
  {
    return false;
  }
  const std::vector<std::string> names = editedMaterials();
  for (const std::string& name : names)
  {
    if (!(library_.at(name).value(key) == library_.at(names.front()).value(key)))
    {
      return true;
    }
  }
  return false;
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
    const ParameterValue v =
        isMaterialKey(keys[i].spec.name)
            ? builtinMaterials().at(kStartMaterialName).value(keys[i].spec.name)
            : startValue(keys[i]);
    if (!(values_[i] == v))
    {
      values_[i] = v;
      changed.push_back(QString::fromStdString(std::string(keys[i].spec.name)));
    }
  }
  std::vector<ScenePart> parts{partOfMesh(text("mesh"), std::string(kStartMaterialName))};
  const bool partsDiffer = parts != parts_;
  const bool materialsDiffer = library_ != builtinMaterials();
  const bool hadSelection = !selection_.empty();
  parts_ = std::move(parts);
  library_ = builtinMaterials();
  selection_.clear();
  for (const QString& key : changed)
  {
    emit valueChanged(key);
  }
  if (materialsDiffer)
  {
    QStringList names;
    for (const Material& m : library_.materials())
    {
      names.push_back(QString::fromStdString(m.name));
    }
    emit materialsChanged(names);
  }
  if (partsDiffer)
  {
    emit partsChanged();
  }
  if (hadSelection)
  {
    emit selectionChanged();
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
