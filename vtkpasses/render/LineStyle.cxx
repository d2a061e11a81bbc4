#include "vtkpasses/render/LineStyle.h"

#include "core/error.h"
#include "vtkpasses/render/DrawingFrame.h"

#include <cmath>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace aniso
{
namespace
{
// (width, unit) of the actor's style.
vtkInformationDoubleVectorKey* styleKey()
{
  static vtkInformationDoubleVectorKey* key =
      vtkInformationDoubleVectorKey::MakeKey("LINE_STYLE", "aniso", 2);
  return key;
}
} // namespace

LineStyle lineStyleFromParameters(const ParameterSet& parameters)
{
  LineStyle style;
  style.width = parameters.real("line-width");
  style.unit = parseLineWidthUnit(parameters.text("line-width-unit"));
  return style;
}

void validateLineStyle(const LineStyle& style)
{
  if (!std::isfinite(style.width) || style.width <= 0.0)
  {
    throw errorAbout("line-width", "must be a positive number");
  }
}

void setLineStyle(vtkActor* actor, const LineStyle& style)
{
  validateLineStyle(style);
  vtkInformation* keys = actor->GetPropertyKeys();
  if (!keys)
  {
    vtkNew<vtkInformation> created;
    actor->SetPropertyKeys(created);
    keys = actor->GetPropertyKeys();
  }
  const double values[2] = {style.width, style.unit == LineWidthUnit::World ? 1.0 : 0.0};
  keys->Set(styleKey(), values, 2);
  actor->GetProperty()->SetLineWidth(static_cast<float>(
      style.unit == LineWidthUnit::World ? kGeometryShaderLineWidth : style.width));
  actor->Modified();
}

LineStyle lineStyle(vtkActor* actor)
{
  LineStyle style;
  vtkInformation* keys = actor ? actor->GetPropertyKeys() : nullptr;
  if (keys && keys->Has(styleKey()) && keys->Length(styleKey()) == 2)
  {
    const double* values = keys->Get(styleKey());
    style.width = values[0];
    style.unit = values[1] != 0.0 ? LineWidthUnit::World : LineWidthUnit::Pixels;
  }
  else if (actor)
  {
    style.width = actor->GetProperty()->GetLineWidth();
  }
  return style;
}

void lineWorldWidthClip(vtkActor* actor, vtkRenderer* renderer, float out[2])
{
  out[0] = out[1] = 0.0f;
  const LineStyle style = lineStyle(actor);
  if (style.unit != LineWidthUnit::World || !renderer || !renderer->GetActiveCamera())
  {
    return;
  }
  const double drawn = style.width / drawingFrame(actor).radius;
  vtkMatrix4x4* projection = renderer->GetActiveCamera()->GetProjectionTransformMatrix(
      renderer->GetTiledAspectRatio(), -1.0, 1.0);
  out[0] = static_cast<float>(projection->GetElement(0, 0) * drawn);
  out[1] = static_cast<float>(projection->GetElement(1, 1) * drawn);
}
} // namespace aniso
