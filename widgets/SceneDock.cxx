#include "widgets/SceneDock.h"

#include "core/error.h"
#include "core/parameters/material_library.h"

#include <QDragEnterEvent>
#include <QDragMoveEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMimeData>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <map>

namespace aniso
{
namespace
{
constexpr int kPartRole = Qt::UserRole + 1; // the part's index on a part's item

// The library list: a dragged material carries its name as kMaterialMime.
class MaterialList : public QListWidget
{
public:
  using QListWidget::QListWidget;

protected:
  QStringList mimeTypes() const override { return {SceneDock::kMaterialMime}; }
  QMimeData* mimeData(const QList<QListWidgetItem*> items) const override
  {
    if (items.isEmpty())
    {
      return nullptr;
    }
    auto* mime = new QMimeData;
    mime->setData(SceneDock::kMaterialMime, items.front()->text().toUtf8());
    return mime;
  }
};

// The part tree: takes a dropped material onto the part under the cursor.
class PartTree : public QTreeWidget
{
public:
  std::function<void(const QString&, int)> dropped;

protected:
  void dragEnterEvent(QDragEnterEvent* event) override
  {
    if (event->mimeData()->hasFormat(SceneDock::kMaterialMime))
    {
      event->acceptProposedAction();
    }
  }
  void dragMoveEvent(QDragMoveEvent* event) override
  {
    QTreeWidgetItem* item = itemAt(event->pos());
    if (event->mimeData()->hasFormat(SceneDock::kMaterialMime) && item &&
        item->data(0, kPartRole).isValid())
    {
      event->acceptProposedAction();
    }
    else
    {
      event->ignore();
    }
  }
  void dropEvent(QDropEvent* event) override
  {
    QTreeWidgetItem* item = itemAt(event->pos());
    if (!item || !item->data(0, kPartRole).isValid() || !dropped)
    {
      event->ignore();
      return;
    }
    dropped(QString::fromUtf8(event->mimeData()->data(SceneDock::kMaterialMime)),
            item->data(0, kPartRole).toInt());
    event->acceptProposedAction();
  }
};

QString qs(const std::string& s)
{
  return QString::fromStdString(s);
}
} // namespace

SceneDock::SceneDock(SceneEditor* editor, QWidget* parent)
    : QDockWidget(tr("Scene"), parent), editor_(editor)
{
  setObjectName("SceneDock");
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);

  auto* tree = new PartTree;
  tree_ = tree;
  tree_->setObjectName("parts");
  tree_->setColumnCount(3);
  tree_->setHeaderLabels({tr("Part"), tr("Material"), tr("Triangles")});
  tree_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  tree_->setAcceptDrops(true);
  tree_->setDropIndicatorShown(true);
  tree_->header()->setStretchLastSection(false);
  tree_->header()->setSectionResizeMode(0, QHeaderView::Stretch);
  tree->dropped = [this](const QString& name, int part) { dropMaterial(name, part); };
  layout->addWidget(tree_, 2);

  layout->addWidget(new QLabel(tr("Material library (drag onto a part)")));
  auto* list = new MaterialList;
  library_ = list;
  library_->setObjectName("library");
  library_->setDragEnabled(true);
  library_->setDragDropMode(QAbstractItemView::DragOnly);
  layout->addWidget(library_, 1);

  auto* buttons = new QHBoxLayout;
  assign_ = new QPushButton(tr("Assign"));
  assign_->setToolTip(tr("Give the selected parts the library material chosen above"));
  unique_ = new QPushButton(tr("Make unique"));
  unique_->setToolTip(tr("Give each selected part a copy of its material of its own"));
  save_ = new QPushButton(tr("Save…"));
  save_->setToolTip(tr("Save the scene's material library as a file"));
  load_ = new QPushButton(tr("Load…"));
  load_->setToolTip(tr("Add the materials of a library file"));
  for (QPushButton* b : {assign_, unique_, save_, load_})
  {
    buttons->addWidget(b);
  }
  layout->addLayout(buttons);
  setWidget(body);

  connect(assign_, &QPushButton::clicked, this,
          [this]
          {
            if (QListWidgetItem* item = library_->currentItem())
            {
              assignToSelection(item->text());
            }
          });
  connect(library_, &QListWidget::itemDoubleClicked, this,
          [this](QListWidgetItem* item) { assignToSelection(item->text()); });
  connect(unique_, &QPushButton::clicked, this,
          [this]
          {
            try
            {
              editor_->makeUnique(editor_->model()->editedParts());
            }
            catch (const Error& e)
            {
              emit errorOccurred(QString::fromStdString(e.what()));
            }
          });
  connect(save_, &QPushButton::clicked, this,
          [this]
          {
            const QString path = QFileDialog::getSaveFileName(
                this, tr("Save the material library"), QString(),
                tr("Material libraries (*.json);;All files (*)"));
            if (!path.isEmpty())
            {
              saveLibrary(path);
            }
          });
  connect(load_, &QPushButton::clicked, this,
          [this]
          {
            const QString path = QFileDialog::getOpenFileName(
                this, tr("Add the materials of a library"), QString(),
                tr("Material libraries (*.json);;All files (*)"));
            if (!path.isEmpty())
            {
              loadLibrary(path);
            }
          });
  connect(tree_, &QTreeWidget::itemSelectionChanged, this, &SceneDock::selectionEdited);
  connect(tree_, &QTreeWidget::itemChanged, this, &SceneDock::itemChanged);

  SceneModel* model = editor_->model();
  connect(model, &SceneModel::partsChanged, this, &SceneDock::rebuild);
  connect(model, &SceneModel::materialsChanged, this, &SceneDock::rebuild);
  connect(model, &SceneModel::selectionChanged, this, &SceneDock::syncSelectionFromModel);
  rebuild();
}

void SceneDock::setTriangleCounts(std::function<long long(int part)> count)
{
  triangles_ = std::move(count);
  refreshCounts();
}

QTreeWidgetItem* SceneDock::partItem(int part) const
{
  return items_.at(std::size_t(part));
}

void SceneDock::refreshCounts()
{
  syncing_ = true;
  for (std::size_t i = 0; i < items_.size(); ++i)
  {
    const long long n = triangles_ ? triangles_(int(i)) : -1;
    items_[i]->setText(2, n < 0 ? tr("not loaded") : QString::number(n));
    items_[i]->setTextAlignment(2, Qt::AlignRight | Qt::AlignVCenter);
  }
  syncing_ = false;
}

namespace
{
// The group item a part's item sits under (null at the top level).
QString groupOf(const QTreeWidgetItem* item)
{
  return item->parent() ? item->parent()->text(0) : QString();
}
} // namespace

bool SceneDock::refreshInPlace()
{
  const auto& parts = editor_->model()->parts();
  if (items_.size() != parts.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    if (items_[i]->text(0) != qs(parts[i].name) || groupOf(items_[i]) != qs(parts[i].group))
    {
      return false;
    }
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    const ScenePart& part = parts[i];
    QTreeWidgetItem* item = items_[i];
    if (item->text(1) != qs(part.material))
    {
      item->setText(1, qs(part.material));
    }
    const Qt::CheckState check = part.visible ? Qt::Checked : Qt::Unchecked;
    if (item->checkState(0) != check)
    {
      item->setCheckState(0, check);
    }
    const QString tip = qs(part.mesh + (part.block.empty() ? "" : " (" + part.block + ")"));
    if (item->toolTip(0) != tip)
    {
      item->setToolTip(0, tip);
    }
  }
  return true;
}

void SceneDock::rebuild()
{
  syncing_ = true;
  const SceneModel& model = *editor_->model();
  // The same parts (names and groups): their rows updated where they differ. A material edit
  // (every slider step) and an assignment touch one column of a few rows, not the whole tree.
  if (refreshInPlace())
  {
    rebuildLibrary();
    syncing_ = false;
    refreshCounts();
    syncSelectionFromModel();
    return;
  }
  tree_->clear();
  items_.clear();
  std::map<std::string, QTreeWidgetItem*> groups;
  const auto& parts = model.parts();
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    const ScenePart& part = parts[i];
    QTreeWidgetItem* parent = nullptr;
    if (!part.group.empty())
    {
      auto& group = groups[part.group];
      if (!group)
      {
        group = new QTreeWidgetItem(tree_, {qs(part.group)});
        group->setFlags(Qt::ItemIsEnabled);
        group->setExpanded(true);
      }
      parent = group;
    }
    auto* item = parent ? new QTreeWidgetItem(parent, {qs(part.name), qs(part.material)})
                        : new QTreeWidgetItem(tree_, {qs(part.name), qs(part.material)});
    item->setData(0, kPartRole, int(i));
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable |
                   Qt::ItemIsDropEnabled);
    item->setCheckState(0, part.visible ? Qt::Checked : Qt::Unchecked);
    item->setToolTip(0, qs(part.mesh + (part.block.empty() ? "" : " (" + part.block + ")")));
    items_.push_back(item);
  }
  for (auto& [name, group] : groups)
  {
    group->setExpanded(true);
  }
  rebuildLibrary();
  syncing_ = false;
  refreshCounts();
  syncSelectionFromModel();
}

void SceneDock::rebuildLibrary()
{
  // The library: the scene's materials, then the built-in metals it does not hold; the list
  // is made again only when those names changed.
  const SceneModel& model = *editor_->model();
  QStringList names;
  for (const Material& m : model.materials().materials())
  {
    names << qs(m.name);
  }
  for (const Material& m : builtinMaterials().materials())
  {
    if (!model.materials().contains(m.name))
    {
      names << qs(m.name);
    }
  }
  QStringList shown;
  for (int i = 0; i < library_->count(); ++i)
  {
    shown << library_->item(i)->text();
  }
  if (shown == names)
  {
    return;
  }
  const QString current = library_->currentItem() ? library_->currentItem()->text() : QString();
  library_->clear();
  library_->addItems(names);
  const auto found = library_->findItems(current, Qt::MatchExactly);
  if (!found.isEmpty())
  {
    library_->setCurrentItem(found.front());
  }
}

void SceneDock::syncSelectionFromModel()
{
  syncing_ = true;
  const std::vector<int>& selection = editor_->model()->selection();
  for (std::size_t i = 0; i < items_.size(); ++i)
  {
    items_[i]->setSelected(std::find(selection.begin(), selection.end(), int(i)) !=
                           selection.end());
  }
  if (!selection.empty() && selection.front() < int(items_.size()))
  {
    tree_->scrollToItem(items_[std::size_t(selection.front())]);
  }
  syncing_ = false;
}

void SceneDock::selectionEdited()
{
  if (syncing_)
  {
    return;
  }
  std::vector<int> selection;
  for (QTreeWidgetItem* item : tree_->selectedItems())
  {
    if (item->data(0, kPartRole).isValid())
    {
      selection.push_back(item->data(0, kPartRole).toInt());
    }
  }
  std::sort(selection.begin(), selection.end());
  editor_->model()->setSelection(selection);
}

void SceneDock::itemChanged(QTreeWidgetItem* item, int column)
{
  if (syncing_ || column != 0 || !item->data(0, kPartRole).isValid())
  {
    return;
  }
  const int part = item->data(0, kPartRole).toInt();
  const bool visible = item->checkState(0) == Qt::Checked;
  if (part < int(editor_->model()->parts().size()) &&
      editor_->model()->parts()[std::size_t(part)].visible != visible)
  {
    // Deferred: the edit rebuilds the tree, which must not happen inside the item's signal.
    QMetaObject::invokeMethod(
        this, [this, part, visible] { editor_->setPartsVisible({part}, visible); },
        Qt::QueuedConnection);
  }
}

void SceneDock::assignToSelection(const QString& name)
{
  try
  {
    editor_->assignMaterial(editor_->model()->editedParts(), name.toStdString());
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromStdString(e.what()));
  }
}

void SceneDock::dropMaterial(const QString& name, int part)
{
  const std::vector<int>& selection = editor_->model()->selection();
  std::vector<int> parts{part};
  if (std::find(selection.begin(), selection.end(), part) != selection.end())
  {
    parts = selection;
  }
  try
  {
    editor_->assignMaterial(parts, name.toStdString());
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromStdString(e.what()));
  }
}

void SceneDock::saveLibrary(const QString& path)
{
  try
  {
    writeMaterialLibrary(path.toStdString(), editor_->model()->materials());
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromStdString(e.what()));
  }
}

void SceneDock::loadLibrary(const QString& path)
{
  try
  {
    const MaterialLibrary read = readMaterialLibrary(path.toStdString());
    MaterialLibrary library = editor_->model()->materials();
    for (const Material& m : read.materials())
    {
      library.put(m);
    }
    editor_->editParts(editor_->model()->parts(), std::move(library),
                       tr("Load materials from %1").arg(path));
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromStdString(e.what()));
  }
}
} // namespace aniso
