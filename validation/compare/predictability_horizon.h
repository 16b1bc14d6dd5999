// The predictability horizon of a trajectory comparison (docs/validation.md, "The
// predictability horizon").
//
// Two exact solvers in double precision do not follow one trajectory: each collision rounds
// the velocities of two disks differently, and in a chaotic scene (a few disks bouncing off
// each other and the walls: a dispersing billiard) a difference delta grows like
// delta * e^(lambda t), lambda the largest Lyapunov exponent. Past some time the reference
// itself no longer predicts the positions to the tolerance, and an error there says nothing
// about the solver under test.
//
// The horizon is measured, not assumed: the reference runs K twins of the case, each from the
// same initial state with every coordinate moved by +-eps*L (eps = 2^-52, L the box's size;
// run/twin_runs.h). Their largest separation from the reference, s(t) in units of the
// smallest radius (as trajectory_error measures), is how far rounding alone has carried the
// reference by time t. The horizon T_h is the last output time up to which s stays within the
// tolerance divided by a margin M (M = 1e3: an error the tolerance allows stays 1e3 times
// larger than what rounding alone has produced). trajectory_error is judged at the output
// times t <= T_h only; after T_h the case is judged by its conservation checks and statistics.
//
// Before T_h a solver that claims exact dynamics is held to more than the tolerance: to the
// rounding level the twins show, M * s(t) (never above the tolerance, since s <= tolerance / M
// there). A stepped solver keeps its tolerance.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "validation/record/trajectory_judgement.h"

namespace collide::validation {

constexpr int horizon_twins = 3;          // K: twins of each reference run
constexpr double horizon_margin = 1e3;    // M: the twins must stay within tolerance / M

// The horizon of one reference run: `times` its output times, `twin_separation` the twins'
// largest separation from it at those times [r_min]. A NaN separation (a twin that did not
// finish) counts as parted. Times and separation must be of equal length.
PredictabilityHorizon predictability_horizon(const std::vector<double>& times,
                                             const std::vector<double>& twin_separation, double tolerance,
                                             double margin = horizon_margin);

// The limit trajectory_error is held to at output k (k < horizon.judged): M * s(t_k) for a
// solver that claims exact dynamics, the tolerance for any other.
double trajectory_limit(bool exact, double tolerance, double twin_separation, double margin = horizon_margin);

// trajectory_error of one case judged up to its reference's horizon: `error` and
// `twin_separation` at the output `times` [r_min]. Without a measured twin separation (an empty
// one: a record written before twins were run) every output is judged with the tolerance.
TrajectoryJudgement judge_trajectory(const std::vector<double>& times, const std::vector<double>& error,
                                     const std::vector<double>& twin_separation, double tolerance, bool exact,
                                     double margin = horizon_margin);

// The sign (+1 or -1) of coordinate `coordinate` (0: x, 1: y) of disk `disk` in twin `twin`
// of the run with scene seed `seed`: a fixed hash (splitmix64), so a twin is the same on
// every machine and at every rerun.
int twin_sign(std::uint64_t seed, int twin, std::size_t disk, int coordinate);

}  // namespace collide::validation
