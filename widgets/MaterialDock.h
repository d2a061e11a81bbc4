#pragma once
// The material dock: AS exponents n_u, n_v on logarithmic sliders with exact spin boxes, their
// roughness view, a link that moves both keeping their ratio, F0 with measured metal presets,
// albedo, specular method, filtered sampling, sample count and quality, and the lookup-table
// settings. The quality is a total sample count (target-samples) or an error target
// (error-target, whose samples follow from the lobe by core/quality's error model), by
// quality-mode; the control of the mode not in use is disabled. Slider and roughness mappings:
// SliderMapping.h.
#include "scene/SceneEditor.h"

#include <QDockWidget>
#include <array>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace aniso
{
class ParameterControl;
class ParameterPanel;

struct MetalPreset
{
  const char* name;
  std::array<double, 3> f0; // linear RGB reflectance at normal incidence
};

// Aluminium, iron, copper, gold, silver, titanium, chromium: linear F0 computed from measured
// optical constants, as tabulated by common physically based rendering references (Al, Cu, Ag,
// Ti, Cr: Real-Time Rendering, 3rd ed., table 7.3; Fe: the Arnold Standard Surface metal table;
// Au: Unreal Engine's physically based materials table).
const std::vector<MetalPreset>& metalPresets();

class MaterialDock : public QDockWidget
{
  Q_OBJECT

public:
  explicit MaterialDock(SceneEditor* editor, QWidget* parent = nullptr);

  bool linked() const;
  void setLinked(bool linked);

signals:
  void errorOccurred(const QString& message);

private:
  SceneModel::Values linkedChanges(const std::string& key, const ParameterValue& value,
                                   bool gestureStart);
  void editRoughness(const std::string& key, double alpha);
  void syncFromModel();

  SceneEditor* editor_;
  ParameterPanel* roughness_;
  ParameterPanel* surface_;
  QCheckBox* link_;
  QDoubleSpinBox* alphaU_;
  QDoubleSpinBox* alphaV_;
  QComboBox* presets_;
  ParameterControl* errorTarget_ = nullptr;
  // The exponents when the current linked gesture began: their ratio is kept.
  double linkNu_ = 1.0;
  double linkNv_ = 1.0;
};
} // namespace aniso
