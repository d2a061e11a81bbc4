#pragma once
// Small previews of environments for the environment dock, made from core's data: an image
// file read by readImage, or a built-in environment sampled by renderEquirect, then a
// tone-mapped downscale.
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
} // namespace aniso
