#pragma once
// The lights dock: the shading model (from the registry of core/models/models.h), the built-in
// sample material of the lit models, and the list of point and directional lights with their
// direction or position and RGB intensity (spin boxes and a colour button). Every change is one
// undoable edit of the scene's "model", "sample-material" or "lights" key (SceneShading.h).
#include "core/lights/light.h"
#include "scene/SceneEditor.h"

#include <QDockWidget>
#include <array>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QListWidget;
class QPushButton;
class QToolButton;

namespace aniso
{
class LightsDock : public QDockWidget
{
  Q_OBJECT

public:
  explicit LightsDock(SceneEditor* editor, QWidget* parent = nullptr);

  // The widgets, for keyboard-free tests and for the window's layout.
  QComboBox* modelBox() const { return model_; }
  QComboBox* sampleBox() const { return sample_; }
  QListWidget* lightList() const { return list_; }
  QComboBox* typeBox() const { return type_; }
  QDoubleSpinBox* vectorBox(int axis) const { return vector_[std::size_t(axis)]; }
  QDoubleSpinBox* intensityBox(int channel) const { return intensity_[std::size_t(channel)]; }
  QPushButton* addButton() const { return add_; }
  QPushButton* removeButton() const { return remove_; }

  // The scene's lights (an unparsable "lights" text counts as none).
  std::vector<Light> lights() const;
  // Appends a copy of the selected light (or the default directional light) and selects it.
  void addLight();
  // Removes the selected light.
  void removeSelectedLight();
  // Replaces the selected light by LIGHT (what the editors do).
  void setSelectedLight(const Light& light);

signals:
  void errorOccurred(const QString& message);

private:
  void editLights(const std::vector<Light>& lights, int select);
  void syncFromModel();
  void showSelected();
  void editorsChanged();
  void chooseColour();

  SceneEditor* editor_;
  QComboBox* model_;
  QComboBox* sample_;
  QListWidget* list_;
  QComboBox* type_;
  std::array<QDoubleSpinBox*, 3> vector_{};
  std::array<QDoubleSpinBox*, 3> intensity_{};
  QToolButton* colour_;
  QPushButton* add_;
  QPushButton* remove_;
  bool syncing_ = false;
};
} // namespace aniso
