// The one drawing path. A frame is a list of textured quads: the box, one quad per disk, a dot
// per overlapping pair, one outline per disk of the comparison state, the legend and every lit
// pixel of the HUD text. All sample one small texture (the atlas: a filled disk, a ring and a
// solid square), so the whole frame is a single SDL_RenderGeometry call, as in ParticleBox; a
// textured quad costs 4 vertices where a smooth triangle fan costs 17 or more.
#pragma once

#include <SDL2/SDL.h>

#include <string>
#include <vector>

#include "color_map.h"
#include "core/particle_state.h"
#include "frame_layout.h"
#include "overlap_pairs.h"

namespace collide::view {

// The cells of the atlas texture, side by side, each atlas_cell pixels square.
enum class AtlasCell { disk = 0, ring = 1, solid = 2 };
inline constexpr int atlas_cell = 64;
inline constexpr int atlas_cells = 3;

// What one frame shows. Pointers may be null (no comparison state).
struct FrameContent {
    const ParticleState<double>* state = nullptr;    // filled disks, coloured by speed
    const ParticleState<double>* compare = nullptr;  // outlines (e.g. the exact `event` solution)
    const std::vector<OverlapMark>* overlaps = nullptr;
    double speed_max = 1;  // the speed drawn in the top colour of the map
    std::string hud;       // the line of text on top
};

struct Geometry {
    std::vector<SDL_Vertex> vertices;
    std::vector<int> indices;
    void clear() { vertices.clear(); indices.clear(); }
};

// Builds the quads of `content` for `layout` into `out` (cleared first).
void build_frame(const FrameContent& content, const FrameLayout& layout, Geometry& out);

// The colour a disk of this speed gets (exposed for tests and the legend).
Rgb speed_color(double speed, double speed_max);

// A sensible top of the colour scale for a scene: the fastest disk of `initial`, or the speed of
// a fall through the box's height under gravity if that is larger (scenes that start at rest).
double default_speed_max(const Scene& scene, const ParticleState<double>& initial);

}  // namespace collide::view
