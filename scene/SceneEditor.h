#pragma once
// Undoable edits of a SceneModel: every change a dock makes goes through here as a QUndoCommand,
// so Edit > Undo steps back through parameter changes. A slider drag is one step: its edits
// carry the same drag id and merge (QUndoCommand::mergeWith) into one command.
#include "scene/SceneModel.h"

#include <QObject>
#include <string>
#include <string_view>
#include <vector>

class QUndoStack;

namespace aniso
{
class SceneEditor : public QObject
{
  Q_OBJECT

public:
  // The steps the history keeps; the oldest goes when a new one would exceed it. A step holds
  // what it changed (6.3 KiB a material edit, 17 KiB an opened file in the soak's mix,
  // docs/RELIABILITY.md), so the history stays under about 20 MiB however long the session.
  static constexpr int kUndoLimit = 1000;

  explicit SceneEditor(SceneModel* model, QObject* parent = nullptr);
  ~SceneEditor() override;

  SceneModel* model() const { return model_; }
  QUndoStack* undoStack() const { return stack_; }

  // Checks every value, then pushes one command setting them all (a linked n_u, n_v move is one
  // step). Values equal to the current ones are left out; nothing is pushed when nothing
  // changes. Consecutive edits with the same non-zero dragId and the same keys merge into one
  // command. Throws aniso::Error "KEY: reason" and pushes nothing when a value is invalid.
  void edit(const SceneModel::Values& changes, int dragId = 0);
  void edit(std::string_view key, const ParameterValue& value, int dragId = 0);

  // A new id for a continuous gesture (a slider drag), never 0.
  int beginDrag();

  // Replaces every value and the camera in one undoable step named TEXT (opening a session).
  // Checked first: throws aniso::Error and leaves the scene and the stack as they were.
  void replaceScene(const SceneModel::Values& values, const CameraState& camera,
                    const QString& text);
  // The first makes the scene one part of the mesh key with the material of VALUES' material
  // keys (onePartScene); the second gives the parts and their library (a session of parts).
  void replaceScene(const SceneModel::Values& values, const CameraState& camera,
                    std::vector<ScenePart> parts, MaterialLibrary library, const QString& text);

  // Replaces the parts and the library as one undoable step named TEXT (adding files, renaming,
  // showing and hiding, assigning). Checked as SceneModel::setParts checks: throws aniso::Error
  // "scene: reason" and pushes nothing. Nothing is pushed when nothing changes.
  void editParts(std::vector<ScenePart> parts, MaterialLibrary library, const QString& text);
  // Gives each of PARTS that shares its material with another part a copy of it of its own,
  // named "MATERIAL (PART)" (made unique), one undoable step.
  void makeUnique(const std::vector<int>& parts);
  // Assigns library material MATERIAL (a built-in metal not in the scene's library is added to
  // it) to PARTS, one undoable step. Throws aniso::Error "MATERIAL: no such material".
  void assignMaterial(const std::vector<int>& parts, const std::string& material);
  // Shows or hides PARTS, one undoable step.
  void setPartsVisible(const std::vector<int>& parts, bool visible);

signals:
  // An undo or redo that could not be applied (an asset that no longer loads); the scene keeps
  // its values.
  void errorOccurred(const QString& message);

private:
  SceneModel* model_;
  QUndoStack* stack_;
  int lastDrag_ = 0;
};
} // namespace aniso
