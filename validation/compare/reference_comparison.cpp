#include "validation/compare/reference_comparison.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <limits>
#include <sstream>

#include "validation/compare/convergence_order.h"
#include "validation/compare/physics_rows.h"
#include "validation/compare/predictability_horizon.h"
#include "validation/compare/reference_runs.h"
#include "validation/record/check_table.h"
#include "validation/judge/observables.h"
#include "validation/judge/statistics.h"
#include "validation/models/statistics_bias_model.h"

namespace collide::validation {

double smallest_radius(const Snapshot& s) {
    double r_min = std::numeric_limits<double>::infinity();
    for (double r : s.radius) r_min = std::min(r_min, r);
    return r_min;
}

double snapshot_separation(const Snapshot& a, const Snapshot& b, double r_min) {
    if (a.x.size() != b.x.size()) return std::nan("");
    double worst = 0;
    for (std::size_t i = 0; i < a.x.size(); ++i) {
        const double d = std::hypot(a.x[i] - b.x[i], a.y[i] - b.y[i]);
        if (!(d <= worst)) worst = d;  // also carries a NaN through
    }
    return worst / r_min;
}

std::vector<double> trajectory_error_series(const CaseResult& a, const CaseResult& ref) {
    if (a.trajectory.empty() || a.trajectory.size() != ref.trajectory.size()) return {};
    const double r_min = smallest_radius(ref.initial);
    std::vector<double> out;
    for (std::size_t k = 0; k < a.trajectory.size(); ++k) {
        if (std::fabs(a.trajectory_time[k] - ref.trajectory_time[k]) > 1e-9) return {};
        out.push_back(snapshot_separation(a.trajectory[k], ref.trajectory[k], r_min));
    }
    return out;
}

double trajectory_error(const CaseResult& a, const CaseResult& ref, const Scene*) {
    const std::vector<double> series = trajectory_error_series(a, ref);
    if (series.empty()) return std::nan("");
    double worst = 0;
    for (double e : series)
        if (!(e <= worst)) worst = e;
    return worst;
}

namespace {

// The replicates of one sweep group and of the matching reference group.
struct Group {
    std::string id;
    std::vector<const CaseResult*> cases;
};

CheckResult make_check(const Group& g, const std::string& check) {
    CheckResult c;
    c.subject = g.id;
    c.scene = g.cases.front()->spec.scene;
    c.backend = g.cases.front()->spec.backend;
    c.check = check;
    return c;
}

void judge_at_most(CheckResult& c, double value, double tolerance, const std::string& what) {
    c.value = value;
    c.tolerance = tolerance;
    c.status = value <= tolerance ? CheckStatus::pass : CheckStatus::fail;
    if (c.status == CheckStatus::fail) {
        std::ostringstream s;
        s << what << " = " << value << " exceeds the tolerance " << tolerance;
        c.detail = s.str();
    }
}

std::vector<double> replicate_values(const Group& g, double (*value)(const CaseResult&)) {
    std::vector<double> out;
    for (const CaseResult* r : g.cases)
        if (r->finished()) out.push_back(value(*r));
    return out;
}

double mean_compressibility(const CaseResult& r) { return mean_and_error(r.compressibility).mean; }
double collision_rate(const CaseResult& r) {
    // Each pair collision involves two disks: collisions per disk per time unit.
    return r.disks && r.duration > 0 ? 2.0 * double(r.contacts) / (double(r.disks) * r.duration) : std::nan("");
}

std::vector<double> pooled_speeds(const Group& g) {
    std::vector<double> out;
    for (const CaseResult* r : g.cases)
        if (r->finished())
            for (std::size_t i = 0; i < r->final_state.vx.size(); ++i)
                out.push_back(std::hypot(r->final_state.vx[i], r->final_state.vy[i]));
    return out;
}

// The plain check of equal means: |mu - mu_ref| / sqrt(se^2 + se_ref^2) <= z_max. With
// `expected` (a stepped backend: statistics_bias_model.h) the same distance is measured from
// the rule's predicted difference instead, |(mu - mu_ref) - predicted| / sqrt(se^2 + se_ref^2
// + u^2) <= z_max, and the prediction is recorded in the check.
// One observable's replicate means on the two sides: what z_check judges and what
// statistical_difference records, computed once.
struct ReplicateMeans {
    MeanAndError a, b;  // the backend's, the reference's
};
ReplicateMeans replicate_means(const Group& g, const Group& ref, double (*value)(const CaseResult&)) {
    return {mean_and_error(replicate_values(g, value)), mean_and_error(replicate_values(ref, value))};
}

void z_check(CheckResult& c, const ReplicateMeans& m, const Group& ref, double z_max, const std::string& what,
             const std::function<BiasPrediction(const MeanAndError& nu_ref)>& expected = {}) {
    const MeanAndError& a = m.a;
    const MeanAndError& b = m.b;
    if (a.count < 2 || b.count < 2) {
        c.status = CheckStatus::left_out;
        c.detail = "needs at least 2 finished replicates on both sides for an error bar";
        return;
    }
    std::ostringstream s;
    s << what << " " << a.mean << " +- " << a.standard_error << " vs reference " << b.mean << " +- "
      << b.standard_error;
    if (expected) {
        const BiasPrediction p = expected(mean_and_error(replicate_values(ref, collision_rate)));
        const double se = std::hypot(a.standard_error, b.standard_error);
        c.predicted = p.value;
        c.predicted_uncertainty = p.uncertainty;
        s << "; difference " << std::showpos << a.mean - b.mean << std::noshowpos << " +- " << se
          << ", the stepped rule predicts " << std::showpos << p.value << std::noshowpos << " +- "
          << p.uncertainty << " (docs/validation.md)";
        judge_at_most(c, bias_z_score(a.mean - b.mean, se, p), z_max, "distance from the predicted bias");
    } else {
        judge_at_most(c, z_score(a, b), z_max, "z-score");
    }
    c.detail = c.status == CheckStatus::fail ? c.detail + " (" + s.str() + ")" : s.str();
}

// The numbers behind a z_check, for the summary: the report draws and states them (never by
// reading the check's prose). Empty when the check has no error bar (fewer than 2 replicates).
std::optional<StatisticalDifference> statistical_difference(const ReplicateMeans& m, const CheckResult& check,
                                                            double z_max) {
    const MeanAndError& a = m.a;
    const MeanAndError& b = m.b;
    if (a.count < 2 || b.count < 2 || !std::isfinite(a.mean) || !std::isfinite(b.mean) || b.mean == 0)
        return std::nullopt;
    StatisticalDifference d;
    d.mean = a.mean;
    d.standard_error = a.standard_error;
    d.reference = b.mean;
    d.reference_standard_error = b.standard_error;
    d.replicates = a.count;
    d.reference_replicates = b.count;
    const double combined = std::hypot(a.standard_error, b.standard_error);
    d.relative = (a.mean - b.mean) / b.mean;
    d.relative_standard_error = combined / std::fabs(b.mean);
    d.sigmas = z_score(a, b);
    d.resolved = d.sigmas >= resolved_standard_errors;
    d.upper_limit_95 = std::fabs(d.relative) + 1.96 * d.relative_standard_error;  // one-sided bound of |relative|
    double judged = combined;
    if (!std::isnan(check.predicted)) {
        d.predicted = check.predicted;
        d.predicted_uncertainty = check.predicted_uncertainty;
        judged = std::hypot(combined, check.predicted_uncertainty);
    }
    d.detectable = z_max * judged / std::fabs(b.mean);
    return d;
}

// Whether `backend` claims exact dynamics in double (BackendInfo::exact, precision): its
// trajectory is then held to the rounding level of the reference's twins.
bool claims_exact_double(const std::map<std::string, const BackendInfo*>& declared, const std::string& backend) {
    const auto it = declared.find(backend);
    return it != declared.end() && it->second->exact && it->second->precision == "double";
}

// The reference run a case's trajectory is compared with (reference_runs.h).
const CaseResult* trajectory_partner(const CaseResult& r, const Group& ref) {
    const CaseResult* partner = nullptr;
    for (const CaseResult* q : ref.cases)
        if (is_reference_run_of(q->spec, r.spec)) partner = q;
    return partner;
}

std::string output_count(std::size_t judged, std::size_t outputs) {
    return std::to_string(judged) + " of " + std::to_string(outputs) + " output times";
}

// Why a group's trajectory_error judged what it judged: the horizon of each seed, in words.
std::string horizon_words(const std::vector<std::pair<const CaseResult*, TrajectoryJudgement>>& judged) {
    std::ostringstream s;
    s << "judged up to the predictability horizon T_h (twins of the reference within tolerance / " << horizon_margin
      << "):";
    for (const auto& [r, j] : judged) {
        s << " seed " << r->spec.seed << ": ";
        if (!j.measured) s << "no twins recorded, all " << output_count(j.times.size(), j.times.size());
        else if (!j.horizon.reached) s << "beyond the run, all " << output_count(j.times.size(), j.times.size());
        else if (!j.judged()) s << "T_h before the first output time, none judged";
        else s << "T_h = " << j.horizon.time << ", " << output_count(j.horizon.judged, j.times.size());
        s << ";";
    }
    s << " after T_h only conservation and statistics judge";
    return s.str();
}

// trajectory_error of one sweep group: each seed's error judged at the output times up to its
// reference's predictability horizon (predictability_horizon.h); the check reports the seed
// and output time with the largest error / limit. The per-case judgements go to `records`.
CheckResult trajectory_check(const Group& g, const Group& ref, double tolerance, bool exact,
                             std::map<std::string, TrajectoryJudgement>& records, std::vector<double>& seconds,
                             std::vector<double>& errors) {
    CheckResult c = make_check(g, "trajectory_error");
    c.tolerance = tolerance;
    std::vector<std::pair<const CaseResult*, TrajectoryJudgement>> judged;
    bool comparable = true;
    for (const CaseResult* r : g.cases) {
        const CaseResult* partner = trajectory_partner(*r, ref);
        std::vector<double> series;
        if (r->finished() && partner && partner->finished()) series = trajectory_error_series(*r, *partner);
        if (series.empty()) {
            comparable = false;
            continue;
        }
        TrajectoryJudgement j = judge_trajectory(partner->trajectory_time, series, partner->twin_separation,
                                                 tolerance, exact);
        records[r->spec.id] = j;
        if (!j.judged()) continue;
        judged.emplace_back(r, j);
        if (std::isfinite(j.error[j.worst])) {
            seconds.push_back(r->wall_seconds / r->duration);
            errors.push_back(*std::max_element(j.error.begin(), j.error.begin() + std::ptrdiff_t(j.horizon.judged)));
        }
    }
    if (!comparable) {
        c.status = CheckStatus::fail;
        c.value = std::nan("");
        c.detail = "no comparable trajectory (the case or its reference did not finish, or too many disks to record)";
        return c;
    }
    if (judged.empty()) {
        c.status = CheckStatus::left_out;
        c.detail = "not judged: in every seed the reference's twins part by more than tolerance / " +
                   std::to_string(int(horizon_margin)) +
                   " before the first output time (the predictability horizon is shorter than the output interval)";
        return c;
    }
    const auto worst = std::max_element(judged.begin(), judged.end(), [](const auto& a, const auto& b) {
        return !std::isnan(a.second.ratio()) && !(b.second.ratio() <= a.second.ratio());
    });
    const TrajectoryJudgement& w = worst->second;
    c.value = w.error[w.worst];
    c.tolerance = w.limit[w.worst];
    bool passed = true;
    for (const auto& [r, j] : judged) passed = passed && j.passed();
    c.status = passed ? CheckStatus::pass : CheckStatus::fail;
    std::ostringstream s;
    if (!passed)
        s << "maximum position error / r_min = " << c.value << " exceeds the limit " << c.tolerance << " at t = "
          << w.times[w.worst] << " (seed " << worst->first->spec.seed << "); ";
    if (w.exact)
        s << "an exact solver is held to " << horizon_margin
          << " x the twins' separation at each output time (rounding level), at most the tolerance " << tolerance
          << "; ";
    c.detail = s.str() + horizon_words(judged);
    return c;
}

// The results in sweep groups (a group: the cases of one id without its seed), in first-seen
// order, so the report follows the suite's order.
std::vector<Group> sweep_groups(const std::vector<CaseResult>& results) {
    std::vector<Group> groups;
    for (const CaseResult& r : results) {
        const std::string id = group_id(r.spec);
        auto it = std::find_if(groups.begin(), groups.end(), [&](const Group& g) { return g.id == id; });
        if (it == groups.end()) groups.push_back({id, {&r}});
        else it->cases.push_back(&r);
    }
    return groups;
}

// All reference cases of a scene as one group, by reference_key (a trajectory scene has one
// reference run per dt).
std::map<std::string, Group> reference_groups(const std::vector<Group>& groups) {
    std::map<std::string, Group> merged;
    for (const Group& g : groups) {
        if (!g.cases.front()->spec.reference) continue;
        Group& m = merged[reference_key(g.cases.front()->spec)];
        if (m.id.empty()) m.id = g.id;
        m.cases.insert(m.cases.end(), g.cases.begin(), g.cases.end());
    }
    return merged;
}

// Why group `g` cannot be compared with its reference group `ref` (null: the reference backend
// is not part of this run), or "" when it can.
// `backend`: what g's backend declares (nullptr if nothing). A sampler's configurations follow no
// trajectory and carry no velocities; its statistics are its own counters (beta_pressure),
// compared in the physics rows.
std::string comparison_obstacle(const Group& g, const Group* ref, const std::string& reference_backend,
                                const BackendInfo* backend) {
    if (g.cases.front()->status == RunStatus::left_out) return "case left out: backend cannot run this scene";
    if (!ref) return "the reference backend '" + reference_backend + "' is not part of this run";
    if (ref->cases.front()->status == RunStatus::left_out)
        return "the reference backend cannot run this scene: " + ref->cases.front()->diagnostic;
    if (backend && backend->sampler) return backend->sampler_left_out();
    return "";
}

// Every comparison check of `g`'s kind, left out for `why`.
void leave_out_comparison(const Group& g, Comparison comparison, const std::string& why,
                          std::vector<CheckResult>& checks) {
    for (const auto& n : check_names(comparison == Comparison::trajectory ? CheckKind::trajectory : CheckKind::statistics)) {
        CheckResult c = make_check(g, n);
        c.detail = why;
        checks.push_back(c);
    }
}

// What the statistics of `g` are expected to differ from the reference's by. A stepping rule
// differs from the exact dynamics by a derived first-order bias in h = dt / substeps
// (statistics_bias_model.h); every other backend (box2d is not the stepped rule) is held to
// equal means: empty models.
struct BiasModels {
    std::function<BiasPrediction(const MeanAndError&)> pressure, collision_rate;
};
BiasModels bias_models(const Group& g, const BackendInfo& backend) {
    if (!backend.stepping_rule()) return {};
    const double h = g.cases.front()->dt / std::max(1, g.cases.front()->substeps);
    return {[h](const MeanAndError& nu) { return predicted_pressure_bias(nu.mean, nu.standard_error, h, contact_shell); },
            [h](const MeanAndError& nu) { return predicted_collision_rate_bias(nu.mean, nu.standard_error, h); }};
}

// speed_distribution: the two-sample Kolmogorov-Smirnov test of the pooled speeds of `g`
// against the reference's; passes at a p-value of at least `p_min`.
CheckResult speed_distribution_check(const Group& g, const Group& ref, double p_min) {
    CheckResult speed = make_check(g, "speed_distribution");
    const auto ks = ks_two_sample(pooled_speeds(g), pooled_speeds(ref));
    speed.value = ks.p_value;
    speed.tolerance = p_min;
    speed.comparison = ">=";
    speed.status = ks.p_value >= p_min ? CheckStatus::pass : CheckStatus::fail;
    std::ostringstream s;
    s << "KS statistic D = " << ks.statistic << ", p = " << ks.p_value;
    speed.detail = speed.status == CheckStatus::pass ? s.str() : s.str() + " below " + std::to_string(p_min);
    return speed;
}

// Why the group's collision rate is unknown, if it is: an outside solver that does not count
// its contacts (no `contacts` line in result.txt, protocol 2) reports 0 collisions, which is no
// measurement of its rate (docs/your-solver.md, "contacts").
std::optional<std::string> contacts_unknown(const Group& g) {
    for (const CaseResult* r : g.cases) {
        const auto reported = r->counters.find("contacts_reported");
        if (r->finished() && reported != r->counters.end() && reported->second == 0)
            return "the solver does not report its contacts (no 'contacts' line in result.txt): its collision rate is unknown";
    }
    return std::nullopt;
}

// The statistic a many-body scene is compared by, seed by seed, where Z is not the point's
// error (docs/validation.md, "Scenes compared seed by seed"): a cooling gas (e < 1) by the cooling
// time tau of Haff's law T(t) = T0 / (1 + t / tau)^2 fitted to each run (haff_cooling_time,
// physics_rows.h): the one number its inelastic dynamics sets; a scene whose Z is left out
// (polydisperse: the stones among the gas) by its collision rate. None for the others.
struct PairedStatistic {
    std::string error_kind;
    std::function<double(const CaseResult&)> value;
    bool counts_contacts = false;  // unknown where the solver does not report its contacts
};
std::optional<PairedStatistic> paired_statistic(const SceneFeatures& features) {
    if (features.restitution < 1) {
        const bool conserved = !momentum_left_out(features);
        return PairedStatistic{"|tau - tau_ref| / tau_ref", [conserved](const CaseResult& r) {
                                   return haff_cooling_time(r, r.duration, r.disks, conserved);
                               }};
    }
    if (pressure_left_out(features)) return PairedStatistic{"|nu - nu_ref| / nu_ref", collision_rate, true};
    return std::nullopt;
}

// The statistic's difference from the reference, paired by seed: a case and the reference's
// case of the same seed start from one configuration, so their difference carries only what
// the dynamics adds, not the scatter of initial states that the replicate means carry (common
// random numbers: Glasserman, Monte Carlo Methods in Financial Engineering (2003), sec. 4.2).
// The relative difference is mean(d) / mean(ref) with SE se(d) / |mean(ref)|. Empty with fewer
// than 2 pairs of finished, finite values.
std::optional<StatisticalDifference> paired_difference(const Group& g, const Group& ref,
                                                       const std::function<double(const CaseResult&)>& value,
                                                       double z_max) {
    std::map<std::uint64_t, double> reference_by_seed;
    for (const CaseResult* r : ref.cases)
        if (r->finished()) reference_by_seed[r->spec.seed] = value(*r);
    std::vector<double> a, b, d;
    for (const CaseResult* r : g.cases) {
        const auto it = reference_by_seed.find(r->spec.seed);
        if (!r->finished() || it == reference_by_seed.end()) continue;
        const double v = value(*r);
        if (!std::isfinite(v) || !std::isfinite(it->second)) continue;
        a.push_back(v), b.push_back(it->second), d.push_back(v - it->second);
    }
    const MeanAndError ma = mean_and_error(a), mb = mean_and_error(b), md = mean_and_error(d);
    if (d.size() < 2 || mb.mean == 0) return std::nullopt;
    StatisticalDifference s;
    s.paired = true;
    s.mean = ma.mean, s.standard_error = ma.standard_error;
    s.reference = mb.mean, s.reference_standard_error = mb.standard_error;
    s.difference = md.mean, s.difference_standard_error = md.standard_error;
    s.relative = md.mean / mb.mean;
    s.relative_standard_error = md.standard_error / std::fabs(mb.mean);
    s.sigmas = md.standard_error > 0 ? std::fabs(md.mean) / md.standard_error : (md.mean == 0 ? 0 : INFINITY);
    s.resolved = s.sigmas >= resolved_standard_errors;
    s.upper_limit_95 = std::fabs(s.relative) + student_t_95(double(d.size() - 1)) * s.relative_standard_error;  // n seeds: t, n - 1 dof
    s.detectable = z_max * s.relative_standard_error;
    s.replicates = s.reference_replicates = d.size();
    return s;
}

// The statistics comparison of a many-body group: pressure, collision_rate and
// speed_distribution against the reference, each appended to `checks`. The work-precision
// point gets the judged differences of the replicate means (what the check judges and the
// figures draw) and, when Z was judged, the run time of every finished case in `seconds`.
void compare_statistics(const Group& g, const Group& ref, const SceneFeatures& features, const Tolerances& tol,
                        const BackendInfo& backend, std::vector<CheckResult>& checks, WorkPrecisionPoint& point,
                        std::vector<double>& seconds) {
    const BiasModels models = bias_models(g, backend);
    CheckResult pressure = make_check(g, "pressure");
    const auto pressure_left_out_why = pressure_left_out(features);
    const ReplicateMeans z = pressure_left_out_why ? ReplicateMeans{} : replicate_means(g, ref, mean_compressibility);
    if (pressure_left_out_why) pressure.detail = *pressure_left_out_why;
    else z_check(pressure, z, ref, tol.statistics_z, "Z = P/(rho kT) (contact-shell estimator)", models.pressure);
    checks.push_back(pressure);
    CheckResult rate = make_check(g, "collision_rate");
    const ReplicateMeans nu = replicate_means(g, ref, collision_rate);
    if (const auto why = contacts_unknown(g)) {
        rate.status = CheckStatus::left_out;
        rate.detail = *why;
    } else {
        z_check(rate, nu, ref, tol.statistics_z, "collisions per disk per time", models.collision_rate);
    }
    checks.push_back(rate);
    if (pressure.status != CheckStatus::left_out) point.pressure = statistical_difference(z, pressure, tol.statistics_z);
    if (rate.status != CheckStatus::left_out) point.collision_rate = statistical_difference(nu, rate, tol.statistics_z);
    checks.push_back(speed_distribution_check(g, ref, tol.speed_ks_p_value));
    if (const auto statistic = paired_statistic(features); statistic && !(statistic->counts_contacts && contacts_unknown(g)))
        point.paired = paired_difference(g, ref, statistic->value, tol.statistics_z);
    if (point.pressure || point.paired)
        for (const CaseResult* r : g.cases)
            if (r->finished()) seconds.push_back(r->wall_seconds / r->duration);
}

// The work-precision point of `g` before it is measured: its sweep values.
WorkPrecisionPoint sweep_point(const Group& g) {
    WorkPrecisionPoint point;
    point.group = g.id;
    point.dt = g.cases.front()->dt;
    point.substeps = g.cases.front()->substeps;
    point.iterations = g.cases.front()->spec.iterations.value_or(0);
    return point;
}

// Sets the point's error and run time: the paired statistic's relative difference where the
// scene has one (`paired_kind`, paired_statistic), else Z's where it was judged, else the mean of
// the per-seed trajectory errors. Returns the error's kind, "" when nothing was measured (no point).
std::string measure_point(WorkPrecisionPoint& point, const std::string& paired_kind, const std::vector<double>& seconds,
                          const std::vector<double>& errors) {
    std::string kind;
    // (A scene with a paired statistic never falls back to Z: one line holds one kind of error.)
    if (const auto& d = paired_kind.empty() ? point.pressure : point.paired; d && !seconds.empty()) {
        point.error = std::fabs(d->relative);
        point.error_standard_error = d->relative_standard_error;
        point.replicates = d->replicates;
        kind = point.paired ? paired_kind : "|Z - Z_ref| / Z_ref";
    } else if (!errors.empty()) {
        const auto e = mean_and_error(errors);
        point.error = e.mean;
        point.error_standard_error = e.standard_error;
        point.replicates = errors.size();
        kind = "trajectory error / r_min";
    } else {
        return "";
    }
    point.seconds_per_time_unit = mean_and_error(seconds).mean;
    return kind;
}

// The work-precision lines, one per (scene, backend) in first-seen order, each with the
// convergence order fitted on its points (convergence_order.h).
class WorkPrecisionLines {
public:
    void add(const std::string& scene, const std::string& backend, const std::string& error_kind,
             const WorkPrecisionPoint& point) {
        const auto key = std::make_pair(scene, backend);
        if (!lines_.count(key)) {
            order_.push_back(key);
            lines_[key] = {scene, backend, error_kind, {}, {}};
        }
        lines_[key].points.push_back(point);
    }
    std::vector<WorkPrecisionLine> fitted() const {
        std::vector<WorkPrecisionLine> out;
        for (const auto& key : order_) {
            WorkPrecisionLine line = lines_.at(key);
            std::vector<ErrorPoint> points;
            // The rule's effective step is dt / substeps (the integrate-first rule sub-steps).
            for (const auto& p : line.points)
                points.push_back({p.dt / std::max(1, p.substeps), p.error, p.error_standard_error});
            line.order = asymptotic_order(points);
            out.push_back(line);
        }
        return out;
    }

private:
    std::map<std::pair<std::string, std::string>, WorkPrecisionLine> lines_;
    std::vector<std::pair<std::string, std::string>> order_;
};

}  // namespace

Comparisons compare_with_reference(const Suite& suite, const std::vector<CaseResult>& results,
                                   const std::vector<SceneFeatures>& features,
                                   const std::map<std::string, Tolerances>& tolerances,
                                   const std::map<std::string, const BackendInfo*>& declared) {
    Comparisons out;
    const std::vector<Group> groups = sweep_groups(results);
    const std::map<std::string, Group> references = reference_groups(groups);
    WorkPrecisionLines lines;
    for (const Group& g : groups) {
        const CaseSpec& spec = g.cases.front()->spec;
        const SuiteScene& entry = suite.scenes[spec.scene_index];
        if (entry.comparison == Comparison::none || spec.reference) continue;
        const auto found = references.find(reference_key(spec));
        const Group* ref = found == references.end() ? nullptr : &found->second;
        const auto it = declared.find(spec.backend);
        const BackendInfo* backend = it == declared.end() ? nullptr : it->second;
        if (const std::string why = comparison_obstacle(g, ref, suite.reference, backend); !why.empty()) {
            leave_out_comparison(g, entry.comparison, why, out.checks);
            continue;
        }
        const bool trajectory = entry.comparison == Comparison::trajectory;
        const Tolerances& tol = tolerances.at(spec.backend);
        WorkPrecisionPoint point = sweep_point(g);
        std::vector<double> seconds, errors;
        if (trajectory)
            out.checks.push_back(trajectory_check(g, *ref, tol.trajectory_error, claims_exact_double(declared, spec.backend),
                                                  out.trajectories, seconds, errors));
        else
            compare_statistics(g, *ref, features[spec.scene_index], tol, *declared.at(spec.backend), out.checks, point,
                               seconds);
        const auto paired = trajectory ? std::nullopt : paired_statistic(features[spec.scene_index]);
        if (const std::string kind = measure_point(point, paired ? paired->error_kind : "", seconds, errors); !kind.empty())
            lines.add(spec.scene, spec.backend, kind, point);
    }
    out.work_precision = lines.fitted();
    return out;
}

}  // namespace collide::validation
