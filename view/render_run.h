// `collide render`: the frames of a run file drawn with the viewer's drawing path into an
// animated GIF, an MP4 (where ffmpeg is installed) or a PNG strip of K frames side by side.
#pragma once

#include <functional>
#include <string>

namespace collide::view {

struct RenderOptions {
    std::string run;         // a run file written with --frames
    std::string out;         // .gif, .mp4 or .png (strip)
    std::string compare;     // optional reference run, drawn as outlines
    int frames = 0;          // frames to draw, evenly spaced (0: all for animations, 6 for a strip)
    int width = 640, height = 360;  // pixels of one frame
    double fps = 20;         // animations
    // Called after each frame is drawn with its time and the last frame's (a progress line).
    std::function<void(double, double)> on_frame;
};

void render_run(const RenderOptions& options);

}  // namespace collide::view
