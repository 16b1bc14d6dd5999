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
    struct ScoreInputs {
        std::string estimator;
        double value = std::nan(""), standard_error = std::nan(""), reference = std::nan(""), reference_uncertainty = 0;
    } score_from;
    bool resolved = true;            // the error bar tells the two published values apart
    PhysicsVerdict verdict = PhysicsVerdict::shown;
    std::string detail;
};

// A curve of a published equation of state, sampled for the report's figure.
struct ReferenceCurve {
    std::string name, citation;
    std::vector<double> eta, z;
};

struct PhysicsComparison {
    std::vector<PhysicsRow> rows;
    std::vector<ReferenceCurve> curves;
};

// The largest |z| (or the smallest p) a judged row may have; docs/validation.md.
inline constexpr double physics_z_max = 3.0;

// `scene_of` gives the scene a case ran (with the case's parameter values), `references` the
// directory of data/references. Rows for every [[scene]] with a `physics` key.
PhysicsComparison compare_with_physics(const Suite& suite, const std::vector<CaseResult>& results,
                                       const std::function<const Scene&(const CaseSpec&)>& scene_of);

// --- The per-case measurements (exposed for tests) ---------------------------------------

// Z = 1 + Delta V / (2 Delta t K0) over the second half of the run, from the collision virial
// V = sum over collisions of m_i Delta v_i . r_ij that the event-driven solvers count
// (2-D virial theorem: P A = N kT + V / (2 t); K = N kT in 2-D). kT is that of the conserved
// energy K0 (the first output), as the e = 1 gas promises: a solver that loses energy reads low.
// NaN without the counters.
double virial_compressibility(const CaseResult& r);
// Collisions per disk per time unit over the second half (each collision involves 2 disks).
double second_half_collision_rate(const CaseResult& r);
// Haff's cooling time tau from a least-squares line through T(t)^(-1/2) = T0^(-1/2) (1 + t/tau)
// over the output times t <= t_max: tau = intercept / slope. NaN with fewer than 3 points.
double haff_cooling_time(const CaseResult& r, double t_max);
// Pearson's chi-square of speeds scaled by sqrt(kT/m) against the 2-D Maxwell-Boltzmann
// (Rayleigh) distribution over `bins` equiprobable bins; returns {chi2, degrees of freedom, p}.
struct ChiSquare { double chi2 = 0; int dof = 0; double p_value = 1; };
ChiSquare maxwell_boltzmann_chi_square(const std::vector<double>& scaled_speeds, int bins);

}  // namespace collide::validation
