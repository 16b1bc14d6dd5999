// A 3x5 pixel font for the HUD line and the legend labels. SDL2 draws no text itself, and a
// font library (SDL_ttf) would add a dependency and a font file for a few dozen characters.
// Lower case is drawn as upper case; a character the font lacks is drawn as '?'.
#pragma once

#include <array>

namespace collide::view {

inline constexpr int glyph_width = 3, glyph_height = 5;
inline constexpr int glyph_advance = 4;  // one column of space between characters

// Row r (0 = top) of the glyph for c: bit 2 is the left column, bit 0 the right.
std::array<unsigned char, glyph_height> glyph_rows(char c);

}  // namespace collide::view
