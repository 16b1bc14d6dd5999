// Where things go on a frame of any size: the HUD line on top, the speed legend on the right,
// and the scene's box in the rest, scaled by one factor on both axes (the aspect ratio of the
// box is kept whatever the window's shape) and centred. World y points up, pixel y down.
#pragma once

#include "core/scene/scene.h"

namespace collide::view {

struct PixelRect {
    float x = 0, y = 0, w = 0, h = 0;
};

struct FrameLayout {
    int width = 0, height = 0;  // pixels of the whole frame
    int text_scale = 1;         // screen pixels per font pixel
    World world;
    PixelRect box;              // the scene's box on screen
    PixelRect legend_bar;       // the colour bar (speed 0 at the bottom)
    float hud_x = 0, hud_y = 0; // top-left of the HUD line
    double scale = 1;           // pixels per world length unit

    float px(double x) const { return box.x + float((x - world.xmin) * scale); }
    float py(double y) const { return box.y + box.h - float((y - world.ymin) * scale); }
};

FrameLayout make_layout(const World& world, int width, int height);

}  // namespace collide::view
