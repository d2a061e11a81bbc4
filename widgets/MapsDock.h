#pragma once
// The maps dock: bump mode, normal and quaternion maps, the TPR map (pattern and parameters, or
// a file), height map with its scale, albedo, AO and metallic maps, and the tangent source with
// its axis (or, for array:NAME, the edited parts' vector arrays, SceneModel::editedPartArrays). Files are checked by the model's validators (the application loads them), so a map
// that does not load is reported and the scene keeps the previous one.
#include "scene/SceneEditor.h"

#include <QDockWidget>
#include <functional>
#include <map>
#include <string>

namespace aniso
{
class FileRow;
class ParameterPanel;
class TangentEditor;
class TprEditor;

class MapsDock : public QDockWidget
{
  Q_OBJECT

public:
  explicit MapsDock(SceneEditor* editor, QWidget* parent = nullptr);

  FileRow* fileRow(const std::string& key) const;
  TprEditor* tprEditor() const { return tpr_; }
  TangentEditor* tangentEditor() const { return tangents_; }

  // How an edited map (file or pattern) or tangent model reaches the scene: by default it is
  // submitted to the editor at once, the model's validation reading the file or preparing the
  // mesh on this thread; an opener set here takes the key and text instead (the main window
  // reads them on a worker first, then edits the scene).
  void setOpener(std::function<void(const std::string& key, const QString& text)> opener)
  {
    opener_ = std::move(opener);
  }

signals:
  void errorOccurred(const QString& message);

private:
  void sync(const QString& key);
  // KEY's new TEXT to the scene (through the opener when there is one).
  void submit(const std::string& key, const QString& text);

  ParameterPanel* panel_;
  std::map<std::string, FileRow*> files_;
  TprEditor* tpr_;
  TangentEditor* tangents_;
  std::function<void(const std::string&, const QString&)> opener_;
};
} // namespace aniso
