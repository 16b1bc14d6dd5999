// Collision times of the event-driven solver: pure functions of the relative position and
// velocity, no state. docs/event-driven.md derives every formula here.
//
// Every function returns the time *from now* until the event, or `never` (infinity) if the
// event does not happen. A result that round-off would place slightly in the past is
// returned as 0 ("happens now"): the solver then processes the event at the current time
// instead of moving a particle backwards (round-off rule 1 in docs/event-driven.md).
#pragma once

#include <cmath>
#include <limits>

namespace collide::event_time {

inline constexpr double never = std::numeric_limits<double>::infinity();

// Pair collision time of two disks in free flight (no relative acceleration).
//   d = x_i - x_j (minimum image), u = v_i - v_j, sigma = r_i + r_j.
// Contact means |d + u t| = sigma, i.e. the quadratic
//   (u.u) t^2 + 2 (d.u) t + (d.d - sigma^2) = 0.
// With b = d.u, c = d.d - sigma^2 and the discriminant D = b^2 - (u.u) c, the earlier root is
//   t = (-b - sqrt(D)) / (u.u) = c / (-b + sqrt(D)),
// and the second form is used: for an approaching pair b < 0, so -b + sqrt(D) adds two
// non-negative numbers and has no cancellation (the first form loses all digits when the
// pair is nearly touching, c -> 0). Only approaching pairs (b < 0) can collide.
// Touching (c = 0) or slightly overlapping (c < 0, round-off) approaching pairs collide now.
//
// The quadratic's coefficients and the tests are kept apart from the time, so that the tuned
// solver can run the tests over many neighbours at once and take the square root and the
// division only for the pairs that collide (reference/event/pair_batch.h); these functions are
// the one source of the arithmetic for both.
struct PairQuadratic {
    double b;             // d.u
    double c;             // d.d - sigma^2
    double discriminant;  // b^2 - (u.u) c
};
inline PairQuadratic pair_quadratic(double dx, double dy, double ux, double uy, double sigma) {
    const double b = dx * ux + dy * uy;
    const double c = dx * dx + dy * dy - sigma * sigma;
    const double uu = ux * ux + uy * uy;
    return {b, c, b * b - uu * c};
}
// Whether the pair collides: approaching (b < 0, which a NaN is not), and either touching or
// overlapping by round-off (c <= 0) or on paths that meet (D > 0; D = 0 is a graze, zero
// impulse). Written with & and | instead of && and ||, so that it needs no branch; a NaN c or D
// counts as colliding, so that it reaches pair_meeting_time and gives a NaN time, which no
// comparison takes as the earliest.
inline bool pair_collides(const PairQuadratic& q) {
    return (q.b < 0) & ((q.c <= 0) | !(q.discriminant <= 0));
}
// The time of a pair that collides: now if it touches already, else the root above.
inline double pair_meeting_time(const PairQuadratic& q) {
    return q.c <= 0 ? 0.0 : q.c / (-q.b + std::sqrt(q.discriminant));
}
inline double pair_collision_time(double dx, double dy, double ux, double uy, double sigma) {
    const PairQuadratic q = pair_quadratic(dx, dy, ux, uy, sigma);
    return pair_collides(q) ? pair_meeting_time(q) : never;
}

// First time at which a coordinate q(t) = q0 + v t + a t^2 / 2 crosses the level q0 + d
// moving *upwards* (q'(t) > 0 at the crossing). Used for cell borders and walls, with or
// without gravity a. Requiring the direction of the crossing picks the right root of the
// quadratic a/2 t^2 + v t - d = 0: a disk that has just crossed a border upwards sits on it
// (d ~ 0) and must not "cross" it again at t ~ 0; its next upward crossing is a different one.
// With D = v^2 + 2 a d the upward root has q'(t) = +sqrt(D), so t = (sqrt(D) - v) / a,
// evaluated as 2 d / (v + sqrt(D)) when v >= 0 (no cancellation, and valid for a = 0).
inline double upward_crossing_time(double d, double v, double a) {
    if (a == 0) {
        // No acceleration (the common case): only a disk moving up crosses, at t = d / v. This
        // is the formula below with sqrt(v^2) = |v| (exact in floating point), without the
        // square root.
        if (!(v > 0)) return never;
        const double t = d / v;
        return t > 0 ? t : 0.0;
    }
    const double discriminant = v * v + 2 * a * d;
    if (discriminant < 0) return never;  // turns around below the level
    const double root = std::sqrt(discriminant);
    double t;
    if (v >= 0) {
        const double denominator = v + root;
        if (denominator == 0) return (a > 0 && d <= 0) ? 0.0 : never;  // at rest on the level
        t = 2 * d / denominator;
    } else {
        if (!(a > 0)) return never;  // moving down and not pulled up: never crosses upwards
        t = (root - v) / a;
    }
    return t > 0 ? t : 0.0;  // a level already passed (round-off): now
}

// First downward crossing of the level q0 + d: the mirror image of the upward crossing.
inline double downward_crossing_time(double d, double v, double a) {
    return upward_crossing_time(-d, -v, -a);
}

// Shell exit time of a disk in free flight (the neighbour-list design of Smallenburg, "Efficient
// event-driven simulations of hard spheres", Eur. Phys. J. E 45, 22 (2022)): the disk leaves
// the circle of radius delta around its shell centre when |d + v t| = delta, d = x - c, i.e.
//   (v.v) t^2 + 2 (d.v) t + (d.d - delta^2) = 0.
// The disk is inside (c = d.d - delta^2 <= 0), so the exit is the later root
//   t = (-b + sqrt(D)) / (v.v) = -c / (b + sqrt(D)),   b = d.v, D = b^2 - (v.v) c,
// the first form when b <= 0 and the second when b > 0 (each adds non-negative numbers: no
// cancellation). A disk on or outside the circle by round-off exits now; one at rest never.
inline double shell_exit_time(double dx, double dy, double vx, double vy, double delta) {
    const double vv = vx * vx + vy * vy;
    if (!(vv > 0)) return never;
    const double b = dx * vx + dy * vy;
    const double c = dx * dx + dy * dy - delta * delta;
    if (c >= 0) return 0;
    const double root = std::sqrt(b * b - vv * c);
    return b <= 0 ? (root - b) / vv : -c / (b + root);
}

}  // namespace collide::event_time
