// What defines a case: every input that decides what the case computes, in named parts, each
// kept as the SHA-256 of its text. The case record stores them ([spec.definition] and
// spec.definition_hash, case_result.h), and `collide validate --resume` keeps a finished case
// only when every part is what it was; otherwise the case runs again and the terminal says
// which parts changed ("3 cases rerun: scene file changed (2), duration changed (1)").
//
// The parts: the scene file (its text and any --set change; a scene built in code, its
// fields), the case itself (backend, seed, dt, substeps, iterations, swept values), the suite
// entry's settings that reach the case (duration, output_interval, frames, comparison, the
// physics rows it feeds), the suite's settings that reach every case (warm-up share, time
// limit, [output] options), the backend variant's settings, an outside solver's spec (every
// field, through the spec's own definition text) and the files its command names, and
// collide's build (version, commit, dirty flag, compiler and flags). What judges a case
// (tolerances, the reference backend) is not part of it: every case, kept or not, is judged
// again by the resumed run.
#pragma once

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "validation/plan/case_plan.h"
#include "validation/plan/suite.h"

namespace collide::validation {

// The definition of `spec` in `suite`; `scene` is the loaded scene of its entry (before the
// case's sweep values and the suite's overrides). `progress` (may be null) hears of any large
// solver file being hashed.
std::map<std::string, std::string> case_definition(const Suite& suite, const Scene& scene, const CaseSpec& spec,
                                                   std::FILE* progress = nullptr);


// The parts whose hash differs between a record and now, in order (a part only one of them
// has counts as changed).
std::vector<std::string> changed_parts(const std::map<std::string, std::string>& recorded,
                                       const std::map<std::string, std::string>& now);

}  // namespace collide::validation
