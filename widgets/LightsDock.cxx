#include "widgets/LightsDock.h"

#include "core/error.h"
#include "core/lights/light_text.h"
#include "core/models/models.h"
#include "scene/SceneShading.h"
#include "widgets/ParameterPanel.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPixmap>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
constexpr double kVectorRange = 1000.0;
constexpr double kIntensityRange = 10000.0;

QDoubleSpinBox* spinBox(double minimum, double maximum, QWidget* parent)
{
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(minimum, maximum);
  box->setDecimals(4);
  box->setSingleStep(0.1);
  box->setKeyboardTracking(false);
  return box;
}

// The colour of an intensity, scaled so its largest channel is full (the brightness is in the
// spin boxes).
QColor chroma(const glm::dvec3& intensity)
{
  const double peak = std::max({intensity.x, intensity.y, intensity.z});
  if (!(peak > 0.0))
  {
    return QColor(0, 0, 0);
  }
  return QColor::fromRgbF(intensity.x / peak, intensity.y / peak, intensity.z / peak);
}

// Same direction (directional lights are stored normalised, the editors may show any length).
bool sameDirection(const glm::dvec3& a, const glm::dvec3& b)
{
  const double la = glm::length(a);
  const double lb = glm::length(b);
  return la > 0.0 && lb > 0.0 && glm::length(a / la - b / lb) <= 1e-12;
}
} // namespace

LightsDock::LightsDock(SceneEditor* editor, QWidget* parent)
    : QDockWidget(tr("Lights"), parent), editor_(editor)
{
  setObjectName("LightsDock");
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);

  auto* form = new QFormLayout;
  model_ = new QComboBox(body);
  for (const ShadingModelInfo& info : shadingModels())
  {
    model_->addItem(QString::fromUtf8(info.title.data(), int(info.title.size())),
                    QString::fromUtf8(info.name.data(), int(info.name.size())));
    model_->setItemData(model_->count() - 1,
                        QString::fromUtf8(info.description.data(), int(info.description.size())),
                        Qt::ToolTipRole);
  }
  sample_ = new QComboBox(body);
  sample_->addItem(
      tr("Uniform (n_u, n_v, F0, albedo)"),
      QString::fromUtf8(kUniformSampleMaterial.data(), int(kUniformSampleMaterial.size())));
  for (const SampleMaterialInfo& info : sampleMaterials())
  {
    sample_->addItem(QString::fromUtf8(info.name.data(), int(info.name.size())),
                     QString::fromUtf8(info.name.data(), int(info.name.size())));
    sample_->setItemData(sample_->count() - 1,
                         QString::fromUtf8(info.description.data(), int(info.description.size())),
                         Qt::ToolTipRole);
  }
  form->addRow(tr("Model"), model_);
  form->addRow(tr("Sample material"), sample_);
  layout->addLayout(form);
  // The environment's sources as lights of the lit models and LEADR, beside the list's.
  auto* shared = new ParameterPanel(editor_, body);
  shared->setObjectName("lightsParameters");
  shared->addParameter("env-lights");
  connect(shared, &ParameterPanel::errorOccurred, this, &LightsDock::errorOccurred);
  layout->addWidget(shared);

  // The declared settings of LEADR and the microstructure, shown while that model is chosen.
  QList<QWidget*> panels;
  for (const char* name : {"leadr", "microstructure"})
  {
    auto* panel = new ParameterPanel(editor_, body);
    panel->setObjectName(QString(name) + "Parameters");
    for (std::string_view key : surfaceModelKeys(name))
    {
      panel->addParameter(key);
    }
    connect(panel, &ParameterPanel::errorOccurred, this, &LightsDock::errorOccurred);
    panels.append(panel);
  }
  QWidget* surface = scrollableColumn(panels, body);
  const auto showPanels = [this, panels, surface]
  {
    const std::string& model = editor_->model()->text("model");
    panels[0]->setVisible(model == "leadr");
    panels[1]->setVisible(model == "microstructure");
    surface->setVisible(!surfaceModelKeys(model).empty());
  };
  connect(editor_->model(), &SceneModel::valueChanged, surface,
          [showPanels](const QString& key)
          {
            if (key == "model")
            {
              showPanels();
            }
          });
  showPanels();
  layout->addWidget(surface, 1);

  list_ = new QListWidget(body);
  layout->addWidget(list_);
  auto* buttons = new QHBoxLayout;
  add_ = new QPushButton(tr("Add"), body);
  remove_ = new QPushButton(tr("Remove"), body);
  buttons->addWidget(add_);
  buttons->addWidget(remove_);
  layout->addLayout(buttons);

  auto* light = new QFormLayout;
  type_ = new QComboBox(body);
  type_->addItem(tr("Directional"));
  type_->addItem(tr("Point"));
  light->addRow(tr("Type"), type_);
  auto* vectorRow = new QHBoxLayout;
  auto* intensityRow = new QHBoxLayout;
  for (std::size_t i = 0; i < 3; ++i)
  {
    vector_[i] = spinBox(-kVectorRange, kVectorRange, body);
    intensity_[i] = spinBox(0.0, kIntensityRange, body);
    vectorRow->addWidget(vector_[i]);
    intensityRow->addWidget(intensity_[i]);
  }
  colour_ = new QToolButton(body);
  colour_->setToolTip(tr("Colour of the light (its brightness stays)"));
  intensityRow->addWidget(colour_);
  light->addRow(tr("X, Y, Z"), vectorRow);
  light->addRow(tr("R, G, B"), intensityRow);
  layout->addLayout(light);
  layout->addStretch(1);
  setWidget(body);

  const auto report = [this](const Error& e) { emit errorOccurred(QString::fromUtf8(e.what())); };
  connect(model_, QOverload<int>::of(&QComboBox::activated), this,
          [this, report](int index)
          {
            try
            {
              editor_->edit("model", textValue(model_->itemData(index).toString().toStdString()));
            }
            catch (const Error& e)
            {
              report(e);
              syncFromModel();
            }
          });
  connect(sample_, QOverload<int>::of(&QComboBox::activated), this,
          [this, report](int index)
          {
            try
            {
              editor_->edit("sample-material",
                            textValue(sample_->itemData(index).toString().toStdString()));
            }
            catch (const Error& e)
            {
              report(e);
              syncFromModel();
            }
          });
  connect(add_, &QPushButton::clicked, this, &LightsDock::addLight);
  connect(remove_, &QPushButton::clicked, this, &LightsDock::removeSelectedLight);
  connect(list_, &QListWidget::currentRowChanged, this, &LightsDock::showSelected);
  connect(type_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          &LightsDock::editorsChanged);
  for (std::size_t i = 0; i < 3; ++i)
  {
    connect(vector_[i], QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
            &LightsDock::editorsChanged);
    connect(intensity_[i], QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
            &LightsDock::editorsChanged);
  }
  connect(colour_, &QToolButton::clicked, this, &LightsDock::chooseColour);
  connect(editor_->model(), &SceneModel::valueChanged, this,
          [this](const QString& key)
          {
            if (key == "model" || key == "sample-material" || key == "lights")
            {
              syncFromModel();
            }
          });
  syncFromModel();
}

std::vector<Light> LightsDock::lights() const
{
  try
  {
    return parseLightList(editor_->model()->text("lights"), "lights");
  }
  catch (const Error&)
  {
    return {};
  }
}

void LightsDock::editLights(const std::vector<Light>& lights, int select)
{
  try
  {
    editor_->edit("lights", textValue(formatLightList(lights)));
    if (select >= 0 && select < list_->count())
    {
      list_->setCurrentRow(select);
    }
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromUtf8(e.what()));
    syncFromModel();
  }
}

void LightsDock::addLight()
{
  std::vector<Light> all = lights();
  const int row = list_->currentRow();
  all.push_back(row >= 0 && row < int(all.size()) ? all[std::size_t(row)] : Light{});
  editLights(all, int(all.size()) - 1);
}

void LightsDock::removeSelectedLight()
{
  std::vector<Light> all = lights();
  const int row = list_->currentRow();
  if (row < 0 || row >= int(all.size()))
  {
    return;
  }
  all.erase(all.begin() + row);
  editLights(all, std::min(row, int(all.size()) - 1));
}

void LightsDock::setSelectedLight(const Light& light)
{
  std::vector<Light> all = lights();
  const int row = list_->currentRow();
  if (row < 0 || row >= int(all.size()))
  {
    return;
  }
  try
  {
    validateLight(light);
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromUtf8(e.what()));
    showSelected();
    return;
  }
  all[std::size_t(row)] = light;
  if (light.type == LightType::Directional)
  {
    all[std::size_t(row)].vector = glm::normalize(light.vector);
  }
  editLights(all, row);
}

void LightsDock::syncFromModel()
{
  syncing_ = true;
  const SceneModel* model = editor_->model();
  model_->setCurrentIndex(model_->findData(QString::fromStdString(model->text("model"))));
  sample_->setCurrentIndex(
      sample_->findData(QString::fromStdString(model->text("sample-material"))));
  const std::vector<Light> all = lights();
  const int row = list_->currentRow();
  list_->clear();
  for (const Light& light : all)
  {
    // Readable words in the list; the stored text (what sessions and --light read) as the tip.
    list_->addItem(QString::fromStdString(lightText(light)));
    list_->item(list_->count() - 1)->setToolTip(QString::fromStdString(formatLight(light)));
  }
  list_->setCurrentRow(all.empty() ? -1 : std::clamp(row, 0, int(all.size()) - 1));
  syncing_ = false;
  showSelected();
}

void LightsDock::showSelected()
{
  if (syncing_)
  {
    return;
  }
  const std::vector<Light> all = lights();
  const int row = list_->currentRow();
  const bool selected = row >= 0 && row < int(all.size());
  remove_->setEnabled(selected);
  add_->setEnabled(int(all.size()) < kMaxSceneLights);
  type_->setEnabled(selected);
  colour_->setEnabled(selected);
  for (std::size_t i = 0; i < 3; ++i)
  {
    vector_[i]->setEnabled(selected);
    intensity_[i]->setEnabled(selected);
  }
  if (!selected)
  {
    return;
  }
  const Light& light = all[std::size_t(row)];
  syncing_ = true;
  type_->setCurrentIndex(light.type == LightType::Point ? 1 : 0);
  const glm::dvec3 shown(vector_[0]->value(), vector_[1]->value(), vector_[2]->value());
  // A direction typed as (1, 1, 0) stays so in the editors although the scene stores it unit.
  if (!(light.type == LightType::Directional && sameDirection(shown, light.vector)))
  {
    for (int i = 0; i < 3; ++i)
    {
      vector_[std::size_t(i)]->setValue(light.vector[i]);
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    intensity_[std::size_t(i)]->setValue(light.intensity[i]);
  }
  QPixmap swatch(16, 16);
  swatch.fill(chroma(light.intensity));
  colour_->setIcon(QIcon(swatch));
  syncing_ = false;
}

void LightsDock::editorsChanged()
{
  if (syncing_)
  {
    return;
  }
  Light light;
  light.type = type_->currentIndex() == 1 ? LightType::Point : LightType::Directional;
  light.vector = glm::dvec3(vector_[0]->value(), vector_[1]->value(), vector_[2]->value());
  light.intensity =
      glm::dvec3(intensity_[0]->value(), intensity_[1]->value(), intensity_[2]->value());
  setSelectedLight(light);
}

void LightsDock::chooseColour()
{
  const std::vector<Light> all = lights();
  const int row = list_->currentRow();
  if (row < 0 || row >= int(all.size()))
  {
    return;
  }
  Light light = all[std::size_t(row)];
  const QColor colour = QColorDialog::getColor(chroma(light.intensity), this, tr("Light colour"));
  if (!colour.isValid())
  {
    return;
  }
  // The brightest channel keeps its value, so only the hue and saturation change.
  const double peak = std::max({light.intensity.x, light.intensity.y, light.intensity.z});
  const double scale = peak > 0.0 ? peak : 1.0;
  light.intensity = glm::dvec3(colour.redF(), colour.greenF(), colour.blueF()) * scale;
  setSelectedLight(light);
}
} // namespace aniso
