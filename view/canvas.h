// Canvas: where a frame's quads are drawn, either on a window (the live viewer) or on a memory
// surface (headless: tests, servers, `collide render`, `collide bench view`). The off-screen
// canvas needs no video driver at all, so it runs where no display exists.
//
// Two ways to draw the same quads (frame_geometry.h), chosen by the renderer:
// - render_geometry: all quads in one SDL_RenderGeometry call on the atlas texture, for
//   accelerated (GPU) renderers, where a draw call is cheap and the GPU fills the pixels;
// - cpu_raster: the CPU rasteriser (raster.h) fills the pixels directly, for software renderers,
//   whose per-triangle set-up is the cost of a frame of many small disks. Off-screen it writes
//   straight into the surface; on a window, into a streaming texture shown with one copy.
#pragma once

#include <SDL2/SDL.h>

#include <cstdint>
#include <string>
#include <vector>

#include "frame_geometry.h"
#include "raster.h"

namespace collide::view {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // row-major, 4 bytes per pixel (R, G, B, A)
    Rgb at(int x, int y) const {
        const std::size_t k = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
        return {rgba[k], rgba[k + 1], rgba[k + 2]};
    }
};

enum class DrawPath { render_geometry, cpu_raster };

class Canvas {
public:
    // Off-screen, SDL's software renderer on a width x height surface; `path` is for the tests
    // that compare the two ways (the CPU rasteriser is the faster one on a software renderer).
    Canvas(int width, int height, DrawPath path = DrawPath::cpu_raster);
    // A resizable window on SDL's default renderer (vsync keeps the live viewer at the display's
    // rate); cpu_raster if that renderer is a software one, render_geometry otherwise.
    Canvas(const std::string& title, int width, int height, bool vsync);
    ~Canvas();
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;

    int width() const;
    int height() const;
    DrawPath path() const { return path_; }
    // Draws the frame over the page colour; threads (cpu_raster only) <= 0: OpenMP's default.
    void draw(const Geometry& geometry, int threads = 0);
    void present();
    // Waits until every queued draw command has reached the pixels (timing the draw alone).
    void flush();
    Image read_pixels() const;
    SDL_Window* window() const { return window_; }

private:
    void create_atlas();
    void draw_with_render_geometry(const Geometry& geometry);
    void draw_with_rasteriser(const Geometry& geometry, int threads);
    void draw_into_streaming_texture(const Geometry& geometry, int threads);

    SDL_Window* window_ = nullptr;
    SDL_Surface* surface_ = nullptr;
    SDL_Renderer* renderer_ = nullptr;
    SDL_Texture* atlas_ = nullptr;
    DrawPath path_ = DrawPath::cpu_raster;
    // render_geometry: the quads as SDL vertices and indices, kept between frames.
    std::vector<SDL_Vertex> vertices_;
    std::vector<int> indices_;
    // cpu_raster: the rasteriser and, on a window, the texture it fills.
    Rasteriser rasteriser_;
    SDL_Texture* frame_texture_ = nullptr;
    int frame_texture_width_ = 0, frame_texture_height_ = 0;
};

}  // namespace collide::view
