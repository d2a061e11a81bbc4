#pragma once
// How an actor's line set (vtkpasses/mesh/LineSet.h) is drawn: its width, in pixels or in the
// mesh's own length units. Kept on the actor (its property and property keys), so that every
// material installed on it draws the same lines:
//   pixels: the actor's vtkProperty line width; VTK 9.1 draws lines wider than the hardware's
//     widest as screen-facing quads of that width through its geometry shader
//     (vtkPolyDataWideLineGS), else as the hardware's wide lines;
//   world:  the quads of that geometry shader, VTK's width in normalised device coordinates
//     replaced at each end of a segment by the world width's projection there:
//     (P00, P11) width_drawn / w_clip, with P the camera's projection and width_drawn the width
//     in the drawing frame (divided by its radius, DrawingFrame.h). The line set looks like a
//     ribbon of that width facing the viewer: thinner where it is farther. The actor's line
//     width is set above any hardware's widest (kGeometryShaderLineWidth) so that VTK always
//     draws through the geometry shader.
// The materials' line variants read the style through ShaderHook::setTransforms (the uniform
// PREFIX + "LineWorldWidthClip") and pass their varyings on with lineGeometryCode (ShaderHook.h).
#include "core/parameters/choices.h"
#include "core/parameters/parameters.h"

class vtkActor;
class vtkRenderer;

namespace aniso
{

struct LineStyle
{
  double width = 2.0; // > 0, finite: pixels, or the mesh's length units
  LineWidthUnit unit = LineWidthUnit::Pixels;
};

// A line width VTK takes as wider than any hardware draws, so that its geometry shader runs.
constexpr double kGeometryShaderLineWidth = 4096.0;

// The declared line-width and line-width-unit of PARAMETERS (a part's: its material's values).
LineStyle lineStyleFromParameters(const ParameterSet& parameters);

// Throws aniso::Error "line-width: reason" for a width that is not positive and finite.
void validateLineStyle(const LineStyle& style);

// Sets STYLE on ACTOR (its property's line width and its property keys).
void setLineStyle(vtkActor* actor, const LineStyle& style);
// The style set on ACTOR (pixels at the actor's property line width when none was set).
LineStyle lineStyle(vtkActor* actor);

// (P00, P11) of RENDERER's active camera times the drawn world width of ACTOR's style, for the
// geometry shader; (0, 0) for a width in pixels.
void lineWorldWidthClip(vtkActor* actor, vtkRenderer* renderer, float out[2]);
} // namespace aniso
