#include "validation/judge/checks.h"

#include "core/io/run_schema.h"
#include "validation/record/check_table.h"
#include "validation/models/energy_loss_model.h"
#include "validation/record/exact_limits.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace collide::validation {

namespace {

// The larger of a and b, where NaN wins: std::max(m, NaN) returns m and would let a NaN
// metric pass as 0 (the `at_most` comparison fails on NaN, so it must reach it).
double max_keeping_nan(double a, double b) { return std::isnan(a) || std::isnan(b) ? NAN : std::max(a, b); }

// max_t of one column of the series (NaN wins, as above).
double max_of(const MetricSeries& series, double (*column)(const Metrics&)) {
    double m = 0;
    for (const Metrics& row : series) m = max_keeping_nan(m, column(row));
    return m;
}

// The name of the first column of the run schema, or total_energy, holding a NaN or Inf, or ""
// when all are finite.
std::string first_nonfinite_series(const MetricSeries& series) {
    for (const MetricColumn& column : metric_columns)
        for (const Metrics& row : series)
            if (!std::isfinite(column.value(row))) return column.name;
    for (const Metrics& row : series)
        if (!std::isfinite(row.total_energy())) return "total_energy";
    return "";
}

class CaseChecker {
public:
    CaseChecker(const CaseResult& r, std::vector<CheckResult>& out) : r_(r), out_(out) {}

    void left_out(const std::string& check, const std::string& reason) {
        out_.push_back(base(check, CheckStatus::left_out, 0, 0, reason));
    }

    void fail(const std::string& check, const std::string& detail) {
        out_.push_back(base(check, CheckStatus::fail, 0, 0, detail));
    }

    void at_most(const std::string& check, double value, double tolerance, const std::string& what) {
        const bool ok = value <= tolerance;  // NaN fails
        std::ostringstream detail;
        if (!ok) detail << what << " = " << value << " exceeds the tolerance " << tolerance;
        out_.push_back(base(check, ok ? CheckStatus::pass : CheckStatus::fail, value, tolerance, detail.str()));
    }

    // Adds the model's prediction to the check just made (reported next to the measured value).
    void predicted(double value, double uncertainty) {
        out_.back().predicted = value;
        out_.back().predicted_uncertainty = uncertainty;
        if (out_.back().status == CheckStatus::fail) {
            std::ostringstream d;
            d << "; the rule predicts " << value << " +- " << uncertainty;
            out_.back().detail += d.str();
        }
    }

private:
    CheckResult base(const std::string& check, CheckStatus status, double value, double tolerance,
                     const std::string& detail) const {
        CheckResult c;
        c.subject = r_.spec.id;
        c.scene = r_.spec.scene;
        c.backend = r_.spec.backend;
        c.check = check;
        c.status = status;
        c.value = value;
        c.tolerance = tolerance;
        c.detail = detail;
        return c;
    }
    const CaseResult& r_;
    std::vector<CheckResult>& out_;
};

// max_t |P(t) - P(0)| scaled by sqrt(2 M K(0)), the momentum the whole mobile mass would have
// at the rms speed (the total momentum itself is often zero, so it cannot be the scale).
double momentum_drift(const CaseResult& r) {
    const MetricSeries& m = r.series;
    const double scale = std::sqrt(2 * r.total_mass * m.front().kinetic_energy);
    double drift = 0;
    for (const Metrics& row : m)
        drift = max_keeping_nan(drift, std::hypot(row.momentum_x - m.front().momentum_x, row.momentum_y - m.front().momentum_y));
    return scale > 0 ? drift / scale : drift;
}

// max_t |E(t) - E(0)| scaled by the largest kinetic energy seen (under gravity the potential
// energy has an arbitrary zero, so E(0) itself is no scale).
double energy_drift(const CaseResult& r, EnergyKind kind) {
    const MetricSeries& m = r.series;
    auto energy = [kind](const Metrics& row) { return kind == EnergyKind::total ? row.total_energy() : row.kinetic_energy; };
    const double scale = max_of(m, [](const Metrics& row) { return row.kinetic_energy; });
    double drift = 0;
    for (const Metrics& row : m) drift = max_keeping_nan(drift, std::fabs(energy(row) - energy(m.front())));
    return scale > 0 ? drift / scale : drift;
}

// Collisions per disk per time unit for the energy model: from kinetic theory for a gas (the
// scene's density and initial temperature), from the run's own contact count in a crystal
// (area fraction >= 0.6, where the Enskog estimate does not apply; see energy_loss_model.h).
double collision_frequency(const CaseResult& r, const SceneFeatures& f) {
    const double n = double(r.disks);
    if (f.area_fraction >= 0.6 || r.initial.radius.empty() || r.series.size() == 0)
        return 2.0 * double(r.contacts) / (n * r.duration);
    double sum_r = 0, sum_r2 = 0;
    for (double x : r.initial.radius) {
        sum_r += x;
        sum_r2 += x * x;
    }
    const double m = double(r.initial.radius.size());
    const double kt_over_m = r.series.front().kinetic_energy / r.total_mass;  // 2D: K = N kT
    return enskog_collision_frequency(f.area_fraction, sum_r / m, sum_r2 / m, kt_over_m);
}

// A contact solver of its own (Box2D, Chipmunk: BackendInfo::limits) solves an isolated contact
// as one constraint, exactly up to rounding (the first sequential-impulse iteration; a wall
// contact likewise). In a scene of fewer than 3 disks every contact is isolated, so at e = 1 its
// kinetic energy moves by the rounding of each collision alone (conservation_rounding: 3.8e-6
// in float with one collision, 16 eps (C + 1); 2.4e-7 measured on head_on_equal), not by its general 5e-2,
// which a restitution of 0.999 (2e-3 lost) would pass. A suite that sets the backend's energy
// limit (box2d[shipped]: a restitution threshold makes slow collisions inelastic) keeps its own,
// whatever its value (Tolerances::set_by_suite), even the backend's own default.
std::optional<double> isolated_contact_energy_limit(const CaseResult& r, const BackendInfo& backend,
                                                    const Tolerances& tol) {
    if (backend.stepping_rule() || r.disks >= 3 || tol.suite_set("energy_drift")) return std::nullopt;
    const bool own_limit = std::any_of(backend.limits.begin(), backend.limits.end(),
                                       [](const auto& kv) { return kv.first == "energy_drift"; });
    if (!own_limit) return std::nullopt;
    return conservation_rounding(machine_epsilon(backend.single_precision()), r.contacts);
}

}  // namespace

std::vector<CheckResult> case_checks(const CaseResult& r, const SceneFeatures& f, const Tolerances& tol,
                                     const BackendInfo& backend) {
    std::vector<CheckResult> out;
    CaseChecker c(r, out);
    std::vector<std::string> per_case = check_names(CheckKind::case_check);  // "run" first, then the rest
    per_case.erase(per_case.begin());
    if (r.status == RunStatus::left_out) {
        c.left_out("run", "backend cannot run this scene: " + r.diagnostic);
        for (const auto& name : per_case) c.left_out(name, "case left out: backend cannot run this scene");
        return out;
    }
    if (!r.finished() || r.series.size() == 0) {
        CheckResult fail;
        fail.subject = r.spec.id;
        fail.scene = r.spec.scene;
        fail.backend = r.spec.backend;
        fail.check = "run";
        fail.status = CheckStatus::fail;
        fail.detail = std::string(to_string(r.status)) + ": " + r.diagnostic;
        out.push_back(fail);
        for (const auto& name : per_case) c.left_out(name, "not evaluated: the run did not finish");
        return out;
    }
    // A finished run with a NaN/Inf metric (an energy overflowing double while every disk is
    // finite) fails; the checks below that read that metric fail too, as NaN reaches them.
    const std::string nonfinite = first_nonfinite_series(r.series);
    if (nonfinite.empty()) c.at_most("run", 0, 0, "run");
    else c.fail("run", "the metric " + nonfinite + " holds NaN/Inf");

    const std::string no_dynamics = backend.sampler_left_out();
    if (!no_dynamics.empty()) c.left_out("momentum_drift", no_dynamics);
    else if (auto why = momentum_left_out(f)) c.left_out("momentum_drift", *why);
    else c.at_most("momentum_drift", momentum_drift(r), tol.momentum_drift, "relative momentum drift");

    const EnergyCheck energy = no_dynamics.empty() ? energy_check(f) : EnergyCheck{EnergyKind::none, no_dynamics};
    if (energy.kind == EnergyKind::none) c.left_out("energy_drift", energy.reason);
    else if (energy.kind == EnergyKind::kinetic && backend.stepping_rule() && r.duration > 0 && r.disks > 0) {
        // The stepped rules lose or gain energy when one disk takes two impulses from one
        // Jacobi snapshot; the bound is the drift the rule itself predicts for this case's
        // collision frequency, dt, duration and size (docs/stepping-rules.md, "Energy at e = 1").
        const double n = double(r.disks);
        const double nu = collision_frequency(r, f);
        // Rounding of the impulses is the floor (alone where no disk can take two impulses).
        const auto p = stepped_energy_drift(nu, r.dt / std::max(1, r.substeps), r.duration, n, f.area_fraction);
        const double rounding = conservation_rounding(machine_epsilon(backend.single_precision()), r.contacts);
        c.at_most("energy_drift", energy_drift(r, energy.kind), std::max(p.tolerance, rounding),
                  "relative kinetic-energy drift");
        c.predicted(p.predicted, p.uncertainty);
    } else if (const auto isolated = energy.kind == EnergyKind::kinetic ? isolated_contact_energy_limit(r, backend, tol)
                                                                        : std::nullopt) {
        c.at_most("energy_drift", energy_drift(r, energy.kind), *isolated,
                  "relative kinetic-energy drift (fewer than 3 disks: every contact isolated, exact to rounding)");
    } else c.at_most("energy_drift", energy_drift(r, energy.kind), tol.energy_drift,
                   energy.kind == EnergyKind::total ? "relative total-energy drift" : "relative kinetic-energy drift");

    c.at_most("max_overlap", max_of(r.series, [](const Metrics& m) { return m.max_overlap; }), tol.max_overlap, "maximum relative overlap depth");
    c.at_most("mean_overlap", max_of(r.series, [](const Metrics& m) { return m.mean_overlap; }), tol.mean_overlap, "mean relative overlap depth");
    const double disks = double(std::max<std::size_t>(1, r.disks));
    if (auto why = overlapping_pairs_too_few(r.disks, tol.overlapping_pairs_per_disk)) c.left_out("overlapping_pairs", *why);
    else c.at_most("overlapping_pairs", max_of(r.series, [](const Metrics& m) { return double(m.overlapping_pairs); }) / disks,
                   tol.overlapping_pairs_per_disk, "overlapping pairs per disk");
    if (auto why = overlap_beyond_step_left_out(r.disks, tol.overlapping_pairs_per_disk)) c.left_out("overlap_beyond_step", *why);
    else c.at_most("overlap_beyond_step", max_of(r.series, [](const Metrics& m) { return m.max_overlap_beyond_step; }),
                   tol.overlap_beyond_step, "overlap depth beyond one step of the pair's approach");
    if (auto why = wall_penetration_left_out(f)) c.left_out("wall_penetration", *why);
    else c.at_most("wall_penetration", max_of(r.series, [](const Metrics& m) { return m.max_wall_penetration; }), tol.wall_penetration,
                   "maximum wall penetration / radius");
    return out;
}

}  // namespace collide::validation
