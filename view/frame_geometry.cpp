#include "frame_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bitmap_font.h"
#include "parallel_chunks.h"

namespace collide::view {
namespace {

// The smallest half-width of a drawn disk in pixels: at 10^5 disks on a screen a disk is about
// one pixel, and a quad smaller than a pixel could fall between pixel centres and vanish.
constexpr float min_half_pixels = 0.75f;

// Appends one quad (pixel corners, y down).
void add_quad(Geometry& g, float x0, float y0, float x1, float y1, Rgb c, AtlasCell cell) {
    g.quads.push_back({x0, y0, x1, y1, c, cell});
}

// The quad of a disk or mark of radius r centred at (x, y), never under min_half_pixels.
Quad circle_quad(const FrameLayout& l, double x, double y, double r, Rgb c, AtlasCell cell) {
    const float cx = l.px(x), cy = l.py(y);
    const float h = std::max(float(r * l.scale), min_half_pixels);
    return {cx - h, cy - h, cx + h, cy + h, c, cell};
}

// One solid quad per lit font pixel, `scale` screen pixels square, from the top-left (x, y).
void add_text(Geometry& g, float x, float y, int scale, const std::string& text, Rgb c) {
    const float s = float(scale);
    for (char ch : text) {
        const auto rows = glyph_rows(ch);
        for (int r = 0; r < glyph_height; ++r)
            for (int col = 0; col < glyph_width; ++col)
                if (rows[r] & (1 << (glyph_width - 1 - col)))
                    add_quad(g, x + col * s, y + r * s, x + (col + 1) * s, y + (r + 1) * s, c, AtlasCell::solid);
        x += glyph_advance * s;
    }
}

// Appends quad_of(i) for i in [0, count), written in place by chunks on up to `threads` threads.
template <typename QuadOf>
void append_in_parallel(Geometry& g, std::size_t count, int threads, QuadOf&& quad_of) {
    const std::size_t base = g.quads.size();
    g.quads.resize(base + count);
    parallel_chunks(plan_chunks(count, threads), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) g.quads[base + i] = quad_of(i);
    });
}

// The filled disks, coloured by speed (stones grey).
void add_disks(Geometry& g, const FrameLayout& l, const ParticleState<double>& s, double speed_max, int threads) {
    append_in_parallel(g, s.size(), threads, [&](std::size_t i) {
        const double speed = std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
        const Rgb c = s.is_stone(i) ? palette::stone : speed_color(speed, speed_max);
        return circle_quad(l, s.x[i], s.y[i], s.radius[i], c, AtlasCell::disk);
    });
}

// The comparison state's outlines.
void add_outlines(Geometry& g, const FrameLayout& l, const ParticleState<double>& s, int threads) {
    append_in_parallel(g, s.size(), threads, [&](std::size_t i) {
        return circle_quad(l, s.x[i], s.y[i], s.radius[i], palette::outline, AtlasCell::ring);
    });
}

void add_legend(Geometry& g, const FrameLayout& l, double speed_max) {
    // The bar is drawn in bands, bottom (speed 0) to top (speed_max and faster).
    const int bands = 64;
    const PixelRect& b = l.legend_bar;
    for (int k = 0; k < bands; ++k) {
        // Whole-pixel edges: fractional ones leave a dark seam between bands.
        const float y1 = std::round(b.y + b.h * float(bands - k) / bands);
        const float y0 = std::round(b.y + b.h * float(bands - k - 1) / bands);
        add_quad(g, b.x, y0, b.x + b.w, y1, viridis((k + 0.5) / bands), AtlasCell::solid);
    }
    const int s = l.text_scale;
    char top[32];
    std::snprintf(top, sizeof top, "%.3g+", speed_max);
    const float label_x = b.x + b.w + 4.0f * s;
    add_text(g, b.x, b.y - float((glyph_height + 3) * s), s, "SPEED", palette::text);
    add_text(g, label_x, b.y, s, top, palette::text);
    add_text(g, label_x, b.y + b.h - float(glyph_height * s), s, "0", palette::text);
}

}  // namespace

Rgb speed_color(double speed, double speed_max) { return viridis(speed_max > 0 ? speed / speed_max : 0); }

double default_speed_max(const Scene& scene, const ParticleState<double>& initial) {
    double v = 0;
    for (std::size_t i = 0; i < initial.size(); ++i)
        if (!initial.is_stone(i)) v = std::max(v, std::hypot(initial.vx[i], initial.vy[i]));
    // v^2 = 2 g h: the speed gained falling through the whole box.
    const double g = std::hypot(scene.physics.gravity_x, scene.physics.gravity_y);
    v = std::max(v, std::sqrt(2 * g * std::max(scene.world.width(), scene.world.height())));
    return v > 0 ? v : 1;
}

void build_frame(const FrameContent& content, const FrameLayout& l, Geometry& g, int threads) {
    g.clear();
    add_quad(g, l.box.x, l.box.y, l.box.x + l.box.w, l.box.y + l.box.h, palette::box, AtlasCell::solid);
    if (content.state) add_disks(g, l, *content.state, content.speed_max, threads);
    if (content.overlaps)
        for (const OverlapMark& m : *content.overlaps)
            g.quads.push_back(circle_quad(l, m.x, m.y, std::max(0.35 * m.radius, 2.0 / l.scale), palette::overlap,
                                          AtlasCell::disk));
    if (content.compare) add_outlines(g, l, *content.compare, threads);
    add_legend(g, l, content.speed_max);
    // Cut to the frame's width: a narrow frame (a strip panel) must not spill into the next.
    const auto fits = std::size_t(std::max(0.0f, (float(l.width) - 2 * l.hud_x) / float(glyph_advance * l.text_scale)));
    add_text(g, l.hud_x, l.hud_y, l.text_scale, content.hud.substr(0, fits), palette::text);
}

}  // namespace collide::view
