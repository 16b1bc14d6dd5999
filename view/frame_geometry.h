// The one frame description. A frame is a list of textured quads: the box, one quad per disk,
// a dot per overlapping pair, one outline per disk of the comparison state, the legend and every
// lit pixel of the HUD text. Each quad samples one cell of the atlas (a filled disk, a ring or a
// solid square) in its own colour. The canvas draws the list either in a single
// SDL_RenderGeometry call (a quad is 4 vertices where a smooth triangle fan is
// 17 or more) or with its CPU rasteriser (software renderers): the same quads, the same atlas.
#pragma once

#include <string>
#include <vector>

#include "atlas.h"
#include "color_map.h"
#include "core/particle_state.h"
#include "frame_layout.h"
#include "overlap_pairs.h"

namespace collide::view {

// What one frame shows. Pointers may be null (no comparison state).
struct FrameContent {
    const ParticleState<double>* state = nullptr;    // filled disks, coloured by speed
    const ParticleState<double>* compare = nullptr;  // outlines (e.g. the exact `event` solution)
    const std::vector<OverlapMark>* overlaps = nullptr;
    double speed_max = 1;  // the speed drawn in the top colour of the map
    std::string hud;       // the line of text on top
};

// An axis-aligned quad in pixels (x0 < x1, y0 < y1; y down) showing one atlas cell in a colour.
struct Quad {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    Rgb color;
    AtlasCell cell = AtlasCell::solid;
};

// The quads of a frame, drawn in order (later ones on top) over the page colour.
struct Geometry {
    std::vector<Quad> quads;
    void clear() { quads.clear(); }
};

// Builds the quads of `content` for `layout` into `out` (cleared first); the disks' quads on up
// to `threads` threads (<= 0: OpenMP's default).
void build_frame(const FrameContent& content, const FrameLayout& layout, Geometry& out, int threads = 0);

// The colour a disk of this speed gets (exposed for tests and the legend).
Rgb speed_color(double speed, double speed_max);

// A sensible top of the colour scale for a scene: the fastest disk of `initial`, or the speed of
// a fall through the box's height under gravity if that is larger (scenes that start at rest).
double default_speed_max(const Scene& scene, const ParticleState<double>& initial);

}  // namespace collide::view
