#include "widgets/ParameterControls.h"

#include "core/fields/color_map.h"
#include "widgets/SliderMapping.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>
#include <QToolButton>
#include <algorithm>
#include <cmath>

namespace aniso
{
namespace
{
QString qstr(std::string_view text)
{
  return QString::fromUtf8(text.data(), static_cast<int>(text.size()));
}

// Enough decimals to show a step of the declaration and one digit more.
int decimalsFor(const ParameterSpec& spec)
{
  if (spec.type == ParameterType::Integer)
  {
    return 0;
  }
  const double step = spec.step > 0.0 ? spec.step : 1.0;
  return std::max(0, static_cast<int>(std::ceil(-std::log10(step)))) + 1;
}

QDoubleSpinBox* makeSpinBox(const ParameterSpec& spec, QWidget* parent)
{
  auto* spin = new QDoubleSpinBox(parent);
  spin->setRange(spec.minimum, spec.maximum);
  spin->setDecimals(decimalsFor(spec));
  spin->setSingleStep(spec.step > 0.0 ? spec.step : 1.0);
  if (spec.scale == ParameterScale::Logarithmic)
  {
    // A step of 1 is nothing at 20000: steps grow with the value's magnitude.
    spin->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
  }
  if (!spec.unit.empty())
  {
    spin->setSuffix(" " + qstr(spec.unit));
  }
  // Arrow keys and Enter edit; typing does not send every keystroke.
  spin->setKeyboardTracking(false);
  spin->setAccelerated(true);
  return spin;
}
} // namespace

double swatchFromLinear(double linear)
{
  return linearToSrgb(std::clamp(linear, 0.0, 1.0));
}

double linearFromSwatch(double encoded)
{
  return srgbToLinear(std::clamp(encoded, 0.0, 1.0));
}

QString parameterToolTip(const ParameterSpec& spec)
{
  QString tip = qstr(spec.help);
  if (spec.type != ParameterType::Text)
  {
    tip += QString(" (%1%2 to %3)")
               .arg(spec.unit.empty() ? QString() : qstr(spec.unit) + ", ")
               .arg(QString::fromStdString(formatNumber(spec.minimum)))
               .arg(QString::fromStdString(formatNumber(spec.maximum)));
  }
  return tip;
}

ParameterControl::ParameterControl(const ParameterSpec& spec, QWidget* parent)
    : QWidget(parent), spec_(spec)
{
  setObjectName(qstr(spec.name));
  setToolTip(parameterToolTip(spec));
}

NumberControl::NumberControl(const ParameterSpec& spec, QWidget* parent)
    : ParameterControl(spec, parent), slider_(new QSlider(Qt::Horizontal, this)),
      spin_(makeSpinBox(spec, this))
{
  slider_->setRange(0, kSliderSteps);
  slider_->setMinimumWidth(48);
  slider_->setPageStep(kSliderSteps / 20);
  slider_->setSingleStep(std::max(1, kSliderSteps / 200));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(slider_, 3);
  layout->addWidget(spin_, 2);
  connect(slider_, &QSlider::valueChanged, this, &NumberControl::sliderMoved);
  connect(slider_, &QSlider::sliderPressed, this, &ParameterControl::dragStarted);
  connect(slider_, &QSlider::sliderReleased, this, &ParameterControl::dragFinished);
  connect(spin_, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
          &NumberControl::spinEdited);
  setValue(defaultParameterValue(spec));
}

void NumberControl::setValue(const ParameterValue& value)
{
  const QSignalBlocker blockSlider(slider_);
  const QSignalBlocker blockSpin(spin_);
  spin_->setValue(value.number[0]);
  // A held slider stays under the hand (its position rounds to a neighbouring step); it is
  // brought in line when released.
  if (!slider_->isSliderDown())
  {
    slider_->setValue(sliderPosition(spec(), value.number[0]));
  }
}

double NumberControl::value() const
{
  return spin_->value();
}

void NumberControl::sliderMoved(int position)
{
  const double v = sliderValue(spec(), position);
  {
    const QSignalBlocker block(spin_);
    spin_->setValue(v);
  }
  ParameterValue value;
  value.number.fill(v);
  emit edited(value, slider_->isSliderDown());
}

void NumberControl::spinEdited(double v)
{
  if (spec().powerOfTwo && v >= 1.0)
  {
    v = std::exp2(std::round(std::log2(v)));
    const QSignalBlocker block(spin_);
    spin_->setValue(v);
  }
  {
    const QSignalBlocker block(slider_);
    slider_->setValue(sliderPosition(spec(), v));
  }
  ParameterValue value;
  value.number.fill(v);
  emit edited(value, false);
}

ColorControl::ColorControl(const ParameterSpec& spec, QWidget* parent)
    : ParameterControl(spec, parent), swatch_(new QToolButton(this))
{
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  const char* names[3] = {"R", "G", "B"};
  for (int i = 0; i < 3; ++i)
  {
    spins_[i] = makeSpinBox(spec, this);
    spins_[i]->setDecimals(3);
    spins_[i]->setPrefix(QString(names[i]) + " ");
    spins_[i]->setObjectName(QString(names[i]));
    layout->addWidget(spins_[i], 1);
    connect(spins_[i], qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            &ColorControl::componentEdited);
  }
  swatch_->setToolTip(tr("Pick a colour (shown sRGB-encoded; the values are linear)"));
  swatch_->setFixedWidth(28);
  layout->addWidget(swatch_);
  connect(swatch_, &QToolButton::clicked, this, &ColorControl::pickColor);
  setValue(defaultParameterValue(spec));
}

void ColorControl::setValue(const ParameterValue& value)
{
  for (int i = 0; i < 3; ++i)
  {
    const QSignalBlocker block(spins_[i]);
    spins_[i]->setValue(value.number[static_cast<std::size_t>(i)]);
  }
  updateSwatch();
}

void ColorControl::componentEdited()
{
  updateSwatch();
  ParameterValue value;
  for (int i = 0; i < 3; ++i)
  {
    value.number[static_cast<std::size_t>(i)] = spins_[i]->value();
  }
  emit edited(value, false);
}

void ColorControl::pickColor()
{
  QColor initial;
  initial.setRgbF(swatchFromLinear(spins_[0]->value()), swatchFromLinear(spins_[1]->value()),
                  swatchFromLinear(spins_[2]->value()));
  const QColor chosen = QColorDialog::getColor(initial, this, qstr(spec().label));
  if (!chosen.isValid())
  {
    return;
  }
  ParameterValue value;
  const double encoded[3] = {chosen.redF(), chosen.greenF(), chosen.blueF()};
  for (int i = 0; i < 3; ++i)
  {
    // Three decimals, as the spin boxes show, so the model holds what the user sees.
    value.number[static_cast<std::size_t>(i)] =
        std::round(linearFromSwatch(encoded[i]) * 1000.0) / 1000.0;
  }
  setValue(value);
  emit edited(value, false);
}

void ColorControl::updateSwatch()
{
  QColor c;
  c.setRgbF(swatchFromLinear(spins_[0]->value()), swatchFromLinear(spins_[1]->value()),
            swatchFromLinear(spins_[2]->value()));
  swatch_->setStyleSheet(
      QString("background-color: %1; border: 1px solid palette(mid);").arg(c.name()));
}

ChoiceControl::ChoiceControl(const ParameterSpec& spec, QWidget* parent)
    : ParameterControl(spec, parent), combo_(new QComboBox(this))
{
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(combo_);
  for (std::string_view choice : spec.choices)
  {
    combo_->addItem(qstr(choice));
  }
  connect(combo_, qOverload<int>(&QComboBox::activated), this,
          [this](int index)
          {
            ParameterValue value;
            value.text = this->spec().choices[static_cast<std::size_t>(index)];
            emit edited(value, false);
          });
  setValue(defaultParameterValue(spec));
}

void ChoiceControl::setValue(const ParameterValue& value)
{
  const QSignalBlocker block(combo_);
  combo_->setCurrentIndex(combo_->findText(QString::fromStdString(value.text)));
}

ParameterControl* makeParameterControl(const ParameterSpec& spec, QWidget* parent)
{
  switch (spec.type)
  {
  case ParameterType::Integer:
  case ParameterType::Real:
    return new NumberControl(spec, parent);
  case ParameterType::Color:
    return new ColorControl(spec, parent);
  case ParameterType::Text:
    break;
  }
  return spec.choices.empty() ? nullptr : new ChoiceControl(spec, parent);
}
} // namespace aniso
