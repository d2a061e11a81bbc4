#pragma once
// Controls for the scene's text values that are not plain choices: a file row (path, open,
// clear), the TPR pattern editor (pattern and its parameters, or a file) and the tangent model
// editor (auto, uv, axis, around, radial with its vector). Each shows a text without
// signalling and reports the text the user composed through `edited`.
#include <QString>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QStackedWidget;
class QToolButton;

namespace aniso
{
// File-dialog filters.
QString imageFileFilter();

class FileRow : public QWidget
{
  Q_OBJECT

public:
  // FILTER: a QFileDialog name filter; CAPTION: the dialog title.
  FileRow(const QString& caption, const QString& filter, QWidget* parent = nullptr);
  void setText(const QString& path);
  QString text() const;
  QLineEdit* lineEdit() const { return edit_; }

signals:
  void edited(const QString& path); // empty: cleared

protected:
  // A file dropped on the row is chosen, as if picked in the dialog.
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

private:
  QString caption_;
  QString filter_;
  QLineEdit* edit_;
};

// "linear:ANGLE", "circular:U,V", "radial:U,V", "spiral:U,V:PITCH", "wave" (parseTprPattern
// reads them), a file path, or empty for no TPR map.
class TprEditor : public QWidget
{
  Q_OBJECT

public:
  explicit TprEditor(QWidget* parent = nullptr);
  void setText(const QString& text);
  QString text() const;
  QComboBox* patternBox() const { return pattern_; }

signals:
  void edited(const QString& text);

private:
  void updateVisibility();
  void emitEdited();

  QComboBox* pattern_;
  QDoubleSpinBox* angle_;
  QDoubleSpinBox* centreU_;
  QDoubleSpinBox* centreV_;
  QDoubleSpinBox* pitch_;
  FileRow* file_;
  QWidget* angleRow_;
  QWidget* centreRow_;
  QWidget* pitchRow_;
};

// "auto", "uv", "axis:X,Y,Z", "around:X,Y,Z[@CX,CY,CZ]", "radial:X,Y,Z", "face-u", "face-v",
// "array:NAME" (BrushingModel.h). For array:NAME, an editable list of the part's vector arrays
// (setArrayNames); a name not in the list is kept as typed.
class TangentEditor : public QWidget
{
  Q_OBJECT

public:
  explicit TangentEditor(QWidget* parent = nullptr);
  void setText(const QString& text);
  QString text() const;
  // The vector arrays offered for array:NAME (the current name stays selected).
  void setArrayNames(const QStringList& names);
  QComboBox* kindBox() const { return kind_; }
  QComboBox* arrayBox() const { return array_; }
  QDoubleSpinBox* component(int i) const { return vector_[i]; }

signals:
  void edited(const QString& text);

private:
  void updateVisibility();

  QComboBox* kind_;
  QComboBox* array_;
  QDoubleSpinBox* vector_[3];
  QLabel* vectorLabel_;
  QWidget* vectorRow_;
  QString centre_; // "@CX,CY,CZ" of an around model, kept as given
};
} // namespace aniso
