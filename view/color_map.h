// The colours of a frame: disks coloured by speed with viridis (a perceptually uniform map,
// readable in grey print and by colour-blind readers), kinematic stones grey, overlapping pairs
// marked red, the comparison state's outlines white.
#pragma once

#include <cstdint>

namespace collide::view {

struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb&) const = default;
};

// Viridis at s in [0, 1] (clamped), linear between nine samples of matplotlib's table.
Rgb viridis(double s);

namespace palette {
inline constexpr Rgb page{36, 36, 44};       // outside the box: margins, legend, HUD
inline constexpr Rgb box{10, 10, 14};        // the inside of the scene's box
inline constexpr Rgb stone{150, 150, 150};   // inverse mass 0: moves, is never pushed
inline constexpr Rgb overlap{235, 40, 40};   // a dot where two disks overlap
inline constexpr Rgb outline{255, 255, 255}; // the comparison state (--compare)
inline constexpr Rgb text{230, 230, 230};
}  // namespace palette

}  // namespace collide::view
