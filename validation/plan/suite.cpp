#include "validation/plan/suite.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>

#include "core/io/input_file.h"
#include "core/scene/scene_loader.h"
#include "core/scene/toml_fields.h"
#include "core/text/printable.h"
#include "validation/record/check_table.h"
#include "validation/plan/external_solvers.h"
#include "validation/plan/solver_tables.h"
#include "validation/compare/physics_rows.h"
#include "validation/compare/published_reference.h"

namespace collide::validation {

const char* to_string(Comparison c) {
    switch (c) {
        case Comparison::trajectory: return "trajectory";
        case Comparison::statistics: return "statistics";
        default: return "none";
    }
}

namespace {

// The suite file is read with the scene reader's strict typed reads (core/scene/toml_fields.h): every
// problem is "file:line: key = value: expected ...". parse_suite turns their SceneError into
// SuiteError. The helpers below are the optional reads a suite needs beyond TomlFields'.
std::optional<std::string> optional_string(const TomlFields& f, std::string_view key) {
    if (!f.has(key)) return std::nullopt;
    return f.string(key);
}

std::optional<double> optional_positive(const TomlFields& f, std::string_view key) {
    if (!f.has(key)) return std::nullopt;
    const double v = f.number(key);
    f.require(v > 0, key, "a positive number");
    return v;
}

std::optional<bool> optional_boolean(const TomlFields& f, std::string_view key) {
    if (!f.has(key)) return std::nullopt;
    return f.boolean(key, false);
}

// An optional non-empty array of positive numbers (integers unless T is floating point).
template <typename T>
std::vector<T> positive_array(const TomlFields& f, std::string_view key, const std::string& what) {
    std::vector<T> out;
    const toml::node* node = f.node(key);
    if (!node) return out;
    const toml::array* array = node->as_array();
    if (!array || array->empty()) f.fail(key, "a non-empty array of " + what);
    for (const auto& element : *array) {
        const auto v = element.value<T>();
        const bool typed = std::is_floating_point_v<T> ? element.is_number() : element.is_integer();
        if (!v || !(*v > 0) || !typed) f.fail(key, "an array of " + what);
        out.push_back(*v);
    }
    return out;
}

// An optional non-empty array of strings (empty when the key is absent).
std::vector<std::string> strings(const TomlFields& f, std::string_view key, const std::string& what) {
    std::vector<std::string> out;
    const toml::node* node = f.node(key);
    if (!node) return out;
    const toml::array* array = node->as_array();
    if (!array || array->empty()) f.fail(key, "a non-empty array of " + what);
    for (const auto& element : *array) {
        if (!element.is_string()) f.fail(key, what);
        out.push_back(*element.value<std::string>());
    }
    return out;
}

void read_tolerances(const toml::table& root, const std::string& file, ToleranceTable& out) {
    const toml::node* node = root.get("tolerances");
    if (!node) return;
    const toml::table* table = node->as_table();
    if (!table) TomlFields(root, "", file).fail("tolerances", "a table of [tolerances.<backend>] tables");
    for (const auto& [backend, sub] : *table) {
        const std::string name(backend.str());
        const toml::table* limits = sub.as_table();
        if (!limits) TomlFields(*table, "tolerances", file).fail(name, "a table of check = limit");
        auto& target = name == "default" ? out.all_backends : out.per_backend[name];
        for (const auto& [key, value] : *limits) {
            const std::string k(key.str());
            const TomlFields reader(*limits, "tolerances." + name, file);
            Tolerances probe;
            try {
                tolerance_field(probe, k);
            } catch (const std::invalid_argument& e) {
                reader.fail(k, std::string("a known check name (") + e.what() + ")");
            }
            const auto v = value.value<double>();
            if (!v || !(*v >= 0)) reader.fail(k, "a non-negative number");
            target[k] = *v;
        }
    }
}

// "BASE[NAME]": the brackets end the label, NAME is plain (it becomes part of file names).
bool is_variant_label(const std::string& label) {
    const auto open = label.find('[');
    return open != std::string::npos && open > 0 && label.size() > open + 2 && label.back() == ']' &&
           label.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-", open + 1) == label.size() - 1;
}

// The names of the case and comparison checks a variant may leave out (check_table.h).
const std::vector<std::string>& known_checks() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const CheckDefinition& c : check_table)
            if (c.kind != CheckKind::stability) out.push_back(c.name);
        return out;
    }();
    return names;
}

// leave_out = ["pressure", ...] and leave_out_reason = "...": both or neither, names known.
void read_variant_leave_out(const toml::table& settings, const std::string& file, BackendVariant& v) {
    const TomlFields r(settings, "variant." + v.label, file);
    const toml::node* list = settings.get("leave_out");
    const toml::node* reason = settings.get("leave_out_reason");
    if (!list && !reason) return;
    if (!list || !list->is_array() || !reason || !reason->is_string() || reason->value<std::string>()->empty())
        r.fail(list ? "leave_out_reason" : "leave_out",
               "leave_out (an array of check names) together with leave_out_reason (a non-empty string)");
    for (const auto& item : *list->as_array()) {
        const auto name = item.value<std::string>();
        const auto& known = known_checks();
        if (!name || std::find(known.begin(), known.end(), *name) == known.end()) {
            std::string names;
            for (const auto& k : known) names += (names.empty() ? "" : ", ") + k;
            r.fail("leave_out", "check names, each one of " + names);
        }
        v.leave_out.push_back(*name);
    }
    v.leave_out_reason = *reason->value<std::string>();
}

// [variant."BASE[NAME]"]: keys of the scene's [backend.BASE] table, kept as text. The label's
// shape is checked here; whether BASE exists is known only to select_backends().
std::vector<BackendVariant> read_variants(const toml::table& root, const std::string& file) {
    std::vector<BackendVariant> out;
    const toml::node* node = root.get("variant");
    if (!node) return out;
    const toml::table* table = node->as_table();
    if (!table) TomlFields(root, "", file).fail("variant", "a table of [variant.\"backend[name]\"] tables");
    for (const auto& [key, sub] : *table) {
        const std::string label(key.str());
        const TomlFields r(*table, "variant", file);
        if (!is_variant_label(label)) r.fail(label, "a label \"backend[name]\" (name: lower-case letters, digits, _ or -)");
        const std::string base = label.substr(0, label.find('['));
        const toml::table* settings = sub.as_table();
        if (!settings || settings->empty()) r.fail(label, "a table of [backend." + base + "] keys");
        BackendVariant v{label, base, {}, {}, {}};
        read_variant_leave_out(*settings, file, v);
        for (const auto& [k, value] : *settings) {
            if (k.str() == "leave_out" || k.str() == "leave_out_reason") continue;
            if (!value.is_string() && !value.is_number() && !value.is_boolean())
                TomlFields(*settings, "variant." + label, file).fail(std::string(k.str()), "a string, number or boolean");
            v.settings[std::string(k.str())] = value.is_string() ? *value.value<std::string>() : toml_value_text(value);
        }
        out.push_back(std::move(v));
    }
    return out;
}

// set = { "particles.0.disks.1.mass" = [1.0, 1e9] }: each key a quoted path into the scene
// file, each value an array of numbers. An unquoted dotted key would make TOML nest tables,
// so a table where an array belongs gets a hint to quote the path.
std::vector<SceneParameter> read_parameter_sweeps(const toml::table& t, const std::string& file,
                                                  const std::string& where) {
    std::vector<SceneParameter> out;
    const toml::node* node = t.get("set");
    if (!node) return out;
    const TomlFields r(t, where, file);
    const toml::table* table = node->as_table();
    if (!table || table->empty()) r.fail("set", "a table of \"scene.key.path\" = [values]");
    for (const auto& [key, value] : *table) {
        const std::string path(key.str());
        const TomlFields inner(*table, where + ".set", file);
        if (has_control_character(path))
            inner.fail(path, "a path into the scene file, without control characters (the key holds one: '" +
                                 printable(path) + "')");
        if (value.is_table())
            inner.fail(path, "an array of numbers (quote a dotted path: \"" + path + ".…\" = [...])");
        const toml::array* values = value.as_array();
        if (!values || values->empty()) inner.fail(path, "a non-empty array of numbers");
        SceneParameter p{path, {}};
        for (const auto& v : *values) {
            if (!v.is_number()) inner.fail(path, "a non-empty array of numbers");
            p.values.push_back(*v.value<double>());
        }
        out.push_back(std::move(p));
    }
    return out;
}

// A `set` of a scene key that the entry's own run settings set again: the case would be
// labelled with the set's value (run.dt=0.002) but run with the entry's (dt = [0.001]),
// since case_scene applies those after the sweep. Refused, naming the file, the line and both.
void refuse_set_beside_run_setting(const toml::table& t, const SuiteScene& s, const std::string& file,
                                   const std::string& where) {
    if (s.set.empty()) return;
    struct Setting {
        const char* scene_key;
        const char* entry_key;
        bool set_by_entry;
    };
    const Setting settings[] = {{"run.dt", "dt", !s.dt.empty()},
                                {"run.substeps", "substeps", !s.substeps.empty()},
                                {"run.duration", "duration", s.duration.has_value()},
                                {"run.output_interval", "output_interval", s.output_interval.has_value()},
                                {"seed", "seeds", true}};
    const TomlFields inner(*t.get("set")->as_table(), where + ".set", file);
    for (const SceneParameter& p : s.set)
        for (const Setting& setting : settings) {
            if (p.path != setting.scene_key || !setting.set_by_entry) continue;
            const std::string entry_key = setting.entry_key;
            inner.fail(p.path, "no sweep of a setting that the entry sets itself: `" + entry_key + "` sets " +
                                   setting.scene_key + " for every case (after the sweep), so the case would be "
                                   "labelled with one value and run with another; sweep it with `" + entry_key +
                                   " = [...]` alone");
        }
}

// `physics = ["equation_of_state", ...]`: each a row of physics_row_kinds().
std::vector<std::string> read_physics_rows(const TomlFields& r) {
    std::string names;
    for (const auto& k : physics_row_kinds()) names += (names.empty() ? "" : ", ") + std::string("\"") + k.name + "\"";
    std::vector<std::string> rows = strings(r, "physics", "an array of row names from " + names);
    for (const std::string& row : rows) {
        const auto& kinds = physics_row_kinds();
        if (std::none_of(kinds.begin(), kinds.end(), [&](const PhysicsRowKind& k) { return row == k.name; }))
            r.fail("physics", "row names from " + names + " (not \"" + row + "\")");
    }
    return rows;
}

// `published = "KEY:ID"`: a row of data/references/KEY.toml whose quantity is beta_pressure_d2,
// checked here so that a misspelt id stops the suite before it runs.
std::string read_published_row(const TomlFields& r, const std::string& reference_dir) {
    const auto value = optional_string(r, "published");
    if (!value) return "";
    const auto colon = value->find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == value->size())
        r.fail("published", "\"KEY:ID\", a reference file's stem and the id of one of its [[rows]] (not \"" + *value + "\")");
    std::string problem;
    try {
        const PublishedReference ref = load_reference(reference_dir, value->substr(0, colon));
        if (ref.quantity != "beta_pressure_d2")
            problem = ref.source_path + " holds \"" + ref.quantity + "\", not beta_pressure_d2 rows";
        else
            ref.finite_n_point(value->substr(colon + 1));
    } catch (const std::runtime_error& e) {
        problem = e.what();
    }
    if (!problem.empty()) r.fail("published", "a published finite-N row (" + problem + ")");
    return *value;
}

SuiteScene read_scene(const toml::table& t, const std::string& file, int index, const std::string& dir,
                      const std::string& scene_dir, const std::string& reference_dir) {
    const TomlFields r(t, "[[scene]] #" + std::to_string(index), file);
    r.allow_only({"name", "path", "compare", "dt", "substeps", "iterations", "seeds", "duration", "output_interval", "set",
            "frames", "physics", "backends", "published"});
    SuiteScene s;
    const auto name = optional_string(r, "name");
    const auto path = optional_string(r, "path");
    if (!name && !path) r.fail("name", "the scene's name (a file in the scene directory) or a path");
    namespace fs = std::filesystem;
    fs::path file_path = path ? fs::path(*path) : fs::path(scene_dir) / (*name + ".toml");
    if (file_path.is_relative()) file_path = fs::path(dir) / file_path;
    file_path = file_path.lexically_normal();
    if (!fs::exists(file_path))
        r.fail(path ? "path" : "name", "an existing scene file (" + file_path.string() + " does not exist)");
    s.path = file_path.string();
    s.name = name ? *name : file_path.stem().string();
    const std::string compare = optional_string(r, "compare").value_or("none");
    if (compare == "trajectory") s.comparison = Comparison::trajectory;
    else if (compare == "statistics") s.comparison = Comparison::statistics;
    else if (compare != "none") r.fail("compare", "\"trajectory\", \"statistics\" or \"none\"");
    s.dt = positive_array<double>(r, "dt", "positive time steps");
    s.substeps = positive_array<int>(r, "substeps", "positive integers");
    s.iterations = positive_array<int>(r, "iterations", "positive integers");
    s.seeds = positive_array<std::uint64_t>(r, "seeds", "positive integer seeds");
    s.duration = optional_positive(r, "duration");
    s.output_interval = optional_positive(r, "output_interval");
    s.frames = optional_boolean(r, "frames");
    s.set = read_parameter_sweeps(t, file, "[[scene]] #" + std::to_string(index));
    refuse_set_beside_run_setting(t, s, file, "[[scene]] #" + std::to_string(index));
    s.physics = read_physics_rows(r);
    s.backends = strings(r, "backends", "an array of backend names");
    s.published = read_published_row(r, reference_dir);
    // Where the run settings a case may break are set (checked against the scene later).
    s.line = int(t.source().begin.line);
    for (const char* key : {"output_interval", "duration", "dt"})
        if (const toml::node* node = t.get(key)) s.line = int(node->source().begin.line);
    return s;
}

// [verdicts]: each threshold a positive number, the default where the key is absent.
VerdictThresholds read_verdict_thresholds(const toml::table& root, const std::string& file) {
    VerdictThresholds t;
    const toml::node* node = root.get("verdicts");
    if (!node) return t;
    if (!node->is_table()) TomlFields(root, "", file).fail("verdicts", "a table");
    const TomlFields v(*node->as_table(), "verdicts", file);
    v.allow_only({"loose_tolerance_ratio", "energy_drift", "pressure_sigmas", "trajectory_accuracy", "pressure_accuracy",
                 "cooling_accuracy", "collision_rate_accuracy"});
    t.loose_tolerance_ratio = optional_positive(v, "loose_tolerance_ratio").value_or(t.loose_tolerance_ratio);
    t.energy_drift = optional_positive(v, "energy_drift").value_or(t.energy_drift);
    t.pressure_sigmas = optional_positive(v, "pressure_sigmas").value_or(t.pressure_sigmas);
    t.trajectory_accuracy = optional_positive(v, "trajectory_accuracy").value_or(t.trajectory_accuracy);
    t.pressure_accuracy = optional_positive(v, "pressure_accuracy").value_or(t.pressure_accuracy);
    t.cooling_accuracy = optional_positive(v, "cooling_accuracy").value_or(t.cooling_accuracy);
    t.collision_rate_accuracy = optional_positive(v, "collision_rate_accuracy").value_or(t.collision_rate_accuracy);
    return t;
}

// [published_precision]: backend name = the relative error its published rows must reach.
std::map<std::string, double> read_published_precision(const toml::table& root, const std::string& file) {
    std::map<std::string, double> precision;
    const toml::node* node = root.get("published_precision");
    if (!node) return precision;
    if (!node->is_table()) TomlFields(root, "", file).fail("published_precision", "a table of backend = relative error");
    const TomlFields p(*node->as_table(), "published_precision", file);
    for (const auto& [key, value] : *node->as_table()) {
        const std::string name(key.str());
        const auto v = optional_positive(p, name);
        if (!v || *v >= 1) p.fail(name, "a relative standard error in (0, 1)");
        precision[name] = *v;
    }
    return precision;
}

// A precision named for a backend no [[scene]] runs is a typo, not a setting.
void refuse_precision_of_absent_backends(const toml::table& root, const Suite& suite, const std::string& file) {
    if (suite.published_precision.empty() || suite.backends == std::vector<std::string>{"all"}) return;
    const TomlFields p(*root.get("published_precision")->as_table(), "published_precision", file);
    for (const auto& [name, value] : suite.published_precision) {
        bool runs = std::count(suite.backends.begin(), suite.backends.end(), name) > 0;
        for (const SuiteScene& s : suite.scenes) runs = runs || std::count(s.backends.begin(), s.backends.end(), name) > 0;
        if (!runs) p.fail(name, "a backend this suite runs (no [[scene]] runs " + name + ")");
    }
}

// The suite's tables, read with TomlFields (their SceneError becomes SuiteError in parse_suite).
Suite read_suite(const toml::table& root, const std::string& file, const std::string& dir) {
    const TomlFields r(root, "", file);
    r.allow_only({"name", "description", "scene_dir", "backends", "reference", "seeds", "time_limit",
            "warmup_fraction", "stability", "output", "tolerances", "scene", "variant", "reference_dir", "solver", "verdicts",
            "published_precision"});
    Suite suite;
    suite.source_path = file;
    suite.name = optional_string(r, "name").value_or(std::filesystem::path(file).stem().string());
    suite.description = optional_string(r, "description").value_or("");
    suite.reference = optional_string(r, "reference").value_or("event");
    if (const toml::node* b = root.get("backends")) {
        if (b->is_string() && b->value<std::string>() == "all") {
            suite.backends = {"all"};
        } else if (const toml::array* list = b->as_array(); list && !list->empty()) {
            for (const auto& e : *list) {
                if (!e.is_string()) r.fail("backends", "\"all\" or an array of backend names");
                suite.backends.push_back(*e.value<std::string>());
            }
        } else {
            r.fail("backends", "\"all\" or an array of backend names");
        }
    } else {
        suite.backends = {"all"};
    }
    if (auto seeds = positive_array<std::uint64_t>(r, "seeds", "positive integer seeds"); !seeds.empty())
        suite.seeds = seeds;
    suite.time_limit_seconds = optional_positive(r, "time_limit").value_or(suite.time_limit_seconds);
    if (const toml::node* w = root.get("warmup_fraction")) {
        const auto v = w->value<double>();
        if (!v || *v < 0 || *v > 1) r.fail("warmup_fraction", "a number in [0, 1]");
        suite.warmup_fraction = *v;
    }
    suite.stability = optional_boolean(r, "stability").value_or(false);
    if (const toml::node* o = root.get("output")) {
        if (!o->is_table()) r.fail("output", "a table");
        const TomlFields out(*o->as_table(), "output", file);
        out.allow_only({"hdf5", "frames", "max_overlap_samples", "max_trajectory_disks"});
        suite.output.hdf5 = optional_boolean(out, "hdf5").value_or(true);
        suite.output.frames = optional_boolean(out, "frames").value_or(false);
        if (auto v = optional_positive(out, "max_overlap_samples")) suite.output.max_overlap_samples = std::size_t(*v);
        if (auto v = optional_positive(out, "max_trajectory_disks")) suite.output.max_trajectory_disks = std::size_t(*v);
    }
    suite.verdicts = read_verdict_thresholds(root, file);
    suite.published_precision = read_published_precision(root, file);
    read_tolerances(root, file, suite.tolerances);
    suite.variants = read_variants(root, file);
    add_solvers(suite, read_solver_tables(root, file, dir));
    const std::string scene_dir = optional_string(r, "scene_dir").value_or("../../data/scenes");
    const std::filesystem::path reference_dir = optional_string(r, "reference_dir").value_or("../../data/references");
    suite.reference_dir = (reference_dir.is_relative() ? std::filesystem::path(dir) / reference_dir : reference_dir)
                              .lexically_normal().string();
    const toml::node* scenes = root.get("scene");
    if (!scenes || !scenes->is_array_of_tables() || scenes->as_array()->empty())
        r.fail("scene", "one or more [[scene]] tables");
    int index = 0;
    for (const auto& node : *scenes->as_array())
        suite.scenes.push_back(read_scene(*node.as_table(), file, ++index, dir, scene_dir, suite.reference_dir));
    refuse_precision_of_absent_backends(root, suite, file);
    return suite;
}

}  // namespace

Suite parse_suite(const std::string& text, const std::string& file, const std::string& dir) {
    toml::table root;
    try {
        root = toml::parse(text, file);
    } catch (const toml::parse_error& e) {
        std::ostringstream msg;
        msg << file << ":" << e.source().begin.line << ": not valid TOML: " << e.description();
        throw SuiteError(msg.str());
    }
    try {
        return read_suite(root, file, dir);
    } catch (const SceneError& e) {
        throw SuiteError(e.what());
    }
}

// A suite is a page of TOML; this bound only keeps a mistaken path (a disk image) from being read whole.
constexpr std::size_t max_suite_file_bytes = 64u << 20;

Suite load_suite(const std::string& path) {
    std::string text;
    try {  // the input guard (core/io/input_file.h): no FIFO or device waited on
        text = read_input_file(path, max_suite_file_bytes);
    } catch (const InputFileError& e) {
        throw SuiteError(path + ": cannot open the suite file: " + e.cause());
    }
    if (text.size() > max_suite_file_bytes) throw SuiteError(path + ": more than 64 MiB: expected a suite file");
    const auto dir = std::filesystem::absolute(path).parent_path().string();
    return parse_suite(text, path, dir);
}

std::vector<Scene> load_suite_scenes(const Suite& suite) {
    std::vector<Scene> scenes;
    for (const SuiteScene& entry : suite.scenes) {
        Scene scene = entry.scene ? *entry.scene : load_scene(entry.path);
        if (scene.name.empty()) scene.name = entry.name;
        scenes.push_back(std::move(scene));
    }
    return scenes;
}

bool stores_frames(const Suite& suite, const SuiteScene& entry) { return entry.frames.value_or(suite.output.frames); }

}  // namespace collide::validation
