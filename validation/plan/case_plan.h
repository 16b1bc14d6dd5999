// The cases of a suite: every scene x backend x sweep point x replicate seed, each with a
// stable id (used for file names, --resume and the report). The reference backend (event)
// has no time step, so it runs once per scene, scene-parameter value and seed whatever the
// dt sweep.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "core/backend_registry.h"
#include "validation/plan/suite.h"
#include "validation/record/case_spec.h"

namespace collide::validation {

// The backends a suite asks for, found in `available` (`"all"` = every one of them, in order,
// then every variant of the suite whose base is available), variants made backends of their
// own (backend_variant.h). Throws SuiteError naming the suite file and the unknown backend.
std::vector<BackendInfo> select_backends(const Suite& suite, const std::vector<BackendInfo>& available);

// Every combination of the values of a scene's `set` sweeps ({{}} when it has none).
std::vector<std::vector<std::pair<std::string, double>>> parameter_points(const SuiteScene& entry);

// Expands a suite; `scenes` are the loaded scenes, parallel to suite.scenes.
std::vector<CaseSpec> plan_cases(const Suite& suite, const std::vector<Scene>& scenes,
                                 const std::vector<BackendInfo>& backends);

// "path=value" for each scene parameter of the case, joined by "__" ("" when none): part of
// the case id and the key that pairs a case with its reference run.
std::string parameter_label(const CaseSpec& spec);

// The scene as this case runs it: the case's seed, dt, substeps and the suite's overrides.
Scene case_scene(const Scene& scene, const SuiteScene& entry, const CaseSpec& spec);

}  // namespace collide::validation
