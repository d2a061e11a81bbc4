#include "app/gui/CompareWindow.h"

#include "app/gui/LitModelView.h"
#include "app/gui/SceneView.h"
#include "core/error.h"
#include "core/models/models.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>
#include <cmath>
#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPolyData.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace aniso
{
// A part as a viewport draws it, kept across updates.
struct CompareWindow::PaneActor
{
  vtkNew<vtkActor> actor;
  vtkNew<vtkAnisoPolyDataMapper> mapper;
  std::unique_ptr<LitModelMaterial> material;
  bool inRenderer = false;
};

struct CompareWindow::Pane
{
  std::string name;
  LitModel model = LitModel::AshikhminShirley;
  vtkNew<vtkOpenGLRenderer> renderer;
  vtkNew<vtkTextActor> label;
  std::vector<std::unique_ptr<PaneActor>> parts; // parallel to the view's parts
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
            else if (!isMaterialKey(key.toStdString()))
            {
              // Material keys are the edited parts' materials: materialsChanged brings them.
              updateMaterials();
            }
          });
  // A part's material edited or replaced.
  connect(model_, &SceneModel::materialsChanged, this, [this] { updateMaterials(); });
  // Parts shown, hidden, added, removed or given other surfaces (the view has them in place).
  connect(view_, &SceneView::partsDrawn, this,
          [this]
          {
            syncParts();
            updateMaterials();
          });
  // A new lighting on screen: its environment's sources (env-lights).
  connect(view_, &SceneView::lightingBusyChanged, this,
          [this](bool busy)
          {
            if (!busy)
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
    for (auto& part : pane->parts)
    {
      if (part->material)
      {
        part->material->detach();
      }
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

vtkActor* CompareWindow::partActor(int index, int part) const
{
  const Pane& pane = *panes_.at(std::size_t(index));
  if (part < 0 || part >= int(pane.parts.size()) || !pane.parts[std::size_t(part)]->inRenderer)
  {
    return nullptr;
  }
  return pane.parts[std::size_t(part)]->actor;
}

void CompareWindow::syncParts()
{
  const int count = view_->partCount();
  for (auto& pane : panes_)
  {
    while (int(pane->parts.size()) > count)
    {
      PaneActor& gone = *pane->parts.back();
      if (gone.material)
      {
        gone.material->detach();
      }
      if (gone.inRenderer)
      {
        pane->renderer->RemoveActor(gone.actor);
      }
      pane->parts.pop_back();
    }
    while (int(pane->parts.size()) < count)
    {
      auto part = std::make_unique<PaneActor>();
      part->mapper->ScalarVisibilityOff();
      part->actor->SetMapper(part->mapper);
      pane->parts.push_back(std::move(part));
    }
    for (int i = 0; i < count; ++i)
    {
      PaneActor& part = *pane->parts[std::size_t(i)];
      // The surface itself, as drawn when still (the view draws a stand-in while moving).
      vtkPolyData* mesh = view_->partDrawnSurface(i);
      if (mesh)
      {
        if (mesh != part.mapper->GetInput())
        {
          part.mapper->SetInputData(mesh);
        }
        setDrawingFrame(part.actor, view_->drawingFrame()); // the scene's parts, point lights
      }
      // Hidden parts (and those that did not load) are not drawn.
      if (mesh && !part.inRenderer)
      {
        pane->renderer->AddActor(part.actor);
        part.inRenderer = true;
      }
      else if (!mesh && part.inRenderer)
      {
        pane->renderer->RemoveActor(part.actor);
        part.inRenderer = false;
      }
    }
  }
}

void CompareWindow::refresh()
{
  syncParts();
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
    // Lights as the scene has them, each part's material; only the model differs per viewport.
    // Every setting is made and checked before any is applied.
    std::vector<LitModelSettings> parts(std::size_t(view_->partCount()));
    for (int i = 0; i < int(parts.size()) && i < int(model_->parts().size()); ++i)
    {
      if (view_->partDrawn(i))
      {
        litSceneOf(*model_, view_->partParameters(i), parts[std::size_t(i)],
                   view_->lighting().get());
        LitModelMaterial::validate(parts[std::size_t(i)]);
      }
    }
    for (auto& pane : panes_)
    {
      for (std::size_t i = 0; i < pane->parts.size() && i < parts.size(); ++i)
      {
        PaneActor& part = *pane->parts[i];
        if (!part.inRenderer)
        {
          continue;
        }
        LitModelSettings settings = parts[i];
        settings.model = pane->model;
        if (!part.material)
        {
          part.material = std::make_unique<LitModelMaterial>(settings);
          part.material->apply(part.actor, pane->renderer);
        }
        else
        {
          part.material->setSettings(settings);
        }
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
