#pragma once
// A turntable: N frames of the scene with the camera turned about the scene's up axis (+Z)
// around the drawn parts' centre, written as numbered PNGs (PREFIX_0000.png, ...) and, where
// ffmpeg is installed, encoded as a video (PREFIX.mp4). File > Export Turntable.
#include "scene/SceneModel.h"
#include "vtkpasses/render/DrawingFrame.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <QString>
#include <QStringList>
#include <functional>
#include <vector>

class QWidget;

namespace aniso
{
struct TurntableOptions
{
  int frames = 36;                // N, 1 to 3600
  int width = 640;                // pixels
  int height = 480;               // pixels
  double elevationDegrees = 25.0; // above the XY plane, -89 to 89
  QString prefix;                 // frames PREFIX_0000.png, ...; the video PREFIX.mp4
  bool video = true;              // encode the video when ffmpeg is found
  int framesPerSecond = 30;
};

// The camera of each of FRAMES frames: frame K at START's azimuth about DRAWING's centre plus
// 360 K / FRAMES degrees, at ELEVATION, at START's distance.
std::vector<CameraState> turntableCameras(const CameraState& start, const DrawingFrame& drawing,
                                          int frames, double elevationDegrees);

// PREFIX_KKKK.png (four digits, more when N needs them).
QString turntableFramePath(const QString& prefix, int frame, int frames);

// ffmpeg on the PATH, or empty.
QString ffmpegExecutable();

struct TurntableResult
{
  QStringList frames; // the PNGs written
  QString video;      // the video written, or empty
  QString videoError; // why no video was written when one was asked for (empty: none asked)
  bool cancelled = false;
};

// Renders SETTINGS (its camera replaced) from each of CAMERAS at OPTIONS' size and writes the
// PNGs (display-transformed 8-bit sRGB, as screenshots), then the video. PROGRESS(K) runs before
// frame K and after the last (K = N); when it returns false the export stops, the frames written
// so far stay and no video is made. Throws aniso::Error "PATH: reason" for invalid options or a
// frame that cannot be written.
TurntableResult exportTurntable(RenderSettings settings, const std::vector<CameraState>& cameras,
                                const TurntableOptions& options,
                                const std::function<bool(int)>& progress);

// File > Export Turntable's dialog (titled "Export turntable"): the files' prefix, N, the size,
// the elevation and the video (offered only where ffmpeg is found), showing OPTIONS and editing
// them. False when cancelled (OPTIONS unchanged then).
bool askTurntableOptions(QWidget* parent, TurntableOptions& options);

// Throws aniso::Error "SUBJECT: reason" for options out of range.
void checkTurntableOptions(const TurntableOptions& options, const std::string& subject);
} // namespace aniso
