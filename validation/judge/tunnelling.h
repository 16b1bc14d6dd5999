// Tunnelling: two disks that pass through each other instead of colliding. Counted against
// the reference (event) run of the same scene, seed and parameters, at the output times both
// recorded (few-body scenes: trajectories are kept up to OutputOptions::max_trajectory_disks).
//
// For a pair (i, j) let u be the unit vector along x_j - x_i at t = 0, and s(t) the pair's
// separation projected on it, s(t) = (x_j(t) - x_i(t)) . u, so s(0) > 0. The pair tunnelled
// in the backend at output time t_k when
//   1. s changes sign between t_(k-1) and t_k in the backend (s_(k-1) > 0 >= s_k),
//   2. at the crossing, interpolated linearly between the two outputs, the separation
//      perpendicular to u is below the contact distance r_i + r_j: the disks' centres passed
//      closer than contact, so the disks went through each other (hard disks cannot), and
//   3. in the reference s(t_k) > 0: the exact dynamics has them still on their first sides.
// Condition 3 keeps out pairs that legitimately get past each other; condition 2 keeps out
// pairs that only passed beside each other. Each pair counts once. Reflecting boxes only: in a
// periodic box s jumps when a disk wraps, which is no crossing.
#pragma once

#include <cstddef>
#include <string>

#include "validation/record/case_result.h"

namespace collide::validation {

struct TunnellingCount {
    bool evaluated = false;
    std::string not_evaluated;  // why not, when not evaluated
    std::size_t pairs = 0;      // pairs that tunnelled
    std::string first;          // "disks 0 and 1 at t = 0.03" for the first one found
};

TunnellingCount count_tunnelling(const CaseResult& backend, const CaseResult& reference, bool periodic);

}  // namespace collide::validation
