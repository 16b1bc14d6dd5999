#include "canvas.h"

#include <stdexcept>

namespace collide::view {
namespace {

[[noreturn]] void sdl_failed(const std::string& what) {
    throw std::runtime_error("SDL: cannot " + what + " (" + SDL_GetError() + ")");
}

bool is_software(SDL_Renderer* renderer) {
    SDL_RendererInfo info;
    return SDL_GetRendererInfo(renderer, &info) == 0 && (info.flags & SDL_RENDERER_SOFTWARE);
}

// A quad as two triangles of SDL vertices sampling its atlas cell, colour from the vertices.
void append_vertices(const Quad& q, std::vector<SDL_Vertex>& vertices, std::vector<int>& indices) {
    const CellUv uv = cell_uv(q.cell);
    const SDL_Color color{q.color.r, q.color.g, q.color.b, 255};
    const int base = int(vertices.size());
    vertices.push_back({{q.x0, q.y0}, color, {uv.u0, uv.v0}});
    vertices.push_back({{q.x1, q.y0}, color, {uv.u1, uv.v0}});
    vertices.push_back({{q.x1, q.y1}, color, {uv.u1, uv.v1}});
    vertices.push_back({{q.x0, q.y1}, color, {uv.u0, uv.v1}});
    for (int offset : {0, 1, 2, 0, 2, 3}) indices.push_back(base + offset);
}

}  // namespace

Canvas::Canvas(int width, int height, DrawPath path) : path_(path) {
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
    path_ = is_software(renderer_) ? DrawPath::cpu_raster : DrawPath::render_geometry;
    create_atlas();
}

Canvas::~Canvas() {
    if (frame_texture_) SDL_DestroyTexture(frame_texture_);
    if (atlas_) SDL_DestroyTexture(atlas_);
    if (renderer_) SDL_DestroyRenderer(renderer_);
    if (surface_) SDL_FreeSurface(surface_);
    if (window_) {
        SDL_DestroyWindow(window_);
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
    }
}

// The atlas texture: white, with the atlas alpha; colour modulation gives each quad its colour.
void Canvas::create_atlas() {
    const std::vector<std::uint8_t> alpha = atlas_alpha();
    std::vector<std::uint8_t> pixels(alpha.size() * 4, 255);
    for (std::size_t k = 0; k < alpha.size(); ++k) pixels[4 * k + 3] = alpha[k];
    atlas_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STATIC, atlas_width, atlas_height);
    if (!atlas_) sdl_failed("create the disk texture");
    if (SDL_UpdateTexture(atlas_, nullptr, pixels.data(), atlas_width * 4) != 0) sdl_failed("fill the disk texture");
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

void Canvas::draw(const Geometry& g, int threads) {
    if (path_ == DrawPath::render_geometry) return draw_with_render_geometry(g);
    if (window_) return draw_into_streaming_texture(g, threads);
    draw_with_rasteriser(g, threads);
}

// Clears to the page colour and draws every quad in one SDL_RenderGeometry call.
void Canvas::draw_with_render_geometry(const Geometry& g) {
    SDL_SetRenderDrawColor(renderer_, palette::page.r, palette::page.g, palette::page.b, 255);
    SDL_RenderClear(renderer_);
    if (g.quads.empty()) return;
    vertices_.clear();
    indices_.clear();
    for (const Quad& q : g.quads) append_vertices(q, vertices_, indices_);
    if (SDL_RenderGeometry(renderer_, atlas_, vertices_.data(), int(vertices_.size()), indices_.data(),
                           int(indices_.size())) != 0)
        sdl_failed("draw the frame");
}

// Off-screen: the rasteriser writes the software renderer's own surface.
void Canvas::draw_with_rasteriser(const Geometry& g, int threads) {
    if (SDL_MUSTLOCK(surface_) && SDL_LockSurface(surface_) != 0) sdl_failed("lock the frame surface");
    rasteriser_.draw(g, palette::page, {static_cast<std::uint8_t*>(surface_->pixels), surface_->w, surface_->h, surface_->pitch},
                     threads);
    if (SDL_MUSTLOCK(surface_)) SDL_UnlockSurface(surface_);
}

// On a window: the rasteriser fills a streaming texture of the window's size, copied once.
void Canvas::draw_into_streaming_texture(const Geometry& g, int threads) {
    const int w = width(), h = height();
    if (!frame_texture_ || w != frame_texture_width_ || h != frame_texture_height_) {
        if (frame_texture_) SDL_DestroyTexture(frame_texture_);
        frame_texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, w, h);
        if (!frame_texture_) sdl_failed("create the frame texture");
        // A plain copy: SDL gives a texture with alpha blending by default, whose approximate
        // arithmetic would change opaque pixels by one unit.
        SDL_SetTextureBlendMode(frame_texture_, SDL_BLENDMODE_NONE);
        frame_texture_width_ = w, frame_texture_height_ = h;
    }
    void* pixels = nullptr;
    int pitch = 0;
    if (SDL_LockTexture(frame_texture_, nullptr, &pixels, &pitch) != 0) sdl_failed("lock the frame texture");
    rasteriser_.draw(g, palette::page, {static_cast<std::uint8_t*>(pixels), w, h, pitch}, threads);
    SDL_UnlockTexture(frame_texture_);
    if (SDL_RenderCopy(renderer_, frame_texture_, nullptr, nullptr) != 0) sdl_failed("show the frame");
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
