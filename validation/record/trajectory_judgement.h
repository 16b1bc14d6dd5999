// The records of a trajectory comparison judged up to the predictability horizon: what the
// comparison hands the runner and the summary. How the horizon is measured and the error
// judged: compare/predictability_horizon.h (docs/validation.md, "The predictability horizon").
#pragma once

#include <cstddef>
#include <vector>

namespace collide::validation {

struct PredictabilityHorizon {
    double threshold = 0;     // tolerance / margin [r_min]
    std::size_t judged = 0;   // output times 0 .. judged-1 lie within the horizon
    bool reached = false;     // the twins crossed the threshold before the run ended
    // T_h: the last output time within the horizon (NaN when none is: judged == 0).
    double time = 0;
    // The first output time past the horizon (NaN when not reached).
    double first_unjudged = 0;

    // Whether an output time after the start lies within the horizon: a horizon shorter than
    // the first output interval judges nothing (at t = 0 every solver starts from one state).
    bool judges_anything(const std::vector<double>& times) const;
};

// A trajectory case's error judged up to its reference's horizon (judge_trajectory).
struct TrajectoryJudgement {
    PredictabilityHorizon horizon;
    bool exact = false;       // held to margin * twin separation (trajectory_limit)
    bool measured = true;     // the twin separation was measured
    std::vector<double> times, error, twin_separation;
    std::vector<double> limit;  // at each judged output (0 .. horizon.judged-1)
    std::size_t worst = 0;      // the judged output with the largest error / limit
    bool judged() const { return horizon.judges_anything(times); }
    bool passed() const;        // every judged output within its limit (NaN fails)
    double ratio() const;       // error / limit at `worst` (inf for an error above a zero limit)
};

// error / limit: NaN for a NaN error, infinity for an error above a zero limit, 0 for none.
double error_ratio(double error, double limit);

}  // namespace collide::validation
