#pragma once
// The cameras of the window's Frame All and of the turntable (View > Standard Views are
// SceneView::showView, as `aniso render --view`):
// cameras that frame the drawn parts' bounding sphere (DrawingFrame.h), in the mesh's
// coordinates as the model stores them (CameraState). Z is up.
#include "scene/SceneModel.h"
#include "vtkpasses/render/DrawingFrame.h"

#include <glm/vec3.hpp>

namespace aniso
{
// The camera looking from DIRECTION (centre towards camera, any length > 0) at DRAWING's centre,
// at the distance that fits its bounding sphere in a WIDTH x HEIGHT view, with CURRENT's
// projection and view angle. Up is +Z, or +Y looking along Z. Throws aniso::Error "view: reason"
// for a direction of no length.
CameraState framedCamera(const glm::dvec3& direction, const DrawingFrame& drawing,
                         const CameraState& current, int width, int height);

// CURRENT's direction kept, the camera moved to frame DRAWING (Frame All).
CameraState frameAll(const CameraState& current, const DrawingFrame& drawing, int width,
                     int height);

// The turntable's camera at AZIMUTH (degrees, counter-clockwise about +Z seen from above, 0 the
// -Y side as in viewDirectionFromAngles) and ELEVATION (degrees above the XY plane) around
// DRAWING's centre, at CURRENT's distance from its focal point, with CURRENT's projection.
CameraState orbitCamera(const CameraState& current, const DrawingFrame& drawing,
                        double azimuthDegrees, double elevationDegrees);
// CURRENT's azimuth and elevation about DRAWING's centre, in the same convention (degrees).
void azimuthElevationOf(const CameraState& current, const DrawingFrame& drawing,
                        double& azimuthDegrees, double& elevationDegrees);
} // namespace aniso
