// Canvas: an SDL renderer plus the atlas texture, either on a window (the live viewer) or on a
// memory surface with SDL's software renderer (headless: tests, servers, `collide render`).
// The off-screen canvas needs no video driver at all, so it runs where no display exists.
#pragma once

#include <SDL2/SDL.h>

#include <cstdint>
#include <string>
#include <vector>

#include "frame_geometry.h"

namespace collide::view {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // row-major, 4 bytes per pixel (R, G, B, A)
    Rgb at(int x, int y) const {
        const std::size_t k = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
        return {rgba[k], rgba[k + 1], rgba[k + 2]};
    }
};

class Canvas {
public:
    // Off-screen, software renderer on a width x height surface.
    Canvas(int width, int height);
    // A resizable window; vsync keeps the live viewer at the display's rate.
    Canvas(const std::string& title, int width, int height, bool vsync);
    ~Canvas();
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;

    int width() const;
    int height() const;
    // Clears to the page colour and draws the geometry in one SDL_RenderGeometry call.
    void draw(const Geometry& geometry);
    void present();
    // Waits until every queued draw command has reached the pixels (timing the draw alone).
    void flush();
    Image read_pixels() const;
    SDL_Window* window() const { return window_; }

private:
    void create_atlas();

    SDL_Window* window_ = nullptr;
    SDL_Surface* surface_ = nullptr;
    SDL_Renderer* renderer_ = nullptr;
    SDL_Texture* atlas_ = nullptr;
};

}  // namespace collide::view
