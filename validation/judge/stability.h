// Stability classification: what happened to one case, as one outcome, for the stability maps.
// The first outcome that applies wins, in this order (the most severe first):
//
//   crash              the process died or the solver threw (runner status crashed / error)
//   hang               killed after the suite's time limit (runner status timed_out)
//   nan                a position or velocity became NaN or Inf
//   stalled            the disks barely moved where the reference moved them: the median
//                      displacement from start to end is below 1/10 of the reference's
//                      (e.g. float coordinates so large that a step's motion rounds away)
//   tunnelling         a pair passed through each other where the reference has them apart
//                      (tunnelling.h; few-body scenes in reflecting boxes)
//   excessive_overlap  the largest relative overlap depth exceeded the backend's max_overlap
//   energy_growth      energy grew above its start by more than the backend's energy_drift
//                      tolerance x K(0), where physics lets it only fall or stay (e <= 1, wall
//                      e <= 1, no moving stones); total energy with gravity, else kinetic
//   stable             none of the above
//
// (left_out: the backend refused the scene; not classified.) Definitions in docs/stability.md.
#pragma once

#include <string>
#include <vector>

#include "validation/judge/applicability.h"
#include "validation/record/case_result.h"
#include "validation/record/tolerances.h"

namespace collide::validation {

enum class Outcome { stable, crash, hang, nan, stalled, tunnelling, excessive_overlap, energy_growth, left_out };
const char* to_string(Outcome o);

// The outcomes, the most severe first: the order above, which classify() applies (left_out last).
// summary.json's `outcome_order`: the report shows the most severe of a cell's cases by it.
inline constexpr Outcome outcome_precedence[] = {Outcome::crash, Outcome::hang, Outcome::nan, Outcome::stalled,
                                                 Outcome::tunnelling, Outcome::excessive_overlap,
                                                 Outcome::energy_growth, Outcome::stable, Outcome::left_out};

struct Classification {
    Outcome outcome = Outcome::stable;
    std::string reason;  // the measured value against its limit, or the runner's diagnostic
};

// `reference` is the reference backend's run of the same scene, parameters and seed (nullptr
// when there is none; tunnelling is then not evaluated).
Classification classify(const CaseResult& result, const CaseResult* reference, const SceneFeatures& features,
                        const Tolerances& tolerances);

// Median over the disks of the distance between their initial and final positions (a disk
// that wrapped around a periodic box counts as having moved across it). 0 without disks.
double median_displacement(const CaseResult& result);

// Largest rise of energy above its initial value divided by K(0) (by max K if K(0) = 0);
// `total` selects kinetic + potential. 0 when it never rises.
double energy_growth(const MetricSeries& series, bool total);

// A stability suite maps where methods break: a case that breaks is a finding, not a failed
// run. What is unexpected there: a case left unclassified, the reference backend (the exact
// solver) not finishing stably, or any crash (a process dying is a defect, not a stability
// limit). A hang of a stepped backend is a finding (too many steps for the time limit).
// Returns one line per unexpected case; empty: every case classified, nothing unexpected.
// `classifications` is parallel to `cases`.
std::vector<std::string> unexpected_outcomes(const std::vector<CaseResult>& cases,
                                             const std::vector<Classification>& classifications);

}  // namespace collide::validation
