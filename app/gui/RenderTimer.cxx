#include "app/gui/RenderTimer.h"

#include <utility>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkMapper.h>
#include <vtkRenderWindow.h>
#include <vtk_glew.h> // before any other GL header

namespace aniso
{
RenderTimer::RenderTimer(vtkRenderWindow* window, RefinementPlanner* planner, Describe drawStarts,
                         Describe renderEnds)
    : window_(window), planner_(planner), drawStarts_(std::move(drawStarts)),
      renderEnds_(std::move(renderEnds))
{
  clock_.start();
  observer_->SetClientData(this);
  observer_->SetCallback([](vtkObject* caller, unsigned long event, void* self, void*)
                         { static_cast<RenderTimer*>(self)->event(caller, event); });
  window_->AddObserver(vtkCommand::StartEvent, observer_);
  window_->AddObserver(vtkCommand::EndEvent, observer_);
}

RenderTimer::~RenderTimer()
{
  window_->RemoveObserver(observer_);
  setMappers({});
}

void RenderTimer::setMappers(const std::vector<vtkMapper*>& mappers)
{
  for (vtkMapper* mapper : mappers_)
  {
    mapper->RemoveObserver(observer_);
  }
  mappers_ = mappers;
  for (vtkMapper* mapper : mappers_)
  {
    mapper->AddObserver(vtkCommand::StartEvent, observer_);
  }
}

void RenderTimer::event(vtkObject* caller, unsigned long event)
{
  if (ignoring_)
  {
    startNs_ = -1;
    return;
  }
  if (caller == window_ && event == vtkCommand::StartEvent)
  {
    startNs_ = clock_.nsecsElapsed();
    drewSurface_ = false;
    planner_->renderStarted();
    return;
  }
  if (caller != window_)
  {
    // A surface's mapper starts drawing: this render adds (a band of) a frame to the mean.
    if (!drewSurface_)
    {
      drewSurface_ = true;
      drawStarts_(drawn_);
    }
    return;
  }
  if (startNs_ < 0)
  {
    return;
  }
  if (drewSurface_)
  {
    // The GL may still be drawing what it was given (a software rasteriser works on its own
    // threads until something needs the result): the render is measured, and its cost paid,
    // here, not in whichever later call waits for it.
    glFinish();
  }
  const double seconds = double(clock_.nsecsElapsed() - startNs_) * 1e-9;
  startNs_ = -1;
  renderedSeconds_ += seconds;
  if (!drewSurface_)
  {
    return; // a converged view shown again, or nothing to draw
  }
  drawn_.seconds = seconds;
  const int* size = window_->GetSize();
  drawn_.pixels = static_cast<long long>(size[0]) * size[1];
  renderEnds_(drawn_);
  planner_->learn(drawn_);
}
} // namespace aniso
