#include "validation/plan/case_plan.h"

#include <algorithm>
#include <map>

#include "validation/plan/backend_variant.h"
#include "core/numerics/number_text.h"

namespace collide::validation {
namespace {

// dt and `set` values in ids: the shortest text that reads back as the same double
// (core/numerics/number_text.h). "%g" kept six digits, so dt = 0.0010000001 and 0.001 shared an id and
// one case's record overwrote the other's.
std::string format_number(double v) { return round_trip_text(v); }

std::string make_id(const CaseSpec& c) {
    std::string id = c.scene + "__" + backend_id_token(c.backend);
    if (!c.parameters.empty()) id += "__" + parameter_label(c);
    if (c.dt) id += "__dt" + format_number(*c.dt);
    if (c.substeps) id += "__sub" + std::to_string(*c.substeps);
    if (c.iterations) id += "__it" + std::to_string(*c.iterations);
    return id + "__seed" + std::to_string(c.seed);
}

// A [[scene]] with `backends = [...]` runs on those alone (the physics scenes: event only,
// where the other backends would only spend the suite's time budget).
bool runs_on(const SuiteScene& entry, const std::string& backend) {
    return entry.backends.empty() || std::find(entry.backends.begin(), entry.backends.end(), backend) != entry.backends.end();
}

// A sweep with no values is one point: "the scene's own setting".
template <typename T>
std::vector<std::optional<T>> sweep(const std::vector<T>& values) {
    if (values.empty()) return {std::nullopt};
    return {values.begin(), values.end()};
}

}  // namespace

std::string parameter_label(const CaseSpec& spec) {
    std::string label;
    for (const auto& [path, value] : spec.parameters)
        label += (label.empty() ? "" : "__") + path + "=" + format_number(value);
    return label;
}

std::vector<std::vector<std::pair<std::string, double>>> parameter_points(const SuiteScene& entry) {
    std::vector<std::vector<std::pair<std::string, double>>> points = {{}};
    for (const SceneParameter& p : entry.set) {
        std::vector<std::vector<std::pair<std::string, double>>> next;
        for (const auto& point : points)
            for (double v : p.values) {
                next.push_back(point);
                next.back().emplace_back(p.path, v);
            }
        points = std::move(next);
    }
    return points;
}

namespace {

const BackendInfo* find_available(const std::string& name, const std::vector<BackendInfo>& available) {
    for (const auto& b : available)
        if (b.name == name) return &b;
    return nullptr;
}

const BackendVariant* find_variant(const std::string& label, const Suite& suite) {
    for (const auto& v : suite.variants)
        if (v.label == label) return &v;
    return nullptr;
}

[[noreturn]] void unknown_backend(const Suite& suite, const std::string& name, const std::vector<BackendInfo>& available) {
    std::string names;
    for (const auto& b : available) names += (names.empty() ? "" : ", ") + b.name;
    for (const auto& v : suite.variants) names += ", " + v.label;
    throw SuiteError(suite.source_path + ": backends: unknown backend '" + name +
                     "'; expected \"all\" or names from: " + names);
}

// Where a case comes from in the suite file, for messages: "suite.toml:12 ([[scene]] 'gas')".
std::string origin(const Suite& suite, const CaseSpec& c) {
    const SuiteScene& entry = suite.scenes[c.scene_index];
    std::string where = suite.source_path.empty() ? std::string("suite") : suite.source_path;
    if (entry.line) where += ":" + std::to_string(entry.line);
    return where + " ([[scene]] #" + std::to_string(c.scene_index + 1) + " '" + entry.name + "')";
}

// A case id names the case's record and run file, its --resume entry and its report row: two
// cases with one id would write one file and lose the other result. Refused before any case
// runs, naming both sources and the usual causes.
// What a backend of the suite is and where it was named, for messages: "the outside solver
// 'box2d-shipped' (--solver)", "the variant 'box2d[shipped]' (suite.toml, [variant."box2d[shipped]"])".
std::string backend_origin(const Suite& suite, const std::string& backend) {
    for (const auto& s : suite.solvers)
        if (s.name == backend) return "the outside solver '" + backend + "' (" + s.origin + ")";
    if (find_variant(backend, suite))
        return "the variant '" + backend + "' (" + suite.source_path + ", [variant.\"" + backend + "\"])";
    return "the built-in backend '" + backend + "'";
}

void refuse_duplicate_ids(const Suite& suite, const std::vector<CaseSpec>& cases) {
    std::map<std::string, std::size_t> first;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto [it, inserted] = first.emplace(cases[i].id, i);
        if (inserted) continue;
        const CaseSpec& a = cases[it->second];
        const CaseSpec& b = cases[i];
        // Two backends whose labels give one id token (box2d[shipped] and box2d-shipped): the
        // clash is theirs, whatever the scenes.
        if (a.backend != b.backend)
            throw SuiteError(backend_origin(suite, a.backend) + " and " + backend_origin(suite, b.backend) +
                             " name their cases alike ('" + backend_id_token(a.backend) + "', as in case '" + b.id +
                             "'): one would overwrite the other's records and runs; rename one of them");
        throw SuiteError(origin(suite, b) + ": case '" + b.id + "' is planned twice (also by " + origin(suite, a) +
                         "); each case needs its own id: give scenes that share a file stem different `name`s (with `path` naming each file), "
                         "and list each seed, dt and `set` value once");
    }
}

// The backends the suite's own `backends` key selects ("all": every one but those left out of
// "all", event-plain; then the variants).
std::vector<BackendInfo> suite_level_backends(const Suite& suite, const std::vector<BackendInfo>& available) {
    std::vector<BackendInfo> out;
    if (suite.backends.size() == 1 && suite.backends[0] == "all") {
        for (const auto& b : available)
            if (b.in_all) out.push_back(b);  // (not event-plain: see BackendInfo::in_all)
        // A variant of a backend this build lacks is left out like the backend itself.
        for (const auto& v : suite.variants)
            if (const BackendInfo* base = find_available(v.base, available)) out.push_back(variant_backend(*base, v));
        return out;
    }
    for (const auto& name : suite.backends) {
        if (const BackendInfo* b = find_available(name, available)) {
            out.push_back(*b);
        } else if (const BackendVariant* v = find_variant(name, suite)) {
            const BackendInfo* base = find_available(v->base, available);
            if (!base) unknown_backend(suite, v->base + " (the base of " + name + ")", available);
            out.push_back(variant_backend(*base, *v));
        } else {
            unknown_backend(suite, name, available);
        }
    }
    return out;
}

// Whether the suite's own list holds `name` (else only the scenes that name it run it).
bool suite_level(const Suite& suite, const BackendInfo& backend) {
    if (suite.backends.size() == 1 && suite.backends[0] == "all") return backend.in_all;
    return std::find(suite.backends.begin(), suite.backends.end(), backend.name) != suite.backends.end();
}

}  // namespace

std::vector<BackendInfo> select_backends(const Suite& suite, const std::vector<BackendInfo>& available) {
    std::vector<BackendInfo> out = suite_level_backends(suite, available);
    // A backend that only some [[scene]]s name (`backends = ["event", "event-plain"]`) joins
    // the list, and runs those scenes alone (suite_level below).
    for (const SuiteScene& entry : suite.scenes)
        for (const std::string& name : entry.backends) {
            if (std::any_of(out.begin(), out.end(), [&](const BackendInfo& b) { return b.name == name; })) continue;
            const BackendInfo* b = find_available(name, available);
            if (!b)
                throw SuiteError(suite.source_path + ":" + std::to_string(entry.line) + ": [[scene]] '" + entry.name +
                                 "'.backends: no backend '" + name + "' in this build (`collide backends` lists them)");
            out.push_back(*b);
        }
    return out;
}

std::vector<CaseSpec> plan_cases(const Suite& suite, const std::vector<Scene>& scenes,
                                 const std::vector<BackendInfo>& backends) {
    std::vector<CaseSpec> cases;
    for (std::size_t s = 0; s < suite.scenes.size(); ++s) {
        const SuiteScene& entry = suite.scenes[s];
        const auto& seeds = entry.seeds.empty() ? suite.seeds : entry.seeds;
        for (const BackendInfo& backend : backends) {
            if (!runs_on(entry, backend.name) || (entry.backends.empty() && !suite_level(suite, backend))) continue;
            const bool reference = backend.name == suite.reference;
            const auto refused = backend.supports(case_scene(scenes[s], entry, CaseSpec{}));
            // The reference solves the exact dynamics: dt, substeps and iterations mean nothing to
            // it. Trajectory scenes are the exception for dt: their replicates start at a collision
            // phase that is a fraction of each dt (phase_shift.h), so the reference runs once per dt.
            const bool per_dt = !reference || entry.comparison == Comparison::trajectory;
            const auto dts = per_dt ? sweep(entry.dt) : sweep<double>({});
            const auto subs = reference ? sweep<int>({}) : sweep(entry.substeps);
            const auto its = reference || !backend.sweeps_iterations ? sweep<int>({}) : sweep(entry.iterations);
            for (const auto& parameters : parameter_points(entry))
            for (const auto& dt : dts)
                for (const auto& sub : subs)
                    for (const auto& it : its)
                        for (std::uint64_t seed : seeds) {
                            CaseSpec c;
                            c.scene_index = s;
                            c.scene = entry.name;
                            c.backend = backend.name;
                            c.reference = reference;
                            c.dt = dt;
                            c.substeps = sub;
                            c.iterations = it;
                            c.parameters = parameters;
                            c.seed = seed;
                            c.left_out = refused.value_or("");
                            c.id = make_id(c);
                            cases.push_back(c);
                        }
        }
    }
    refuse_duplicate_ids(suite, cases);
    return cases;
}

Scene case_scene(const Scene& scene, const SuiteScene& entry, const CaseSpec& spec) {
    Scene out = scene;
    if (spec.seed) out.seed = spec.seed;
    if (entry.duration) out.run.duration = *entry.duration;
    if (entry.output_interval) out.run.output_interval = *entry.output_interval;
    if (spec.dt) out.run.dt = *spec.dt;
    if (spec.substeps) out.run.substeps = *spec.substeps;
    return out;
}

}  // namespace collide::validation
