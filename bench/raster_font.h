#pragma once
// A 5x7 bitmap font for printable ASCII (32 to 126), drawn for the benchmark plots' PNG files.

namespace aniso::bench
{
constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;

// Whether pixel (column, row) of CHARACTER's glyph is set; row 0 is the top. Characters outside
// printable ASCII show as a filled box.
bool glyphPixel(char character, int column, int row);
} // namespace aniso::bench
