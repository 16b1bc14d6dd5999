// The schedule of one time step dt of a scene's stepping rule (docs/stepping-rules.md, section 5),
// shared by every backend that implements the rules (step, cpu, opencl): either one
// collide-first step of length dt, or `substeps` integrate-first sub-steps of h = dt/substeps.
// Backends supply the two bodies; the order in which they are called lives only here.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/scene.h"

namespace collide {

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

// The number of the time step that ends at absolute time t (a whole number of steps, by scene
// validation). Throws if it lies before `current`: a solver never steps backwards.
inline std::int64_t target_step(const Scene& scene, double t, std::int64_t current, const char* backend) {
    const std::int64_t target = scene.steps_for(t);
    if (target < current)
        throw std::invalid_argument(std::string(backend) + ": advance_to(" + std::to_string(t) + ") is in the past");
    return target;
}

}  // namespace collide
