// Runs one case in the current process and measures it: warm-up, timed run through
// run_scene (the loop every consumer shares), metrics series, snapshots, observables, and
// the case's HDF5 file. Judging the measurements is left to checks.h.
#pragma once

#include <string>

#include "case_result.h"
#include "core/backend_registry.h"

namespace collide::validation {

struct CaseContext {
    const Suite* suite = nullptr;
    const Scene* scene = nullptr;         // the loaded scene (before the case's overrides)
    const BackendInfo* backend = nullptr;
    std::string output_dir;               // HDF5 file goes to <output_dir>/runs/<id>.h5
};

// Never throws for a problem of the case itself (a solver exception or NaN becomes
// status = error with the message); throws only when the output cannot be written.
CaseResult execute_case(const CaseSpec& spec, const CaseContext& context);

}  // namespace collide::validation
