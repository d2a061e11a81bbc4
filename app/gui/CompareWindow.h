#pragma once
// The comparison view: the scene drawn by every lit model of the registry side by side, one
// viewport each in a grid, with one camera for all (moving it in any viewport moves every one),
// the scene's lights. Every viewport draws each of the main view's drawn parts (its surface as
// drawn when still, SceneView::partDrawnSurface) with an actor of its own and that part's
// material (SceneView::partParameters); actors and materials are kept per part and follow the
// scene's changes (values, materials, parts shown, hidden, added or removed) while open.
#include "scene/SceneModel.h"

#include <QWidget>
#include <memory>
#include <string>
#include <vector>
#include <vtkNew.h>

class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkCamera;
class vtkGenericOpenGLRenderWindow;
class vtkRenderer;

namespace aniso
{
class SceneView;

// The models compared: the lit ones of shadingModels(), in its order.
std::vector<std::string> comparedLitModels();

class CompareWindow : public QWidget
{
  Q_OBJECT

public:
  // MODEL and VIEW (whose mesh and camera are shown) must outlive the window.
  CompareWindow(SceneModel* model, SceneView* view, QWidget* parent = nullptr);
  ~CompareWindow() override;

  int viewportCount() const;
  vtkRenderer* viewport(int index) const;
  // The actor viewport INDEX draws part PART with (null while the part is not drawn).
  vtkActor* partActor(int index, int part) const;
  QVTKOpenGLNativeWidget* vtkWidget() const { return widget_; }

  // Takes the main view's mesh and camera again.
  void refresh();

signals:
  void errorOccurred(const QString& message);

protected:
  // Opening the window takes the view's current mesh and camera.
  void showEvent(QShowEvent* event) override;

private:
  struct Pane;
  struct PaneActor;
  // Each pane's actors in line with the view's drawn parts and their surfaces.
  void syncParts();
  void updateMaterials();

  SceneModel* model_;
  SceneView* view_;
  QVTKOpenGLNativeWidget* widget_;
  vtkNew<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkCamera> camera_;
  std::vector<std::unique_ptr<Pane>> panes_;
};
} // namespace aniso
