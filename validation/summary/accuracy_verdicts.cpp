#include "validation/summary/accuracy_verdicts.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "validation/judge/statistics.h"
#include "validation/plan/backend_variant.h"

namespace collide::validation {

double confidence_factor(const WorkPrecisionPoint& p) {
    if (p.paired && p.paired->paired && p.paired->replicates >= 2) return student_t_95(double(p.paired->replicates - 1));
    return confidence_95;
}

namespace {

// The point's error as the verdict states it: the signed relative difference where the line
// measures a statistic (a paired one, else Z; its error is |difference|), else the error itself.
double signed_error(const WorkPrecisionPoint& p) {
    if (p.paired) return p.paired->relative;
    return p.pressure ? p.pressure->relative : p.error;
}

bool within(const WorkPrecisionPoint& p, double accuracy) {
    return p.error + confidence_factor(p) * p.error_standard_error <= accuracy;
}

void judge_line(const WorkPrecisionLine& line, double accuracy, AccuracyVerdict& v) {
    const WorkPrecisionPoint* best = nullptr;   // the largest dt within the accuracy
    const WorkPrecisionPoint* worst = nullptr;  // the largest error among the points not within it
    double dt_min = INFINITY, dt_max = -INFINITY;
    for (const WorkPrecisionPoint& p : line.points) {
        if (!std::isfinite(p.error)) continue;
        if (within(p, accuracy)) {
            if (!best || p.dt > best->dt) best = &p;
            continue;
        }
        dt_min = std::min(dt_min, p.dt);
        dt_max = std::max(dt_max, p.dt);
        if (!worst || p.error > worst->error) worst = &p;
    }
    if (best)
        v.use_for.push_back({line.scene, line.error_kind, accuracy, best->dt, best->error, best->error_standard_error,
                             best->replicates, confidence_factor(*best)});
    if (worst) {
        NotFor n{line.scene, line.error_kind, accuracy, dt_min, dt_max, worst->dt, signed_error(*worst),
                 worst->error_standard_error, 0, worst->replicates, false, confidence_factor(*worst)};
        n.sigmas = n.standard_error > 0 ? std::fabs(n.error) / n.standard_error : INFINITY;
        n.resolved = std::fabs(n.error) - n.confidence_factor * n.standard_error > accuracy;
        v.not_for.push_back(n);
    }
}

// The subjects (sweep groups) of the backend's passing checks named `check`.
std::set<std::string> passing_subjects(const std::string& backend, const std::string& check,
                                       const std::vector<CheckResult>& checks) {
    std::set<std::string> out;
    for (const CheckResult& c : checks)
        if (c.backend == backend && c.check == check && c.status == CheckStatus::pass) out.insert(c.subject);
    return out;
}

// The line's passing Z checks whose detectable bias exceeds the accuracy (LowPowerPass); none
// where every pass could have seen a bias of the accuracy. `passed`: passing_subjects(.., "pressure").
std::optional<LowPowerPass> low_power_pass(const WorkPrecisionLine& line, double accuracy,
                                           const std::set<std::string>& passed) {
    LowPowerPass l{line.scene, "pressure", accuracy, INFINITY, -INFINITY, INFINITY, 0, 0};
    for (const WorkPrecisionPoint& p : line.points) {
        if (!p.pressure || !passed.count(p.group) || !(p.pressure->detectable > accuracy)) continue;
        ++l.passes;
        l.dt_min = std::min(l.dt_min, p.dt);
        l.dt_max = std::max(l.dt_max, p.dt);
        if (p.pressure->detectable < l.detectable) {
            l.detectable = p.pressure->detectable;
            l.replicates = p.pressure->replicates;
        }
    }
    if (l.passes == 0) return std::nullopt;
    return l;
}

// The line's cost at `accuracy` (CostAtAccuracy): from coarse to fine dt, the first point whose
// mean error is within it, interpolated against the point before.
CostAtAccuracy cost_at(const WorkPrecisionLine& line, double accuracy) {
    CostAtAccuracy c{line.scene, line.error_kind, accuracy, false, false, 0, 0, 0};
    std::vector<const WorkPrecisionPoint*> points;
    for (const WorkPrecisionPoint& p : line.points)
        if (std::isfinite(p.error) && p.error > 0 && p.seconds_per_time_unit > 0) points.push_back(&p);
    std::sort(points.begin(), points.end(), [](auto* a, auto* b) { return a->dt > b->dt; });
    for (std::size_t k = 0; k < points.size(); ++k) {
        const WorkPrecisionPoint& p = *points[k];
        if (p.error > accuracy) continue;
        c.reached = true;
        if (k == 0) {
            c.at_most = true;
            c.seconds_per_time_unit = c.low = c.high = p.seconds_per_time_unit;
            return c;
        }
        const WorkPrecisionPoint& q = *points[k - 1];  // the coarser point, beyond the accuracy
        const double f = std::log(accuracy / q.error) / std::log(p.error / q.error);
        c.seconds_per_time_unit =
            std::exp(std::log(q.seconds_per_time_unit) + f * std::log(p.seconds_per_time_unit / q.seconds_per_time_unit));
        c.low = std::min(p.seconds_per_time_unit, q.seconds_per_time_unit);
        c.high = std::max(p.seconds_per_time_unit, q.seconds_per_time_unit);
        return c;
    }
    return c;
}

bool has_limit(const CheckResult& c) { return std::isfinite(c.tolerance) && c.tolerance != 0; }

bool passes(double value, double tolerance, const std::string& comparison) {
    return comparison == ">=" ? value >= tolerance : std::fabs(value) <= tolerance;
}

// A check's subject with the backend's token taken out ("gas__box2d-shipped__dt0.004__seed1" ->
// "gas____dt0.004__seed1"), so that a variant's case meets its base's case of the same scene,
// dt and seed.
std::string subject_without_backend(const CheckResult& c) {
    const std::string token = "__" + backend_id_token(c.backend);
    const std::size_t at = c.subject.find(token);
    return at == std::string::npos ? c.subject : c.subject.substr(0, at) + "__" + c.subject.substr(at + token.size());
}

// Each value of the variant's checks against its base's limit for the same check and case; only
// where the base judged the check with a limit and the variant measured a finite value (its own
// check may be left out as "does not apply": the value still says what it does).
std::optional<UnderPresetLimits> under_base_limits(const std::string& variant, const std::vector<CheckResult>& checks) {
    const std::string base = variant.substr(0, variant.find('['));
    if (base == variant) return std::nullopt;
    std::map<std::pair<std::string, std::string>, const CheckResult*> limits;  // (subject, check) -> base's check
    for (const CheckResult& c : checks)
        if (c.backend == base && c.status != CheckStatus::left_out && has_limit(c))
            limits[{subject_without_backend(c), c.check}] = &c;
    if (limits.empty()) return std::nullopt;
    UnderPresetLimits u{base, 0, 0, {}};
    for (const CheckResult& c : checks) {
        if (c.backend != variant || !std::isfinite(c.value)) continue;
        const auto it = limits.find({subject_without_backend(c), c.check});
        if (it == limits.end()) continue;
        ++u.compared;
        if (!passes(c.value, it->second->tolerance, it->second->comparison)) {
            ++u.failing;
            ++u.failing_by_check[c.check];
        }
    }
    return u;
}

// Why the backend's scene has no error against the reference: the detail of a comparison check
// of it that was left out, else that the suite asks for no comparison of the scene.
std::string why_checked_only(const std::string& backend, const std::string& scene, const std::vector<CheckResult>& checks) {
    static const std::set<std::string> comparisons = {"trajectory_error", "pressure", "collision_rate"};
    for (const CheckResult& c : checks)
        if (c.backend == backend && c.scene == scene && comparisons.count(c.check) && c.status == CheckStatus::left_out &&
            !c.detail.empty())
            return c.detail;
    return "the suite sets no `compare` for this scene; where it has physics rows, they hold it against published values";
}

// Scenes whose every `run` check of the backend is left out, and scenes it ran.
void scenes_run(const std::string& backend, const std::vector<CheckResult>& checks, std::set<std::string>& ran,
                std::set<std::string>& declined) {
    for (const CheckResult& c : checks)
        if (c.backend == backend && c.check == "run") (c.status == CheckStatus::left_out ? declined : ran).insert(c.scene);
    for (const std::string& s : ran) declined.erase(s);
}

}  // namespace

std::optional<double> stated_accuracy(const std::string& error_kind, const VerdictThresholds& thresholds) {
    if (error_kind.find("trajectory") != std::string::npos) return thresholds.trajectory_accuracy;
    if (error_kind.find("Z_ref") != std::string::npos) return thresholds.pressure_accuracy;
    if (error_kind.find("tau_ref") != std::string::npos) return thresholds.cooling_accuracy;
    if (error_kind.find("nu_ref") != std::string::npos) return thresholds.collision_rate_accuracy;
    return std::nullopt;
}

std::map<std::string, AccuracyVerdict> accuracy_verdicts(const std::string& reference,
                                                         const std::vector<CheckResult>& checks,
                                                         const std::vector<WorkPrecisionLine>& lines,
                                                         const VerdictThresholds& thresholds) {
    std::set<std::string> backends;
    for (const CheckResult& c : checks) backends.insert(c.backend);
    std::map<std::string, AccuracyVerdict> out;
    for (const std::string& b : backends) {
        AccuracyVerdict& v = out[b];
        std::set<std::string> measured, ran, declined;
        const std::set<std::string> z_passed = passing_subjects(b, "pressure", checks);
        for (const WorkPrecisionLine& line : lines) {
            if (line.backend != b) continue;
            // Z is held to the stated Z accuracy on every line that measures it, whatever the
            // line's own error (a cooling gas's line may be judged by another statistic).
            if (auto l = low_power_pass(line, thresholds.pressure_accuracy, z_passed)) v.low_power.push_back(*l);
            const auto accuracy = stated_accuracy(line.error_kind, thresholds);
            if (!accuracy) continue;
            judge_line(line, *accuracy, v);
            v.cost_at_accuracy.push_back(cost_at(line, *accuracy));
            measured.insert(line.scene);
        }
        scenes_run(b, checks, ran, declined);
        for (const std::string& s : ran)
            if (!measured.count(s)) {
                v.checked_only.push_back(s);
                v.checked_only_reasons[s] = b == reference ? "the reference: the other backends are compared with it"
                                                           : why_checked_only(b, s, checks);
            }
        v.cannot_run.assign(declined.begin(), declined.end());
        if (b != reference) v.under_preset_limits = under_base_limits(b, checks);
    }
    return out;
}

}  // namespace collide::validation
