#include "validation/plan/external_solvers.h"

#include <algorithm>

#include "core/scene/toml_fields.h"
#include "validation/plan/backend_variant.h"
#include "validation/plan/solver_tables.h"
#include "validation/plan/class_declarations.h"

namespace collide::validation {
namespace {

// The share of a case's time limit one program call may take: a case calls the program for
// its warm-up and again for the timed run, and the program's own limit must fire first so
// that the fault names the solver rather than the whole case.
constexpr double call_share_of_case_limit = 0.45;

[[noreturn]] void fail(const std::string& file, const toml::node& node, const std::string& where, const std::string& expected) {
    throw SuiteError(location(file, int(node.source().begin.line)) + where + ": expected " + expected);
}

std::string string_key(const toml::table& t, const std::string& key, const std::string& file, const std::string& where) {
    const toml::node* node = t.get(key);
    if (!node) return "";
    if (!node->is_string() || node->value<std::string>()->empty()) fail(file, *node, where + "." + key, "a non-empty string");
    return *node->value<std::string>();
}

// An array of non-empty strings, or nullopt when the key is absent.
std::optional<std::vector<std::string>> string_list(const toml::table& t, const std::string& key, const std::string& file,
                                                    const std::string& where, const std::string& what) {
    const toml::node* node = t.get(key);
    if (!node) return std::nullopt;
    const toml::array* array = node->as_array();
    if (!array) fail(file, *node, where + "." + key, what);
    std::vector<std::string> out;
    for (const auto& v : *array) {
        if (!v.is_string() || v.value<std::string>()->empty()) fail(file, *node, where + "." + key, what);
        out.push_back(*v.value<std::string>());
    }
    return out;
}

}  // namespace

std::vector<external::ExternalSolverSpec> read_solver_tables(const toml::table& root, const std::string& file,
                                                             const std::string& dir) {
    std::vector<external::ExternalSolverSpec> out;
    const toml::node* node = root.get("solver");
    if (!node) return out;
    const toml::table* table = node->as_table();
    if (!table) fail(file, *node, "solver", "a table of [solver.NAME] tables");
    for (const auto& [key, sub] : *table) {
        const std::string name(key.str());
        const std::string where = "solver." + name;
        if (const std::string why = external::solver_name_problem(name); !why.empty()) fail(file, sub, where, why);
        const toml::table* t = sub.as_table();
        if (!t) fail(file, sub, where, "a table with command = \"...\" or python = \"module:Class\"");
        for (const auto& [k, v] : *t)
            if (k.str() != "command" && k.str() != "python" && k.str() != "rule" && k.str() != "exact" && k.str() != "precision" &&
                k.str() != "handles" && k.str() != "files" && k.str() != "long_lived")
                fail(file, v, where + "." + std::string(k.str()),
                     "no such key here (allowed: command, python, rule, exact, precision, handles, files, long_lived)");
        external::ExternalSolverSpec spec;
        spec.name = name;
        spec.command = string_key(*t, "command", file, where);
        spec.python_class = string_key(*t, "python", file, where);
        spec.rule = string_key(*t, "rule", file, where);
        if (const toml::node* exact = t->get("exact")) {
            if (!exact->is_boolean()) fail(file, *exact, where + ".exact", "true or false");
            spec.exact = *exact->value<bool>();
        }
        if (const std::string precision = string_key(*t, "precision", file, where); !precision.empty()) {
            spec.precision = precision;
            if (const std::string why = external::precision_problem(precision); !why.empty())
                fail(file, *t->get("precision"), where + ".precision", why);
        }
        spec.handles = string_list(*t, "handles", file, where,
                                   "an array of capability names (" + external::capabilities_text() + ")");
        if (spec.handles)
            if (const std::string why = external::handles_problem(*spec.handles); !why.empty())
                fail(file, *t->get("handles"), where + ".handles", why);
        if (const toml::node* long_lived = t->get("long_lived")) {
            if (!long_lived->is_boolean()) fail(file, *long_lived, where + ".long_lived", "true or false");
            spec.long_lived = *long_lived->value<bool>();
            if (const std::string why = external::long_lived_problem(spec); !why.empty())
                fail(file, *long_lived, where + ".long_lived", why);
        }
        spec.files = string_list(*t, "files", file, where, "an array of file paths (relative to the suite file)").value_or(std::vector<std::string>{});
        spec.directory = dir;
        spec.origin = file + ":" + std::to_string(sub.source().begin.line);
        if (spec.command.empty() == spec.python_class.empty())
            fail(file, sub, where, "either command = \"...\" (a program) or python = \"module:Class\", not both or neither");
        if (!spec.python_class.empty() && spec.python_class.find(':') == std::string::npos)
            fail(file, *t->get("python"), where + ".python", "\"module:Class\" or \"file.py:Class\"");
        if (const std::string why = external::rule_problem(spec.rule); !why.empty())
            fail(file, *t->get("rule"), where + ".rule", why);
        if (const std::string why = external::claims_problem(spec.exact, spec.rule); !why.empty())
            throw SuiteError(location(file, int(t->get("exact")->source().begin.line)) + where + ".exact: " + why);
        // (the checks above, with each key's line, are those of external::spec_problem)
        out.push_back(std::move(spec));
    }
    return out;
}

void add_solvers(Suite& suite, const std::vector<external::ExternalSolverSpec>& solvers) {
    for (const auto& spec : solvers) {
        const bool taken = std::any_of(suite.solvers.begin(), suite.solvers.end(),
                                       [&](const auto& s) { return s.name == spec.name; });
        if (taken) throw SuiteError(spec.origin + ": a solver named '" + spec.name + "' is already in the suite");
        suite.solvers.push_back(spec);
        const bool all = suite.backends.size() == 1 && suite.backends[0] == "all";
        if (!all) suite.backends.push_back(spec.name);
    }
}

std::vector<BackendInfo> backends_with_solvers(const Suite& suite, std::vector<BackendInfo> built_in,
                                               const PythonRunner& python) {
    if (!suite.solvers.empty())
        if (const std::string problem = external::request_root_problem(); !problem.empty()) throw SuiteError(problem);
    for (external::ExternalSolverSpec spec : suite.solvers) {
        // A clash of the names that case ids and file names spell (backend_id_token): the
        // variant box2d[shipped] writes box2d-shipped's files.
        const auto clash = [&](const std::string& n) { return backend_id_token(n) == backend_id_token(spec.name); };
        for (const BackendInfo& b : built_in)
            if (clash(b.name))
                throw SuiteError(spec.origin + ": the outside solver '" + spec.name + "' is named like the backend '" +
                                 b.name + "', whose case ids and files it would share; choose another name");
        for (const auto& v : suite.variants)
            if (clash(v.label))
                throw SuiteError(spec.origin + ": the outside solver '" + spec.name + "' is named like the variant '" +
                                 v.label + "' (" + suite.source_path + ", [variant.\"" + v.label + "\"]), whose case "
                                 "ids and files spell it '" + backend_id_token(v.label) + "'; choose another name");
        add_class_declarations(spec, python);
        if (!spec.python_class.empty())
            spec.command = shell_quote(python.python) + " " + shell_quote(python.runner) + " " + shell_quote(spec.python_class);
        spec.call_time_limit = call_share_of_case_limit * suite.time_limit_seconds;
        built_in.push_back(external::external_backend(spec));
    }
    return built_in;
}

}  // namespace collide::validation
