#pragma once
// The scene as the docks see it: every declared parameter (core/parameters/parameters.h), the
// asset paths (mesh and maps) and the camera, with one signal per change. Widgets edit the
// scene only through this model (usually through a SceneEditor, which makes edits undoable);
// the renderer listens to it. Qt-only: no VTK, no GL.
#include "core/parameters/parameters.h"

#include <QObject>
#include <QString>
#include <array>
#include <functional>
#include <map>
#include <string>
#include <string_view>
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

ParameterValue numberValue(double value);
ParameterValue colorValue(double r, double g, double b);
ParameterValue textValue(std::string text);

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

// Throws aniso::Error "view: reason" unless every number is finite, the view angle is in
// (0, 180), the parallel scale positive, and position, focal point and up make a frame.
void checkCameraState(const CameraState& camera);

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
  // Every key back to its default (validators are not consulted: defaults are always valid).
  void reset();

  void setValidator(std::string_view key, Validator validator);

  const CameraState& camera() const { return camera_; }
  // Throws aniso::Error "view: reason" (checkCameraState) and keeps the previous camera.
  void setCamera(const CameraState& camera);

signals:
  void valueChanged(const QString& key);
  void cameraChanged();

private:
  std::vector<ParameterValue> values_; // parallel to sceneKeys()
  std::vector<Validator> validators_;
  CameraState camera_;
};
} // namespace aniso
