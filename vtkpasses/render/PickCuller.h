#pragma once
// A culler for a pick at one pixel: of the props a render would draw, only those whose screen
// rectangle (their bounding box's corners projected by the renderer's camera) holds the pixel
// stay. Added to a renderer for the hardware selector's id render (vtkHardwareSelector), it keeps
// that render to the few props that can be under the pixel: the others are not drawn, and their
// mappers do not switch to their picking shaders and back. Conservative: a prop whose box reaches
// behind the camera, or that has no bounds, stays. Culling changes no prop's modification time
// (vtkProp::SetRenderTimeMultiplier does not), so a view's accumulated mean is not disturbed.
#include <vtkCuller.h>

class vtkProp;
class vtkRenderer;

namespace aniso
{
class PickCuller : public vtkCuller
{
public:
  static PickCuller* New();

  // The pixel, in display coordinates (VTK's: origin at the window's bottom left).
  void SetPixel(int x, int y);

  double Cull(vtkRenderer* renderer, vtkProp** props, int& count, int& initialized) override;

  vtkTypeMacro(PickCuller, vtkCuller)

protected:
  PickCuller() = default;
  ~PickCuller() override = default;

private:
  PickCuller(const PickCuller&) = delete;
  void operator=(const PickCuller&) = delete;

  int X = 0;
  int Y = 0;
};
} // namespace aniso
