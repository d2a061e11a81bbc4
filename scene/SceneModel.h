#pragma once
// The scene as the docks see it: every declared parameter (core/parameters/parameters.h), the
// asset paths (mesh and maps) and the camera, with one signal per change. Widgets edit the
// scene only through this model (usually through a SceneEditor, which makes edits undoable);
// the renderer listens to it. Qt-only: no VTK, no GL.
#include "core/parameters/material_library.h"
#include "core/parameters/parameters.h"
#include "core/placement.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <array>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace aniso
{
// A key of the scene: a declared parameter, or an asset (text that may be empty: "no map").
struct SceneKey
{
  ParameterSpec spec;
  bool asset = false;
};

// Every key, declared parameters first (in declaration order), then the shading model's keys
// (SceneShading.h: model, sample-material, lights), then the assets:
// mesh (a path or builtin:sphere|torus|plate), normal-map, quaternion-map, tpr (a pattern as
// parseTprPattern reads it, or an image path), height-map, albedo-map, ao-map, metallic-map.
const std::vector<SceneKey>& sceneKeys();
// Throws aniso::Error "KEY: unknown parameter".
const SceneKey& sceneKey(std::string_view key);
bool isSceneKey(std::string_view key);
// Whether a change of KEY affects any of WHAT (ParameterSpec::affects); false for a key that is
// no scene key.
bool sceneKeyAffects(std::string_view key, Affects what);

// Where the camera is; unset until a view was recorded (then the renderer frames the mesh).
struct CameraState
{
  bool set = false;
  std::array<double, 3> position{0.0, 0.0, 1.0};
  std::array<double, 3> focalPoint{0.0, 0.0, 0.0};
  std::array<double, 3> viewUp{0.0, 1.0, 0.0};
  double viewAngle = 30.0; // degrees, perspective
  bool parallel = false;
  double parallelScale = 1.0;

  bool operator==(const CameraState& o) const
  {
    return set == o.set && position == o.position && focalPoint == o.focalPoint &&
           viewUp == o.viewUp && viewAngle == o.viewAngle && parallel == o.parallel &&
           parallelScale == o.parallelScale;
  }
  bool operator!=(const CameraState& o) const { return !(*this == o); }
};

// A part of the scene: one surface (a mesh file, or one block of it) with a reference to a
// material of the scene's library. Parts are grouped by the file they came from (GROUP, shown as
// the parent of its parts in the scene dock).
struct ScenePart
{
  std::string name;     // unique in the scene
  std::string mesh;     // a mesh text: a file path or builtin:NAME
  std::string block;    // the block of the file (loadMeshBlocks' name); empty: the whole file
  std::string group;    // the file (or other source) the part belongs to; empty: none
  std::string material; // a material of the scene's library
  bool visible = true;
  // Where the part sits in the scene (core/placement.h): its tangent model's axes and centres
  // are in the part's own frame and turn with it.
  PartMatrix placement = kIdentityPlacement;

  bool operator==(const ScenePart& o) const
  {
    return name == o.name && mesh == o.mesh && block == o.block && group == o.group &&
           material == o.material && visible == o.visible && placement == o.placement;
  }
  bool operator!=(const ScenePart& o) const { return !(*this == o); }
};

// Throws aniso::Error "view: reason" unless every number is finite, the view angle is in
// (0, 180), the parallel scale positive, and position, focal point and up make a frame.
void checkCameraState(const CameraState& camera);

// The scene model. Scene-scope keys (environment, quality, display, the mesh) have one value;
// material keys (core/parameters/material_library.h: n_u, n_v, F0, ..., the maps) are the
// values of the materials of the edited parts: the selected parts, or every part when none is
// selected. value(KEY) of a material key is the first edited part's material's; setting it sets
// it in the material of every edited part (so in every part that shares one of those materials).
// The scene always has at least one part; setting the mesh key makes it one part of that mesh
// (the material of the first edited part kept), as opening a file does.
class SceneModel;

// The start-up scene (the window's first, and reset()'s; ./run renders the same offscreen): the
// built-in sphere (the mesh key's default) of the library's kStartMaterialName, aluminium brushed
// along the parallels (n_u 10000 along them, n_v 20 across), under the default studio at one
// stop under the declared exposure, so that each of the studio's windows is spread across the
// brushing into a thin streak from pole to pole: the brushing shows at a glance. Every other
// value is its key's default.
inline constexpr std::string_view kStartMesh = "builtin:sphere";
inline constexpr double kStartExposure = -1.0;

// The one part of a scene of MESH (a mesh text) with MATERIAL: named by the file's stem or the
// built-in's name, in no group.
ScenePart partOfMesh(const std::string& mesh, const std::string& material);

class SceneModel : public QObject
{
  Q_OBJECT

public:
  using Values = std::map<std::string, ParameterValue, std::less<>>;
  // Throws aniso::Error "SUBJECT: reason" when TEXT cannot be used (a file that does not load,
  // a tangent model that does not parse). Set by whoever can tell: the application installs
  // validators that load (and keep) meshes, images and environments.
  using Validator = std::function<void(const std::string& text, const std::string& subject)>;

  explicit SceneModel(QObject* parent = nullptr);
  ~SceneModel() override;

  const ParameterValue& value(std::string_view key) const;
  double real(std::string_view key) const;
  int integer(std::string_view key) const;
  std::array<double, 3> color(std::string_view key) const;
  const std::string& text(std::string_view key) const;
  // The declared parameters only, for code that takes a ParameterSet (the material).
  ParameterSet parameters() const;

  // Throws aniso::Error "KEY: reason" unless VALUE is valid for KEY: its declared range, type
  // and choices (an empty text is valid for assets: none), then its validator if any.
  void check(std::string_view key, const ParameterValue& value) const;
  // Checks, then sets and emits valueChanged if the value differs. On error the model is
  // unchanged.
  void setValue(std::string_view key, const ParameterValue& value);
  // All or nothing: every value is checked before any is set; one valueChanged per change.
  void setValues(const Values& values);
  // Every key with its value.
  Values values() const;
  // Back to the start-up scene (above): every key to its default but the exposure, one part of
  // the default mesh with the start-up material, the built-in library (validators are not
  // consulted: these values are always valid).
  void reset();

  void setValidator(std::string_view key, Validator validator);

  // The parts, in order, and the library their materials come from.
  const std::vector<ScenePart>& parts() const { return parts_; }
  const MaterialLibrary& materials() const { return library_; }
  // Sets the parts and the library together. Throws aniso::Error "scene: reason" and changes
  // nothing unless there is a part, part names are unique and not empty, and every part's
  // material is in LIBRARY. The selection keeps the parts that are still there (by name); the
  // material keys' values follow the edited parts' first material. Emits partsChanged,
  // materialsChanged (the names of the materials that changed or went) and valueChanged of the
  // material keys whose value changed.
  void setParts(std::vector<ScenePart> parts, MaterialLibrary library);
  // The material of part I (a valid index).
  const Material& partMaterial(int part) const;
  // The declared parameters as part I draws them: the scene's, with its material's over them.
  ParameterSet partParameters(int part) const;

  // Selected parts, by index, in the order selected (not part of the scene: not saved, not
  // undone). Out-of-range indices are dropped.
  const std::vector<int>& selection() const { return selection_; }
  void setSelection(std::vector<int> parts);
  // The parts material edits go to: the selection, or every part when none is selected.
  std::vector<int> editedParts() const;
  // The distinct materials of the edited parts, in part order.
  std::vector<std::string> editedMaterials() const;
  // Whether the edited materials differ in material key KEY (a dock shows such a value as mixed).
  bool mixed(std::string_view key) const;

  // The names of the vector arrays (fields of 2 or 3 components) a part's mesh carries, for the
  // tangent model array:NAME, by part name: told by whoever loads the meshes (the application),
  // not part of the scene (not saved, not undone). Emits partArraysChanged when they change.
  void setPartArrays(const std::string& part, std::vector<std::string> names);
  const std::vector<std::string>& partArrays(const std::string& part) const;
  // Those of the edited parts, each name once, in part order.
  std::vector<std::string> editedPartArrays() const;
  // Likewise what a part's mesh offers the `field` key (its data arrays, a vector's components:
  // "NAME", "NAME:x", ...), for the Maps dock's list; emits partArraysChanged when they change.
  void setPartFields(const std::string& part, std::vector<std::string> names);
  const std::vector<std::string>& partFields(const std::string& part) const;
  // Those of the edited parts, each once, in part order.
  std::vector<std::string> editedPartFields() const;

  const CameraState& camera() const { return camera_; }
  // Throws aniso::Error "view: reason" (checkCameraState) and keeps the previous camera.
  void setCamera(const CameraState& camera);

signals:
  void valueChanged(const QString& key);
  void cameraChanged();
  void partsChanged();
  // Materials of the library whose values changed (or that were added or removed).
  void materialsChanged(const QStringList& names);
  void selectionChanged();
  void partArraysChanged();

private:
  // The material keys' values from the first edited part's material; emits valueChanged for
  // those that changed.
  std::vector<QString> projectMaterial();

  std::vector<ParameterValue> values_; // parallel to sceneKeys()
  std::vector<ScenePart> parts_;
  MaterialLibrary library_;
  std::vector<int> selection_;
  std::map<std::string, std::vector<std::string>> partArrays_;
  std::map<std::string, std::vector<std::string>> partFields_;
  std::vector<Validator> validators_;
  CameraState camera_;
};

// The scene of one part that VALUES (every key, as a session of the single-material version
// held them) make: the mesh key's part with a material of the values' material keys, which is
// LIBRARY's material of those values when there is one, else a new one named "material" (made
// unique) added to LIBRARY.
std::pair<std::vector<ScenePart>, MaterialLibrary> onePartScene(const SceneModel::Values& values,
                                                                MaterialLibrary library);
} // namespace aniso
