// "Reference against physics": the rows of the report that hold the reference solver (and,
// for information, every other backend that ran the same scene) against published physics
// rather than against `event` itself. Each row: what is measured, its value with the standard
// error over replicates, the published value and its citation (published_reference.h), the
// score and the verdict. docs/validation.md, "Reference against physics", defines each row.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/thermo/kinetic_temperature.h"
#include "validation/record/case_result.h"
#include "validation/compare/published_reference.h"
#include "validation/plan/suite.h"

namespace collide::validation {

// The rows a [[scene]] can feed (its `physics = [...]` key), each with the reference it is
// judged against. One definition: the suite reader checks names against this list.
struct PhysicsRowKind {
    const char* name;        // "equation_of_state", ...
    const char* reference;   // data/references/<reference>.toml
    const char* measures;    // in words, for the report
};
const std::vector<PhysicsRowKind>& physics_row_kinds();

enum class PhysicsVerdict {
    pass,
    fail,
    shown,   // informational: a backend whose estimator or rule is not the exact one (not judged)
};
const char* to_string(PhysicsVerdict v);

struct PhysicsRow {
    std::string row;                 // a PhysicsRowKind name
    std::string scene, backend, group;
    std::string parameter_name;      // "area fraction", "mass ratio", "restitution"
    double parameter = std::nan("");
    std::string measured;            // what is measured, in words
    std::string estimator;           // how: "collision virial", "contact shell (s = 0.05)", ...
    double value = std::nan(""), standard_error = std::nan("");
    std::size_t replicates = 0;
    double reference = std::nan(""), reference_uncertainty = 0;  // absolute, of the reference
    std::string reference_name, citation;
    double second_reference = std::nan("");  // drawn beside (Henderson beside Kolafa & Rottner)
    std::string second_reference_name;
    std::string statistic;           // "z" (|difference| / combined error), "p" (chi-square), "exact"
    double score = std::nan("");
    // A "z" row's score from these numbers: z = (value - reference) / hypot(standard_error,
    // reference_uncertainty), score = |z|. They are value ± SE and the reference above except
    // where the row judges per-replicate ratios measured / predicted (estimator says so).
    // With degrees_of_freedom > 0 the SE is the scatter of that few replicates: the quotient is
    // Student's t, and score = normal_equivalent_of_t(|t|, degrees_of_freedom) (statistics.h).
    struct ScoreInputs {
        std::string estimator;
        double value = std::nan(""), standard_error = std::nan(""), reference = std::nan(""), reference_uncertainty = 0;
        double degrees_of_freedom = 0;  // 0: the SE is a batch-means (normal) error
    } score_from;
    bool resolved = true;            // the error bar tells the two published values apart
    PhysicsVerdict verdict = PhysicsVerdict::shown;
    bool judged_by_score = false;    // the verdict is score <= the suite's z_max (family_z_max)
    std::string detail;
    // Rows of published finite-N points (published_rows.h): the row they are held to ("KEY:ID"),
    // the box ("9 : 8 sqrt(3)/2 periodic") and the facts of the estimate: "disks",
    // "equilibration" and "correlation_time" (the run's time unit), "batches", "relative_error",
    // "psi6_traversals", "mixed" (1 or 0), "replicate_chi2".
    std::string published, box;
    std::map<std::string, double> facts;
};

// A curve of a published equation of state, sampled for the report's figure.
struct ReferenceCurve {
    std::string name, citation;
    std::vector<double> eta, z;
};

struct PhysicsComparison {
    std::vector<PhysicsRow> rows;
    std::vector<ReferenceCurve> curves;
    double z_max = 3.0;  // the threshold every judged_by_score row was held to (family_z_max)
};

// The largest |z| (or the smallest p) one judged row may have; docs/validation.md.
inline constexpr double physics_z_max = 3.0;

// The threshold for each of `rows` rows judged together, so that a suite of correct solvers
// fails no row more often than a single row fails at 3 standard errors (two-sided 0.27 %):
// Bonferroni, z_max = Q^-1(Q(3) / rows) with Q the normal upper tail (3 for one row, 4.06 for
// 56). Without it a suite of 56 rows at 3 each would fail a correct solver in 14 % of runs.
double family_z_max(std::size_t rows);

// `scene_of` gives the scene a case ran (with the case's parameter values), `references` the
// directory of data/references. Rows for every [[scene]] with a `physics` key.
PhysicsComparison compare_with_physics(const Suite& suite, const std::vector<CaseResult>& results,
                                       const std::function<const Scene&(const CaseSpec&)>& scene_of);

// --- The per-case measurements (exposed for tests) ---------------------------------------

// The kinetic temperature of a case from its first output (core/thermo/kinetic_temperature.h,
// the one definition): K_int / (N - 1) where momentum is conserved, K / N with walls. From the
// recorded totals K, P (series) and M (total_mass) of the N moving disks.
KineticTemperature case_temperature(const CaseResult& r, std::size_t moving_disks, bool momentum_conserved);

// Z = 1 + ((N - 1) / N) W / K_int over the second half of the run (core/thermo/pressure_estimator.h),
// W = Delta V / (2 Delta t) the rate of the collision virial V = sum over collisions of
// m_i Delta v_i . r_ij that the event-driven solvers count. K_int is that of the conserved
// energy (the first output), as the e = 1 gas promises: a solver that loses energy reads low.
// NaN without the counters.
double virial_compressibility(const CaseResult& r, const KineticTemperature& t);
// Collisions per disk per time unit over the second half (each collision involves 2 disks).
double second_half_collision_rate(const CaseResult& r);
// Haff's cooling time tau from a least-squares line through T(t)^(-1/2) = T0^(-1/2) (1 + t/tau)
// over the output times t <= t_max: tau = intercept / slope, T the kinetic temperature of each
// output (the centre of mass's energy left out where momentum is conserved). NaN with fewer
// than 3 points.
double haff_cooling_time(const CaseResult& r, double t_max, std::size_t moving_disks, bool momentum_conserved);
// The speeds of a state's disks (equal masses m) in the frame of the centre of mass where
// momentum is conserved, scaled by sqrt(kT / m) with the same kT: what the Rayleigh
// distribution describes.
std::vector<double> scaled_speeds(const Snapshot& s, double mass, bool momentum_conserved);
// Pearson's chi-square of speeds scaled by sqrt(kT/m) against the 2-D Maxwell-Boltzmann
// (Rayleigh) distribution over `bins` equiprobable bins; returns {chi2, degrees of freedom, p}.
struct ChiSquare { double chi2 = 0; int dof = 0; double p_value = 1; };
ChiSquare maxwell_boltzmann_chi_square(const std::vector<double>& scaled_speeds, int bins);

}  // namespace collide::validation
