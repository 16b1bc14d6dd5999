// The stepped rules' first-order bias in the two many-body statistics that the validation
// suite compares with the exact solver: the contact-value pressure Z (observables.h) and the
// collision rate per disk. A stepped rule (docs/stepping-rules.md) finds a contact only at the
// first step that ends in overlap, so it is a different dynamics, not a noisy copy of the exact
// one: once enough replicates resolve its difference from `event`, a test of "equal means"
// must fail. The model below predicts that difference; the check compares the measured
// difference with the prediction (reference_comparison.cpp, docs/validation.md).
//
// Derivation (first order in the step h = dt / substeps). A pair crosses the contact distance
// sigma at a uniformly distributed time tau in [0, h) before the step that detects it. The
// rule then moves the pair back to exactly sigma and reverses its normal velocity, while the
// exact pair would already be tau |u_n| outside sigma: the stepped pair is delayed by tau, on
// average h/2, and spends that much extra time inside the estimator's shell
// sigma <= d < sigma (1 + s). With N nu / 2 pair collisions per time unit the shell holds
// N nu h / 4 extra pairs; divided by the ideal-gas count (N/2) rho pi sigma^2 ((1+s)^2 - 1)
// and multiplied by (pi/2) rho sigma^2 (the virial expression Z = 1 + (pi/2) rho sigma^2 g):
//
//     Z_step - Z_exact = c_Z * nu h / (4 s (2 + s)),           c_Z = 1 from the derivation.
//
// The same delay lengthens every disk's cycle between collisions from 1/nu to 1/nu + h/2, so
//
//     nu_step - nu_exact = -c_nu * nu^2 h / 2,                  c_nu = 1 from the derivation.
//
// nu is the exact collision rate (from the reference's replicates). c_Z and c_nu are fitted to
// step and cpu on both default gases (scripts/fit_statistics_bias.py); their uncertainties
// carry the fit's error, widened where the points scatter more than their error bars.
#pragma once

#include <string>
#include <vector>

namespace collide::validation {

// A predicted difference (backend - reference) with its one-standard-deviation uncertainty.
struct BiasPrediction {
    double value = 0;
    double uncertainty = 0;
};

// The fitted constants (docs/validation.md, "The stepped rules' bias in Z and the collision rate").
struct StatisticsBiasConstants {
    double pressure = 0, pressure_uncertainty = 0;      // c_Z
    double rate = 0, rate_uncertainty = 0;              // c_nu
};
const StatisticsBiasConstants& fitted_statistics_bias();

// Which backends are judged by this model: those that declare a stepping rule
// (BackendInfo::rule, and `rule` of an outside solver), read by the caller.

// Z_backend - Z_reference for a stepped rule of step h on a gas whose reference collision rate
// per disk is nu (standard error nu_se), for the contact estimator of shell fraction `shell`.
BiasPrediction predicted_pressure_bias(double nu, double nu_se, double h, double shell,
                                       const StatisticsBiasConstants& c = fitted_statistics_bias());

// nu_backend - nu_reference for the same rule and gas.
BiasPrediction predicted_collision_rate_bias(double nu, double nu_se, double h,
                                             const StatisticsBiasConstants& c = fitted_statistics_bias());

// The check: how many standard deviations the measured difference (standard error se_diff,
// both sides combined) lies from the prediction, |measured - predicted| / sqrt(se^2 + u^2).
// It passes at most `statistics_z` (4), as the plain z-check does for equal means.
double bias_z_score(double measured, double se_diff, const BiasPrediction& predicted);

}  // namespace collide::validation
