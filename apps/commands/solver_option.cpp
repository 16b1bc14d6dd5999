// `--solver NAME=COMMAND`, `--python-solver NAME=MODULE:CLASS` and `--solver-rule NAME=RULE`:
// outside solvers joining a suite run as backends (docs/your-solver.md).
#include <stdexcept>

#include "apps/python_script.h"
#include "apps/resource_path.h"
#include "commands.h"

namespace collide::cli {

void add_solver_options(CLI::App& cmd, SolverArgs& args) {
    cmd.add_option("--solver", args.programs,
                   "NAME=COMMAND: an outside program as a backend of this run (docs/your-solver.md); repeatable");
    cmd.add_option("--python-solver", args.classes,
                   "NAME=MODULE:CLASS or NAME=FILE.py:CLASS: a Python class as a backend of this run; repeatable");
    cmd.add_option("--solver-rule", args.rules,
                   "NAME=RULE: the outside solver NAME implements the stepping rule RULE (collide-first or "
                   "integrate-first) and is judged as the stepped backends are; repeatable");
}

std::vector<external::ExternalSolverSpec> solver_specs(const SolverArgs& args) {
    std::vector<external::ExternalSolverSpec> specs;
    for (const auto& text : args.programs) specs.push_back(external::parse_solver_option(text));
    for (const auto& text : args.classes) {
        auto spec = external::parse_solver_option(text);
        spec.python_class = spec.command;
        spec.command.clear();
        spec.origin = "--python-solver " + text;
        if (spec.python_class.find(':') == std::string::npos)
            throw std::invalid_argument(spec.origin + ": expected NAME=MODULE:CLASS or NAME=FILE.py:CLASS");
        specs.push_back(spec);
    }
    for (const auto& text : args.rules) {
        const auto eq = text.find('=');
        const std::string name = text.substr(0, eq), rule = eq == std::string::npos ? "" : text.substr(eq + 1);
        if (const std::string why = external::rule_problem(rule); eq == std::string::npos || rule.empty() || !why.empty())
            throw std::invalid_argument("--solver-rule " + text + ": expected NAME=collide-first or NAME=integrate-first");
        bool found = false;
        for (auto& spec : specs)
            if (spec.name == name) spec.rule = rule, found = true;
        if (!found) throw std::invalid_argument("--solver-rule " + text + ": no --solver or --python-solver named '" + name + "'");
    }
    for (const auto& spec : specs)
        if (std::string problem = external::spec_problem(spec); !problem.empty())
            throw std::invalid_argument(spec.origin + ": " + problem);
    return specs;
}

validation::PythonRunner python_runner() {
    return {python_interpreter(), resource_path("python/collide") + "/solver_runner.py"};
}

}  // namespace collide::cli
