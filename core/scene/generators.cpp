// Initial states from a scene's [[particles]] blocks (docs/scenes.md, "Generators").
//
// Reproducibility: all randomness comes from one GSL Mersenne Twister (gsl_rng_mt19937)
// seeded with the scene's seed, drawn through GSL functions whose algorithms are fixed
// (gsl_rng_uniform, gsl_ran_gaussian = Box-Muller in GSL's own code). The C++ <random>
// distributions are not used: their algorithms differ between standard libraries, so the
// same seed would give different states on different machines.
//
// Order of draws, block after block: all radii of the block, then all positions (random
// sequential addition), then all velocities. Changing this order changes every golden hash.
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/scene/disk_placement.h"
#include "core/scene/filled_lattice.h"
#include "core/scene/memory_estimate.h"
#include "core/scene/scene_loader.h"
#include "core/thermo/kinetic_temperature.h"

namespace collide {
namespace {

constexpr double pi = 3.14159265358979323846;

using Rng = std::unique_ptr<gsl_rng, decltype(&gsl_rng_free)>;

struct Disk {
    double x = 0, y = 0, vx = 0, vy = 0, radius = 0, mass = 0;
};

// "FILE:LINE: [[particles]][k]: " for errors found while generating.
std::string block_location(const Scene& scene, const ParticleGenerator& g, std::size_t index) {
    std::ostringstream out;
    out << (scene.source_path.empty() ? (scene.name.empty() ? std::string("scene") : scene.name) : scene.source_path);
    if (g.source_line > 0) out << ':' << g.source_line;
    out << ": [[particles]][" << index + 1 << "] (" << g.kind << "): ";
    return out.str();
}

std::array<double, 4> region_of(const Scene& scene, const ParticleGenerator& g) {
    const World& w = scene.world;
    return g.region.value_or(std::array<double, 4>{w.xmin, w.ymin, w.xmax, w.ymax});
}

// Radii: fixed; uniform in [min, max]; or bidisperse with exactly round(f N) large disks,
// which come first (random sequential addition places large disks more easily first).
std::vector<double> draw_radii(const ParticleGenerator& g, gsl_rng* rng) {
    const auto n = std::size_t(g.count);
    if (g.radius_kind == "uniform") {
        std::vector<double> r(n);
        for (double& ri : r) ri = g.radius_min + (g.radius_max - g.radius_min) * gsl_rng_uniform(rng);
        return r;
    }
    if (g.radius_kind == "bidisperse") {
        const auto large = std::size_t(std::llround(g.fraction_large * double(n)));
        std::vector<double> r(n, g.radius_small);
        std::fill(r.begin(), r.begin() + std::ptrdiff_t(large), g.radius_large);
        return r;
    }
    return std::vector<double>(n, g.radius);
}

// Velocities. Maxwell-Boltzmann at temperature kT: in equilibrium each Cartesian component
// is Gaussian with variance kT/m (equipartition, 1/2 m <v_x^2> = 1/2 kT). Fixed speed: an
// angle uniform in [0, 2 pi).
void draw_raw_velocities(const ParticleGenerator& g, gsl_rng* rng, std::vector<Disk>& disks) {
    for (Disk& d : disks) {
        if (g.velocity_kind == "maxwell") {
            const double sigma = std::sqrt(g.temperature / d.mass);
            d.vx = gsl_ran_gaussian(rng, sigma);
            d.vy = gsl_ran_gaussian(rng, sigma);
        } else if (g.velocity_kind == "fixed_speed") {
            const double angle = 2 * pi * gsl_rng_uniform(rng);
            d.vx = g.speed * std::cos(angle);
            d.vy = g.speed * std::sin(angle);
        }
    }
}

// The centre of mass of a periodic box moves freely and for ever: a Maxwell draw leaves it a
// velocity of order sqrt(kT / M), whose kinetic energy (about kT) no collision can share out,
// and which an estimator that reads kT from the whole kinetic energy would count as heat.
// Subtracting the mass-weighted mean velocity V = sum m v / sum m leaves the block no momentum.
void remove_drift(std::vector<Disk>& disks) {
    double px = 0, py = 0, m = 0;
    for (const Disk& d : disks) px += d.mass * d.vx, py += d.mass * d.vy, m += d.mass;
    for (Disk& d : disks) d.vx -= px / m, d.vy -= py / m;
}

// Scales every velocity by one factor so that the block's kinetic temperature is exactly kT:
// K / (N - 1) with the drift removed (N - 1 disks' worth of degrees of freedom in 2-D,
// core/thermo/kinetic_temperature.h), K / N otherwise.
void rescale_to_temperature(std::vector<Disk>& disks, double kT, bool drift_removed) {
    double k = 0;
    for (const Disk& d : disks) k += 0.5 * d.mass * (d.vx * d.vx + d.vy * d.vy);
    const double degrees = double(disks.size()) - (drift_removed ? 1 : 0);
    if (!(k > 0) || degrees <= 0) return;
    const double factor = std::sqrt(degrees * kT / k);
    for (Disk& d : disks) d.vx *= factor, d.vy *= factor;
}

// The velocities of a block: the raw draw, then, for a Maxwell block, the drift removed (by
// default where momentum is conserved: a periodic box without gravity) and the temperature made
// exact where the scene asks (docs/scenes.md, `velocity`).
void draw_velocities(const Scene& scene, const ParticleGenerator& g, gsl_rng* rng, std::vector<Disk>& disks) {
    draw_raw_velocities(g, rng, disks);
    if (g.velocity_kind != "maxwell" || disks.empty() || g.stone) return;
    const bool remove = g.drift.empty() ? momentum_conserved(scene) : g.drift == "removed";
    if (remove) remove_drift(disks);
    if (g.exact_temperature) rescale_to_temperature(disks, g.temperature, remove);
}

double mass_of(const Scene& scene, const ParticleGenerator& g, std::size_t index, double radius) {
    const double m = g.mass ? *g.mass : *g.density * pi * radius * radius;
    if (!(m > 0) || !std::isfinite(m))  // density * pi r^2 can underflow to 0 or overflow
        throw SceneError(block_location(scene, g, index) + "mass " + std::to_string(m) +
                         " from density and radius: expected a finite mass > 0");
    return m;
}

// Why random sequential addition gave up, with what to do instead.
std::string jammed_message(const std::string& where, std::size_t placed, std::int64_t count, std::int64_t attempts,
                           double area_fraction) {
    std::ostringstream msg;
    msg << where << "placed only " << placed << " of " << count << " disks after " << attempts
        << " attempts: the requested area fraction in the region is " << area_fraction
        << ": expected fewer or smaller disks, a larger region, or a lattice generator for dense packings "
           "(random sequential addition jams near 0.547 in 2D and slows down well before)";
    return msg.str();
}

// RSA only gets slower as the region fills (the area where a new centre fits shrinks with
// every disk placed), so the attempts per placed disk over the last stretch estimate a lower
// bound on the cost of every disk still to come. Once that cost times the disks left exceeds the
// attempts left, the budget cannot suffice and spending it would only waste minutes. Not
// while a bidisperse block places its large disks: the small ones after them fit far more
// easily.
class AttemptBudget {
public:
    explicit AttemptBudget(std::int64_t count) : budget_(std::max<std::int64_t>(1000 * count, 1000000)) {}

    // Counts one attempt; false once the budget is spent or cannot suffice.
    bool attempt(std::size_t placed, std::size_t left, bool cost_only_grows) {
        ++attempts_;
        if (attempts_ > budget_) return false;
        if (attempts_ - checkpoint_attempts_ < stretch) return true;
        const double placed_in_stretch = double(std::max<std::size_t>(1, placed - checkpoint_placed_));
        const double attempts_per_disk = double(attempts_ - checkpoint_attempts_) / placed_in_stretch;
        checkpoint_attempts_ = attempts_;
        checkpoint_placed_ = placed;
        return !(cost_only_grows && attempts_per_disk * double(left) > double(budget_ - attempts_));
    }
    std::int64_t attempts() const { return attempts_; }

private:
    static constexpr std::int64_t stretch = 1 << 16;  // attempts between two estimates of the cost
    std::int64_t budget_, attempts_ = 0, checkpoint_attempts_ = 0;
    std::size_t checkpoint_placed_ = 0;
};

// The densest packing of equal disks, the hexagonal one (Thue; Fejes Toth 1940): no random
// placement comes anywhere near it, so a request beyond it is refused without an attempt.
constexpr double densest_packing = 0.9068996821171089;  // pi / sqrt(12)

// Random sequential addition (RSA; Feder, J. Theor. Biol. 87, 237 (1980)): propose a
// uniformly random centre, keep it if the disk overlaps nothing placed so far, else draw
// again. Centres keep the whole disk inside the region, except for a periodic world with
// no region, where any centre in the box is valid. RSA jams: in 2D no more disks fit once
// the area fraction nears 0.547, and it slows down long before. The attempt budget turns
// a hopeless request into an error instead of an endless loop.
std::vector<Disk> place_gas(const Scene& scene, const ParticleGenerator& g, std::size_t index, gsl_rng* rng,
                            DiskPlacement& placed, double earlier_area_in_region) {
    const std::vector<double> radii = draw_radii(g, rng);
    const auto region = region_of(scene, g);
    const bool wrap_whole_box = scene.periodic() && !g.region;
    const double region_area = (region[2] - region[0]) * (region[3] - region[1]);
    double requested_area = earlier_area_in_region;
    for (double r : radii) requested_area += pi * r * r;
    const double area_fraction = requested_area / region_area;
    const std::string where = block_location(scene, g, index);
    if (area_fraction > densest_packing) {
        std::ostringstream msg;
        msg << where << "the requested area fraction in the region is " << area_fraction
            << ", beyond pi/sqrt(12) = 0.9069 (the densest packing of equal disks): expected fewer or smaller "
               "disks or a larger region (random sequential addition jams near 0.547 in 2D)";
        throw SceneError(msg.str());
    }

    AttemptBudget budget(g.count);
    std::vector<Disk> disks;
    disks.reserve(radii.size());
    for (double r : radii) {
        const double margin = wrap_whole_box ? 0.0 : r;
        const double x0 = region[0] + margin, w = region[2] - region[0] - 2 * margin;
        const double y0 = region[1] + margin, h = region[3] - region[1] - 2 * margin;
        if (w < 0 || h < 0)
            throw SceneError(where + "a disk of radius " + std::to_string(r) + " does not fit in the region");
        const bool cost_only_grows = g.radius_kind != "bidisperse" || r == g.radius_small;
        for (;;) {
            if (!budget.attempt(disks.size(), radii.size() - disks.size(), cost_only_grows))
                throw SceneError(jammed_message(where, disks.size(), g.count, budget.attempts(), area_fraction));
            const double x = x0 + w * gsl_rng_uniform(rng);
            const double y = y0 + h * gsl_rng_uniform(rng);
            // gsl_rng_uniform lies in [0, 1), but x0 + w * u can still round up to xmax; a
            // periodic centre must stay in [xmin, xmax).
            if (wrap_whole_box && (x >= scene.world.xmax || y >= scene.world.ymax)) continue;
            if (placed.find_overlap(x, y, r) >= 0) continue;
            placed.insert(x, y, r);
            disks.push_back({x, y, 0, 0, r, mass_of(scene, g, index, r)});
            break;
        }
    }
    draw_velocities(scene, g, rng, disks);
    return disks;
}

// Lattice: `columns` disks per row, rows of `spacing`; a hexagonal lattice shifts every
// other row by spacing/2 and packs rows at spacing * sqrt(3)/2 (each disk then has six
// neighbours at distance `spacing`). The block of centres is centred in the region.
// A lattice that fills the periodic box (core/scene/filled_lattice.h; the loader has checked that
// its nearest distance holds two radii).
std::vector<Disk> fill_box_with_lattice(const Scene& scene, const ParticleGenerator& g, std::size_t index,
                                        DiskPlacement& placed) {
    const World& w = scene.world;
    const FilledLattice l = filled_lattice(w.width(), w.height(), g.columns, g.count / g.columns, g.lattice == "hexagonal");
    std::vector<Disk> disks;
    for (std::int64_t k = 0; k < g.count; ++k) {
        const double x = w.xmin + l.x(k), y = w.ymin + l.y(k);
        if (placed.find_overlap(x, y, g.radius) >= 0)
            throw SceneError(block_location(scene, g, index) + "lattice disk " + std::to_string(k + 1) +
                             " overlaps a disk placed before it: expected a radius of at most " +
                             std::to_string(l.nearest_distance() / 2) + " and no other block in the filled box");
        placed.insert(x, y, g.radius);
        disks.push_back({x, y, 0, 0, g.radius, mass_of(scene, g, index, g.radius)});
    }
    return disks;
}

std::vector<Disk> place_lattice(const Scene& scene, const ParticleGenerator& g, std::size_t index, gsl_rng* rng,
                                DiskPlacement& placed) {
    if (g.fill_box) {
        std::vector<Disk> disks = fill_box_with_lattice(scene, g, index, placed);
        draw_velocities(scene, g, rng, disks);
        return disks;
    }
    const bool hex = g.lattice == "hexagonal";
    const std::int64_t columns = std::min(g.columns, g.count);
    const std::int64_t rows = (g.count + columns - 1) / columns;
    const double dx = g.spacing, dy = hex ? g.spacing * std::sqrt(3.0) / 2 : g.spacing;
    const double shift = hex && rows > 1 ? dx / 2 : 0.0;
    const double span_x = double(columns - 1) * dx + shift, span_y = double(rows - 1) * dy;
    const auto region = region_of(scene, g);
    if (span_x + 2 * g.radius > region[2] - region[0] || span_y + 2 * g.radius > region[3] - region[1]) {
        std::ostringstream msg;
        msg << block_location(scene, g, index) << "a " << columns << " x " << rows << " " << g.lattice
            << " lattice with spacing " << g.spacing << " and radius " << g.radius << " needs "
            << span_x + 2 * g.radius << " x " << span_y + 2 * g.radius << " but the region is "
            << region[2] - region[0] << " x " << region[3] - region[1]
            << ": expected fewer columns or rows, a smaller spacing or a larger region";
        throw SceneError(msg.str());
    }
    const double x0 = 0.5 * (region[0] + region[2] - span_x), y0 = 0.5 * (region[1] + region[3] - span_y);
    std::vector<Disk> disks;
    for (std::int64_t k = 0; k < g.count; ++k) {
        const std::int64_t row = k / columns, column = k % columns;
        const double x = x0 + double(column) * dx + (hex && row % 2 == 1 ? shift : 0.0);
        const double y = y0 + double(row) * dy;
        if (placed.find_overlap(x, y, g.radius) >= 0)
            throw SceneError(block_location(scene, g, index) + "lattice disk " + std::to_string(k + 1) +
                             " overlaps a disk of an earlier [[particles]] block: expected non-overlapping blocks");
        placed.insert(x, y, g.radius);
        disks.push_back({x, y, 0, 0, g.radius, mass_of(scene, g, index, g.radius)});
    }
    draw_velocities(scene, g, rng, disks);
    return disks;
}

std::vector<Disk> place_list(const Scene& scene, const ParticleGenerator& g, std::size_t index,
                             DiskPlacement& placed) {
    std::vector<Disk> disks;
    for (std::size_t i = 0; i < g.disks.size(); ++i) {
        const auto& d = g.disks[i];
        if (placed.find_overlap(d.x, d.y, d.radius) >= 0)
            throw SceneError(block_location(scene, g, index) + "disk " + std::to_string(i + 1) +
                             " overlaps another disk: expected non-overlapping disks");
        placed.insert(d.x, d.y, d.radius);
        disks.push_back({d.x, d.y, d.vx, d.vy, d.radius, d.mass});
    }
    return disks;
}

double area_inside(const std::vector<Disk>& disks, const std::array<double, 4>& region) {
    double area = 0;
    for (const Disk& d : disks)
        if (d.x >= region[0] && d.x <= region[2] && d.y >= region[1] && d.y <= region[3])
            area += pi * d.radius * d.radius;
    return area;
}

}  // namespace

ParticleState<double> generate_initial_state(const Scene& scene) {
    std::size_t total = 0;
    for (const auto& g : scene.generators) total += g.kind == "list" ? g.disks.size() : std::size_t(g.count);
    if (total == 0) throw SceneError((scene.name.empty() ? "scene" : scene.name) + ": no disks: expected N >= 1");
    check_memory(scene);  // before the first allocation that grows with N

    Rng rng(gsl_rng_alloc(gsl_rng_mt19937), &gsl_rng_free);
    gsl_rng_set(rng.get(), static_cast<unsigned long>(scene.seed));
    DiskPlacement placed(scene.world, scene.max_radius(), total);

    ParticleState<double> state;
    std::vector<Disk> all;
    all.reserve(total);
    for (std::size_t b = 0; b < scene.generators.size(); ++b) {
        const ParticleGenerator& g = scene.generators[b];
        std::vector<Disk> disks;
        if (g.kind == "list") disks = place_list(scene, g, b, placed);
        else if (g.kind == "gas") disks = place_gas(scene, g, b, rng.get(), placed, area_inside(all, region_of(scene, g)));
        else if (g.kind == "lattice") disks = place_lattice(scene, g, b, rng.get(), placed);
        else throw SceneError(block_location(scene, g, b) + "unknown generator kind: expected list, gas or lattice");
        for (std::size_t i = 0; i < disks.size(); ++i) {
            const Disk& d = disks[i];
            const bool stone = g.kind == "list" ? g.disks[i].stone : g.stone;
            state.append_disk(d.x, d.y, d.vx, d.vy, d.radius, d.mass, stone);
        }
        all.insert(all.end(), disks.begin(), disks.end());
    }
    return state;
}

}  // namespace collide
