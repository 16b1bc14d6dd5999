// What a solver given as a Python class declares about itself as class attributes (`exact`,
// `precision`, `rule`: docs/your-solver.md, "Declaring an exact solver"). Read here, once, by
// the class's runner (python/collide/solver_runner.py --declarations), for every way a class is
// named: a suite's `python = "..."`, `collide validate --python-solver`, and
// `collide.validate(solvers=...)`, so that all three judge the class alike.
#pragma once

#include "external/external_solver.h"
#include "validation/plan/external_solvers.h"

namespace collide::validation {

// Adds the class's declarations to `spec` (nothing for a program): an attribute the suite or
// the command line declares too must agree with it. Throws SuiteError naming the solver's
// origin and the class when the class cannot be loaded, an attribute has no valid value, the
// two disagree, or the result contradicts itself (exact with a rule).
void add_class_declarations(external::ExternalSolverSpec& spec, const PythonRunner& python);

}  // namespace collide::validation
