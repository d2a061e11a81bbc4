#include "widgets/ParameterPanel.h"

#include "core/error.h"
#include "widgets/ParameterControls.h"

#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>

namespace aniso
{
ParameterPanel::ParameterPanel(SceneEditor* editor, QWidget* parent)
    : QWidget(parent), editor_(editor), form_(new QFormLayout(this))
{
  form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  connect(model(), &SceneModel::valueChanged, this, &ParameterPanel::modelChanged);
  // Several parts of different materials selected: their differing values are marked mixed.
  connect(model(), &SceneModel::selectionChanged, this, &ParameterPanel::markMixed);
  connect(model(), &SceneModel::materialsChanged, this, &ParameterPanel::markMixed);
  connect(model(), &SceneModel::partsChanged, this, &ParameterPanel::markMixed);
}

void ParameterPanel::markMixed()
{
  for (const auto& [key, control] : controls_)
  {
    auto* label = qobject_cast<QLabel*>(form_->labelForField(control));
    if (!label || !isMaterialKey(key))
    {
      continue;
    }
    const QString base = QString::fromStdString(std::string(sceneKey(key).spec.label));
    const bool mixed = model()->mixed(key);
    // The control shows the first selected part's value; the label says the others differ.
    label->setText(mixed ? tr("%1 (mixed)").arg(base) : base);
    QFont font = label->font();
    font.setItalic(mixed);
    label->setFont(font);
    control->setToolTip(mixed ? tr("The selected parts' materials differ here; the value shown "
                                   "is the first part's, an edit sets it on all of them")
                              : parameterToolTip(control->spec()));
  }
}

ParameterControl* ParameterPanel::addParameter(std::string_view key)
{
  const SceneKey& k = sceneKey(key);
  ParameterControl* c = makeParameterControl(k.spec, this);
  if (!c)
  {
    throw errorAbout(std::string(key), "free text has no generic control");
  }
  c->setValue(model()->value(key));
  const std::string name(key);
  connect(c, &ParameterControl::dragStarted, this,
          [this]
          {
            drag_ = editor_->beginDrag();
            dragStartPending_ = true;
          });
  connect(c, &ParameterControl::dragFinished, this,
          [this, c, name]
          {
            drag_ = 0;
            dragStartPending_ = false;
            // The slider was left where the hand put it; show what the model holds now.
            c->setValue(model()->value(name));
          });
  connect(c, &ParameterControl::edited, this,
          [this, name](const ParameterValue& value, bool dragging)
          { submit(name, value, dragging); });
  auto* label = new QLabel(QString::fromStdString(std::string(k.spec.label)), this);
  label->setToolTip(c->toolTip());
  label->setBuddy(c);
  form_->addRow(label, c);
  controls_.emplace(name, c);
  markMixed();
  return c;
}

void ParameterPanel::addRow(const QString& label, QWidget* widget)
{
  form_->addRow(label, widget);
}

ParameterControl* ParameterPanel::control(std::string_view key) const
{
  const auto it = controls_.find(key);
  return it == controls_.end() ? nullptr : it->second;
}

void ParameterPanel::setExpander(Expander expander)
{
  expander_ = std::move(expander);
}

void ParameterPanel::submit(const std::string& key, const ParameterValue& value, bool dragging)
{
  const bool gestureStart = !dragging || dragStartPending_;
  dragStartPending_ = false;
  try
  {
    SceneModel::Values changes;
    if (expander_)
    {
      changes = expander_(key, value, gestureStart);
    }
    else
    {
      changes.emplace(key, value);
    }
    editor_->edit(changes, dragging ? drag_ : 0);
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromStdString(e.what()));
  }
  // Show what the model holds: a refused or adjusted value does not stay on screen.
  ParameterControl* c = control(key);
  if (c && !(model()->value(key) == value))
  {
    c->setValue(model()->value(key));
  }
}

void ParameterPanel::modelChanged(const QString& key)
{
  const std::string name = key.toStdString();
  if (ParameterControl* c = control(name))
  {
    c->setValue(model()->value(name));
  }
}

QWidget* scrollableColumn(const QList<QWidget*>& panels, QWidget* parent)
{
  auto* scroll = new QScrollArea(parent);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  // Rows shrink to the dock's width rather than scrolling sideways.
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  auto* inner = new QWidget(scroll);
  auto* column = new QVBoxLayout(inner);
  for (QWidget* panel : panels)
  {
    column->addWidget(panel);
  }
  column->addStretch(1);
  scroll->setWidget(inner);
  // Wide enough for the rows (they cannot shrink further), plus the vertical scroll bar.
  scroll->setMinimumWidth(inner->minimumSizeHint().width() +
                          scroll->verticalScrollBar()->sizeHint().width());
  return scroll;
}
} // namespace aniso
