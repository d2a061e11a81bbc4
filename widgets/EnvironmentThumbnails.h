#pragma once
// Small previews of environments for the environment dock, made from core's data: an image
// file read by readImage, or a built-in environment sampled by renderEquirect, then a
// tone-mapped downscale; and the environment analysis' sources marked on a preview.
#include "core/env/env_sources.h"
#include "core/env/environment.h"
#include "core/image/image.h"

#include <QImage>
#include <string>

namespace aniso
{
// Box-filtered downscale of an equirectangular HDR to WIDTH x WIDTH/2 (at least 1 x 1; never
// larger than the image), then a display transform: exposure that maps the log-average
// luminance to middle grey 0.18 (Reinhard's key value), the ACES filmic fit of Narkowicz
// x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), and sRGB encoding. Non-finite and negative texels
// count as black. Returns RGB in [0, 1]. Throws aniso::Error for an empty image.
Image toneMappedThumbnail(const Image& hdr, int width);

// RGB in [0, 1] as an 8-bit image.
QImage toQImage(const Image& rgb);

// The preview of an environment spec as the "env" parameter takes it ("builtin:studio",
// "builtin:white" or a file path). Throws aniso::Error "SPEC: reason".
QImage environmentThumbnail(const std::string& spec, int width);
// The same of an open environment: an EquirectEnvironment's image, any other sampled.
QImage environmentThumbnail(const Environment& env, int width);

// The smallest radius of a source's mark, in pixels: a sun is far smaller than a preview's texel.
constexpr int kMinimumMarkRadius = 5;

// The preview with each listed source of ANALYSIS marked: an ellipse centred at the source's
// direction on the image (directionToEquirect's (u, v) at x = u W, y = (1 - v) H, wrapping
// across the left and right edges), its radii the source's angular radius there (r H / pi
// vertically, over cos(elevation) horizontally, at most W / 2), each at least
// kMinimumMarkRadius; drawn as a ring in the kind's colour (sun amber, lamp cyan, window
// magenta) over a dark one, so it shows on bright and dark skies. Safe off the UI thread.
QImage markedSources(const QImage& preview, const EnvAnalysis& analysis);
} // namespace aniso
