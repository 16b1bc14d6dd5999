// Scene-parameter sweeps: a suite's `set = { "particles.0.disks.1.mass" = [1, 1e9] }` changes
// one key of the scene file per sweep point. The path is followed, and the changed table read
// again, by the same code as `collide run --set` (core/scene/scene_overrides.h), so every rule a scene
// file must obey (positive masses, disks inside the box, no overlaps) holds for every swept value
// too. Unlike --set, a sweep changes only a number that the scene file already holds.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/scene/scene.h"
#include "validation/plan/suite.h"

namespace collide::validation {

// The scene with each (path, value) applied to its source text. A path names tables by key and
// array elements by index ("particles.0.disks.1.mass"); the key must already exist and hold a
// number (an integer key takes only integral values). Throws SuiteError naming the scene file,
// the path and the part of it that does not exist; a scene rule the new value breaks is
// reported as SuiteError too, with the path and value in front of the scene's own message.
Scene scene_with_parameters(const Scene& scene, const std::vector<std::pair<std::string, double>>& parameters);

}  // namespace collide::validation
