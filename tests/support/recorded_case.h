// A solver run recorded as the validation runner records a case, in process: the solver runs
// the scene it is `given`, while the record (duration, dt, initial state) is that of the scene
// the suite `declared`, so that a defect injected through the given scene is judged against the
// declared one.
#pragma once

#include <string>

#include "core/run_driver.h"
#include "core/scene/scene_loader.h"
#include "validation/record/case_result.h"

namespace collide::test {

inline validation::CaseResult recorded_case(Solver& solver, const Scene& declared, const Scene& given,
                                            const std::string& id, const std::string& backend) {
    const ParticleState<double> initial = generate_initial_state(declared);
    validation::CaseResult r;
    RunOptions options;
    options.on_state = [&](const ParticleState<double>&, const Metrics& m) { r.series.push_back(m); };
    const RunResult run = run_scene(given, solver, initial, options);
    r.spec.id = id;
    r.spec.backend = backend;
    r.disks = initial.size();
    r.duration = declared.run.duration;
    r.dt = declared.run.dt;
    r.contacts = run.stats.contacts;
    for (double w : initial.inv_mass) r.total_mass += 1 / w;
    r.initial.radius = initial.radius;
    return r;
}

}  // namespace collide::test
