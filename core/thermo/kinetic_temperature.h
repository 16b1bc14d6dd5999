// The kinetic temperature of a state, defined once for every estimator of collide (the
// equation of state, the collision rate against Enskog, Haff's law, the speed distribution,
// the pressure `collide run` records). docs/validation.md, "Temperature and degrees of
// freedom", derives it.
//
//  - Periodic box (total momentum conserved): the centre of mass moves freely and carries no
//    heat. The heat is the kinetic energy in the centre-of-mass frame,
//        K_int = K - |P|^2 / (2 M),   P = sum m v,  M = sum m,
//    shared by N - 1 disks' worth of degrees of freedom (2 per disk in 2-D, minus the 2 of
//    the centre of mass), so kT = K_int / (N - 1).
//  - Reflecting walls (momentum not conserved): the whole kinetic energy over N, kT = K / N.
// Stones (kinematic disks, inverse mass 0) are left out of every sum and of N.
#pragma once

#include <cstddef>

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide {

struct KineticTemperature {
    double kinetic_energy = 0;           // K: sum m |v|^2 / 2 over moving disks
    double internal_kinetic_energy = 0;  // K_int: K in the centre-of-mass frame (periodic), else K
    std::size_t moving_disks = 0;        // N: disks that are not stones
    double degrees_of_freedom = 0;       // per two dimensions: N - 1 (periodic) or N (walls)
    double kT() const { return degrees_of_freedom > 0 ? internal_kinetic_energy / degrees_of_freedom : 0; }
};

KineticTemperature kinetic_temperature(const Scene& scene, const ParticleState<double>& state);

// The same definition from the totals alone (for the records of a run: K, P and M of its
// moving disks). momentum_conserved: a periodic box without gravity.
KineticTemperature kinetic_temperature(double kinetic_energy, double momentum_x, double momentum_y,
                                       double total_mass, std::size_t moving_disks, bool momentum_conserved);

// True where the centre of mass is free and the N - 1 definition applies.
bool momentum_conserved(const Scene& scene);

}  // namespace collide
