#pragma once
// Sessions: the whole scene (every parameter and asset path, and the camera) as versioned JSON.
//
//   {
//     "format": "aniso-session", "version": 1,
//     "parameters": {"nu": 1000, "f0": [0.913, 0.922, 0.924], "method": "exact", ...},
//     "assets": {"mesh": "part.stl", "normal-map": "", ...},
//     "view": {"position": [x, y, z], "focal-point": [...], "view-up": [...],
//              "view-angle": 30, "parallel": false, "parallel-scale": 1},
//     "parts": [{"name": "shaft", "mesh": "gearbox.obj", "block": "shaft",
//                "group": "gearbox.obj", "material": "brushed steel", "visible": true,
//                "placement": [16 numbers, row-major; left out when the identity]}, ...],
//     "materials": {"brushed steel": {"nu": 800, ...}, ...}
//   }
//
// "materials" is the "materials" object of a material library file (material_library.h). The
// material keys in "parameters" are those of the first edited part's material, so a reader of
// version 1 sees that material; this version takes the library's. A version-1 session (no
// "parts") opens as one part of its mesh with a material of its parameters.
//
// Numbers are written in the shortest form that reads back to the same double, so a session
// round-trips exactly. Paths under the session's directory are written relative to it (the
// folder can move as a whole) and read back against it; others stay absolute. Keys and sections
// this version does not know (a session from a newer version) are kept and written back on save,
// and reported once when the session is opened. A missing key takes its default.
#include "scene/SceneEditor.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace aniso
{
// Version 2 adds the parts and the material library; a version-1 session opens as one part.
constexpr int kSessionVersion = 2;

struct SessionContent
{
  SceneModel::Values values; // every key
  std::vector<ScenePart> parts; // never empty (a version-1 session: onePartScene)
  MaterialLibrary library;
  CameraState camera;
  QJsonObject unknown;     // what this version does not know, in the session's layout
  QStringList unknownKeys; // "parameters/foo", "future-section", for the report
};

// The scene as a session document; UNKNOWN is merged back in. Paths are made relative to
// BASE_DIRECTORY when they lie under it (empty: all paths kept as they are).
QJsonObject sessionToJson(const SceneModel& model, const QJsonObject& unknown,
                          const QString& baseDirectory);
// Reads a session document: types, ranges and choices are checked here (not file contents,
// which the model's validators check when the content is applied). Throws aniso::Error
// "SUBJECT: reason" (SUBJECT: the file) naming the key at fault.
SessionContent sessionFromJson(const QJsonObject& json, const QString& baseDirectory,
                               const QString& subject);

// Reads the session file PATH (sessionFromJson, paths relative to its folder), nothing applied;
// any thread. Throws aniso::Error "PATH: reason" (unreadable, not JSON, wrong format or version,
// a bad value).
SessionContent readSessionFile(const QString& path);

// Opening and saving, with the unknown keys of the last opened session kept for the next save.
class SessionFile
{
public:
  // Reads PATH and applies it to the editor's scene as one undoable step. Throws aniso::Error
  // "PATH: reason" (unreadable, not JSON, wrong format or version, a bad value, an asset that
  // does not load) and then leaves the scene and the kept keys as they were. Returns the keys
  // this version does not know.
  QStringList open(SceneEditor& editor, const QString& path);
  // Writes atomically (a failure leaves any existing file as it was). Throws aniso::Error.
  void save(const SceneModel& model, const QString& path) const;

  const QJsonObject& unknown() const { return unknown_; }

private:
  QJsonObject unknown_;
};
} // namespace aniso
