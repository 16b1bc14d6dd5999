// The schedule of one time step dt of a scene's stepping rule (docs/stepping-rules.md, section 5),
// shared by every backend that implements the rules (step, cpu, opencl): either one
// collide-first step of length dt, or `substeps` integrate-first sub-steps of h = dt/substeps.
// Backends supply the two bodies; the order in which they are called lives only here.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/scene/scene.h"
#include "core/numerics/number_text.h"
#include "core/numerics/target_time.h"

namespace collide {

// The engine steps per scene time step dt of a game engine (box2d, chipmunk): its own
// `substeps` option where set, else the scene's run.substeps. Throws naming the engine and the
// scene unless dt > 0 and there is at least one.
inline int engine_substeps(const char* engine, const Scene& scene, std::optional<int> own) {
    const int substeps = own.value_or(scene.run.substeps);
    if (!(scene.run.dt > 0) || substeps < 1)
        throw std::runtime_error(std::string(engine) + ": scene '" + scene.name + "': needs dt > 0 and substeps >= 1 (dt = " +
                                 round_trip_text(scene.run.dt) + ", substeps = " + std::to_string(substeps) + ")");
    return substeps;
}

template <typename Real, typename CollideFirstStep, typename IntegrateFirstSubstep>
void step_by_rule(const RunSettings& run, CollideFirstStep&& collide_first_step,
                  IntegrateFirstSubstep&& integrate_first_substep) {
    if (run.order == StepOrder::collide_first) {
        collide_first_step(Real(run.dt));
        return;
    }
    const Real h = Real(run.dt / run.substeps);
    for (int k = 0; k < run.substeps; ++k) integrate_first_substep(h);
}

// The number of the time step nearest to absolute time t. Throws std::invalid_argument (the
// one target-time check, core/numerics/target_time.h) if t is not finite, needs more than max_steps
// steps, or rounds to a step before `current`: a solver never steps backwards.
inline std::int64_t target_step(const Scene& scene, double t, std::int64_t current, const char* backend) {
    check_target_time(backend, t, double(current) * scene.run.dt, scene.run.dt, true);
    return scene.steps_for(t);
}

}  // namespace collide
