// Changing keys of a scene file without editing it: `collide run SCENE --set run.dt=2.5e-4`
// (and `view`, `explain`, Python's Scene.with_overrides), and a suite's parameter sweeps
// (`set = { "run.dt" = [...] }`, validation/plan/scene_parameters.h). Both name a key by the same
// dotted path and go through the same code: the change is made in the scene's parsed TOML
// table, and the changed table is read again by the scene loader, so every rule a scene file
// obeys (known keys, types, ranges, disks inside the box) holds for the changed scene too, with
// the loader's own messages.
#pragma once

#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace collide {

// One `PATH=VALUE`. PATH names tables by key and array elements by index
// ("physics.restitution", "particles.0.disks.1.mass"). VALUE is a TOML value as it would stand
// in the file (2.5e-4, 3, true, "text", [0, 0, 20, 20], { maxwell = 2.0 }); a bare word that is
// no TOML value (periodic, integrate-first) is taken as a string, so no quotes are needed on a
// shell's command line.
struct SceneOverride {
    std::string path;
    std::string value;
    std::string text() const { return path + "=" + value; }
};

// "PATH=VALUE" -> SceneOverride; throws SceneError("--set TEXT: ...") without a '=' or a path.
SceneOverride parse_override(const std::string& text);

// The scene with each override applied in order. A key the scene file leaves out (at its
// default) is added, with the tables on its path; an array index must exist. Errors are
// SceneError: "--set PATH=VALUE: WHY" for a path that leads nowhere, and
// "--set PATH=VALUE: " + the loader's message for a key or value the file could not hold either
// (an unknown key, a negative mass, ...). The result's source_text is the changed scene file, so
// a run's provenance can repeat it; name and source_path stay those of `scene`.
Scene scene_with_overrides(const Scene& scene, const std::vector<SceneOverride>& overrides);

// "run.dt=0.00025; world.boundary=periodic" (empty without overrides): for provenance.
std::string overrides_text(const std::vector<SceneOverride>& overrides);

}  // namespace collide
