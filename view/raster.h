// The CPU rasteriser: draws a frame's quads (frame_geometry.h) into a pixel buffer. SDL's
// software renderer sets up and clips every triangle of SDL_RenderGeometry on its own, which at
// 10^5 disks of a pixel or two costs far more than filling their pixels; this path fills the
// pixels of each quad directly, sampling the same atlas alpha at the same texture coordinates,
// so it draws the same picture. The rows are shared among threads in bands; every band walks
// the quads in order, so later quads stay on top.
#pragma once

#include <cstdint>
#include <vector>

#include "color_map.h"
#include "frame_geometry.h"

namespace collide::view {

// A buffer of 4 bytes per pixel in the order R, G, B, A (SDL_PIXELFORMAT_RGBA32).
struct PixelTarget {
    std::uint8_t* pixels = nullptr;
    int width = 0, height = 0;
    int pitch = 0;  // bytes from one row to the next
};

class Rasteriser {
public:
    Rasteriser();
    // Fills `target` with `background`, then draws the quads in order, blending by the atlas
    // alpha as SDL_BLENDMODE_BLEND does. threads <= 0: OpenMP's default.
    void draw(const Geometry& geometry, Rgb background, const PixelTarget& target, int threads) const;

private:
    void draw_band(const Geometry& geometry, Rgb background, const PixelTarget& target, int row_begin,
                   int row_end) const;
    void clear_band(const Geometry& geometry, Rgb background, const PixelTarget& target, int row_begin,
                    int row_end) const;
    void draw_quad(const Quad& quad, const PixelTarget& target, int row_begin, int row_end) const;

    std::vector<std::uint8_t> alpha_;  // the atlas (atlas.h)
};

}  // namespace collide::view
