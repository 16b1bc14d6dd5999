// Running one of the Python scripts the program ships (the report renderer, the comparison of
// two result directories, the GSD writer) as a child process: fork + exec of the Python the
// build was configured with, no shell (so file names need no quoting), stdout flushed first so
// the child's lines follow the parent's in order.
#pragma once

#include <string>
#include <vector>

namespace collide::cli {

// Runs `script` (a path, e.g. resource_path("validation/report") + "/make_report.py") with
// `arguments` and waits for it. The child learns this program's path in COLLIDE_EXECUTABLE
// (unless the caller set it), so a script can call `collide render` or `collide explain` back.
// Returns the script's exit status, or -1 if it did not exit normally (a signal).
int run_python_script(const std::string& script, const std::vector<std::string>& arguments);

// The interpreter, for messages: "/usr/bin/python3".
const char* python_interpreter();

}  // namespace collide::cli
