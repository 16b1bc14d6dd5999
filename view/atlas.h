// The atlas: one small picture of white shapes that every quad of a frame samples, its colour
// coming from the quad: a filled disk, a ring (outline) and a solid square, side by side, each
// atlas_cell pixels square; only the alpha varies. Both drawing paths read the same alpha and
// the same texture coordinates: SDL_RenderGeometry from a texture made of it, the CPU
// rasteriser from the array itself.
#pragma once

#include <cstdint>
#include <vector>

namespace collide::view {

enum class AtlasCell : std::uint8_t { disk = 0, ring = 1, solid = 2 };
inline constexpr int atlas_cell = 64;
inline constexpr int atlas_cells = 3;
inline constexpr int atlas_width = atlas_cell * atlas_cells, atlas_height = atlas_cell;

// The alpha of every atlas pixel, row-major (atlas_width x atlas_height).
std::vector<std::uint8_t> atlas_alpha();

// The texture coordinates (0..1 over the whole atlas) of a cell. The solid cell is sampled well
// inside its border so that the neighbouring cells never bleed in.
struct CellUv {
    float u0 = 0, v0 = 0, u1 = 1, v1 = 1;
};
CellUv cell_uv(AtlasCell cell);

}  // namespace collide::view
