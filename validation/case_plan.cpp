#include "case_plan.h"

#include <cstdio>

namespace collide::validation {
namespace {

std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string make_id(const CaseSpec& c) {
    std::string id = c.scene + "__" + c.backend;
    if (!c.parameters.empty()) id += "__" + parameter_label(c);
    if (c.dt) id += "__dt" + format_number(*c.dt);
    if (c.substeps) id += "__sub" + std::to_string(*c.substeps);
    if (c.iterations) id += "__it" + std::to_string(*c.iterations);
    return id + "__seed" + std::to_string(c.seed);
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

std::vector<const BackendInfo*> select_backends(const Suite& suite, const std::vector<BackendInfo>& available) {
    std::vector<const BackendInfo*> out;
    if (suite.backends.size() == 1 && suite.backends[0] == "all") {
        for (const auto& b : available) out.push_back(&b);
        return out;
    }
    for (const auto& name : suite.backends) {
        const BackendInfo* found = nullptr;
        std::string names;
        for (const auto& b : available) {
            if (b.name == name) found = &b;
            names += (names.empty() ? "" : ", ") + b.name;
        }
        if (!found)
            throw SuiteError(suite.source_path + ": backends: unknown backend '" + name +
                             "'; expected \"all\" or names from: " + names);
        out.push_back(found);
    }
    return out;
}

std::vector<CaseSpec> plan_cases(const Suite& suite, const std::vector<Scene>& scenes,
                                 const std::vector<const BackendInfo*>& backends) {
    std::vector<CaseSpec> cases;
    for (std::size_t s = 0; s < suite.scenes.size(); ++s) {
        const SuiteScene& entry = suite.scenes[s];
        const auto& seeds = entry.seeds.empty() ? suite.seeds : entry.seeds;
        for (const BackendInfo* backend : backends) {
            const bool reference = backend->name == suite.reference;
            const auto refused = backend->supports(case_scene(scenes[s], entry, CaseSpec{}));
            // The reference solves the exact dynamics: dt, substeps and iterations mean nothing to
            // it. Trajectory scenes are the exception for dt: their replicates start at a collision
            // phase that is a fraction of each dt (phase_shift.h), so the reference runs once per dt.
            const bool per_dt = !reference || entry.comparison == Comparison::trajectory;
            const auto dts = per_dt ? sweep(entry.dt) : sweep<double>({});
            const auto subs = reference ? sweep<int>({}) : sweep(entry.substeps);
            const auto its = reference ? sweep<int>({}) : sweep(entry.iterations);
            for (const auto& parameters : parameter_points(entry))
            for (const auto& dt : dts)
                for (const auto& sub : subs)
                    for (const auto& it : its)
                        for (std::uint64_t seed : seeds) {
                            CaseSpec c;
                            c.scene_index = s;
                            c.scene = entry.name;
                            c.backend = backend->name;
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
