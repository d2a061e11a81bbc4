#include "app/gui/CompareWindow.h"

#include "app/gui/LitModelView.h"
#include "app/gui/SceneView.h"
#include "core/error.h"
#include "core/models/models.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/LitModelMaterial.h"

#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>
#include <cmath>
#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyData.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace aniso
{
struct CompareWindow::Pane
{
  std::string name;
  LitModel model = LitModel::AshikhminShirley;
  vtkNew<vtkOpenGLRenderer> renderer;
  vtkNew<vtkActor> actor;
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  vtkNew<vtkTextActor> label;
  std::unique_ptr<LitModelMaterial> material;
};

std::vector<std::string> comparedLitModels()
{
  std::vector<std::string> names;
  for (const ShadingModelInfo& info : shadingModels())
  {
    LitModel lit;
    if (litModelFromName(info.name, lit))
    {
      names.emplace_back(info.name);
    }
  }
  return names;
}

CompareWindow::CompareWindow(SceneModel* model, SceneView* view, QWidget* parent)
    : QWidget(parent, Qt::Window), model_(model), view_(view),
      widget_(new QVTKOpenGLNativeWidget(this))
{
  setWindowTitle(tr("Compare models"));
  setObjectName("CompareWindow");
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(widget_);
  widget_->setRenderWindow(window_);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  window_->GetInteractor()->SetInteractorStyle(style);

  const std::vector<std::string> names = comparedLitModels();
  // A grid as square as the count allows: 5 models in 3 columns and 2 rows.
  const int count = int(names.size());
  const int columns = int(std::ceil(std::sqrt(double(count))));
  const int rows = (count + columns - 1) / columns;
  for (int i = 0; i < count; ++i)
  {
    auto pane = std::make_unique<Pane>();
    pane->name = names[std::size_t(i)];
    litModelFromName(pane->name, pane->model);
    const int column = i % columns;
    const int row = rows - 1 - i / columns; // first model top left
    pane->renderer->SetViewport(double(column) / columns, double(row) / rows,
                                double(column + 1) / columns, double(row + 1) / rows);
    pane->renderer->SetActiveCamera(camera_);
    pane->renderer->SetBackground(0.12, 0.12, 0.12);
    pane->mapper->ScalarVisibilityOff();
    pane->actor->SetMapper(pane->mapper);
    pane->renderer->AddActor(pane->actor);
    const ShadingModelInfo& info = shadingModel(pane->name, "model");
    pane->label->SetInput(std::string(info.title).c_str());
    pane->label->GetTextProperty()->SetFontSize(14);
    pane->label->SetDisplayPosition(8, 8);
    pane->renderer->AddViewProp(pane->label);
    window_->AddRenderer(pane->renderer);
    panes_.push_back(std::move(pane));
  }
  connect(model_, &SceneModel::valueChanged, this,
          [this](const QString& key)
          {
            if (key == "mesh" || key == "tangents")
            {
              refresh();
            }
            else
            {
              updateMaterials();
            }
          });
  resize(300 * columns, 300 * rows);
  refresh();
}

CompareWindow::~CompareWindow()
{
  for (auto& pane : panes_)
  {
    if (pane->material)
    {
      pane->material->detach();
    }
  }
}

int CompareWindow::viewportCount() const
{
  return int(panes_.size());
}

vtkRenderer* CompareWindow::viewport(int index) const
{
  return panes_.at(std::size_t(index))->renderer;
}

void CompareWindow::refresh()
{
  // The view's own actor (the first one) carries the drawing frame whatever model the view
  // shows; the mesh is the surface itself (the view's mapper draws a stand-in while moving).
  vtkPolyData* mesh = view_->drawnSurface();
  for (auto& pane : panes_)
  {
    pane->mapper->SetInputData(mesh);
    setDrawingFrame(pane->actor, view_->drawingFrame()); // the scene's parts, point lights
  }
  camera_->DeepCopy(view_->renderer()->GetActiveCamera());
  for (auto& pane : panes_)
  {
    pane->renderer->ResetCameraClippingRange();
  }
  updateMaterials();
}

void CompareWindow::updateMaterials()
{
  try
  {
    // Lights and material as the scene has them; only the model differs per viewport.
    LitModelSettings settings;
    litSceneOf(*model_, settings);
    for (auto& pane : panes_)
    {
      settings.model = pane->model;
      if (!pane->material)
      {
        pane->material = std::make_unique<LitModelMaterial>(settings);
        pane->material->apply(pane->actor, pane->renderer);
      }
      else
      {
        pane->material->setSettings(settings);
      }
    }
  }
  catch (const Error& e)
  {
    emit errorOccurred(QString::fromUtf8(e.what()));
  }
  if (isVisible())
  {
    window_->Render();
  }
}

void CompareWindow::showEvent(QShowEvent* event)
{
  QWidget::showEvent(event);
  refresh();
}
} // namespace aniso
