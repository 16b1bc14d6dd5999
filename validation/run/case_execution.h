// Runs one case in the current process and measures it: warm-up, timed run through
// run_scene (the loop every consumer shares), metrics series, snapshots, observables, and
// the case's HDF5 file. Judging the measurements is left to checks.h.
#pragma once

#include <string>

#include "validation/plan/case_plan.h"
#include "validation/record/case_result.h"
#include "core/backend_registry.h"

namespace collide::validation {

struct CaseContext {
    const Suite* suite = nullptr;
    const Scene* scene = nullptr;         // the loaded scene (before the case's overrides)
    const BackendInfo* backend = nullptr;
    std::string output_dir;               // HDF5 file goes to <output_dir>/runs/<id>.h5
};

// The options a case's solver is created with (a swept `iterations` value).
BackendOptions case_backend_options(const CaseSpec& spec);

// The case's initial state: the scene's generated disks, for trajectory comparisons shifted to
// replicate `seed`'s collision phase (phase_shift.h), identically for the reference and every
// tested backend.
ParticleState<double> case_initial_state(const Scene& scene, const SuiteScene& entry, std::uint64_t seed);

// Never throws for a problem of the case itself (a solver exception or NaN becomes
// status = error with the message); throws only when the output cannot be written.
CaseResult execute_case(const CaseSpec& spec, const CaseContext& context);

}  // namespace collide::validation
