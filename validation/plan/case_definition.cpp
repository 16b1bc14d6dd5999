#include "validation/plan/case_definition.h"

#include <algorithm>
#include <array>
#include <optional>
#include <type_traits>

#include "core/aggregate_fields.h"
#include "core/io/provenance.h"
#include "core/numerics/number_text.h"
#include "external/sha256.h"
#include "external/solver_files.h"
#include "validation/plan/case_plan.h"

namespace collide::validation {
namespace {

template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};

// A value as text that no other value shares: strings with their length in front (so that
// "a", "bc" and "ab", "c" differ), numbers as round-trip text, containers element by element.
template <class T>
std::string field_text(const T& v) {
    if constexpr (std::is_same_v<T, std::string>) {
        return std::to_string(v.size()) + ":" + v;
    } else if constexpr (std::is_same_v<T, bool>) {
        return v ? "true" : "false";
    } else if constexpr (std::is_floating_point_v<T>) {
        return round_trip_text(double(v));
    } else if constexpr (std::is_integral_v<T>) {
        return std::to_string(v);
    } else if constexpr (std::is_enum_v<T>) {
        return std::to_string(static_cast<long long>(v));
    } else if constexpr (is_optional<T>::value) {
        if (!v) return "none";
        std::string out = "(";  // appended, not "(" + text: GCC 12 warns falsely (-Wrestrict) on that
        out += field_text(*v);
        return out += ")";
    } else if constexpr (requires { v.first; v.second; }) {
        return field_text(v.first) + "=" + field_text(v.second);
    } else if constexpr (requires { v.begin(); v.end(); }) {
        std::string out = "[";
        for (const auto& e : v) out += field_text(e) + ",";
        return out + "]";
    } else {
        std::string out = "{";  // a plain struct: every field, named or added later
        for_each_field(v, [&out](const auto& field) { out += field_text(field) + ";"; });
        return out + "}";
    }
}

// A scene file's text and its --set changes define it; a scene built in code (tests) has no
// text, and its fields stand in (the generators' fields by name: more than for_each_field takes).
std::string scene_text(const Scene& s) {
    if (!s.source_text.empty()) return s.source_text + "\n--set " + s.overrides;
    std::string out = field_text(s.world) + field_text(s.physics) + field_text(s.run) + field_text(s.seed) +
                      field_text(s.backend_options);
    for (const ParticleGenerator& g : s.generators)
        out += field_text(g.kind) + field_text(g.disks) + field_text(g.count) + field_text(g.region) +
               field_text(g.radius_kind) + field_text(std::array{g.radius, g.radius_min, g.radius_max, g.radius_small,
                                                                 g.radius_large, g.fraction_large, g.temperature,
                                                                 g.speed, g.spacing}) +
               field_text(g.mass) + field_text(g.density) + field_text(g.velocity_kind) + field_text(g.lattice) +
               field_text(g.columns) + field_text(g.stone) +
               (g.fill_box ? "fill_box" : "");  // only when set: older definitions keep their hash
    return out;
}

// collide's build: a case computed by another commit, a tree with uncommitted changes, or
// other compiler flags may compute otherwise.
std::string build_text() {
    const auto build = build_provenance();
    std::string out;
    for (const char* key : {"collide_version", "git_commit", "git_dirty", "compiler", "compiler_flags", "build_type"})
        if (const auto it = build.find(key); it != build.end()) out += std::string(key) + "=" + it->second + "\n";
    return out;
}

std::string hash(const std::string& text) { return external::sha256_hex(text); }

}  // namespace

std::map<std::string, std::string> case_definition(const Suite& suite, const Scene& scene, const CaseSpec& spec,
                                                   std::FILE* progress) {
    const SuiteScene& entry = suite.scenes.at(spec.scene_index);
    std::map<std::string, std::string> parts;
    parts["scene file"] = hash(scene_text(scene));
    parts["case"] = hash(field_text(spec.backend) + field_text(spec.reference) + field_text(spec.seed) +
                         field_text(spec.dt) + field_text(spec.substeps) + field_text(spec.iterations) +
                         field_text(spec.parameters) + field_text(spec.left_out));
    parts["duration"] = hash(field_text(entry.duration));
    parts["output_interval"] = hash(field_text(entry.output_interval));
    parts["frames"] = hash(field_text(stores_frames(suite, entry)));
    parts["comparison"] = hash(to_string(entry.comparison));
    parts["physics rows"] = hash(field_text(entry.physics));
    parts["warmup_fraction"] = hash(field_text(suite.warmup_fraction));
    parts["time_limit"] = hash(field_text(suite.time_limit_seconds));
    parts["[output] settings"] = hash(field_text(suite.output.hdf5) + field_text(suite.output.max_overlap_samples) +
                                      field_text(suite.output.max_trajectory_disks));
    for (const BackendVariant& v : suite.variants)
        if (v.label == spec.backend) parts["backend settings"] = hash(field_text(v.base) + field_text(v.settings));
    for (external::ExternalSolverSpec solver : suite.solvers)
        if (solver.name == spec.backend) {
            solver.origin.clear();  // where it was named (a line of the suite file) is not what it is
            parts["solver"] = hash(field_text(solver));
            parts["solver files"] = hash(external::solver_files_digest(solver, progress));
        }
    parts["collide build"] = hash(build_text());
    return parts;
}

std::vector<std::string> changed_parts(const std::map<std::string, std::string>& recorded,
                                       const std::map<std::string, std::string>& now) {
    std::vector<std::string> changed;
    for (const auto& [name, part] : now) {
        const auto it = recorded.find(name);
        if (it == recorded.end() || it->second != part) changed.push_back(name);
    }
    for (const auto& [name, part] : recorded)
        if (!now.count(name)) changed.push_back(name);
    return changed;
}

}  // namespace collide::validation
