// One call of an outside program: `sh -c COMMAND ARG` in a process group of its own, with
// its output captured to a file and a wall-clock limit. Whatever the program does (crash,
// hang, exit with any status, print anything), the caller gets an outcome, never a hang:
// at the limit the whole process group is killed, and if the caller itself dies (the suite
// runner kills a case past its time limit) the program gets SIGKILL too (PR_SET_PDEATHSIG).
// A descendant that leaves the group (setsid, a daemon) is adopted by the caller as its child
// subreaper and ended with the call too (core/process/descendants.h).
#pragma once

#include <sys/types.h>

#include <set>
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

// The descriptors a started program gets as its stdin, stdout and stderr (in < 0: /dev/null).
struct ChildStreams {
    int in = -1;
    int out = -1;
    int err = -1;
};

// Starts `sh -c 'COMMAND "$1"' collide-solver ARGUMENT` in `directory`, in a process group of
// its own (its id is the returned pid) that dies with this process (PR_SET_PDEATHSIG). The
// one starting step of a one-shot call (call_program) and a long-lived solver (solver_server.h).
// Throws std::runtime_error when fork fails.
pid_t start_program(const std::string& command, const std::string& argument, const std::string& directory,
                    const ChildStreams& streams);

// Ends what a program left behind: the rest of its process group, and every descendant that
// left the group (setsid) and was adopted here as an orphan (SubreaperScope): every child of
// this process not in `children_before`. A process of the group that is still dying may yet
// orphan a child, so the group is waited for until it is gone, at most a second.
void end_process_group(pid_t group, const std::set<pid_t>& children_before);

// The exit status or signal of a waitpid status.
void set_outcome_status(ProgramOutcome& outcome, int wait_status);

// Runs `command` through /bin/sh with `argument` appended (as "$1", quoted), in `directory`,
// stdin from /dev/null, stdout and stderr into `output_path`. Throws std::runtime_error only
// when the process cannot be started at all (fork fails).
ProgramOutcome call_program(const std::string& command, const std::string& argument, const std::string& directory,
                            const std::string& output_path, double limit_seconds);

}  // namespace collide::external
