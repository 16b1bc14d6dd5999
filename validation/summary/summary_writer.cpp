#include "validation/summary/summary_writer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <thread>
#include <vector>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/io/output_file.h"
#include "core/io/provenance.h"
#include "validation/compare/predictability_horizon.h"
#include "validation/record/check_table.h"
#include "validation/models/bias_fit.h"
#include "validation/models/statistics_bias_model.h"
#include "validation/summary/drawn_cases.h"
#include "validation/summary/accuracy_verdicts.h"
#include "validation/summary/verdict_facts.h"

namespace collide::validation {
namespace {

// nlohmann::ordered_json keeps the keys in the order they are set, so the file lists them in
// the order below (id, scene, backend, ...), as a reader expects. NaN and infinities, which
// JSON lacks, are written as null (the report shows "n/a").
using Json = nlohmann::ordered_json;

// A JSON object built field by field (the chained calls below read like the file they write).
class Object {
public:
    Object& field(const std::string& key, Json value) {
        json_[key] = std::move(value);
        return *this;
    }
    Object& text(const std::string& key, const std::string& v) { return field(key, v); }
    Object& number(const std::string& key, double v) { return field(key, v); }
    Object& integer(const std::string& key, long long v) { return field(key, v); }
    Object& boolean(const std::string& key, bool v) { return field(key, v); }
    const Json& json() const { return json_; }

private:
    Json json_ = Json::object();
};

template <typename Range, typename ToJson>
Json array(const Range& items, ToJson&& to_json) {
    Json out = Json::array();
    for (const auto& item : items) out.push_back(to_json(item));
    return out;
}

Json nullable(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json string_map(const std::map<std::string, std::string>& m) {
    Object o;
    for (const auto& [k, v] : m) o.text(k, v);
    return o.json();
}

const char* to_string(CheckKind kind) {
    switch (kind) {
        case CheckKind::case_check: return "case";
        case CheckKind::trajectory: return "trajectory";
        case CheckKind::statistics: return "statistics";
        case CheckKind::stability: return "stability";
    }
    return "case";
}

// The check table (check_table.h), in its order: the report lays out its columns from it.
Json check_definitions_json() {
    return array(check_table, [](const CheckDefinition& c) {
        Object o;
        o.text("name", c.name).text("kind", to_string(c.kind)).text("measures", c.measures)
            .text("passes_when", c.passes_when).text("tolerance_key", c.tolerance_key).text("applies", c.applies)
            .text("computed_by", c.computed_by);
        return o.json();
    });
}

double per_time_unit(const CaseResult& r) {
    return r.finished() && r.duration > 0 && std::isfinite(r.wall_seconds) ? r.wall_seconds / r.duration : std::nan("");
}

Json numbers_json(const std::vector<double>& v) { return array(v, [](double x) { return nullable(x); }); }

// A trajectory case's judgement up to its reference's predictability horizon
// (predictability_horizon.h): the horizon and what was judged; the series themselves only for
// a drawn case (the report draws them: error, limit and twin separation against time).
Json trajectory_json(const TrajectoryJudgement& j, bool series) {
    Object o;
    o.field("horizon", nullable(j.horizon.time)).boolean("horizon_reached", j.horizon.reached)
        .field("first_unjudged", nullable(j.horizon.first_unjudged)).number("threshold", j.horizon.threshold)
        .number("margin", horizon_margin).integer("twins", j.measured ? horizon_twins : 0)
        .boolean("judged", j.judged()).integer("judged_outputs", (long long)j.horizon.judged)
        .integer("outputs", (long long)j.times.size()).boolean("exact", j.exact);
    if (!j.limit.empty())
        o.number("worst_time", j.times[j.worst]).field("worst_error", nullable(j.error[j.worst]))
            .number("worst_limit", j.limit[j.worst]);
    if (series)
        o.field("times", numbers_json(j.times)).field("error", numbers_json(j.error))
            .field("twin_separation", numbers_json(j.twin_separation)).field("limit", numbers_json(j.limit));
    return o.json();
}

Json case_json(const CaseResult& r, const Classification* c, bool frames, bool drawn,
               const TrajectoryJudgement* trajectory) {
    Object o;
    o.text("id", r.spec.id).text("scene", r.spec.scene).text("backend", r.spec.backend)
        .boolean("reference", r.spec.reference).text("group", group_id(r.spec))
        .integer("seed", (long long)r.spec.seed).number("dt", r.dt).integer("substeps", r.substeps)
        .field("iterations", r.spec.iterations ? Json(*r.spec.iterations) : Json(nullptr))
        .text("status", to_string(r.status)).text("diagnostic", r.diagnostic)
        .integer("disks", (long long)r.disks).number("duration", r.duration)
        .number("wall_seconds", r.wall_seconds).number("warmup_seconds", r.warmup_seconds)
        .integer("steps", r.steps).integer("contacts", r.contacts)
        .integer("outputs", (long long)r.series.size())
        .field("seconds_per_time_unit", nullable(per_time_unit(r)))
        .text("result_file", "cases/" + r.spec.id + ".toml").text("hdf5_file", r.hdf5_file)
        .boolean("frames", !r.hdf5_file.empty() && frames).boolean("drawn", drawn)
        .field("provenance", string_map(r.provenance));
    Object phases;
    for (const auto& [k, v] : r.phase_seconds) phases.number(k, v);
    o.field("phase_seconds", phases.json());
    Object parameters;  // path -> value of the scene-parameter sweep point
    for (const auto& [path, value] : r.spec.parameters) parameters.number(path, value);
    o.field("parameters", parameters.json());
    if (c) o.text("outcome", to_string(c->outcome)).text("outcome_reason", c->reason);
    if (trajectory) o.field("trajectory", trajectory_json(*trajectory, drawn));
    return o.json();
}

// measured / tolerance for an upper bound, tolerance / measured for a lower bound (the KS
// p-value): 1 is at the tolerance, above 1 fails. NaN where there is no number to compare.
double margin(const CheckResult& c) {
    if ((c.status != CheckStatus::pass && c.status != CheckStatus::fail) || !std::isfinite(c.value) ||
        !(c.tolerance > 0) || c.comparison.empty())
        return std::nan("");
    if (c.comparison == ">=") return c.value <= 0 ? std::numeric_limits<double>::infinity() : c.tolerance / c.value;
    return std::fabs(c.value) / c.tolerance;
}

// A check whose value counts something per disk (overlapping pairs / N) can take only the
// values k / N: with fewer than overlapping_pairs_counted_from steps below its tolerance, its
// margin is a count (for two disks 0 or 0.5), not a measure of how close the backend came. The
// judge leaves such a count out (overlap_beyond_step judges in its place), so a judged one is
// never quantised; the flag stays in summary.json for the report that reads it.
bool quantised(const CheckResult& c, long long disks) {
    return c.check == "overlapping_pairs" && disks > 0 && c.tolerance * double(disks) < overlapping_pairs_counted_from;
}

Json check_json(const CheckResult& c, long long disks) {
    Object o;
    o.text("subject", c.subject).text("scene", c.scene).text("backend", c.backend).text("check", c.check)
        .text("status", to_string(c.status)).number("value", c.value).number("tolerance", c.tolerance)
        .text("comparison", c.comparison).field("margin", nullable(margin(c)))
        .boolean("quantised", quantised(c, disks)).text("detail", c.detail);
    // a stepped backend's energy drift, pressure or collision rate: what the rule's model predicts
    // (energy_loss_model.h, statistics_bias_model.h)
    if (!std::isnan(c.predicted))
        o.number("predicted", c.predicted).number("predicted_uncertainty", c.predicted_uncertainty);
    return o.json();
}

// The checks, each with the disk count of its case or group (the subject is a case id or a
// sweep group's id).
Json checks_json(const SuiteOutcome& outcome) {
    std::map<std::string, long long> disks;
    for (const auto& r : outcome.cases) {
        disks[r.spec.id] = (long long)r.disks;
        disks[group_id(r.spec)] = (long long)r.disks;
    }
    return array(outcome.checks, [&](const CheckResult& c) {
        const auto it = disks.find(c.subject);
        return check_json(c, it == disks.end() ? 0 : it->second);
    });
}

// The checks' names in the order the suite produced them first: the report's column order.
Json check_order_json(const SuiteOutcome& outcome) {
    Json out = Json::array();
    for (const auto& c : outcome.checks)
        if (std::find(out.begin(), out.end(), c.check) == out.end()) out.push_back(c.check);
    return out;
}

// What the report needs to know of each backend of the run, so that it names none itself: what
// the backend declares (BackendInfo: precision, exact, rule, conserves), which every judgement
// of it read. `stepping_rule` is whether it declares a rule; a variant inherits its base's.
//
// `ran_on`: what its first case's provenance says it ran on, found by the keys' endings so that
// every backend names them alike: the device, its type and platform (an OpenCL device: PoCL is a
// CPU device), the precision it computed in ("real"), its threads per case, its preset, and for
// an engine its version and the hashes of its package files (an outside solver's `files`).
Json ran_on_json(const std::map<std::string, std::string>& provenance) {
    const auto ends = [](const std::string& key, const std::string& tail) {
        return key.size() >= tail.size() && key.compare(key.size() - tail.size(), tail.size(), tail) == 0;
    };
    Object o;
    for (const auto& [key, value] : provenance) {
        if (ends(key, "_device")) o.text("device", value);
        else if (ends(key, "_device_type")) o.text("device_type", value);
        else if (ends(key, "_platform")) o.text("platform", value);
        else if (key == "real") o.text("precision", value);
        else if (ends(key, "threads")) o.text("threads", value);
        else if (ends(key, "_preset")) o.text("preset", value);
        else if (ends(key, "_version") && !ends(key, "_device_version")) o.text("version", value);
        else if (key == "solver_files_sha256") o.text("files_sha256", value);
        else if (key == "variant_settings") o.text("variant_settings", value);
    }
    return o.json();
}

Json backends_json(const Suite& suite, const SuiteOutcome& outcome) {
    Object o;
    for (const auto& r : outcome.cases) {
        const std::string& b = r.spec.backend;
        if (o.json().contains(b)) continue;
        const auto d = outcome.declared.find(b);
        const BackendInfo declared = d == outcome.declared.end() ? BackendInfo{} : d->second;
        Json conserves = Json::array();
        for (const auto& q : declared.conserves) conserves.push_back(q);
        Object x;
        x.text("base", b.substr(0, b.find('['))).text("precision", declared.precision)
            .boolean("float", declared.single_precision()).boolean("reference", b == suite.reference)
            .boolean("stepping_rule", declared.stepping_rule()).text("rule", declared.rule)
            .boolean("exact", declared.exact).boolean("sampler", declared.sampler)
            .field("conserves", conserves).text("description", declared.description)
            .field("ran_on", ran_on_json(r.provenance));
        o.field(b, x.json());
    }
    return o.json();
}

// What each backend costs on each scene: per sweep group the mean over replicates of wall
// seconds per simulated time unit (with the smallest and largest replicate, the timing noise),
// the cheapest group kept; `relative_to_reference` divides by the reference's cost on the scene.
Json costs_json(const Suite& suite, const SuiteOutcome& outcome) {
    struct Group { std::string scene, backend, id; double dt = 0; std::vector<double> seconds; };
    std::vector<Group> groups;
    std::map<std::string, std::size_t> index;
    for (const auto& r : outcome.cases) {
        const double s = per_time_unit(r);
        if (!std::isfinite(s)) continue;
        const std::string id = group_id(r.spec);
        if (!index.count(id)) {
            index[id] = groups.size();
            groups.push_back({r.spec.scene, r.spec.backend, id, r.dt, {}});
        }
        groups[index[id]].seconds.push_back(s);
    }
    std::vector<std::pair<const Group*, double>> cheapest;  // per (scene, backend), in first-seen order
    std::map<std::pair<std::string, std::string>, std::size_t> at;
    for (const auto& g : groups) {
        double mean = 0;
        for (double x : g.seconds) mean += x / double(g.seconds.size());
        const auto key = std::make_pair(g.scene, g.backend);
        if (!at.count(key)) {
            at[key] = cheapest.size();
            cheapest.push_back({&g, mean});
        } else if (mean < cheapest[at[key]].second) {
            cheapest[at[key]] = {&g, mean};
        }
    }
    Json out = Json::array();
    for (const auto& [g, mean] : cheapest) {
        const auto ref = at.find({g->scene, suite.reference});
        const double reference = ref == at.end() ? std::nan("") : cheapest[ref->second].second;
        Object o;
        o.text("scene", g->scene).text("backend", g->backend).text("group", g->id).number("dt", g->dt)
            .number("seconds_per_time_unit", mean)
            .number("fastest_replicate", *std::min_element(g->seconds.begin(), g->seconds.end()))
            .number("slowest_replicate", *std::max_element(g->seconds.begin(), g->seconds.end()))
            .integer("replicates", (long long)g->seconds.size())
            .field("relative_to_reference", nullable(mean / reference));
        out.push_back(o.json());
    }
    return out;
}

// The machine the timings were taken on: its processor, its cores, and the load averages over
// the last 1, 5 and 15 minutes when the run ended (/proc/loadavg; the 5-minute one covers most
// of a default-suite run), so that a reader can tell an idle machine from an oversubscribed one.
Json machine_json() {
    Object o;
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model;
    while (model.empty() && std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
            model = line.substr(line.find(':') + 2);
    o.text("cpu_model", model).integer("cores", (long long)std::thread::hardware_concurrency());
    std::ifstream loadavg("/proc/loadavg");
    double l1 = std::nan(""), l5 = std::nan(""), l15 = std::nan("");
    loadavg >> l1 >> l5 >> l15;
    o.field("load_1min", nullable(l1)).field("load_5min", nullable(l5)).field("load_15min", nullable(l15));
    return o.json();
}

Json difference_json(const std::optional<StatisticalDifference>& d) {
    if (!d) return nullptr;
    Object o;
    o.number("mean", d->mean).number("standard_error", d->standard_error).number("reference", d->reference)
        .number("reference_standard_error", d->reference_standard_error).number("relative", d->relative)
        .number("relative_standard_error", d->relative_standard_error).number("sigmas", d->sigmas)
        .boolean("resolved", d->resolved).number("upper_limit_95", d->upper_limit_95)
        .number("detectable", d->detectable).field("predicted", nullable(d->predicted))
        .field("predicted_uncertainty", nullable(d->predicted_uncertainty))
        .integer("replicates", (long long)d->replicates)
        .integer("reference_replicates", (long long)d->reference_replicates).boolean("paired", d->paired);
    if (d->paired)
        o.number("difference", d->difference).number("difference_standard_error", d->difference_standard_error);
    return o.json();
}

// The order on the asymptotic range (convergence_order.h) with the range it was fitted on and
// the floor below it; "order" and "order_standard_error" stay top-level numbers of the line.
Json order_json(const ConvergenceOrder& c) {
    Object o;
    o.integer("used", (long long)c.used).integer("points", (long long)c.points).number("h_coarse", c.h_coarse)
        .number("h_fine", c.h_fine).boolean("bending", c.bending);
    if (c.floor) {
        Object f;
        f.number("h", c.floor->h).number("error", c.floor->error).number("finest_h", c.floor->finest_h)
            .number("finest_error", c.floor->finest_error).integer("excluded", (long long)c.floor->excluded);
        o.field("floor", f.json());
    } else {
        o.field("floor", nullptr);
    }
    return o.json();
}

Json line_json(const WorkPrecisionLine& line) {
    Object o;
    o.text("scene", line.scene).text("backend", line.backend).text("error_kind", line.error_kind)
        .number("order", line.order.order ? *line.order.order : std::nan(""))
        .number("order_standard_error", line.order.standard_error ? *line.order.standard_error : std::nan(""))
        .text("order_note", line.order.note).field("order_range", order_json(line.order));
    o.field("points", array(line.points, [](const WorkPrecisionPoint& p) {
        Object q;
        q.text("group", p.group).number("dt", p.dt).integer("substeps", p.substeps)
            .integer("iterations", p.iterations).number("seconds_per_time_unit", p.seconds_per_time_unit)
            .number("error", p.error).number("error_standard_error", p.error_standard_error)
            .integer("replicates", (long long)p.replicates)
            .field("pressure", difference_json(p.pressure)).field("collision_rate", difference_json(p.collision_rate))
            .field("paired", difference_json(p.paired));
        return q.json();
    }));
    return o.json();
}

Json bias_fit_json(const BiasConstantFit& f) {
    Object o;
    o.text("backend", f.backend).text("observable", f.observable).number("constant", f.constant)
        .number("standard_error", f.standard_error).number("model", f.model)
        .number("model_uncertainty", f.model_uncertainty).number("chi2", f.chi2)
        .integer("degrees_of_freedom", (long long)f.points - 1).number("chi2_model", f.chi2_model)
        .integer("points", (long long)f.points);
    return o.json();
}

// The numbers a z row's score was computed from, with z signed (null where the row has none).
Json score_from_json(const PhysicsRow::ScoreInputs& f) {
    if (!std::isfinite(f.value)) return nullptr;
    Object o;
    o.text("estimator", f.estimator).number("value", f.value).field("standard_error", nullable(f.standard_error))
        .number("reference", f.reference).number("reference_uncertainty", f.reference_uncertainty)
        .number("degrees_of_freedom", f.degrees_of_freedom)
        // the signed quotient: z for a batch-means SE, Student's t for a replicate scatter
        .field(f.degrees_of_freedom > 0 ? "t" : "z",
               nullable((f.value - f.reference) / std::hypot(f.standard_error, f.reference_uncertainty)));
    return o.json();
}

Json physics_row_json(const PhysicsRow& r) {
    Object o;
    o.text("row", r.row).text("scene", r.scene).text("backend", r.backend).text("group", r.group)
        .text("parameter_name", r.parameter_name).number("parameter", r.parameter).text("measured", r.measured)
        .text("estimator", r.estimator).number("value", r.value).number("standard_error", r.standard_error)
        .integer("replicates", (long long)r.replicates).number("reference", r.reference)
        .number("reference_uncertainty", r.reference_uncertainty).text("reference_name", r.reference_name)
        .text("citation", r.citation).number("second_reference", r.second_reference)
        .text("second_reference_name", r.second_reference_name).text("statistic", r.statistic)
        .number("score", r.score).field("score_from", score_from_json(r.score_from)).boolean("resolved", r.resolved).text("verdict", to_string(r.verdict))
        .text("detail", r.detail);
    if (!r.published.empty()) {  // a published finite-N row (published_rows.h)
        Object facts;
        for (const auto& [name, value] : r.facts) facts.field(name, nullable(value));
        o.text("published", r.published).text("box", r.box).field("facts", facts.json());
    }
    return o.json();
}

Json physics_json(const PhysicsComparison& p) {
    Object o;
    o.field("rows", array(p.rows, physics_row_json));
    o.field("curves", array(p.curves, [](const ReferenceCurve& c) {
        Object q;
        q.text("name", c.name).text("citation", c.citation).field("eta", c.eta).field("z", c.z);
        return q.json();
    }));
    o.number("z_max", p.z_max);
    return o.json();
}

std::string xml_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') ? ' ' : c;
        }
    }
    return out;
}

Json cases_json(const Suite& suite, const SuiteOutcome& outcome) {
    Json out = Json::array();
    const std::vector<bool> drawn = drawn_cases(outcome.cases);
    for (std::size_t k = 0; k < outcome.cases.size(); ++k) {
        const Classification* c = k < outcome.classifications.size() ? &outcome.classifications[k] : nullptr;
        const CaseSpec& spec = outcome.cases[k].spec;
        const bool frames = spec.scene_index < suite.scenes.size() && stores_frames(suite, suite.scenes[spec.scene_index]);
        const auto judgement = outcome.trajectories.find(spec.id);
        out.push_back(case_json(outcome.cases[k], c, frames, drawn[k],
                                judgement == outcome.trajectories.end() ? nullptr : &judgement->second));
    }
    return out;
}

Json thresholds_json(const VerdictThresholds& t) {
    Object o;
    o.number("loose_tolerance_ratio", t.loose_tolerance_ratio).number("energy_drift", t.energy_drift)
        .number("pressure_sigmas", t.pressure_sigmas).number("trajectory_accuracy", t.trajectory_accuracy)
        .number("pressure_accuracy", t.pressure_accuracy).number("cooling_accuracy", t.cooling_accuracy)
        .number("collision_rate_accuracy", t.collision_rate_accuracy).number("confidence_z", confidence_95);
    return o.json();
}

Json strings_json(const std::vector<std::string>& v) { return array(v, [](const std::string& s) { return Json(s); }); }

// What a backend can be used for, from its measured accuracy (accuracy_verdicts.h).
Json accuracy_json(const AccuracyVerdict& v) {
    Object o;
    o.field("use_for", array(v.use_for, [](const UseFor& u) {
        Object x;
        x.text("scene", u.scene).text("error_kind", u.error_kind).number("accuracy", u.accuracy).number("dt", u.dt)
            .number("error", u.error).number("standard_error", u.standard_error)
            .integer("replicates", (long long)u.replicates).number("confidence_factor", u.confidence_factor);
        return x.json();
    }));
    o.field("not_for", array(v.not_for, [](const NotFor& n) {
        Object x;
        x.text("scene", n.scene).text("error_kind", n.error_kind).number("accuracy", n.accuracy)
            .number("dt_min", n.dt_min).number("dt_max", n.dt_max).number("dt", n.dt).number("error", n.error)
            .number("standard_error", n.standard_error).field("sigmas", nullable(n.sigmas))
            .integer("replicates", (long long)n.replicates).boolean("resolved", n.resolved)
            .number("confidence_factor", n.confidence_factor);
        return x.json();
    }));
    o.field("cost_at_accuracy", array(v.cost_at_accuracy, [](const CostAtAccuracy& c) {
        Object x;
        x.text("scene", c.scene).text("error_kind", c.error_kind).number("accuracy", c.accuracy)
            .boolean("reached", c.reached).boolean("at_most", c.at_most);
        if (c.reached) x.number("seconds_per_time_unit", c.seconds_per_time_unit).number("low", c.low).number("high", c.high);
        return x.json();
    }));
    o.field("low_power", array(v.low_power, [](const LowPowerPass& l) {
        Object x;
        x.text("scene", l.scene).text("check", l.check).number("accuracy", l.accuracy).number("dt_min", l.dt_min)
            .number("dt_max", l.dt_max).number("detectable", l.detectable)
            .integer("replicates", (long long)l.replicates).integer("passes", (long long)l.passes);
        return x.json();
    }));
    Object reasons;
    for (const auto& [scene, why] : v.checked_only_reasons) reasons.text(scene, why);
    o.field("checked_only", strings_json(v.checked_only)).field("checked_only_reasons", reasons.json())
        .field("cannot_run", strings_json(v.cannot_run));
    if (v.under_preset_limits) {
        const UnderPresetLimits& u = *v.under_preset_limits;
        Object by_check;
        for (const auto& [check, n] : u.failing_by_check) by_check.integer(check, (long long)n);
        Object x;
        x.text("preset", u.preset).integer("compared", (long long)u.compared).integer("failing", (long long)u.failing)
            .field("failing_by_check", by_check.json());
        o.field("under_preset_limits", x.json());
    } else {
        o.field("under_preset_limits", nullptr);
    }
    return o.json();
}

// What each backend's verdict names (verdict_facts.h): the report words it, deciding nothing.
Json verdicts_json(const Suite& suite, const SuiteOutcome& outcome) {
    std::map<std::string, bool> stepping_rule;  // what each backend declares (BackendInfo::rule)
    for (const auto& [name, backend] : outcome.declared) stepping_rule[name] = backend.stepping_rule();
    const auto accuracy = accuracy_verdicts(suite.reference, outcome.checks, outcome.work_precision, suite.verdicts);
    Object out;
    for (const auto& [backend, f] : verdict_facts(suite.reference, outcome.checks, outcome.work_precision,
                                                   suite.verdicts, stepping_rule)) {
        Object o;
        if (f.loosest_tolerance) {
            Object l;
            l.number("ratio", f.loosest_tolerance->ratio).text("check", f.loosest_tolerance->check)
                .number("tolerance", f.loosest_tolerance->tolerance).boolean("named", f.loosest_tolerance->named);
            o.field("loosest_tolerance", l.json());
        } else {
            o.field("loosest_tolerance", nullptr);
        }
        if (f.largest_energy_drift) {
            Object d;
            d.number("value", f.largest_energy_drift->value).text("scene", f.largest_energy_drift->scene)
                .boolean("named", f.largest_energy_drift->named);
            o.field("largest_energy_drift", d.json());
        } else {
            o.field("largest_energy_drift", nullptr);
        }
        const PressureOffset& p = f.pressure_offset;
        Object q;
        q.field("sigmas", p.sigmas ? Json(*p.sigmas) : Json(nullptr)).boolean("left_out", p.left_out)
            .boolean("named", p.named);
        o.field("pressure_offset", q.json());
        const auto a = accuracy.find(backend);
        o.field("accuracy", a == accuracy.end() ? Json(nullptr) : accuracy_json(a->second));
        out.field(backend, o.json());
    }
    return out.json();
}

// A stability suite's unexpected cases (stability.h), none for another suite (it classifies none).
Json unexpected_json(const Suite& suite, const SuiteOutcome& outcome) {
    Json out = Json::array();
    if (suite.stability)
        for (const std::string& line : unexpected_outcomes(outcome.cases, outcome.classifications)) out.push_back(line);
    return out;
}

Json outcome_order_json() {
    Json out = Json::array();
    for (Outcome o : outcome_precedence) out.push_back(to_string(o));
    return out;
}

}  // namespace

void write_summary_json(const Suite& suite, const SuiteOutcome& outcome, const std::string& path) {
    Object counts;
    counts.integer("pass", (long long)outcome.count(CheckStatus::pass))
        .integer("fail", (long long)outcome.count(CheckStatus::fail))
        .integer("left_out", (long long)outcome.count(CheckStatus::left_out))
        .integer("physics_fail", (long long)outcome.physics_failures());
    std::map<std::string, std::string> seeds;
    for (const auto& s : suite.scenes) {
        std::string list;
        for (auto seed : s.seeds.empty() ? suite.seeds : s.seeds) {
            if (!list.empty()) list += ' ';
            list += std::to_string(seed);
        }
        seeds[s.name] = list;
    }
    std::map<std::string, std::string> scene_files;
    // Absolute paths: `collide report` and `collide explain` may run from another directory.
    auto absolute = [](const std::string& path) {
        return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
    };
    for (const auto& s : suite.scenes) scene_files[s.name] = absolute(s.path);
    Object root;
    root.text("suite", suite.name).boolean("stability", suite.stability).text("description", suite.description).text("suite_file", absolute(suite.source_path))
        .text("reference", suite.reference).boolean("passed", outcome.passed())
        .number("wall_seconds", outcome.wall_seconds).integer("cases_run", (long long)outcome.cases_run)
        .integer("cases_resumed", (long long)outcome.cases_resumed).field("counts", counts.json())
        .field("provenance", string_map(build_provenance())).text("command_line", command_line())
        .field("execution", string_map(outcome.execution))
        .field("seeds", string_map(seeds)).field("scene_files", string_map(scene_files))
        .field("cases", cases_json(suite, outcome))
        .field("check_definitions", check_definitions_json())
        .field("machine", machine_json()).field("backends", backends_json(suite, outcome))
        .field("check_order", check_order_json(outcome))
        .field("checks", checks_json(outcome))
        .field("work_precision", array(outcome.work_precision, line_json))
        .field("bias_fits", array(fit_bias_constants(outcome.work_precision), bias_fit_json))
        .field("costs", costs_json(suite, outcome))
        .field("physics", physics_json(outcome.physics))
        .field("verdict_thresholds", thresholds_json(suite.verdicts)).field("verdicts", verdicts_json(suite, outcome))
        .field("unexpected_outcomes", unexpected_json(suite, outcome)).field("outcome_order", outcome_order_json())
        .field("energy_jumps", Json::parse(outcome.energy_jumps.dump()));  // report_jumps.h
    // Bytes that are not UTF-8 (in a path or a diagnostic) are replaced, not fatal: the summary
    // of a suite that ran for hours must still be written.
    write_file_atomically(path, root.json().dump(1, ' ', false, Json::error_handler_t::replace) + "\n");
}

void write_junit_xml(const Suite& suite, const SuiteOutcome& outcome, const std::string& path) {
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    x << "<testsuites name=\"" << xml_escape(suite.name) << "\" tests=\"" << outcome.checks.size()
      << "\" failures=\"" << outcome.count(CheckStatus::fail) << "\" skipped=\""
      << outcome.count(CheckStatus::left_out) << "\" time=\"" << outcome.wall_seconds << "\">\n";
    x << "  <testsuite name=\"" << xml_escape(suite.name) << "\" tests=\"" << outcome.checks.size()
      << "\" failures=\"" << outcome.count(CheckStatus::fail) << "\" skipped=\""
      << outcome.count(CheckStatus::left_out) << "\">\n";
    for (const auto& c : outcome.checks) {
        x << "    <testcase classname=\"" << xml_escape(c.subject) << "\" name=\"" << xml_escape(c.check) << "\"";
        if (c.status == CheckStatus::pass) {
            x << "/>\n";
            continue;
        }
        x << ">\n      <" << (c.status == CheckStatus::fail ? "failure" : "skipped") << " message=\""
          << xml_escape(c.detail) << "\"/>\n    </testcase>\n";
    }
    x << "  </testsuite>\n</testsuites>\n";
    write_file_atomically(path, x.str());
}

}  // namespace collide::validation
