#pragma once
// A form of parameter rows (label + control from the declaration) bound to a scene: it shows
// the model's values as they change and sends what the user does through the SceneEditor (one
// undoable command per edit, one per slider drag). Docks are made of these.
#include "scene/SceneEditor.h"

#include <QWidget>
#include <functional>
#include <map>
#include <string>
#include <string_view>

class QFormLayout;

namespace aniso
{
class ParameterControl;

class ParameterPanel : public QWidget
{
  Q_OBJECT

public:
  explicit ParameterPanel(SceneEditor* editor, QWidget* parent = nullptr);

  SceneEditor* editor() const { return editor_; }
  SceneModel* model() const { return editor_->model(); }

  // A row for KEY, its control made from the declaration (makeParameterControl); returns it.
  ParameterControl* addParameter(std::string_view key);
  // A row with any widget (custom controls; the caller keeps it in sync).
  void addRow(const QString& label, QWidget* widget);
  ParameterControl* control(std::string_view key) const;

  // Turns one edit of KEY into the full set of changes (a linked n_u also moves n_v).
  // `gestureStart` is true for the first edit of a drag or for an edit outside a drag.
  using Expander = std::function<SceneModel::Values(
      const std::string& key, const ParameterValue& value, bool gestureStart)>;
  void setExpander(Expander expander);

  // Sends an edit through the editor; errors are reported by errorOccurred, not thrown.
  void submit(const std::string& key, const ParameterValue& value, bool dragging);

signals:
  void errorOccurred(const QString& message);

private:
  // The label of each material key's control says "(mixed)" when the edited parts' materials
  // differ in it (SceneModel::mixed).
  void markMixed();
  void modelChanged(const QString& key);

  SceneEditor* editor_;
  QFormLayout* form_;
  std::map<std::string, ParameterControl*, std::less<>> controls_;
  Expander expander_;
  int drag_ = 0;
  bool dragStartPending_ = false;
};

// Lays PANELS out in one scrollable column: the widget of a dock.
QWidget* scrollableColumn(const QList<QWidget*>& panels, QWidget* parent);
} // namespace aniso
