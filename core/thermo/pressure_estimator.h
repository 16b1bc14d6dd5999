// The pressure of a hard-disk system from the collision virial, in the form that an ensemble
// with a fixed centre of mass (what Monte Carlo and event-chain Monte Carlo sample) gives, so
// that molecular dynamics and sampling are compared at finite N without a bias.
// docs/validation.md, "The equation of state at finite N", derives it.
//
// W = sum over collisions of sigma |Delta p| / (2 t): the collision virial per unit time
// (sigma the contact distance, Delta p the impulse). The mechanical pressure of the MD in its
// rest frame is P A = K_int + W. Divided by rho kT with kT = K_int / (N - 1) it is low by
// exactly one ideal-gas unit in beta P A; the sampler's pressure is
//     Z = beta P / rho = 1 + ((N - 1) / N) W / K_int
// (equal disks; in a walled box, where momentum is not conserved, the factor is 1 and
// K_int = K).
#pragma once

#include <cmath>

#include "core/thermo/kinetic_temperature.h"

namespace collide {

// Z = beta P / rho from the virial rate W and the temperature of the state (one definition:
// kinetic_temperature.h). degrees_of_freedom / moving_disks is (N - 1) / N or 1.
inline double compressibility_factor(double virial_rate, const KineticTemperature& t) {
    if (t.internal_kinetic_energy <= 0 || t.moving_disks == 0) return std::nan("");
    return 1 + (t.degrees_of_freedom / double(t.moving_disks)) * virial_rate / t.internal_kinetic_energy;
}

// beta P d^2 with d the diameter (Li et al. 2022's beta P (2 sigma)^2, sigma their radius):
// Z rho d^2, rho = N / A the number density. The one unit of every published pressure row.
inline double beta_pressure_d2(double compressibility, std::size_t moving_disks, double area, double diameter) {
    return compressibility * double(moving_disks) / area * diameter * diameter;
}

}  // namespace collide
