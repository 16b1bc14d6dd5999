// Comparisons of every backend with the reference backend (event): trajectory error on
// few-body scenes, statistical observables with replicate error bars on many-body scenes,
// and the work-precision data (run time against error over the dt / substeps sweep).
#pragma once

#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "validation/judge/applicability.h"
#include "validation/plan/suite.h"
#include "validation/record/case_result.h"
#include "validation/record/comparisons.h"
#include "validation/record/tolerances.h"

namespace collide::validation {

// `tolerances` maps a backend name to its tolerances and `declared` to what it declares (a
// stepping rule's statistics are held to the rule's predicted bias; an exact solver in double has
// its trajectory held to the rounding level of the reference's twins); `features` is parallel to
// suite.scenes.
Comparisons compare_with_reference(const Suite& suite, const std::vector<CaseResult>& results,
                                   const std::vector<SceneFeatures>& features,
                                   const std::map<std::string, Tolerances>& tolerances,
                                   const std::map<std::string, const BackendInfo*>& declared);
// The smallest radius of a snapshot's disks: trajectory errors are measured in it.
double smallest_radius(const Snapshot& s);

// The largest distance between a disk of `a` and the same disk of `b`, / r_min (NaN when the
// snapshots hold different numbers of disks or a position is not finite).
double snapshot_separation(const Snapshot& a, const Snapshot& b, double r_min);

// snapshot_separation at every common output time, in the reference's r_min; empty when the
// trajectories cannot be compared (not recorded, other output times).
std::vector<double> trajectory_error_series(const CaseResult& a, const CaseResult& reference);

// max over common output times and disks of the (minimum-image) distance between two
// trajectories, divided by the smallest radius; NaN when they cannot be compared.
double trajectory_error(const CaseResult& a, const CaseResult& reference, const Scene* scene = nullptr);

}  // namespace collide::validation
