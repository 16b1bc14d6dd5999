#include "canvas.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace collide::view {
namespace {

[[noreturn]] void sdl_failed(const std::string& what) {
    throw std::runtime_error("SDL: cannot " + what + " (" + SDL_GetError() + ")");
}

// Coverage of a pixel by the band inner <= d <= outer, 1 px of linear smoothing at each
// edge: smooth rims when a disk is drawn larger than the atlas, and an exact, opaque centre.
std::uint8_t band_alpha(double d, double inner, double outer) {
    const double a = std::clamp(outer - d + 0.5, 0.0, 1.0) * std::clamp(d - inner + 0.5, 0.0, 1.0);
    return std::uint8_t(std::lround(255 * a));
}

}  // namespace

Canvas::Canvas(int width, int height) {
    surface_ = SDL_CreateRGBSurfaceWithFormat(0, width, height, 32, SDL_PIXELFORMAT_RGBA32);
    if (!surface_) sdl_failed("create a " + std::to_string(width) + "x" + std::to_string(height) + " surface");
    renderer_ = SDL_CreateSoftwareRenderer(surface_);
    if (!renderer_) sdl_failed("create the software renderer");
    create_atlas();
}

Canvas::Canvas(const std::string& title, int width, int height, bool vsync) {
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) sdl_failed("start the video subsystem (no display? use --headless)");
    window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height,
                               SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (!window_) sdl_failed("open a window");
    renderer_ = SDL_CreateRenderer(window_, -1, vsync ? SDL_RENDERER_PRESENTVSYNC : 0);
    if (!renderer_) sdl_failed("create a renderer");
    create_atlas();
}

Canvas::~Canvas() {
    if (atlas_) SDL_DestroyTexture(atlas_);
    if (renderer_) SDL_DestroyRenderer(renderer_);
    if (surface_) SDL_FreeSurface(surface_);
    if (window_) {
        SDL_DestroyWindow(window_);
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
    }
}

// The atlas: white shapes whose colour comes from the vertices (colour modulation), alpha
// from the shape: a filled disk, a ring (outline) and a solid square.
void Canvas::create_atlas() {
    const int w = atlas_cell * atlas_cells, h = atlas_cell;
    std::vector<std::uint8_t> pixels(std::size_t(w * h) * 4, 255);
    const double c = atlas_cell / 2.0, outer = c - 1.0, ring_width = 0.12 * atlas_cell;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int cell = x / atlas_cell;
            const double d = std::hypot(x % atlas_cell + 0.5 - c, y + 0.5 - c);
            std::uint8_t alpha = 255;
            if (cell == 0) alpha = band_alpha(d, -1.0, outer);
            if (cell == 1) alpha = band_alpha(d, outer - ring_width, outer);
            pixels[(std::size_t(y) * w + x) * 4 + 3] = alpha;
        }
    atlas_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STATIC, w, h);
    if (!atlas_) sdl_failed("create the disk texture");
    if (SDL_UpdateTexture(atlas_, nullptr, pixels.data(), w * 4) != 0) sdl_failed("fill the disk texture");
    SDL_SetTextureBlendMode(atlas_, SDL_BLENDMODE_BLEND);
}

int Canvas::width() const {
    int w = 0, h = 0;
    SDL_GetRendererOutputSize(renderer_, &w, &h);
    return w;
}

int Canvas::height() const {
    int w = 0, h = 0;
    SDL_GetRendererOutputSize(renderer_, &w, &h);
    return h;
}

void Canvas::draw(const Geometry& g) {
    SDL_SetRenderDrawColor(renderer_, palette::page.r, palette::page.g, palette::page.b, 255);
    SDL_RenderClear(renderer_);
    if (g.indices.empty()) return;
    if (SDL_RenderGeometry(renderer_, atlas_, g.vertices.data(), int(g.vertices.size()), g.indices.data(),
                           int(g.indices.size())) != 0)
        sdl_failed("draw the frame");
}

void Canvas::present() { SDL_RenderPresent(renderer_); }

void Canvas::flush() { SDL_RenderFlush(renderer_); }

Image Canvas::read_pixels() const {
    Image image;
    image.width = width();
    image.height = height();
    image.rgba.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
    // The software renderer batches draw commands; reading flushes them first.
    if (SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_RGBA32, image.rgba.data(), image.width * 4) != 0)
        sdl_failed("read the frame back");
    return image;
}

}  // namespace collide::view
