#pragma once
// Material maps read from files (or, for TPR, written as a pattern), decoded the way the
// renderer takes them. Shared by `aniso render` and the window, so both read a file alike.
#include "core/image/image.h"

#include <string>

namespace aniso
{
// Texels per side of a map baked from a TPR pattern: finer than any view needs.
constexpr int kTprPatternSide = 1024;

// Signed vectors (normal, quaternion and two-channel TPR maps): integer-encoded files hold
// them as c = (v + 1) / 2, so their values become 2c - 1; float files hold v itself.
Image decodeSignedMap(Image image, bool integerFormat);
// readImage, then decodeSignedMap. Throws aniso::Error "PATH: reason".
Image readSignedMap(const std::string& path);

// A TPR map from an image file's content: one channel is an angle image (tprFromAngleImage),
// more are signed (x, y) vectors (decodeSignedMap).
Image tprFromFileImage(Image image, bool integerFormat);
// A TPR map from TEXT: the file of that name if one exists, else a pattern
// (parseTprPattern) baked at kTprPatternSide. A text that is neither throws aniso::Error
// "SUBJECT: 'TEXT' is no file, nor a pattern (reason)"; an unreadable file "PATH: reason".
Image readTprMap(const std::string& text, const std::string& subject);
} // namespace aniso
