// The mean of a correlated, stationary time series and its standard error, with the
// correlation time measured and the equilibration cut chosen from the data. Every recorded
// pressure (`event`'s collision virial, a sampler's lifts) goes through here, so that error
// bars mean the same thing for every backend. docs/validation.md, "Error bars", explains it.
//
//  - Integrated autocorrelation time tau_int = 1/2 + sum_{k>=1} rho(k), summed up to Sokal's
//    self-consistent window M >= 5 tau_int (A. D. Sokal, "Monte Carlo methods in statistical
//    mechanics", Cargese lectures 1996, sec. 3); in units of one series entry. The statistical
//    inefficiency is g = 2 tau_int (at least 1).
//  - Equilibration cut: the start t0, among the first half of the series in steps of 1/20 of
//    it, that maximises the number of effectively independent samples (n - t0) / g(t0)
//    (J. D. Chodera, J. Chem. Theory Comput. 12, 1799 (2016)). A series still drifting has a
//    large g until the drift is cut away.
//  - Error: batch means over what is left, in `batches` equal batches (the batch length at
//    least several tau_int where the series allows); the error of the mean is the standard
//    deviation of the batch means over sqrt(batches).
#pragma once

#include <cstddef>
#include <vector>

namespace collide {

// One candidate start of the stationary part: the entries cut, and the effectively independent
// samples (n - cut) / max(1, 2 tau_int) of what is left. The cut is the candidate with the most.
struct CutCandidate {
    std::size_t cut = 0;
    double effective_samples = 0;
};

struct SeriesEstimate {
    double mean = 0;
    double error = 0;                    // standard error of the mean, by batch means
    double autocorrelation_time = 0;     // tau_int, in series entries
    std::size_t equilibration_cut = 0;   // entries left out at the start
    std::size_t batches = 0;             // batch means used for the error
    std::size_t used = 0;                // entries after the cut
    std::vector<CutCandidate> candidates;  // the starts weighed for the cut (none without a cut from the data)
    // Batches shorter than 5 tau_int: the error bar is too small; a row shows it.
    bool batches_too_short() const { return batches > 0 && double(used) / double(batches) < 5 * autocorrelation_time; }
};

// tau_int of x (Sokal's window); 0.5 for an uncorrelated series, 0 for fewer than 2 entries.
double integrated_autocorrelation_time(const std::vector<double>& x);

// The candidates t0 = 0, n/20, 2n/20, ... up to n/2 (every entry for n < 20), in order.
std::vector<CutCandidate> equilibration_candidates(const std::vector<double>& x);

// The estimate of x's stationary mean: cut chosen from the data, then batch means.
// With cut_from_data false the whole series is used (for series known to start stationary).
SeriesEstimate estimate_stationary_mean(const std::vector<double>& x, bool cut_from_data = true,
                                        std::size_t batches = 20);

}  // namespace collide
