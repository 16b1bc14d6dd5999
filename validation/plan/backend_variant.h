// A backend variant as a backend: the registry entry of its base with a new name, whose
// solver and `supports` see every scene with the variant's settings written into the scene's
// [backend.BASE] table. The runner, the checks and the report then treat "box2d[shipped]"
// like any other backend: its own cases, result files, tolerances and report column.
#pragma once

#include <vector>

#include "validation/record/check_result.h"
#include "core/backend_registry.h"
#include "validation/plan/suite.h"

namespace collide::validation {

// The scene as the variant runs it: its settings over the scene's own [backend.BASE] keys.
Scene scene_for_variant(const Scene& scene, const BackendVariant& variant);

// `base` renamed to variant.label, running scenes through scene_for_variant().
BackendInfo variant_backend(const BackendInfo& base, const BackendVariant& variant);

// Marks every check that a variant's leave_out names as left out, with its leave_out_reason:
// e.g. statistics against the e = 1 hard-disk gas for a Box2D that makes slow collisions
// perfectly inelastic. The check's measured value stays in the record.
void apply_variant_leave_outs(std::vector<CheckResult>& checks, const std::vector<BackendVariant>& variants);

// The part of a case id (and so of file names) that names the backend: the label with its
// brackets, which shells and URLs treat specially, turned into "BASE-NAME" ("box2d-shipped").
std::string backend_id_token(const std::string& label);

}  // namespace collide::validation
