// Writes a suite's outcome as machine-readable files: summary.json (read by the report
// renderer and by anyone scripting over results) and junit.xml (for CI systems).
#pragma once

#include <string>

#include "validation/suite_outcome.h"

namespace collide::validation {

void write_summary_json(const Suite& suite, const SuiteOutcome& outcome, const std::string& path);
void write_junit_xml(const Suite& suite, const SuiteOutcome& outcome, const std::string& path);

}  // namespace collide::validation
