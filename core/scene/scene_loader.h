// Reading scene files (TOML, see docs/scenes.md) and turning them into initial states.
#pragma once

#include <stdexcept>
#include <string>

#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "core/numerics/target_time.h"  // max_steps: the cap on duration / dt

namespace collide {

// Thrown for any problem with a scene: the message names the file, the key, the line (when
// known) and what was expected, e.g.
//   scenes/gas.toml:12: [physics].restitution = 1.5: expected a number in [0, 1]
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

Scene load_scene(const std::string& path);

// Why the run settings break a scene rule (dt > 0; duration and output_interval whole
// multiples of dt, at most max_steps steps), as "KEY: expected ...", or "" when they do not.
// For settings changed after loading (a suite's overrides), which must obey the same rules.
std::string run_settings_problem(const RunSettings& run);
Scene parse_scene(const std::string& text, const std::string& source_name);

// Places the scene's disks (GSL mt19937 seeded with scene.seed, GSL distributions), so a
// seed gives the same state on every machine. Throws SceneError when the requested packing
// cannot be placed or explicit disks overlap or leave the box.
ParticleState<double> generate_initial_state(const Scene& scene);

}  // namespace collide
