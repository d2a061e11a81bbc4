#include "widgets/MapsDock.h"

#include "widgets/AssetControls.h"
#include "widgets/ParameterPanel.h"

#include <QGroupBox>
#include <QStringList>
#include <QVBoxLayout>

namespace aniso
{
namespace
{
QString label(const std::string& key)
{
  return QString::fromStdString(std::string(sceneKey(key).spec.label));
}
} // namespace

MapsDock::MapsDock(SceneEditor* editor, QWidget* parent)
    : QDockWidget(tr("Maps"), parent), panel_(new ParameterPanel(editor, this)),
      tpr_(new TprEditor(this)), tangents_(new TangentEditor(this))
{
  setObjectName("MapsDock");
  auto addFile = [this](const std::string& key)
  {
    auto* row = new FileRow(tr("Open %1").arg(label(key)), imageFileFilter(), this);
    row->setObjectName(QString::fromStdString(key));
    row->setToolTip(QString::fromStdString(std::string(sceneKey(key).spec.help)));
    panel_->addRow(label(key), row);
    files_.emplace(key, row);
    connect(row, &FileRow::edited, this, [this, key](const QString& path) { submit(key, path); });
  };

  panel_->addParameter("bump");
  addFile("normal-map");
  addFile("quaternion-map");
  tpr_->setObjectName("tpr");
  panel_->addRow(label("tpr"), tpr_);
  connect(tpr_, &TprEditor::edited, this, [this](const QString& text) { submit("tpr", text); });
  addFile("height-map");
  panel_->addParameter("height-scale");
  addFile("albedo-map");
  addFile("ao-map");
  addFile("metallic-map");
  tangents_->setObjectName("tangents");
  panel_->addRow(label("tangents"), tangents_);
  connect(tangents_, &TangentEditor::edited, this,
          [this](const QString& text) { submit("tangents", text); });
  // How STEP and IGES parts are tessellated: beside the tangents, which face-u and face-v take
  // from the same faces.
  panel_->addParameter("cad-deflection");
  panel_->addParameter("cad-angle");

  connect(panel_, &ParameterPanel::errorOccurred, this, &MapsDock::errorOccurred);
  connect(editor->model(), &SceneModel::valueChanged, this, &MapsDock::sync);
  // The vector arrays of the edited parts, for the tangent model array:NAME.
  const auto offerArrays = [this]
  {
    QStringList names;
    for (const std::string& name : panel_->model()->editedPartArrays())
    {
      names.push_back(QString::fromStdString(name));
    }
    tangents_->setArrayNames(names);
  };
  connect(editor->model(), &SceneModel::partArraysChanged, this, offerArrays);
  connect(editor->model(), &SceneModel::selectionChanged, this, offerArrays);
  connect(editor->model(), &SceneModel::partsChanged, this, offerArrays);
  offerArrays();
  for (const auto& [key, row] : files_)
  {
    sync(QString::fromStdString(key));
  }
  sync("tpr");
  sync("tangents");
  setWidget(scrollableColumn({panel_}, this));
}

void MapsDock::submit(const std::string& key, const QString& text)
{
  if (opener_)
  {
    opener_(key, text);
  }
  else
  {
    panel_->submit(key, textValue(text.toStdString()), false);
  }
  // The row shows the scene's value until it changes.
  sync(QString::fromStdString(key));
}

FileRow* MapsDock::fileRow(const std::string& key) const
{
  const auto it = files_.find(key);
  return it == files_.end() ? nullptr : it->second;
}

void MapsDock::sync(const QString& key)
{
  const std::string name = key.toStdString();
  const SceneModel* model = panel_->model();
  if (name == "tpr")
  {
    tpr_->setText(QString::fromStdString(model->text("tpr")));
  }
  else if (name == "tangents")
  {
    tangents_->setText(QString::fromStdString(model->text("tangents")));
  }
  else if (FileRow* row = fileRow(name))
  {
    row->setText(QString::fromStdString(model->text(name)));
  }
}
} // namespace aniso
