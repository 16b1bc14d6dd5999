// Outside solvers in a suite run (docs/your-solver.md): the [solver.NAME] tables of a suite
// file, `collide validate --solver NAME=COMMAND`, and Python's validate(solvers=...) all end up
// here, as ExternalSolverSpecs in Suite::solvers, and join the suite's backends as rows of
// their own (external/external_solver.h): every consumer of the backend list (the runner,
// `collide explain`) gets them from backends_with_solvers().
#pragma once

#include <string>
#include <vector>

#include "core/backend_registry.h"
#include "core/io/shell_quote.h"
#include "external/external_solver.h"
#include "validation/plan/suite.h"

namespace collide::validation {

// How a Python class is run: `python runner module:Class` (python/collide/solver_runner.py).
struct PythonRunner {
    std::string python;  // the interpreter
    std::string runner;  // the runner script's path
};

// Adds outside solvers to the suite: each joins its backend list for this run (a list of
// names gets the name; "all" takes every backend given to the runner anyway). Throws
// SuiteError for a name given twice.
void add_solvers(Suite& suite, const std::vector<external::ExternalSolverSpec>& solvers);

// `built_in` plus one backend per outside solver of the suite (a Python class as its runner's
// command; each program call limited to 45 % of the case's time limit, as a case calls it
// twice: warm-up and timed run), declaring what its spec declares and, for a class, what its
// attributes declare (class_declarations.h). Throws SuiteError for a name a built-in backend
// has, or a class whose declarations cannot be read or contradict the spec's.
std::vector<BackendInfo> backends_with_solvers(const Suite& suite, std::vector<BackendInfo> built_in,
                                               const PythonRunner& python);

}  // namespace collide::validation
