#include "widgets/MapsDock.h"

#include "widgets/AssetControls.h"
#include "widgets/ParameterPanel.h"

#include <QComboBox>
#include <QGroupBox>
#include <QLineEdit>
#include <QSignalBlocker>
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

QString help(const std::string& key)
{
  return QString::fromStdString(std::string(sceneKey(key).spec.help));
}

QGroupBox* group(const QString& title, QWidget* content, QWidget* parent)
{
  auto* box = new QGroupBox(title, parent);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(content);
  return box;
}
} // namespace

MapsDock::MapsDock(SceneEditor* editor, QWidget* parent)
    : QDockWidget(tr("Maps"), parent), panel_(new ParameterPanel(editor, this)),
      fields_(new ParameterPanel(editor, this)), field_(new QComboBox(this)),
      fieldRange_(new QLineEdit(this)), tpr_(new TprEditor(this)),
      tangents_(new TangentEditor(this))
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

  // The data field that drives the material (core/fields/field_mapping.h): typed, or chosen
  // from the edited parts' arrays; submitted when chosen or when its editing is finished.
  field_->setObjectName("field");
  field_->setEditable(true);
  field_->setInsertPolicy(QComboBox::NoInsert);
  field_->setToolTip(help("field"));
  fields_->addRow(label("field"), field_);
  connect(field_, qOverload<int>(&QComboBox::activated), this,
          [this](int index) { submitField("field", field_->itemText(index)); });
  connect(field_->lineEdit(), &QLineEdit::editingFinished, this,
          [this] { submitField("field", field_->currentText()); });
  fields_->addParameter("field-target");
  fields_->addParameter("field-colormap");
  fieldRange_->setObjectName("field-range");
  fieldRange_->setToolTip(help("field-range"));
  fields_->addRow(label("field-range"), fieldRange_);
  connect(fieldRange_, &QLineEdit::editingFinished, this,
          [this] { submitField("field-range", fieldRange_->text()); });
  fields_->addParameter("field-low");
  fields_->addParameter("field-high");
  fields_->addParameter("legend");

  connect(panel_, &ParameterPanel::errorOccurred, this, &MapsDock::errorOccurred);
  connect(fields_, &ParameterPanel::errorOccurred, this, &MapsDock::errorOccurred);
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
  // The field's choices follow the edited parts; whether their values differ too.
  for (auto signal :
       {&SceneModel::partArraysChanged, &SceneModel::selectionChanged, &SceneModel::partsChanged})
  {
    connect(editor->model(), signal, this, &MapsDock::offerFields);
  }
  connect(editor->model(), &SceneModel::materialsChanged, this,
          [this]
          {
            sync("field");
            sync("field-range");
          });
  offerFields();
  for (const auto& [key, row] : files_)
  {
    sync(QString::fromStdString(key));
  }
  sync("tpr");
  sync("tangents");
  sync("field-range");
  setWidget(scrollableColumn({panel_, group(tr("Field"), fields_, this)}, this));
}

void MapsDock::offerFields()
{
  {
    const QSignalBlocker block(field_);
    field_->clear();
    field_->addItem("none");
    for (const std::string& name : panel_->model()->editedPartFields())
    {
      field_->addItem(QString::fromStdString(name));
    }
  }
  sync("field");
}

void MapsDock::submitField(const std::string& key, const QString& text)
{
  const SceneModel* model = panel_->model();
  const std::string wanted = text.trimmed().toStdString();
  // Return in the combo's line both finishes the editing and may activate an item: one edit.
  if (wanted != model->text(key) || model->mixed(key))
  {
    fields_->submit(key, textValue(wanted), false);
  }
  // The row shows the scene's value (a refused text does not stay).
  sync(QString::fromStdString(key));
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
  else if (name == "field" || name == "field-range")
  {
    // A mixed value shows the first edited part's, as the other rows do; the tooltip tells.
    const QString text = QString::fromStdString(model->text(name));
    const QString tip = model->mixed(name)
                            ? tr("The selected parts' materials differ here; the value shown is "
                                 "the first part's, an edit sets it on all of them")
                            : help(name);
    if (name == "field")
    {
      const QSignalBlocker block(field_);
      field_->setCurrentIndex(field_->findText(text));
      field_->setEditText(text);
      field_->setToolTip(tip);
    }
    else
    {
      const QSignalBlocker block(fieldRange_);
      fieldRange_->setText(text);
      fieldRange_->setToolTip(tip);
    }
  }
  else if (FileRow* row = fileRow(name))
  {
    row->setText(QString::fromStdString(model->text(name)));
  }
}
} // namespace aniso
