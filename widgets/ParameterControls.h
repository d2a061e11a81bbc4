#pragma once
// One control per declared parameter type, built from its declaration (range, step, scale,
// choices, help): NumberControl (slider + exact spin box), ColorControl (R, G, B + swatch),
// ChoiceControl (combo box). A control shows values it is given without signalling and reports
// what the user does through `edited`; it never touches the model itself.
#include "core/parameters/parameters.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QSlider;
class QToolButton;

namespace aniso
{
class ParameterControl : public QWidget
{
  Q_OBJECT

public:
  explicit ParameterControl(const ParameterSpec& spec, QWidget* parent = nullptr);
  const ParameterSpec& spec() const { return spec_; }
  // Shows VALUE; emits nothing.
  virtual void setValue(const ParameterValue& value) = 0;

signals:
  // The user chose VALUE; `dragging` while a slider is held (between dragStarted and
  // dragFinished).
  void edited(const aniso::ParameterValue& value, bool dragging);
  void dragStarted();
  void dragFinished();

private:
  ParameterSpec spec_;
};

// "help (unit, min to max)": the tooltip of a parameter's control.
QString parameterToolTip(const ParameterSpec& spec);

class NumberControl : public ParameterControl
{
  Q_OBJECT

public:
  explicit NumberControl(const ParameterSpec& spec, QWidget* parent = nullptr);
  void setValue(const ParameterValue& value) override;
  double value() const;
  QSlider* slider() const { return slider_; }
  QDoubleSpinBox* spinBox() const { return spin_; }

private:
  void sliderMoved(int position);
  void spinEdited(double value);

  QSlider* slider_;
  QDoubleSpinBox* spin_;
};

class ColorControl : public ParameterControl
{
  Q_OBJECT

public:
  explicit ColorControl(const ParameterSpec& spec, QWidget* parent = nullptr);
  void setValue(const ParameterValue& value) override;
  QDoubleSpinBox* component(int i) const { return spins_[i]; }

private:
  void componentEdited();
  void pickColor();
  void updateSwatch();

  QDoubleSpinBox* spins_[3];
  QToolButton* swatch_;
};

class ChoiceControl : public ParameterControl
{
  Q_OBJECT

public:
  explicit ChoiceControl(const ParameterSpec& spec, QWidget* parent = nullptr);
  void setValue(const ParameterValue& value) override;
  QComboBox* comboBox() const { return combo_; }

private:
  QComboBox* combo_;
};

// The control for SPEC's type: ChoiceControl for texts with choices, ColorControl for colours,
// NumberControl for numbers. Free text has no generic control (null).
ParameterControl* makeParameterControl(const ParameterSpec& spec, QWidget* parent);

// Linear <-> sRGB-encoded components clamped to [0, 1] (core/fields/color_map.h's IEC
// 61966-2-1 curve), for swatches.
double swatchFromLinear(double linear);
double linearFromSwatch(double encoded);
} // namespace aniso

Q_DECLARE_METATYPE(aniso::ParameterValue)
