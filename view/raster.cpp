#include "raster.h"

#include <algorithm>
#include <cmath>

#include "parallel_chunks.h"

namespace collide::view {
namespace {

// The pixels whose centres lie in [lo, hi) along one axis, clipped to [first, last).
struct Span {
    int begin = 0, end = 0;
};
Span covered_pixels(float lo, float hi, int first, int last) {
    return {std::max(first, int(std::ceil(lo - 0.5f))), std::min(last, int(std::ceil(hi - 0.5f)))};
}

// The atlas texel (along one axis, `texels` across) that the centre of pixel p samples in a quad
// spanning [lo, hi) on screen and [t0, t1) of the texture.
int texel_of(int p, float lo, float hi, float t0, float t1, int texels) {
    const float t = t0 + (float(p) + 0.5f - lo) / (hi - lo) * (t1 - t0);
    return std::clamp(int(t * float(texels)), 0, texels - 1);
}

// Source-over blending of colour c with alpha a onto pixel p (opaque destination).
void blend(std::uint8_t* p, Rgb c, unsigned a) {
    if (a == 0) return;
    if (a == 255) {
        p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 255;
        return;
    }
    auto mix = [a](unsigned src, unsigned dst) { return std::uint8_t((src * a + dst * (255 - a) + 127) / 255); };
    p[0] = mix(c.r, p[0]), p[1] = mix(c.g, p[1]), p[2] = mix(c.b, p[2]);
}

void fill_rows(const PixelTarget& t, Span rows, Span columns, Rgb c) {
    for (int y = rows.begin; y < rows.end; ++y) {
        std::uint8_t* p = t.pixels + std::ptrdiff_t(y) * t.pitch + std::ptrdiff_t(columns.begin) * 4;
        for (int x = columns.begin; x < columns.end; ++x, p += 4) p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 255;
    }
}

}  // namespace

Rasteriser::Rasteriser() : alpha_(atlas_alpha()) {}

void Rasteriser::draw(const Geometry& g, Rgb background, const PixelTarget& target, int threads) const {
    // One band of rows per thread: every band walks all quads, so more bands cost more walks.
    parallel_chunks(split_into(std::size_t(std::max(target.height, 0)), std::size_t(thread_count(threads))), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
        draw_band(g, background, target, int(begin), int(end));
    });
}

void Rasteriser::draw_band(const Geometry& g, Rgb background, const PixelTarget& target, int row_begin,
                           int row_end) const {
    clear_band(g, background, target, row_begin, row_end);
    for (const Quad& q : g.quads) draw_quad(q, target, row_begin, row_end);
}

// The background, except where the first quad is a solid one (the box) that will paint the
// pixels opaquely anyway: each pixel of the page and of the box is written once.
void Rasteriser::clear_band(const Geometry& g, Rgb background, const PixelTarget& target, int row_begin,
                            int row_end) const {
    Span skip_rows{row_begin, row_begin}, skip_columns{0, 0};
    if (!g.quads.empty() && g.quads.front().cell == AtlasCell::solid) {
        const Quad& first = g.quads.front();
        skip_rows = covered_pixels(first.y0, first.y1, row_begin, row_end);
        skip_columns = covered_pixels(first.x0, first.x1, 0, target.width);
    }
    for (int y = row_begin; y < row_end; ++y) {
        if (y < skip_rows.begin || y >= skip_rows.end || skip_columns.begin >= skip_columns.end) {
            fill_rows(target, {y, y + 1}, {0, target.width}, background);
            continue;
        }
        fill_rows(target, {y, y + 1}, {0, skip_columns.begin}, background);
        fill_rows(target, {y, y + 1}, {skip_columns.end, target.width}, background);
    }
}

void Rasteriser::draw_quad(const Quad& q, const PixelTarget& target, int row_begin, int row_end) const {
    const Span rows = covered_pixels(q.y0, q.y1, row_begin, row_end);
    if (rows.begin >= rows.end) return;
    const Span columns = covered_pixels(q.x0, q.x1, 0, target.width);
    if (columns.begin >= columns.end) return;
    if (q.cell == AtlasCell::solid) return fill_rows(target, rows, columns, q.color);  // opaque everywhere
    const CellUv uv = cell_uv(q.cell);
    for (int y = rows.begin; y < rows.end; ++y) {
        const std::uint8_t* alpha_row = alpha_.data() + std::size_t(texel_of(y, q.y0, q.y1, uv.v0, uv.v1, atlas_height)) * atlas_width;
        std::uint8_t* p = target.pixels + std::ptrdiff_t(y) * target.pitch + std::ptrdiff_t(columns.begin) * 4;
        for (int x = columns.begin; x < columns.end; ++x, p += 4)
            blend(p, q.color, alpha_row[texel_of(x, q.x0, q.x1, uv.u0, uv.u1, atlas_width)]);
    }
}

}  // namespace collide::view
