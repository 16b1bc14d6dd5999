// `--solver NAME=COMMAND`, `--python-solver NAME=MODULE:CLASS`, and what they declare:
// `--solver-rule NAME=RULE`, `--solver-exact NAME`, `--solver-precision NAME=PRECISION`,
// `--solver-long-lived NAME`:
// outside solvers joining a suite run as backends (docs/your-solver.md).
#include <stdexcept>
#include <utility>

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
    cmd.add_option("--solver-exact", args.exact,
                   "NAME: the outside solver NAME is exact (event-driven, no time step) and is held to what exact "
                   "dynamics allows in its precision (docs/validation.md); repeatable");
    cmd.add_option("--solver-long-lived", args.long_lived,
                   "NAME: the outside program NAME serves many calls: started once per worker as `COMMAND --serve`, it "
                   "reads request directories on stdin and answers each with a line (docs/your-solver.md); repeatable");
    cmd.add_option("--solver-precision", args.precisions,
                   "NAME=PRECISION: the precision (double or float) the outside solver NAME computes in; default "
                   "double; repeatable");
}

namespace {

// The spec named `name` among `specs`; throws naming the option when there is none.
external::ExternalSolverSpec& named_spec(std::vector<external::ExternalSolverSpec>& specs, const std::string& name,
                                         const std::string& option) {
    for (auto& spec : specs)
        if (spec.name == name) return spec;
    throw std::invalid_argument(option + ": no --solver or --python-solver named '" + name + "'");
}

// NAME and VALUE of NAME=VALUE; VALUE empty when there is no '='.
std::pair<std::string, std::string> name_and_value(const std::string& text) {
    const auto eq = text.find('=');
    return {text.substr(0, eq), eq == std::string::npos ? "" : text.substr(eq + 1)};
}

}  // namespace

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
        const auto [name, rule] = name_and_value(text);
        if (const std::string why = external::rule_problem(rule); rule.empty() || !why.empty())
            throw std::invalid_argument("--solver-rule " + text + ": expected NAME=collide-first or NAME=integrate-first");
        named_spec(specs, name, "--solver-rule " + text).rule = rule;
    }
    for (const auto& name : args.exact) named_spec(specs, name, "--solver-exact " + name).exact = true;
    for (const auto& name : args.long_lived) named_spec(specs, name, "--solver-long-lived " + name).long_lived = true;
    for (const auto& text : args.precisions) {
        const auto [name, precision] = name_and_value(text);
        if (const std::string why = external::precision_problem(precision); precision.empty() || !why.empty())
            throw std::invalid_argument("--solver-precision " + text + ": expected NAME=double or NAME=float");
        named_spec(specs, name, "--solver-precision " + text).precision = precision;
    }
    for (const auto& spec : specs)
        if (const std::string why = external::claims_problem(spec.exact, spec.rule); !why.empty())
            throw std::invalid_argument("--solver-exact " + spec.name + " and --solver-rule " + spec.name + "=" + spec.rule +
                                        ": " + why);
    for (const auto& spec : specs)
        if (std::string problem = external::spec_problem(spec); !problem.empty())
            throw std::invalid_argument(spec.origin + ": " + problem);
    return specs;
}

validation::PythonRunner python_runner() {
    return {python_interpreter(), resource_path("python/collide") + "/solver_runner.py"};
}

}  // namespace collide::cli
