// Rows of "Reference against physics" that hold a run to a pressure published at finite N: the
// pressure beta P d^2 (d the diameter) that Li et al. (2022) measured with event-chain Monte
// Carlo at N = 72 and 870, or Engel et al. (2013) at N = 256^2 ... 1024^2, at the same N, in the
// same box shape, at the same area fraction (data/references/li_2022.toml, engel_2013.toml).
// A suite's [[scene]] names its row, `published = "li_2022:N72_crystal_0.670"`; the row reads the
// pressure counters every finished case recorded (beta_pressure, beta_pressure_error, ...,
// psi6_mixed: docs/validation.md, "Published finite-N rows") and judges
//   z = |P - P_published| / sqrt(se^2 + se_published^2) <= 3   and   se / P <= 2e-4,
// unless a case's orientational order psi6 did not mix (then "not mixed": shown, not judged).
// The precision 2e-4 is what `event` is held to; a suite may hold another backend to its own
// (`[published_precision] ecmc = 5e-4`). Where the reference backend (`event`) and another
// backend ran the same published point, a row "routes_agree" holds the two pooled estimates
// to |z| <= 3 on their difference: three routes to one equilibrium (docs/monte-carlo.md).
#pragma once

#include <functional>
#include <vector>

#include "validation/compare/physics_rows.h"

namespace collide::validation {

// The largest relative standard error a judged row may have: the precision the published
// values are held to (issue 47; Li et al.'s errors at N = 72 are 6e-6 to 1e-4 relative).
inline constexpr double published_relative_error_max = 2e-4;

// One row per [[scene]] with a `published` key and per backend that ran it (finished cases only),
// then one "routes_agree" row per such row of a backend other than the suite's reference.
// Throws std::runtime_error naming the reference file when a `published` row cannot be read.
std::vector<PhysicsRow> published_finite_n_rows(const Suite& suite, const std::vector<CaseResult>& results,
                                                const std::function<const Scene&(const CaseSpec&)>& scene_of);

}  // namespace collide::validation
