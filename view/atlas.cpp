#include "atlas.h"

#include <algorithm>
#include <cmath>

namespace collide::view {
namespace {

// Coverage of a pixel by the band inner <= d <= outer, 1 px of linear smoothing at each
// edge: smooth rims when a disk is drawn larger than the atlas, and an exact, opaque centre.
std::uint8_t band_alpha(double d, double inner, double outer) {
    const double a = std::clamp(outer - d + 0.5, 0.0, 1.0) * std::clamp(d - inner + 0.5, 0.0, 1.0);
    return std::uint8_t(std::lround(255 * a));
}

}  // namespace

std::vector<std::uint8_t> atlas_alpha() {
    std::vector<std::uint8_t> alpha(std::size_t(atlas_width) * atlas_height, 255);
    const double c = atlas_cell / 2.0, outer = c - 1.0, ring_width = 0.12 * atlas_cell;
    for (int y = 0; y < atlas_height; ++y)
        for (int x = 0; x < atlas_width; ++x) {
            const auto cell = AtlasCell(x / atlas_cell);
            const double d = std::hypot(x % atlas_cell + 0.5 - c, y + 0.5 - c);
            std::uint8_t& a = alpha[std::size_t(y) * atlas_width + x];
            if (cell == AtlasCell::disk) a = band_alpha(d, -1.0, outer);
            if (cell == AtlasCell::ring) a = band_alpha(d, outer - ring_width, outer);
        }
    return alpha;
}

CellUv cell_uv(AtlasCell cell) {
    const float k = float(static_cast<int>(cell));
    const float inset = cell == AtlasCell::solid ? 0.25f : 0.0f;
    return {(k + inset) / atlas_cells, inset, (k + 1 - inset) / atlas_cells, 1 - inset};
}

}  // namespace collide::view
