#pragma once
// A view's camera as the model stores it (CameraState, in the mesh's coordinates) and as its
// renderer's vtkCamera holds it, in the frame the surface is drawn in (DrawingFrame.h).
#include "scene/SceneModel.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/ViewSettings.h"

class vtkCamera;

namespace aniso
{
// CAMERA set to STATE, mapped to DRAWING's frame.
void setCameraState(vtkCamera* camera, const CameraState& state, const DrawingFrame& drawing);
// What CAMERA, in DRAWING's frame, is in the mesh's coordinates (set).
CameraState cameraStateOf(vtkCamera* camera, const DrawingFrame& drawing);
// STATE as a placement in the same coordinates (renderOffscreen's camera).
CameraPlacement placementOf(const CameraState& state);
// The default view (defaultViewSettings: the three-quarter view, `aniso render`'s default too)
// of the drawing frame's unit sphere in a window of WIDTH x HEIGHT, with room for a narrow
// window (fittedToFrame), as renderOffscreen places its camera.
CameraPlacement defaultPlacement(int width, int height);
// VIEW of the drawing frame's unit sphere in a window of WIDTH x HEIGHT (a named view of the
// View menu: viewPresets).
CameraPlacement viewPlacement(const ViewSettings& view, int width, int height);
} // namespace aniso
