#include "widgets/MaterialDock.h"

#include "core/brdf/ashikhmin_shirley.h"
#include "core/error.h"
#include "core/parameters/choices.h"
#include "widgets/ParameterControls.h"
#include "widgets/ParameterPanel.h"
#include "widgets/SliderMapping.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <algorithm>

namespace aniso
{
namespace
{
QGroupBox* group(const QString& title, QWidget* content, QWidget* parent)
{
  auto* box = new QGroupBox(title, parent);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(content);
  return box;
}

QDoubleSpinBox* roughnessSpinBox(const QString& name, QWidget* parent)
{
  auto* spin = new QDoubleSpinBox(parent);
  spin->setObjectName(name);
  spin->setDecimals(4);
  spin->setRange(roughnessFromExponent(kMaxExponent), 1.0);
  spin->setSingleStep(0.01);
  spin->setKeyboardTracking(false);
  spin->setToolTip(QObject::tr("Beckmann roughness of the same lobe: alpha = sqrt(2 / (n + 2)), "
                               "n = 2 / alpha^2 - 2"));
  return spin;
}
} // namespace

const std::vector<MetalPreset>& metalPresets()
{
  static const std::vector<MetalPreset> presets = {
      {"Aluminium", {0.913, 0.922, 0.924}}, {"Iron", {0.531, 0.512, 0.496}},
      {"Copper", {0.955, 0.638, 0.538}},    {"Gold", {1.000, 0.766, 0.336}},
      {"Silver", {0.972, 0.960, 0.915}},    {"Titanium", {0.542, 0.497, 0.449}},
      {"Chromium", {0.549, 0.556, 0.554}},
  };
  return presets;
}

MaterialDock::MaterialDock(SceneEditor* editor, QWidget* parent)
    : QDockWidget(tr("Material"), parent), editor_(editor),
      roughness_(new ParameterPanel(editor, this)), surface_(new ParameterPanel(editor, this)),
      link_(new QCheckBox(tr("Link n_u and n_v (keep their ratio)"), this)),
      alphaU_(roughnessSpinBox("alpha-u", this)), alphaV_(roughnessSpinBox("alpha-v", this)),
      presets_(new QComboBox(this))
{
  setObjectName("MaterialDock");

  // Roughness: exponents on log sliders, their Beckmann roughness, the link.
  roughness_->addParameter("nu");
  roughness_->addParameter("nv");
  auto* alphas = new QWidget(this);
  auto* alphaRow = new QHBoxLayout(alphas);
  alphaRow->setContentsMargins(0, 0, 0, 0);
  alphaRow->addWidget(new QLabel(tr("α_u"), alphas));
  alphaRow->addWidget(alphaU_, 1);
  alphaRow->addWidget(new QLabel(tr("α_v"), alphas));
  alphaRow->addWidget(alphaV_, 1);
  roughness_->addRow(tr("Roughness"), alphas);
  link_->setObjectName("link");
  roughness_->addRow(QString(), link_);
  auto* mapping = new QLabel(tr("Slider position ∝ log10(1 + n). α = √(2 / (n + 2)): the "
                                "Beckmann roughness of the same lobe."),
                             this);
  mapping->setWordWrap(true);
  mapping->setEnabled(false);
  roughness_->addRow(QString(), mapping);
  roughness_->setExpander(
      [this](const std::string& key, const ParameterValue& value, bool gestureStart)
      { return linkedChanges(key, value, gestureStart); });
  connect(alphaU_, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
          [this](double alpha) { editRoughness("nu", alpha); });
  connect(alphaV_, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
          [this](double alpha) { editRoughness("nv", alpha); });

  // Surface: F0 with metal presets, albedo.
  presets_->setObjectName("f0-preset");
  presets_->addItem(tr("Custom"));
  for (const MetalPreset& preset : metalPresets())
  {
    presets_->addItem(tr(preset.name));
  }
  surface_->addRow(tr("Metal"), presets_);
  surface_->addParameter("f0");
  surface_->addParameter("albedo");
  connect(presets_, qOverload<int>(&QComboBox::activated), this,
          [this](int index)
          {
            if (index > 0)
            {
              const auto& f0 = metalPresets()[static_cast<std::size_t>(index - 1)].f0;
              surface_->submit("f0", colorValue(f0[0], f0[1], f0[2]), false);
            }
          });

  auto* sampling = new ParameterPanel(editor, this);
  for (const char* key : {"method", "filtered", "samples", "quality-mode"})
  {
    sampling->addParameter(key);
  }
  // The quality as a sample count or as an error target: the error target is shown disabled in
  // samples mode, its value kept for when the mode comes back; the sample count bounds both.
  sampling->addParameter("target-samples");
  errorTarget_ = sampling->addParameter("error-target");
  auto* tables = new ParameterPanel(editor, this);
  for (const char* key : {"half-vectors", "lut-size", "lut-samples"})
  {
    tables->addParameter(key);
  }

  for (ParameterPanel* panel : {roughness_, surface_, sampling, tables})
  {
    connect(panel, &ParameterPanel::errorOccurred, this, &MaterialDock::errorOccurred);
  }
  setWidget(scrollableColumn(
      {group(tr("Roughness"), roughness_, this), group(tr("Surface"), surface_, this),
       group(tr("Sampling"), sampling, this), group(tr("Lookup tables"), tables, this)},
      this));
  connect(editor->model(), &SceneModel::valueChanged, this,
          [this](const QString& key)
          {
            if (key == "nu" || key == "nv" || key == "f0" || key == "quality-mode")
            {
              syncFromModel();
            }
          });
  syncFromModel();
}

bool MaterialDock::linked() const
{
  return link_->isChecked();
}

void MaterialDock::setLinked(bool linked)
{
  link_->setChecked(linked);
}

SceneModel::Values MaterialDock::linkedChanges(const std::string& key, const ParameterValue& value,
                                               bool gestureStart)
{
  SceneModel::Values changes{{key, value}};
  if (!linked() || (key != "nu" && key != "nv"))
  {
    return changes;
  }
  if (gestureStart)
  {
    linkNu_ = editor_->model()->real("nu");
    linkNv_ = editor_->model()->real("nv");
  }
  // The link keeps n_v / n_u; with a zero exponent that ratio is undefined, so it keeps
  // (n_v + 1) / (n_u + 1) instead. Beyond the range the moved exponent is held back so the
  // ratio survives.
  const bool plain = linkNu_ > 0.0 && linkNv_ > 0.0;
  const bool movingU = key == "nu";
  const double from = movingU ? linkNu_ : linkNv_;
  const double to = movingU ? linkNv_ : linkNu_;
  const double ratio = plain ? to / from : (to + 1.0) / (from + 1.0);
  double moved = value.number[0];
  double partner = plain ? moved * ratio : (moved + 1.0) * ratio - 1.0;
  if (partner > kMaxExponent)
  {
    partner = kMaxExponent;
    moved = plain ? partner / ratio : (partner + 1.0) / ratio - 1.0;
  }
  partner = std::clamp(partner, 0.0, kMaxExponent);
  changes[key] = numberValue(moved);
  changes[movingU ? "nv" : "nu"] = numberValue(partner);
  return changes;
}

void MaterialDock::editRoughness(const std::string& key, double alpha)
{
  roughness_->submit(key, numberValue(exponentFromRoughness(alpha)), false);
}

void MaterialDock::syncFromModel()
{
  const SceneModel* model = editor_->model();
  const bool byError = parseQualityMode(model->text("quality-mode")) == QualityMode::Error;
  errorTarget_->setEnabled(byError);
  {
    const QSignalBlocker blockU(alphaU_);
    const QSignalBlocker blockV(alphaV_);
    alphaU_->setValue(roughnessFromExponent(model->real("nu")));
    alphaV_->setValue(roughnessFromExponent(model->real("nv")));
  }
  const auto f0 = model->color("f0");
  int match = 0;
  for (std::size_t i = 0; i < metalPresets().size(); ++i)
  {
    if (metalPresets()[i].f0 == f0)
    {
      match = static_cast<int>(i) + 1;
    }
  }
  const QSignalBlocker block(presets_);
  presets_->setCurrentIndex(match);
}
} // namespace aniso
