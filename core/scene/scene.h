// Scene: everything that defines one simulation, as read from a scene file (see
// docs/scenes.md). A scene plus its seed determines the initial ParticleState exactly.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace collide {

// The most disks a scene may hold: the uniform grids index disks with 32-bit integers.
constexpr std::int64_t max_disk_count = 2147483647;  // 2^31 - 1

enum class Boundary { reflect, periodic };
enum class StepOrder { collide_first, integrate_first };

const char* to_string(Boundary b);
const char* to_string(StepOrder o);

struct World {
    double xmin = 0, ymin = 0, xmax = 1, ymax = 1;
    Boundary boundary = Boundary::reflect;
    double width() const { return xmax - xmin; }
    double height() const { return ymax - ymin; }
};

struct Physics {
    double restitution = 1.0;       // pair restitution e, 0 <= e <= 1
    double wall_restitution = 1.0;  // restitution at reflecting walls
    double friction = 0.0;          // Coulomb coefficient mu on the contact tangent
    double gravity_x = 0.0, gravity_y = 0.0;
    double damping = 0.0;           // linear drag rate gamma [1/time]: dv/dt = -gamma v
};

struct RunSettings {
    double duration = 1.0;
    double output_interval = 0.1;
    double dt = 1e-3;               // time step of the stepped backends
    int substeps = 1;               // sub-steps per dt (integrate-first rule)
    StepOrder order = StepOrder::collide_first;
    // The length of a sampler's run (sampling/: no time, no velocities): event chains (`ecmc`)
    // or sweeps of N trial moves (`metropolis`); 0: the default derived from `duration`
    // (docs/monte-carlo.md, "How long a sampler runs"). The output times still divide the run:
    // a sampler has done the fraction t / duration of its chains at output time t.
    std::int64_t chains = 0;
    std::int64_t sweeps = 0;
};

// The longest sampler run a scene may ask for (chains or sweeps).
constexpr std::int64_t max_sampler_length = 1'000'000'000'000'000;

// One generator block ([[particles]] in the file). Which fields matter depends on `kind`;
// docs/scenes.md lists them. The loader validates them; generators.cpp turns them into disks.
struct ParticleGenerator {
    std::string kind;  // "list", "gas", "lattice"

    // kind = "list": explicit disks
    struct Disk {
        double x, y, vx, vy, radius, mass;
        bool stone;
        int source_line = 0;  // line of the disk's inline table, for error messages
    };
    std::vector<Disk> disks;

    // kind = "gas" and "lattice": count and region (defaults to the whole box)
    std::int64_t count = 0;
    std::optional<std::array<double, 4>> region;  // xmin, ymin, xmax, ymax

    // radius: "fixed" (radius), "uniform" (radius_min..radius_max), "bidisperse"
    // (radius_small, radius_large, fraction_large)
    std::string radius_kind = "fixed";
    double radius = 0, radius_min = 0, radius_max = 0;
    double radius_small = 0, radius_large = 0, fraction_large = 0.5;

    // mass: fixed `mass`, or from an areal `density` (m = density * pi r^2)
    std::optional<double> mass, density;

    // velocity: "maxwell" (temperature kT), "fixed_speed" (speed, random direction), "zero"
    std::string velocity_kind = "zero";
    double temperature = 0, speed = 0;
    // Maxwell only (docs/scenes.md): `drift` "removed" subtracts the block's mass-weighted mean
    // velocity, "raw" keeps the draw; "" chooses by the box: removed where momentum is conserved
    // (periodic, no gravity), raw with walls. `exact_temperature` rescales the draw so that the
    // block's kinetic temperature is exactly kT.
    std::string drift;
    bool exact_temperature = false;

    // lattice: "hexagonal" or "square", spacing between neighbouring centres
    std::string lattice = "square";
    double spacing = 0;
    std::int64_t columns = 0;  // lattice columns (rows follow from count)
    // lattice: columns x rows fill the periodic box exactly, spacings from the box and no
    // `spacing` key (core/scene/filled_lattice.h)
    bool fill_box = false;

    bool stone = false;        // every disk of this block is a kinematic stone
    int source_line = 0;       // line in the scene file, for error messages

    double max_radius() const;  // the largest radius this block can produce
};

struct Scene {
    std::string name;          // file stem, e.g. "head_on_equal"
    std::string description;   // one line, shown by `collide scenes`
    std::string source_path;   // the file it was read from ("" if built in code)
    std::string source_text;   // the full file text, stored in every output for provenance
    std::string overrides;     // `--set` changes made to the file ("run.dt=0.001; ..."), else ""
    std::uint64_t seed = 1;

    World world;
    Physics physics;
    RunSettings run;
    std::vector<ParticleGenerator> generators;

    // Backend-specific settings, [backend.NAME] tables: name -> key -> value as text.
    // Each backend validates its own keys.
    std::map<std::string, std::map<std::string, std::string>> backend_options;
    // Where each of those values was set, for messages (core/scene/option_reader.h): "FILE:LINE" for a
    // scene file's key, "--set backend.NAME.KEY" for the command line's; absent for a value set
    // in code or by a Python keyword (whoever changes a value drops or replaces its origin).
    std::map<std::string, std::map<std::string, std::string>> backend_option_origins;

    bool has_gravity() const { return physics.gravity_x != 0 || physics.gravity_y != 0; }
    bool has_friction() const { return physics.friction != 0; }
    bool has_damping() const { return physics.damping != 0; }
    bool periodic() const { return world.boundary == Boundary::periodic; }

    // The largest radius any generator can produce (the grid cell size must be >= 2 r_max).
    double max_radius() const;

    // Number of stepped time steps that make up `t` (t is a multiple of dt by validation).
    std::int64_t steps_for(double t) const;
};

}  // namespace collide
