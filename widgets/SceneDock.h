#pragma once
// The scene dock (outliner): the parts of the scene as a tree (parts under the file they came
// from), each with its visibility (the check box), its material and its triangle count; several
// parts can be selected (the selection is the model's: the Material and Maps docks then edit the
// selected parts' materials, and the view outlines them). Below it the material library: a
// library material is assigned to the selected parts with Assign or by dragging it onto a part;
// Make unique gives each selected part a copy of its material of its own; the library can be
// saved as a material file (core/parameters/material_library.h) and materials read from one.
// Every change is one undoable edit (SceneEditor). No VTK: triangle counts come from whoever
// draws the parts (setTriangleCounts).
#include "scene/SceneEditor.h"

#include <QDockWidget>
#include <QString>
#include <functional>
#include <vector>

class QListWidget;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace aniso
{
class SceneDock : public QDockWidget
{
  Q_OBJECT

public:
  // The MIME type of a library material dragged from the dock's list: its name as UTF-8.
  static constexpr const char* kMaterialMime = "application/x-aniso-material";

  explicit SceneDock(SceneEditor* editor, QWidget* parent = nullptr);

  // Triangles of part I (a valid index), or a negative count when it did not load.
  void setTriangleCounts(std::function<long long(int part)> count);

  // The widgets, for keyboard-free tests.
  QTreeWidget* tree() const { return tree_; }
  QListWidget* library() const { return library_; }
  QPushButton* assignButton() const { return assign_; }
  QPushButton* uniqueButton() const { return unique_; }
  // The tree item of part I (a valid index).
  QTreeWidgetItem* partItem(int part) const;

  // Assigns library material NAME to the selected parts (all parts when none is selected).
  void assignToSelection(const QString& name);
  // Assigns NAME to part PART, and to the rest of the selection when PART is selected (a drop).
  void dropMaterial(const QString& name, int part);
  // Writes the scene's library to PATH; reads the materials of PATH into the library (a
  // material of a name already there replaces it). Errors are reported (errorOccurred).
  void saveLibrary(const QString& path);
  void loadLibrary(const QString& path);

public slots:
  // The triangle counts again (the view loaded or dropped a part's surface).
  void refreshCounts();

signals:
  void errorOccurred(const QString& message);

private:
  // Updates the rows of the parts when the parts are the same ones (names and groups) as the
  // rows; false (nothing changed) otherwise.
  bool refreshInPlace();
  void rebuildLibrary();
  void rebuild();
  void syncSelectionFromModel();
  void selectionEdited();
  void itemChanged(QTreeWidgetItem* item, int column);

  SceneEditor* editor_;
  QTreeWidget* tree_;
  QListWidget* library_;
  QPushButton* assign_;
  QPushButton* unique_;
  QPushButton* save_;
  QPushButton* load_;
  std::vector<QTreeWidgetItem*> items_; // parallel to the model's parts
  std::function<long long(int)> triangles_;
  bool syncing_ = false;
};
} // namespace aniso
