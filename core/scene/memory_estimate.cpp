#include "core/scene/memory_estimate.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/scene/scene_loader.h"

namespace collide {
namespace {

std::int64_t disks_in(const ParticleGenerator& g) {
    return g.kind == "list" ? std::int64_t(g.disks.size()) : g.count;
}

// Cells of side 2 r_max along each axis (at least one), as the grids lay them out.
double grid_cells(const Scene& scene) {
    const double side = 2 * scene.max_radius();
    if (!(side > 0)) return 1;
    const double along_x = std::max(1.0, std::floor(scene.world.width() / side));
    const double along_y = std::max(1.0, std::floor(scene.world.height() / side));
    return std::min(along_x * along_y, max_grid_cells);
}

std::string gibibytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
    return text;
}

}  // namespace

MemoryEstimate estimate_memory(const Scene& scene) {
    MemoryEstimate estimate;
    for (const ParticleGenerator& g : scene.generators) estimate.disks += disks_in(g);
    estimate.grid_cells = grid_cells(scene);
    return estimate;
}

double physical_memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page_size = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page_size <= 0) return std::numeric_limits<double>::infinity();
    return double(pages) * double(page_size);
}

void check_memory(const Scene& scene, double physical_bytes) {
    const MemoryEstimate whole = estimate_memory(scene);
    const double limit = max_memory_share * physical_bytes;
    if (whole.bytes() <= limit) return;
    // Name the block whose disks take the running total past the limit.
    MemoryEstimate so_far{0, whole.grid_cells};
    std::size_t block = 0;
    while (block + 1 < scene.generators.size()) {
        so_far.disks += disks_in(scene.generators[block]);
        if (so_far.bytes() > limit) break;
        ++block;
    }
    const ParticleGenerator& g = scene.generators[block];
    const std::string file = scene.source_path.empty() ? (scene.name.empty() ? "scene" : scene.name) : scene.source_path;
    throw SceneError(file + (g.source_line > 0 ? ":" + std::to_string(g.source_line) : std::string()) +
                     ": [[particles]][" + std::to_string(block + 1) + "] (" + g.kind + "): " +
                     std::to_string(disks_in(g)) + " disks (N = " + std::to_string(whole.disks) +
                     " in the scene) need about " + gibibytes(whole.bytes()) + " (" +
                     std::to_string(int(bytes_per_disk)) + " B per disk + " +
                     std::to_string(int(bytes_per_grid_cell)) + " B per grid cell x " +
                     std::to_string(std::int64_t(whole.grid_cells)) + " cells), more than " +
                     std::to_string(int(100 * max_memory_share)) + "% of this machine's " +
                     gibibytes(physical_bytes) + " of physical memory: expected at most about " +
                     std::to_string(std::int64_t(std::max(0.0, limit - whole.grid_cells * bytes_per_grid_cell) /
                                                 bytes_per_disk)) +
                     " disks in the scene on this machine");
}

}  // namespace collide
