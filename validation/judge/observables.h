// Observables measured from a snapshot of the disks, the same way for every backend, so that
// the statistics of a many-body scene can be compared between a backend and the reference.
#pragma once

#include <vector>

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide::validation {

// Compressibility factor Z = P / (rho kT) of a monodisperse hard-disk fluid from the contact
// value of the pair distribution, Z = 1 + (pi/2) rho sigma^2 g(sigma+) (the 2D virial theorem
// for hard disks: Hansen & McDonald, "Theory of Simple Liquids", 4th ed., sec. 2.5; sigma =
// 2 r). g(sigma+) is estimated by counting pairs closer than sigma (1 + shell) and dividing by
// the ideal-gas count in that shell; pairs that overlap (stepped backends) count as in contact.
// The estimator's bias is O(shell) and the same for every backend, so a comparison between
// backends is fair; it is not a precision equation of state. Returns NaN for polydisperse
// states (no single sigma) or fewer than two disks.
// The shell fraction s of the contact-value estimator: pairs closer than sigma (1 + s) count.
inline constexpr double contact_shell = 0.05;
double compressibility_factor(const Scene& scene, const ParticleState<double>& state,
                              double shell = contact_shell);

// |v| of every mobile disk.
std::vector<double> speeds(const ParticleState<double>& state);

}  // namespace collide::validation
