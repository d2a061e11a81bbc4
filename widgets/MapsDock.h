#pragma once
// The maps dock: bump mode, normal and quaternion maps, the TPR map (pattern and parameters, or
// a file), height map with its scale, albedo, AO and metallic maps, and the tangent source with
// its axis. Files are checked by the model's validators (the application loads them), so a map
// that does not load is reported and the scene keeps the previous one.
#include "SceneEditor.h"

#include <QDockWidget>
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

signals:
  void errorOccurred(const QString& message);

private:
  void sync(const QString& key);

  ParameterPanel* panel_;
  std::map<std::string, FileRow*> files_;
  TprEditor* tpr_;
  TangentEditor* tangents_;
};
} // namespace aniso
