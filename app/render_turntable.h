#pragma once
// `aniso render --turntable N`: N images with the camera turned about the scene's up axis (+Z)
// around the framed parts' centre, from the azimuth and elevation of the render's view
// (--view, --azimuth, --elevation), written as OUT_0000.png, OUT_0001.png, ... (OUT's
// extension kept).
#include "vtkpasses/render/OffscreenRenderer.h"

#include <ostream>
#include <string>

namespace aniso::cli
{
// The digits of the images' numbers: four, more when N needs them.
int turntableDigits(int frames);
// OUTPUT's stem, _ and K in turntableDigits(N) digits, OUTPUT's extension.
std::string turntableFramePath(const std::string& output, int frame, int frames);

// RESULT written to OUTPUT by its extension: .exr linear RGBA float; else the displayed 8-bit
// values, with alpha when the background is transparent. Throws aniso::Error "OUTPUT: reason".
void writeRendered(const std::string& output, const RenderResult& result, bool transparent);

// Renders SETTINGS from FRAMES azimuths, 360 / FRAMES degrees apart counter-clockwise seen from
// above, the first SETTINGS' own view direction (its elevation kept), and writes each to
// turntableFramePath(OUTPUT, K, FRAMES); one line per image on OUT. Returns the images' frame
// times together (for --time).
std::vector<double> renderTurntable(RenderSettings settings, int frames, const std::string& output,
                                    std::ostream& out);
} // namespace aniso::cli
