// The frame loop of `collide view`: a window with keys, or headless (off-screen, a fixed number
// of frames, a screenshot at the end). Also the timed frame used by `collide bench view`.
#pragma once

#include <string>

#include "canvas.h"
#include "view_session.h"

namespace collide::view {

struct ViewOptions {
    int width = 1280, height = 720;
    bool headless = false;
    int frames = 0;              // stop after this many frames (0: until quit; headless needs > 0)
    std::string screenshot;      // PNG of the last frame ("" = none)
};

// Seconds one frame spent in each part.
struct FrameTimes {
    double simulation = 0;       // advance_to + read_state of the backend(s)
    double geometry = 0;         // metrics, overlap marks and the quads of the frame
    double draw = 0;             // the canvas's drawing of the quads, until the pixels are written
};

// Advances `session` by `output_steps` (0: redraw only) and draws the frame on `canvas`.
FrameTimes draw_frame(ViewSession& session, Canvas& canvas, Geometry& geometry, int output_steps,
                      const std::string& extra_hud);

void run_viewer(ViewSession& session, const ViewOptions& options);

}  // namespace collide::view
