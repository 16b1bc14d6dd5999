// One call of an outside program: `sh -c COMMAND ARG` in a process group of its own, with
// its output captured to a file and a wall-clock limit. Whatever the program does (crash,
// hang, exit with any status, print anything), the caller gets an outcome, never a hang:
// at the limit the whole process group is killed, and if the caller itself dies (the suite
// runner kills a case past its time limit) the program gets SIGKILL too (PR_SET_PDEATHSIG).
// A descendant that leaves the group (setsid, a daemon) is adopted by the caller as its child
// subreaper and ended with the call too (core/process/descendants.h).
#pragma once

#include <string>

namespace collide::external {

struct ProgramOutcome {
    bool timed_out = false;
    int exit_status = -1;   // when it exited
    int signal = 0;         // when a signal ended it
    double seconds = 0;     // wall time from start to end
    bool succeeded() const { return !timed_out && signal == 0 && exit_status == 0; }
    // "exit status 3", "killed by signal 11 (Segmentation fault)", "still running after 5 s"
    std::string describe(double limit_seconds) const;
};

// Runs `command` through /bin/sh with `argument` appended (as "$1", quoted), in `directory`,
// stdin from /dev/null, stdout and stderr into `output_path`. Throws std::runtime_error only
// when the process cannot be started at all (fork fails).
ProgramOutcome call_program(const std::string& command, const std::string& argument, const std::string& directory,
                            const std::string& output_path, double limit_seconds);

}  // namespace collide::external
