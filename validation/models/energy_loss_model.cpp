#include "validation/models/energy_loss_model.h"

#include <cmath>

namespace collide::validation {

namespace {

// Fitted with `step` by bench/energy_loss/fit.py over measure.toml (four replicates, T = 10):
// gas at area fractions 0.11, 0.31, 0.45 and dt 5e-4 .. 4e-3 (2368 multi-contact events);
// the hexagonal crystal (area fraction 0.82) at dt 2.5e-4 .. 2e-3 (88 events). In a crystal the
// neighbours that a disk rattles between sit on both sides of it, so two contacts in one step
// are twice as likely as in a gas of the same nu, and the disks are squeezed harder.
struct ModelParameters {
    double a, a_err;  // multi-contact disk-steps per disk per time unit / (nu^2 dt)
    double s, s_err;  // rms energy change per such disk-step / (K/N)
};
constexpr ModelParameters gas{0.277, 0.006, 1.50, 0.31};
constexpr ModelParameters crystal{0.562, 0.060, 3.53, 1.25};
constexpr double dense_area_fraction = 0.6;  // between the densest gas and the crystal fitted
constexpr double k_sigma = 4.5;              // 4 (1 - Phi(4.5)) = 1.4e-5 false alarms per check

}  // namespace

double enskog_collision_frequency(double area_fraction, double mean_radius, double mean_radius_squared,
                                  double kt_over_m) {
    const double phi = area_fraction;
    const double n = phi / (M_PI * mean_radius_squared);  // disks per unit area
    const double g = (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi));
    return 2 * (2 * mean_radius) * n * g * std::sqrt(M_PI * kt_over_m);
}

EnergyDriftPrediction stepped_energy_drift(double nu, double dt, double duration, double disks,
                                           double area_fraction) {
    const ModelParameters& p = area_fraction >= dense_area_fraction ? crystal : gas;
    // expected multi-contact disk-steps: none where no disk can have two partners
    const double events = disks < 3 ? 0.0 : p.a * nu * nu * dt * duration * disks;
    const double sigma = p.s * std::sqrt(events) / disks;
    // the model's own relative error (s and a enter as s sqrt(a))
    const double model_rel = std::hypot(p.s_err / p.s, 0.5 * p.a_err / p.a);
    EnergyDriftPrediction out;
    out.predicted = std::sqrt(M_PI / 2) * sigma;
    // spread of max|W| over [0, T]: sd ~ 0.51 sigma (a simulation of Gaussian walks)
    out.uncertainty = std::hypot(0.51 * sigma, out.predicted * model_rel);
    out.tolerance = k_sigma * sigma * (1 + model_rel);
    return out;
}

}  // namespace collide::validation
