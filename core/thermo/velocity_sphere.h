// The relative velocity of a pair at finite N, on the velocity sphere. docs/validation.md,
// "Temperature and degrees of freedom", derives both statements.
//
// With the energy fixed (and, in a periodic box, the total momentum fixed at 0), the velocities
// of N equal disks lie uniformly on a sphere of dimension D = 2 f (f = N - 1 periodic, N with
// walls: KineticTemperature::degrees_of_freedom), independently of the positions: hard disks
// have no potential energy, so the microcanonical measure is (uniform over allowed
// configurations) x (uniform on the sphere). The component w of a pair's relative velocity
// along any unit vector is a one-dimensional projection of that sphere. Its second moment is
// exactly the Maxwell-Boltzmann value at kT = K_int / f,
//     <w^2> = 2 kT / m,
// so estimators that sum momentum transfer (the collision virial) need no factor beyond the
// definition of kT. Its first moment, which sets how often pairs collide, is not: relative to
// the Gaussian of the same variance,
//     <|w|> / <|w|>_Gauss = Gamma(f) sqrt(f) / Gamma(f + 1/2) = 1 + 1/(8 f) + O(1/f^2),
// 1.128 at f = 1 (two disks: a Sinai billiard at fixed speed), 1.0017 at f = 71.
#pragma once

#include <cmath>

namespace collide {

// The finite-N factor on a collision rate predicted with a Maxwell-Boltzmann (Gaussian)
// relative velocity at kT = K_int / f (Enskog's rate): Gamma(f) sqrt(f) / Gamma(f + 1/2).
inline double collision_rate_finite_n_factor(double degrees_of_freedom) {
    const double f = degrees_of_freedom;
    if (!(f > 0)) return std::nan("");
    return std::exp(std::lgamma(f) - std::lgamma(f + 0.5)) * std::sqrt(f);
}

}  // namespace collide
