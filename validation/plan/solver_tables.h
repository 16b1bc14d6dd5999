// The [solver.NAME] tables of a suite file (docs/your-solver.md), read by parse_suite.
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "external/external_solver.h"

namespace collide::validation {

// [solver.NAME] tables: command = "..." or python = "module:Class", optional rule. Commands run
// in `dir` (the suite file's directory). Throws SuiteError naming the file, table and key.
std::vector<external::ExternalSolverSpec> read_solver_tables(const toml::table& root, const std::string& file,
                                                             const std::string& dir);

}  // namespace collide::validation
