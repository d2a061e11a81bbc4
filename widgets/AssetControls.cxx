#include "widgets/AssetControls.h"

#include "core/error.h"
#include "core/maps/tpr_map.h"
#include "core/parameters/parameters.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QSignalBlocker>
#include <QStringList>
#include <QToolButton>
#include <QUrl>

namespace aniso
{
namespace
{
QString number(double value)
{
  return QString::fromStdString(formatNumber(value));
}

QDoubleSpinBox* spinBox(double minimum, double maximum, double step, int decimals, QWidget* parent)
{
  auto* spin = new QDoubleSpinBox(parent);
  spin->setRange(minimum, maximum);
  spin->setSingleStep(step);
  spin->setDecimals(decimals);
  spin->setKeyboardTracking(false);
  return spin;
}

QWidget* row(const QList<QWidget*>& widgets, QWidget* parent)
{
  auto* w = new QWidget(parent);
  auto* layout = new QHBoxLayout(w);
  layout->setContentsMargins(0, 0, 0, 0);
  for (QWidget* item : widgets)
  {
    layout->addWidget(item, item->inherits("QLabel") ? 0 : 1);
  }
  return w;
}
} // namespace

QString imageFileFilter()
{
  return QObject::tr("Images (*.exr *.hdr *.tif *.tiff *.png *.jpg *.jpeg *.tga *.bmp *.dds);;"
                     "All files (*)");
}

FileRow::FileRow(const QString& caption, const QString& filter, QWidget* parent)
    : QWidget(parent), caption_(caption), filter_(filter), edit_(new QLineEdit(this))
{
  edit_->setPlaceholderText(tr("none"));
  edit_->setClearButtonEnabled(true);
  // Drops go to the row (a file), not into the text as a URL.
  edit_->setAcceptDrops(false);
  setAcceptDrops(true);
  auto* open = new QToolButton(this);
  open->setText(tr("…"));
  open->setToolTip(tr("Choose a file"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(edit_, 1);
  layout->addWidget(open);
  connect(open, &QToolButton::clicked, this,
          [this]
          {
            const QString start =
                edit_->text().isEmpty() ? QString() : QFileInfo(edit_->text()).path();
            const QString path = QFileDialog::getOpenFileName(this, caption_, start, filter_);
            if (!path.isEmpty())
            {
              edit_->setText(path);
              emit edited(path);
            }
          });
  connect(edit_, &QLineEdit::editingFinished, this,
          [this]
          {
            if (edit_->isModified())
            {
              edit_->setModified(false);
              emit edited(edit_->text().trimmed());
            }
          });
}

void FileRow::dragEnterEvent(QDragEnterEvent* event)
{
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.size() == 1 && urls.front().isLocalFile())
  {
    event->acceptProposedAction();
  }
}

void FileRow::dropEvent(QDropEvent* event)
{
  const QString path = event->mimeData()->urls().front().toLocalFile();
  event->acceptProposedAction();
  setText(path);
  emit edited(path);
}

void FileRow::setText(const QString& path)
{
  const QSignalBlocker block(edit_);
  edit_->setText(path);
  edit_->setModified(false);
  edit_->setToolTip(path);
}

QString FileRow::text() const
{
  return edit_->text().trimmed();
}

TprEditor::TprEditor(QWidget* parent)
    : QWidget(parent), pattern_(new QComboBox(this)), angle_(spinBox(-180.0, 180.0, 1.0, 2, this)),
      centreU_(spinBox(-1.0, 2.0, 0.01, 3, this)), centreV_(spinBox(-1.0, 2.0, 0.01, 3, this)),
      pitch_(spinBox(-90.0, 90.0, 1.0, 2, this)),
      file_(new FileRow(tr("Open a TPR map"), imageFileFilter(), this))
{
  const std::pair<const char*, const char*> patterns[] = {
      {"", "None"},         {"linear", "Linear"}, {"circular", "Circular"}, {"radial", "Radial"},
      {"spiral", "Spiral"}, {"wave", "Wave"},     {"file", "File"}};
  for (const auto& [value, label] : patterns)
  {
    pattern_->addItem(tr(label), QString(value));
  }
  angle_->setSuffix(" deg");
  pitch_->setSuffix(" deg");
  const TprParams defaults;
  angle_->setValue(defaults.angleDegrees);
  centreU_->setValue(defaults.centre.x);
  centreV_->setValue(defaults.centre.y);
  pitch_->setValue(defaults.pitchDegrees);
  angle_->setObjectName("tpr-angle");
  centreU_->setObjectName("tpr-u");
  centreV_->setObjectName("tpr-v");
  pitch_->setObjectName("tpr-pitch");

  angleRow_ = row({new QLabel(tr("Angle"), this), angle_}, this);
  centreRow_ = row({new QLabel(tr("Centre u, v"), this), centreU_, centreV_}, this);
  pitchRow_ = row({new QLabel(tr("Pitch"), this), pitch_}, this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  for (QWidget* w : {static_cast<QWidget*>(pattern_), angleRow_, centreRow_, pitchRow_,
                     static_cast<QWidget*>(file_)})
  {
    layout->addWidget(w);
  }
  connect(pattern_, qOverload<int>(&QComboBox::activated), this,
          [this](int index)
          {
            pattern_->setCurrentIndex(index);
            updateVisibility();
            emitEdited();
          });
  for (QDoubleSpinBox* spin : {angle_, centreU_, centreV_, pitch_})
  {
    connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &TprEditor::emitEdited);
  }
  connect(file_, &FileRow::edited, this, &TprEditor::emitEdited);
  updateVisibility();
}

void TprEditor::setText(const QString& text)
{
  const QSignalBlocker blocks[] = {QSignalBlocker(pattern_), QSignalBlocker(angle_),
                                   QSignalBlocker(centreU_), QSignalBlocker(centreV_),
                                   QSignalBlocker(pitch_)};
  QString kind;
  if (text.isEmpty())
  {
    kind = "";
  }
  else
  {
    try
    {
      const TprParams p = parseTprPattern(text.toStdString());
      const char* names[] = {"linear", "circular", "radial", "spiral", "wave"};
      kind = names[static_cast<int>(p.pattern)];
      angle_->setValue(p.angleDegrees);
      centreU_->setValue(p.centre.x);
      centreV_->setValue(p.centre.y);
      pitch_->setValue(p.pitchDegrees);
    }
    catch (const Error&)
    {
      // Not a pattern: a file.
      kind = "file";
    }
  }
  file_->setText(kind == "file" ? text : QString());
  pattern_->setCurrentIndex(pattern_->findData(kind));
  updateVisibility();
}

QString TprEditor::text() const
{
  const QString kind = pattern_->currentData().toString();
  const QString centre = number(centreU_->value()) + "," + number(centreV_->value());
  if (kind == "linear")
  {
    return "linear:" + number(angle_->value());
  }
  if (kind == "circular" || kind == "radial")
  {
    return kind + ":" + centre;
  }
  if (kind == "spiral")
  {
    return "spiral:" + centre + ":" + number(pitch_->value());
  }
  if (kind == "file")
  {
    return file_->text();
  }
  return kind; // "wave" or "" (none)
}

void TprEditor::updateVisibility()
{
  const QString kind = pattern_->currentData().toString();
  angleRow_->setVisible(kind == "linear");
  centreRow_->setVisible(kind == "circular" || kind == "radial" || kind == "spiral");
  pitchRow_->setVisible(kind == "spiral");
  file_->setVisible(kind == "file");
}

void TprEditor::emitEdited()
{
  // Choosing "File" says nothing until a file is chosen.
  if (pattern_->currentData().toString() == "file" && file_->text().isEmpty())
  {
    return;
  }
  emit edited(text());
}

TangentEditor::TangentEditor(QWidget* parent)
    : QWidget(parent), kind_(new QComboBox(this)), array_(new QComboBox(this)),
      vectorLabel_(new QLabel(this))
{
  const std::pair<const char*, const char*> kinds[] = {
      {"auto", "Automatic (mesh, UVs, else along X)"},
      {"uv", "From UVs"},
      {"axis", "Along an axis (linear brushing)"},
      {"around", "Around an axis (turned)"},
      {"radial", "Radial from a point"},
      {"face-u", "Along the CAD faces' u"},
      {"face-v", "Along the CAD faces' v"},
      {"array", "Along a vector array of the data"}};
  for (const auto& [value, label] : kinds)
  {
    kind_->addItem(tr(label), QString(value));
  }
  QList<QWidget*> items{vectorLabel_};
  const char* names[3] = {"tangent-x", "tangent-y", "tangent-z"};
  for (int i = 0; i < 3; ++i)
  {
    vector_[i] = spinBox(-1000.0, 1000.0, 0.1, 3, this);
    vector_[i]->setObjectName(names[i]);
    items.push_back(vector_[i]);
  }
  vector_[2]->setValue(1.0);
  vectorRow_ = row(items, this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(kind_);
  layout->addWidget(vectorRow_);
  array_->setObjectName("tangent-array");
  array_->setEditable(true);
  array_->setInsertPolicy(QComboBox::NoInsert);
  array_->setToolTip(tr("The part's point or cell array of 2 or 3 components the brushing "
                        "follows, projected into the surface"));
  layout->addWidget(array_);
  connect(array_, qOverload<int>(&QComboBox::activated), this,
          [this](int) { emit edited(text()); });
  connect(array_->lineEdit(), &QLineEdit::editingFinished, this,
          [this]
          {
            if (!array_->currentText().trimmed().isEmpty())
            {
              emit edited(text());
            }
          });
  connect(kind_, qOverload<int>(&QComboBox::activated), this,
          [this](int index)
          {
            kind_->setCurrentIndex(index);
            centre_.clear();
            updateVisibility();
            if (kind_->currentData().toString() == "array" &&
                array_->currentText().trimmed().isEmpty())
            {
              // The first of the part's arrays; with none, nothing to say until a name is typed.
              if (array_->count() == 0)
              {
                return;
              }
              array_->setCurrentIndex(0);
            }
            emit edited(text());
          });
  for (QDoubleSpinBox* spin : vector_)
  {
    connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            [this] { emit edited(text()); });
  }
  updateVisibility();
}

void TangentEditor::setArrayNames(const QStringList& names)
{
  const QSignalBlocker block(array_);
  const QString current = array_->currentText();
  array_->clear();
  array_->addItems(names);
  array_->setCurrentText(current);
}

void TangentEditor::setText(const QString& text)
{
  const QSignalBlocker blocks[] = {QSignalBlocker(kind_), QSignalBlocker(vector_[0]),
                                   QSignalBlocker(vector_[1]), QSignalBlocker(vector_[2]),
                                   QSignalBlocker(array_)};
  const int colon = text.indexOf(':');
  const QString kind = colon < 0 ? text : text.left(colon);
  QString rest = colon < 0 ? QString() : text.mid(colon + 1);
  if (kind == "array")
  {
    // The name is everything after the colon, '@' and ',' included.
    array_->setCurrentText(rest.trimmed());
    rest.clear();
  }
  centre_.clear();
  const int at = rest.indexOf('@');
  if (at >= 0)
  {
    centre_ = rest.mid(at);
    rest = rest.left(at);
  }
  const QStringList parts = rest.split(',');
  if (parts.size() == 3)
  {
    for (int i = 0; i < 3; ++i)
    {
      vector_[i]->setValue(parts[i].toDouble());
    }
  }
  const int index = kind_->findData(kind);
  kind_->setCurrentIndex(index < 0 ? 0 : index);
  updateVisibility();
}

QString TangentEditor::text() const
{
  const QString kind = kind_->currentData().toString();
  if (kind == "auto" || kind == "uv" || kind == "face-u" || kind == "face-v")
  {
    return kind;
  }
  if (kind == "array")
  {
    return "array:" + array_->currentText().trimmed();
  }
  return kind + ":" + number(vector_[0]->value()) + "," + number(vector_[1]->value()) + "," +
         number(vector_[2]->value()) + (kind == "around" ? centre_ : QString());
}

void TangentEditor::updateVisibility()
{
  const QString kind = kind_->currentData().toString();
  vectorRow_->setVisible(kind == "axis" || kind == "around" || kind == "radial");
  array_->setVisible(kind == "array");
  vectorLabel_->setText(kind == "radial" ? tr("Point") : tr("Axis"));
}
} // namespace aniso
