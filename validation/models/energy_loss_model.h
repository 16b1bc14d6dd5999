// The kinetic-energy drift the stepped rules are expected to show at e = 1, from the rule
// itself (docs/stepping-rules.md, "Energy at e = 1"; fit: bench/energy_loss/).
//
// An isolated pair conserves kinetic energy exactly at e = 1. A disk that receives two or more
// impulses computed from one Jacobi snapshot does not: its energy changes by an amount of
// either sign, of the order of a disk's own kinetic energy (rms s K/N). Such multi-contact
// disk-steps occur at a rate a nu^2 dt per disk per time unit (nu: collisions per disk per time
// unit; the chance that a second collision of the same disk falls in the same step is ~ nu dt).
// Over a duration T the kinetic energy therefore makes a random walk of M = a nu^2 dt T N steps
// of rms size s K/N, so the relative drift has the scale
//     sigma = s sqrt(a nu^2 dt T N) / N,
// and max_t |K(t) - K(0)| / K has mean sqrt(pi/2) sigma (Brownian motion, reflection principle)
// and exceeds k sigma with probability at most 4 (1 - Phi(k)).
#pragma once

namespace collide::validation {

struct EnergyDriftPrediction {
    double predicted = 0;     // expected max_t |K(t) - K(0)| / max K
    double uncertainty = 0;   // one standard deviation: the random walk's spread and the model's
    double tolerance = 0;     // the bound a correct rule exceeds with probability < 1e-5
};

// Collisions per disk per time unit of a hard-disk gas in equilibrium (Enskog): a disk meets
// the centres of others within its contact distance sigma, a strip of width 2 sigma, at the mean
// relative speed sqrt(pi kT / m) (2D Maxwell distribution), enhanced by the contact value of
// the pair correlation g(sigma) = (1 - 7 phi / 16) / (1 - phi)^2 (Henderson, Mol. Phys. 30, 971
// (1975)): nu = 2 sigma n g sqrt(pi kT / m). It depends only on the scene, not on the run, so a
// defect that heats the gas cannot widen its own bound. Polydisperse: sigma = 2 <r>, approximate.
double enskog_collision_frequency(double area_fraction, double mean_radius, double mean_radius_squared,
                                  double kt_over_m);

// nu: collisions per disk per time unit (measured on the case), dt: step, duration: T,
// disks: N, area_fraction: of the disks in the box (above 0.6 the crystal fit applies).
// With fewer than three disks no disk has two partners, so there is no multi-contact step and
// the prediction and its tolerance are 0: rounding alone moves the energy there (the caller's
// floor, exact_limits.h: conservation_rounding).
EnergyDriftPrediction stepped_energy_drift(double nu, double dt, double duration, double disks,
                                           double area_fraction);

}  // namespace collide::validation
