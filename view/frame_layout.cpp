#include "frame_layout.h"

#include <algorithm>

#include "bitmap_font.h"

namespace collide::view {

FrameLayout make_layout(const World& world, int width, int height) {
    FrameLayout l;
    l.width = width;
    l.height = height;
    l.world = world;
    // Font pixels double on frames wide enough for the whole HUD line at that size.
    l.text_scale = width >= 900 ? 2 : 1;
    const float margin = 6.0f * float(l.text_scale);
    const float hud_height = float(glyph_height * l.text_scale) + 2 * margin;
    const float legend_width = float(12 * glyph_advance * l.text_scale) + 3 * margin;
    l.hud_x = margin;
    l.hud_y = margin;

    const float area_w = std::max(1.0f, float(width) - legend_width - 2 * margin);
    const float area_h = std::max(1.0f, float(height) - hud_height - margin);
    l.scale = std::min(area_w / world.width(), area_h / world.height());
    l.box.w = float(world.width() * l.scale);
    l.box.h = float(world.height() * l.scale);
    l.box.x = margin + (area_w - l.box.w) / 2;
    l.box.y = hud_height + (area_h - l.box.h) / 2;

    l.legend_bar.x = float(width) - legend_width + margin;
    l.legend_bar.w = 3.0f * margin;
    l.legend_bar.y = hud_height + 2 * margin + float(glyph_height * l.text_scale);
    l.legend_bar.h = std::max(1.0f, float(height) - l.legend_bar.y - 3 * margin - float(glyph_height * l.text_scale));
    return l;
}

}  // namespace collide::view
