// The scene-file reader: TOML text -> Scene, strictly (docs/scenes.md is the format's
// reference). Every value is checked where it is read, so each error can name the file,
// the line and the key; checks that need several values (disks inside the box, no
// overlaps, periodic box wide enough for the grid) run once the whole file is read.
#include "core/scene/scene_loader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/scene/backend_table.h"
#include "core/scene/disk_placement.h"
#include "core/scene/filled_lattice.h"
#include "core/io/input_file.h"
#include "core/scene/toml_fields.h"

namespace collide {
namespace {

World read_world(const TomlFields& world) {
    world.allow_only({"box", "boundary"});
    const std::vector<double> box = world.numbers("box", 4);
    world.require(box[2] > box[0] && box[3] > box[1] && std::isfinite(box[2] - box[0]) && std::isfinite(box[3] - box[1]),
                  "box", "[xmin, ymin, xmax, ymax] with xmax > xmin and ymax > ymin (and a finite size)");
    World w{box[0], box[1], box[2], box[3]};
    w.boundary = world.choice("boundary", {"reflect", "periodic"}, "reflect") == "periodic" ? Boundary::periodic
                                                                                          : Boundary::reflect;
    return w;
}

Physics read_physics(const TomlFields& physics) {
    physics.allow_only({"restitution", "wall_restitution", "friction", "gravity", "damping"});
    Physics p;
    p.restitution = physics.number("restitution", 1.0);
    physics.require(p.restitution >= 0 && p.restitution <= 1, "restitution", "a number in [0, 1]");
    p.wall_restitution = physics.number("wall_restitution", 1.0);
    physics.require(p.wall_restitution >= 0 && p.wall_restitution <= 1, "wall_restitution", "a number in [0, 1]");
    p.friction = physics.number("friction", 0.0);
    physics.require(p.friction >= 0, "friction", "a number >= 0 (Coulomb coefficient)");
    if (physics.has("gravity")) {
        const std::vector<double> g = physics.numbers("gravity", 2);
        p.gravity_x = g[0];
        p.gravity_y = g[1];
    }
    p.damping = physics.number("damping", 0.0);
    physics.require(p.damping >= 0, "damping", "a number >= 0 (drag rate, 1/time)");
    return p;
}

// Why `t` is not a whole number (>= 1, at most max_steps) of steps dt, or "" when it is; whole
// to a relative tolerance of 1e-9: decimal values such as 0.1 / 1e-3 are not exact in binary.
std::string steps_problem(double t, double dt) {
    if (std::string cap = steps_cap_problem(t, dt); !cap.empty()) return cap;  // advance_to's words too
    const double n = std::round(t / dt);
    if (n < 1 || std::fabs(t / dt - n) > 1e-9 * n)
        return "a whole multiple of dt = " + toml_value_text(toml::value(dt));
    return "";
}

RunSettings read_run(const TomlFields& run) {
    run.allow_only({"duration", "output_interval", "dt", "substeps", "order", "chains", "sweeps"});
    RunSettings r;
    r.dt = run.number("dt", r.dt);
    run.require(r.dt > 0, "dt", "a time step > 0");
    r.duration = run.number("duration", r.duration);
    run.require(r.duration > 0, "duration", "a time > 0");
    const std::string duration_problem = steps_problem(r.duration, r.dt);
    run.require(duration_problem.empty(), "duration", duration_problem);
    r.output_interval = run.number("output_interval", std::min(r.output_interval, r.duration));
    run.require(r.output_interval > 0 && r.output_interval <= r.duration, "output_interval", "a time in (0, duration]");
    const std::string interval_problem = steps_problem(r.output_interval, r.dt);
    run.require(interval_problem.empty(), "output_interval", interval_problem);
    const std::int64_t substeps = run.integer("substeps", 1);
    run.require(substeps >= 1 && substeps <= 1000000, "substeps", "an integer in [1, 1000000]");
    r.substeps = int(substeps);
    r.order = run.choice("order", {"collide-first", "integrate-first"}, "collide-first") == "integrate-first"
                  ? StepOrder::integrate_first
                  : StepOrder::collide_first;
    // A sampler's length (sampling/): event chains for `ecmc`, sweeps for `metropolis`; 0 takes
    // the default each sampler derives from the duration (docs/monte-carlo.md).
    r.chains = run.integer("chains", 0);
    run.require(r.chains >= 0 && r.chains <= max_sampler_length, "chains", "an integer in [0, 1e15] (0: from the duration)");
    r.sweeps = run.integer("sweeps", 0);
    run.require(r.sweeps >= 0 && r.sweeps <= max_sampler_length, "sweeps", "an integer in [0, 1e15] (0: from the duration)");
    return r;
}

// radius = 0.5 | { uniform = [min, max] } | { bidisperse = [small, large], fraction_large = f }
void read_radius(const TomlFields& block, ParticleGenerator& g, bool fixed_only) {
    const toml::node* n = block.node("radius");
    if (n && !n->is_table()) {
        g.radius = block.number("radius");
        block.require(g.radius > 0, "radius", "a radius > 0");
        return;
    }
    if (!n || fixed_only) block.fail("radius", fixed_only ? "a radius > 0" : "a radius > 0, { uniform = [min, max] } or { bidisperse = [small, large] }");
    const TomlFields r = block.table("radius");
    if (r.has("uniform")) {
        r.allow_only({"uniform"});
        const std::vector<double> range = r.numbers("uniform", 2);
        r.require(range[0] > 0 && range[1] > range[0], "uniform", "[min, max] with 0 < min < max");
        g.radius_kind = "uniform";
        g.radius_min = range[0];
        g.radius_max = range[1];
    } else if (r.has("bidisperse")) {
        r.allow_only({"bidisperse", "fraction_large"});
        const std::vector<double> radii = r.numbers("bidisperse", 2);
        r.require(radii[0] > 0 && radii[1] > radii[0], "bidisperse", "[small, large] with 0 < small < large");
        g.radius_kind = "bidisperse";
        g.radius_small = radii[0];
        g.radius_large = radii[1];
        g.fraction_large = r.number("fraction_large", 0.5);
        r.require(g.fraction_large >= 0 && g.fraction_large <= 1, "fraction_large", "a number in [0, 1]");
    } else {
        r.fail_here("expected { uniform = [min, max] } or { bidisperse = [small, large], fraction_large = f }");
    }
}

// mass = m (every disk) or density = rho (areal: m = rho * pi r^2), exactly one of them.
void read_mass(const TomlFields& block, ParticleGenerator& g) {
    if (block.has("mass") == block.has("density"))
        block.fail_here("expected exactly one of mass = m or density = rho (m = rho * pi r^2)");
    if (block.has("mass")) {
        g.mass = block.number("mass");
        block.require(*g.mass > 0, "mass", "a mass > 0");
    } else {
        g.density = block.number("density");
        block.require(*g.density > 0, "density", "an areal density > 0");
    }
}

// velocity = "zero" | { maxwell = kT [, drift = "removed" | "raw"] [, exact = bool] } | { speed = v };
// default "zero".
void read_velocity(const TomlFields& block, ParticleGenerator& g) {
    const toml::node* n = block.node("velocity");
    const char* expected = "\"zero\", { maxwell = kT } or { speed = v }";
    if (!n) return;
    if (n->is_string()) {
        if (n->as_string()->get() != "zero") block.fail("velocity", expected);
        return;
    }
    if (!n->is_table()) block.fail("velocity", expected);
    const TomlFields v = block.table("velocity");
    if (v.has("maxwell")) {
        v.allow_only({"maxwell", "drift", "exact"});
        g.velocity_kind = "maxwell";
        g.temperature = v.number("maxwell");
        v.require(g.temperature >= 0, "maxwell", "a temperature kT >= 0 (energy units)");
        if (v.has("drift")) g.drift = v.choice("drift", {"removed", "raw"}, "raw");
        g.exact_temperature = v.boolean("exact", false);
    } else if (v.has("speed")) {
        v.allow_only({"speed"});
        g.velocity_kind = "fixed_speed";
        g.speed = v.number("speed");
        v.require(g.speed >= 0, "speed", "a speed >= 0");
    } else {
        block.fail("velocity", expected);
    }
}

void read_region(const TomlFields& block, const World& world, ParticleGenerator& g) {
    if (!block.has("region")) return;
    const std::vector<double> r = block.numbers("region", 4);
    block.require(r[2] > r[0] && r[3] > r[1], "region", "[xmin, ymin, xmax, ymax] with xmax > xmin and ymax > ymin");
    block.require(r[0] >= world.xmin && r[1] >= world.ymin && r[2] <= world.xmax && r[3] <= world.ymax, "region",
                  "a rectangle inside the world box");
    g.region = std::array<double, 4>{r[0], r[1], r[2], r[3]};
}

const char* const count_range = "an integer in [1, 2^31 - 1] (the grids index disks with 32-bit integers)";

std::int64_t read_count(const TomlFields& block) {
    const std::int64_t count = block.integer("count");
    block.require(count >= 1 && count <= max_disk_count, "count", count_range);
    return count;
}

void read_list(const TomlFields& block, ParticleGenerator& g) {
    block.allow_only({"kind", "disks"});
    const toml::node* n = block.node("disks");
    if (!n || !n->is_array() || n->as_array()->empty()) block.fail("disks", "a non-empty array of { x, y, radius, mass, ... } tables");
    std::size_t index = 0;
    for (const toml::node& element : *n->as_array()) {
        const std::string name = block.key_name("disks") + "[" + std::to_string(++index) + "]";
        if (!element.is_table())
            throw SceneError(location(block.file(), int(element.source().begin.line)) + name +
                             ": expected an inline table { x = .., y = .., radius = .., mass = .. }");
        const TomlFields d(*element.as_table(), name, block.file());
        d.allow_only({"x", "y", "vx", "vy", "radius", "mass", "stone"});
        ParticleGenerator::Disk disk{d.number("x"), d.number("y"), d.number("vx", 0.0), d.number("vy", 0.0),
                                     d.number("radius"), d.number("mass"), d.boolean("stone", false), d.line()};
        d.require(disk.radius > 0, "radius", "a radius > 0");
        d.require(disk.mass > 0, "mass", "a mass > 0");
        g.disks.push_back(disk);
    }
}

void read_gas(const TomlFields& block, const World& world, ParticleGenerator& g) {
    block.allow_only({"kind", "count", "radius", "mass", "density", "velocity", "region", "stone"});
    g.count = read_count(block);
    read_radius(block, g, false);
    read_mass(block, g);
    read_velocity(block, g);
    read_region(block, world, g);
    g.stone = block.boolean("stone", false);
}

// `fill_box = true`: the lattice fills the periodic box (core/scene/filled_lattice.h), so the
// box sets the spacings and N must make whole rows; its nearest distance must hold two radii.
void read_filled_lattice(const TomlFields& block, const World& world, ParticleGenerator& g) {
    block.require(world.boundary == Boundary::periodic, "fill_box", "false unless the boundary is \"periodic\" (a lattice "
                                                                     "fills a box exactly only across periodic walls)");
    block.require(!block.has("spacing"), "spacing", "no spacing with fill_box = true (the box and columns set it)");
    block.require(!block.has("region"), "region", "no region with fill_box = true (the lattice fills the whole box)");
    block.require(g.count % g.columns == 0, "count", "a whole number of rows of `columns` disks with fill_box = true");
    const FilledLattice l = filled_lattice(world.width(), world.height(), g.columns, g.count / g.columns, g.lattice == "hexagonal");
    if (l.nearest_distance() < 2 * g.radius) {
        std::ostringstream msg;
        msg << "a radius of at most " << l.nearest_distance() / 2 << " (the " << g.columns << " x " << l.rows
            << " lattice that fills the box has neighbours " << l.nearest_distance() << " apart)";
        block.fail("radius", msg.str());
    }
}

void read_lattice(const TomlFields& block, const World& world, ParticleGenerator& g) {
    block.allow_only({"kind", "lattice", "count", "columns", "spacing", "radius", "mass", "density", "velocity",
                      "region", "stone", "fill_box"});
    g.lattice = block.choice("lattice", {"hexagonal", "square"}, "");
    g.count = read_count(block);
    g.columns = block.integer("columns");
    block.require(g.columns >= 1, "columns", "an integer >= 1");
    read_radius(block, g, true);
    g.fill_box = block.boolean("fill_box", false);
    if (g.fill_box) read_filled_lattice(block, world, g);
    else {
        g.spacing = block.number("spacing");
        block.require(g.spacing >= 2 * g.radius, "spacing", "a centre-to-centre distance >= 2 radius (disks must not overlap)");
    }
    read_mass(block, g);
    read_velocity(block, g);
    read_region(block, world, g);
    g.stone = block.boolean("stone", false);
}

ParticleGenerator read_particles(const TomlFields& block, const World& world) {
    ParticleGenerator g;
    g.kind = block.choice("kind", {"list", "gas", "lattice"}, "");
    g.source_line = block.line();
    if (g.kind == "list") read_list(block, g);
    else if (g.kind == "gas") read_gas(block, world, g);
    else read_lattice(block, world, g);
    return g;
}

// [backend.NAME] tables: plain values kept as text, with where each was set; each backend
// reads its own keys through core/scene/option_reader.h, which refuses unknown ones. A
// table for no backend (a typo) is refused here, as is what backend_key_problem refuses (any
// key under [backend.step]).
void read_backend_options(const TomlFields& root, Scene& scene) {
    const TomlFields backends = root.table("backend");
    backends.allow_only({"event", "step", "cpu", "opencl", "box2d", "chipmunk"});
    for (const auto& [name, node] : backends.raw()) {
        const TomlFields options = backends.table(name.str());
        for (const auto& [key, value] : options.raw()) {
            const std::string problem = backend_key_problem(name.str(), key.str());
            if (!problem.empty()) options.fail(key.str(), problem);
        }
        auto& out = scene.backend_options[std::string(name.str())];
        auto& origins = scene.backend_option_origins[std::string(name.str())];
        for (const auto& [key, value] : options.raw()) {
            const auto text = backend_value_text(value);
            if (!text) options.fail(key.str(), backend_value_expected);
            out[std::string(key.str())] = *text;
            // A node without a line was not read from the file: --set added it (scene_overrides.h).
            const auto line = value.source().begin.line;
            origins[std::string(key.str())] =
                line > 0 ? options.file() + ":" + std::to_string(line)
                         : "--set backend." + std::string(name.str()) + "." + shortened(key.str());
        }
    }
}

// Explicit disks: each inside the box (reflecting walls: the whole disk; periodic: the
// centre in [min, max)) and no two overlapping, also across different list blocks.
void check_explicit_disks(const Scene& scene, const std::string& file) {
    const World& w = scene.world;
    std::size_t total = 0;
    for (const auto& g : scene.generators) total += g.disks.size();
    DiskPlacement placed(w, scene.max_radius(), total);
    std::vector<std::string> names;
    for (std::size_t b = 0; b < scene.generators.size(); ++b) {
        const auto& disks = scene.generators[b].disks;
        for (std::size_t i = 0; i < disks.size(); ++i) {
            const auto& d = disks[i];
            const std::string name = "[[particles]][" + std::to_string(b + 1) + "].disks[" + std::to_string(i + 1) + "]";
            const bool inside = scene.periodic()
                                    ? d.x >= w.xmin && d.x < w.xmax && d.y >= w.ymin && d.y < w.ymax
                                    : d.x - d.radius >= w.xmin && d.x + d.radius <= w.xmax &&
                                          d.y - d.radius >= w.ymin && d.y + d.radius <= w.ymax;
            if (!inside)
                throw SceneError(location(file, d.source_line) + name + " at (" + toml_value_text(toml::value(d.x)) +
                                 ", " + toml_value_text(toml::value(d.y)) + ") with radius " +
                                 toml_value_text(toml::value(d.radius)) + ": expected a disk inside the world box" +
                                 (scene.periodic() ? " (periodic: centre in [min, max))" : ""));
            const std::int64_t other = placed.find_overlap(d.x, d.y, d.radius);
            if (other >= 0)
                throw SceneError(location(file, d.source_line) + name + " overlaps " + names[std::size_t(other)] +
                                 ": expected non-overlapping disks (distance >= r_i + r_j)");
            placed.insert(d.x, d.y, d.radius);
            names.push_back(name);
        }
    }
}

Scene read_scene(const toml::table& root_table, const std::string& file) {
    if (root_table.empty())
        throw SceneError(location(file, 0) + "no keys in the file: expected a scene with description, [world] and "
                                             "[[particles]] (docs/scenes.md)");
    const TomlFields root(root_table, "", file);
    root.allow_only({"description", "seed", "world", "physics", "run", "particles", "backend"});
    Scene scene;
    scene.description = root.string("description");
    root.require(!scene.description.empty() && scene.description.find('\n') == std::string::npos, "description",
                 "a non-empty one-line string");
    const std::int64_t seed = root.integer("seed", 1);
    // gsl_rng_mt19937 uses the low 32 bits of its seed: larger seeds would silently collide.
    root.require(seed >= 0 && seed <= 4294967295, "seed", "an integer in [0, 2^32 - 1]");
    scene.seed = std::uint64_t(seed);
    scene.world = read_world(root.table("world"));
    if (root.has("physics")) scene.physics = read_physics(root.table("physics"));
    if (root.has("run")) scene.run = read_run(root.table("run"));

    const toml::node* particles = root.node("particles");
    if (!particles || !particles->is_array_of_tables() || particles->as_array()->empty())
        root.fail("particles", "one or more [[particles]] tables");
    std::size_t index = 0;
    std::int64_t total = 0;
    for (const toml::node& block : *particles->as_array()) {
        const TomlFields fields(*block.as_table(), "[[particles]][" + std::to_string(++index) + "]", file);
        scene.generators.push_back(read_particles(fields, scene.world));
        const ParticleGenerator& g = scene.generators.back();
        total += g.kind == "list" ? std::int64_t(g.disks.size()) : g.count;
        // Each block is below the limit, so the sum cannot overflow before this test fails.
        if (total > max_disk_count)
            fields.fail("count", "at most 2^31 - 1 disks in all blocks together (the grids index disks with "
                                 "32-bit integers); with this block the scene holds " + std::to_string(total));
    }
    if (root.has("backend")) read_backend_options(root, scene);

    // The uniform grid needs at least 2 cells of side 2 r_max along a periodic axis, or a disk
    // could meet two images of the same neighbour.
    const double r_max = scene.max_radius();
    if (scene.periodic())
        root.table("world").require(scene.world.width() >= 4 * r_max && scene.world.height() >= 4 * r_max, "box",
                                    "a periodic box at least 2 x (2 r_max) = " + toml_value_text(toml::value(4 * r_max)) +
                                        " wide and high");
    check_explicit_disks(scene, file);
    return scene;
}

}  // namespace

Scene read_scene_table(const toml::table& root, const std::string& file) { return read_scene(root, file); }

Scene parse_scene(const std::string& text, const std::string& source_name) {
    check_toml_nesting(text, source_name);  // before toml++ recurses into a hostile file
    toml::table table;
    try {
        table = toml::parse(text, source_name);
    } catch (const toml::parse_error& e) {
        throw SceneError(location(source_name, int(e.source().begin.line)) + "malformed TOML: " +
                         std::string(e.description()));
    }
    Scene scene = read_scene(table, source_name);
    scene.name = std::filesystem::path(source_name).stem().string();
    scene.source_text = text;
    return scene;
}

// Scene files are small (generators make the large scenes); a limit keeps a huge or endless
// file (a device, a pipe) from being read into memory: reading stops once the limit is passed.
constexpr std::size_t max_scene_file_bytes = 64u << 20;

std::string run_settings_problem(const RunSettings& run) {
    if (!(run.dt > 0)) return "dt: expected a time step > 0";
    if (!(run.duration > 0)) return "duration: expected a time > 0";
    if (auto why = steps_problem(run.duration, run.dt); !why.empty()) return "duration: expected " + why;
    if (!(run.output_interval > 0 && run.output_interval <= run.duration))
        return "output_interval: expected a time in (0, duration]";
    if (auto why = steps_problem(run.output_interval, run.dt); !why.empty()) return "output_interval: expected " + why;
    return "";
}

Scene load_scene(const std::string& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw SceneError(path + ": is a directory: expected a scene file (TOML)");
    std::string text;
    try {  // the input guard: the system's cause, and no FIFO or device waited on (core/io/input_file.h)
        text = read_input_file(path, max_scene_file_bytes);
    } catch (const InputFileError& e) {
        throw SceneError(path + ": cannot open scene file: " + e.cause());
    }
    if (text.size() > max_scene_file_bytes)
        throw SceneError(path + ": more than 64 MiB: expected a scene file of at most 64 MiB (gas and lattice "
                                "generators describe large scenes in a few lines)");
    Scene scene = parse_scene(text, path);
    scene.source_path = path;
    return scene;
}

}  // namespace collide
