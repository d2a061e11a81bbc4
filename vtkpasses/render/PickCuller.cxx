#include "vtkpasses/render/PickCuller.h"

#include "vtkpasses/render/RendererMatrices.h"

#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>
#include <limits>
#include <vtkObjectFactory.h>
#include <vtkProp.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

namespace aniso
{
vtkStandardNewMacro(PickCuller);

void PickCuller::SetPixel(int x, int y)
{
  this->X = x;
  this->Y = y;
}

namespace
{
// Where the renderer's world goes on the window: its world-to-clip matrix and its viewport in
// pixels.
struct Projection
{
  glm::dmat4 clip{1.0};
  double left = 0.0;
  double bottom = 0.0;
  double width = 0.0;
  double height = 0.0;
};

// Whether PROP's screen rectangle holds the point (PX, PY): its bounding box's corners projected,
// a pixel of margin; a box reaching behind the camera, or no bounds, always may.
bool mayCover(const Projection& p, vtkProp* prop, double px, double py)
{
  const double* bounds = prop->GetBounds();
  if (!bounds || !(bounds[0] <= bounds[1]) || !(bounds[2] <= bounds[3]) ||
      !(bounds[4] <= bounds[5]))
  {
    return true; // nothing to judge by
  }
  double low[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double high[2] = {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec4 world(bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
                           bounds[4 + ((corner >> 2) & 1)], 1.0);
    const glm::dvec4 c = p.clip * world;
    if (!(c.w > 0.0) || !std::isfinite(c.x) || !std::isfinite(c.y))
    {
      return true; // reaches behind the camera: its projection is not bounded by the corners'
    }
    const double display[2] = {p.left + 0.5 * (c.x / c.w + 1.0) * p.width,
                               p.bottom + 0.5 * (c.y / c.w + 1.0) * p.height};
    for (int axis = 0; axis < 2; ++axis)
    {
      low[axis] = std::min(low[axis], display[axis]);
      high[axis] = std::max(high[axis], display[axis]);
    }
  }
  return px >= low[0] - 1.0 && px <= high[0] + 1.0 && py >= low[1] - 1.0 && py <= high[1] + 1.0;
}
} // namespace

double PickCuller::Cull(vtkRenderer* renderer, vtkProp** props, int& count, int& initialized)
{
  vtkRenderWindow* window = renderer ? renderer->GetRenderWindow() : nullptr;
  if (!window)
  {
    // Nothing to project with: every prop stays.
    double total = 0.0;
    for (int i = 0; i < count; ++i)
    {
      total += props[i] ? props[i]->GetRenderTimeMultiplier() : 0.0;
    }
    return total;
  }
  Projection projection;
  projection.clip = worldToClip(renderer);
  const int* size = window->GetSize();
  const double* viewport = renderer->GetViewport();
  projection.left = viewport[0] * size[0];
  projection.bottom = viewport[1] * size[1];
  projection.width = (viewport[2] - viewport[0]) * size[0];
  projection.height = (viewport[3] - viewport[1]) * size[1];
  // A pixel's centre is at +0.5.
  const double px = this->X + 0.5;
  const double py = this->Y + 0.5;
  int kept = 0;
  double total = 0.0;
  for (int i = 0; i < count; ++i)
  {
    if (props[i] && mayCover(projection, props[i], px, py))
    {
      props[kept++] = props[i];
      total += props[i]->GetRenderTimeMultiplier();
    }
  }
  count = kept;
  initialized = 1;
  return total;
}
} // namespace aniso
