#pragma once
// Times every render of a window (a view's progressive frames and the interactor's own) on the
// UI thread, the GL's work included, and hands each that drew the surface (its mapper started
// drawing) to a RefinementPlanner to learn from; each render that starts tells the planner so.
#include "core/quality/refinement_planner.h"

#include <QElapsedTimer>
#include <functional>
#include <vector>
#include <vtkNew.h>

class vtkCallbackCommand;
class vtkMapper;
class vtkObject;
class vtkRenderWindow;

namespace aniso
{
class RenderTimer
{
public:
  // Fills in what a render draws: DRAW_STARTS as the surface's draw starts (its samples, bands,
  // band and whether it is the stand-in), RENDER_ENDS once the render is done (whether it
  // measures the load); the timer adds the window's pixels and the seconds.
  using Describe = std::function<void(MeasuredRender&)>;
  RenderTimer(vtkRenderWindow* window, RefinementPlanner* planner, Describe drawStarts,
              Describe renderEnds);
  // The mappers of the surfaces (a scene's parts): a render in which one of them draws is one
  // the planner learns from.
  void setMappers(const std::vector<vtkMapper*>& mappers);
  ~RenderTimer();
  // Renders while IGNORING is set are not timed (a part pick's id renders: not frames).
  void setIgnoring(bool ignoring) { ignoring_ = ignoring; }
  // Seconds of every render timed so far, whether it drew the surface or not: what renders took
  // of a longer stretch of the UI thread's work (a repaint of the window that rendered).
  double renderedSeconds() const { return renderedSeconds_; }
  RenderTimer(const RenderTimer&) = delete;
  RenderTimer& operator=(const RenderTimer&) = delete;

private:
  // Window render start and end, the surface's draw in between: a render's cost.
  void event(vtkObject* caller, unsigned long event);

  vtkRenderWindow* window_;
  std::vector<vtkMapper*> mappers_;
  RefinementPlanner* planner_;
  Describe drawStarts_;
  Describe renderEnds_;
  vtkNew<vtkCallbackCommand> observer_;
  QElapsedTimer clock_;
  qint64 startNs_ = -1;
  bool drewSurface_ = false;
  bool ignoring_ = false;
  double renderedSeconds_ = 0.0;
  MeasuredRender drawn_; // what the surface's draw of the render in progress draws
};
} // namespace aniso
