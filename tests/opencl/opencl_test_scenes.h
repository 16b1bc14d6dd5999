// Scenes shared by the opencl tests: small, seeded, each exercising a set of kernel features.
#pragma once

#include <string>
#include <vector>

#include "core/backend_registry.h"
#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide::test {

struct OpenclCase {
    std::string name;
    Scene scene;
    ParticleState<double> initial;
};

// Reflecting gas (collide-first), periodic gas (collide-first), gravity + friction + damping
// with restitution below 1 (integrate-first, 4 sub-steps), and a polydisperse box with
// stones. Every case runs `steps` steps of its dt.
std::vector<OpenclCase> opencl_cases(int steps);

// The registered backend `name` (looked up in all_backends(), which also makes the static
// link pull in the registry ahead of core's find_backend).
const BackendInfo& backend(const std::string& name);

}  // namespace collide::test
