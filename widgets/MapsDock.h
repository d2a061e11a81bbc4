#pragma once
// The maps dock: bump mode, normal and quaternion maps, the TPR map (pattern and parameters, or
// a file), height map with its scale, albedo, AO and metallic maps, and the tangent source with
// its axis (or, for array:NAME, the edited parts' vector arrays, SceneModel::editedPartArrays).
// Files are checked by the model's validators (the application loads them), so a map that does not
// load is reported and the scene keeps the previous one. Then the data field that drives the
// material: field (typed, or one of the edited parts' arrays and components,
// SceneModel::editedPartFields), what it drives, its colour map, range and low and high values,
// and the scene's legend.
#include "scene/SceneEditor.h"

#include <QDockWidget>
#include <QString>
#include <functional>
#include <map>
#include <string>

class QComboBox;
class QLineEdit;

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
  // The field (editable: "none", the offered choices, or any text the field key takes) and its
  // range ("auto" or MIN,MAX); each submits its text when edited.
  QComboBox* fieldBox() const { return field_; }
  QLineEdit* fieldRangeEdit() const { return fieldRange_; }

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
  // The field's or its range's TEXT to the scene (not through the opener: no file to read),
  // unless it is what the edited parts already hold.
  void submitField(const std::string& key, const QString& text);
  // The field's choices: none, then the edited parts' arrays and components.
  void offerFields();

  ParameterPanel* panel_;
  ParameterPanel* fields_;
  QComboBox* field_;
  QLineEdit* fieldRange_;
  std::map<std::string, FileRow*> files_;
  TprEditor* tpr_;
  TangentEditor* tangents_;
  std::function<void(const std::string&, const QString&)> opener_;
};
} // namespace aniso
