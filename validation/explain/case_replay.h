// A case of a finished suite, rebuilt from its suite file: the scene exactly as the case ran it
// (the scene file, the sweep's parameters, the suite's overrides, the seed), its initial state
// (the phase replicate included) and its backend (a variant such as box2d[shipped] included).
// Every backend here is deterministic for a given thread count, so running the rebuilt case
// again retraces the run, step by step; `collide explain` uses this to look inside one step.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "validation/plan/case_plan.h"
#include "validation/record/case_result.h"
#include "core/backend_registry.h"
#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "core/scene/scene_overrides.h"

namespace collide::validation {

struct ReplayedCase {
    CaseSpec spec;
    Scene scene;                     // as the case ran it
    ParticleState<double> initial;
    BackendInfo backend;
    BackendOptions options;
};

// Throws std::runtime_error naming the suite file and the case id when the suite does not plan
// that case (another suite, an edited suite, a backend this build lacks) or left it out.
// `overrides` (`collide explain --set`) change the case's scene file as `collide run --set`
// does; a run setting they name (run.dt, ...) or the seed wins over the suite's own for the case.
// Such a case is a what-if: it no longer retraces the recorded run.
// `suite` is the loaded suite file (load_suite), read once by the caller.
ReplayedCase replay_case(const Suite& suite, const std::string& case_id, const std::vector<BackendInfo>& available,
                         const std::vector<SceneOverride>& overrides = {});

// Throws std::runtime_error, naming what differs, unless the rebuilt case ran with the run
// settings, disk count and initial state (bit for bit) that the case's record holds: a suite or
// scene file edited since the run would otherwise be replayed silently under the same id.
void require_same_start(const ReplayedCase& replay, const CaseResult& record);

// The kinetic energy the record holds at output time t (within 1e-9 dt), if it holds one.
std::optional<double> recorded_kinetic_energy(const CaseResult& record, double t);

}  // namespace collide::validation
