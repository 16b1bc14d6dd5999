// The one test "are two centres closer than a distance?", written so that it cannot underflow
// or overflow. The usual dx^2 + dy^2 < R^2 fails at the ends of the range: with R = 2e-170,
// R^2 = 4e-340 lies below double's smallest subnormal (4.9e-324, IEEE 754) and rounds to 0, so
// two disks at the same centre would "not overlap"; with R = 1e200, R^2 overflows to infinity.
// Here the separation is first compared per axis (no arithmetic at all) and then divided by
// R: the scaled components are below 1, so their squares neither overflow nor lose anything
// that matters against 1. The scene reader, the generators, the event solver's initial check
// and the overlap metrics all use it, so every backend sees the same answer.
#pragma once

#include <cmath>

namespace collide {

// |(dx, dy)| < distance (distance > 0); false for NaN.
inline bool centres_closer_than(double dx, double dy, double distance) {
    const double ax = std::fabs(dx), ay = std::fabs(dy);
    if (!(ax < distance && ay < distance)) return false;  // the common case in a cell search
    const double sx = ax / distance, sy = ay / distance;
    return sx * sx + sy * sy < 1.0;
}

}  // namespace collide
