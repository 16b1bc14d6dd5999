// The `collide` program run from a test as a user runs it (tests/support/program_runner.h).
// The including test target defines COLLIDE_EXECUTABLE, the built program's path.
#pragma once

#include <string>
#include <vector>

#include "tests/support/program_runner.h"
#include "tests/support/scratch_directory.h"

namespace collide::test {

inline ProgramResult run_collide(const std::vector<std::string>& args, const ScratchDirectory& dir) {
    return run_program(COLLIDE_EXECUTABLE, args, dir);
}

// `collide ARGS` ended by timeout(1) after `seconds`: for a writer that could wait forever
// (one that opened a FIFO); a program ended that way exits with 124.
inline ProgramResult run_collide_within(int seconds, const std::vector<std::string>& args, const ScratchDirectory& dir) {
    std::vector<std::string> limited{std::to_string(seconds), COLLIDE_EXECUTABLE};
    limited.insert(limited.end(), args.begin(), args.end());
    return run_program("timeout", limited, dir);
}

}  // namespace collide::test
