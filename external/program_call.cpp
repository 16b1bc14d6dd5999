#include "program_call.h"

#include "core/process/descendants.h"
#include "core/io/output_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace collide::external {
namespace {

// In the child between fork and exec: only async-signal-safe calls (no allocation), so every
// string is made before the fork. `in` < 0: stdin from /dev/null.
[[noreturn]] void exec_child(const char* script, const char* argument, const char* directory, const ChildStreams& streams,
                             pid_t parent) {
    ::setpgid(0, 0);                      // its own group: the limit kills its children too
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);   // and it dies with the case process
    if (::getppid() != parent) ::_exit(125);  // the parent died before prctl took effect
    const int in = streams.in >= 0 ? streams.in : ::open("/dev/null", O_RDONLY);
    if (in < 0 || streams.out < 0 || streams.err < 0 || ::chdir(directory) != 0) ::_exit(126);
    // dup2 clears close-on-exec on the copies: the program gets exactly fds 0, 1 and 2 of these.
    ::dup2(in, 0);
    ::dup2(streams.out, 1);
    ::dup2(streams.err, 2);
    ::execl("/bin/sh", "sh", "-c", script, "collide-solver", argument, static_cast<char*>(nullptr));
    ::_exit(127);
}

}  // namespace

std::string ProgramOutcome::describe(double limit_seconds) const {
    std::ostringstream out;
    if (timed_out) out << "still running after the limit of " << limit_seconds << " s (killed)";
    else if (signal) out << "killed by signal " << signal << " (" << strsignal(signal) << ")";
    else if (exit_status == 127) out << "exit status 127 (the shell found no such command)";
    else if (exit_status == 126) out << "exit status 126 (the command could not be executed)";
    else out << "exit status " << exit_status;
    return out.str();
}

void end_process_group(pid_t group, const std::set<pid_t>& children_before) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    for (;;) {
        ::kill(-group, SIGKILL);
        end_children_except(children_before);
        if (::kill(-group, 0) != 0 || Clock::now() - start > std::chrono::seconds(1)) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    end_children_except(children_before);
}

pid_t start_program(const std::string& command, const std::string& argument, const std::string& directory,
                    const ChildStreams& streams) {
    const std::string script = command + " \"$1\"";  // the argument (a request directory, --serve) last
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
    if (pid == 0) exec_child(script.c_str(), argument.c_str(), directory.c_str(), streams, parent);
    ::setpgid(pid, pid);  // also here, so the group exists before any kill
    return pid;
}

void set_outcome_status(ProgramOutcome& outcome, int wait_status) {
    if (WIFEXITED(wait_status)) outcome.exit_status = WEXITSTATUS(wait_status);
    else if (WIFSIGNALED(wait_status)) outcome.signal = WTERMSIG(wait_status);
}

ProgramOutcome call_program(const std::string& command, const std::string& argument, const std::string& directory,
                            const std::string& output_path, double limit_seconds) {
    using Clock = std::chrono::steady_clock;
    const SubreaperScope adopt_orphans;  // the program's orphans are adopted here, not by init
    const std::set<pid_t> children_before = child_processes();
    // Opened here through the output guard (core/io/output_file.h), not in the child, which
    // may not allocate: a link or a FIFO at the output's place is refused, not written into.
    const int out = open_output_stream(output_path);
    const auto start = Clock::now();
    pid_t pid = 0;
    try {
        pid = start_program(command, argument, directory, ChildStreams{-1, out, out});
    } catch (...) {
        ::close(out);
        throw;
    }
    ::close(out);
    ProgramOutcome outcome;
    int status = 0;
    // Poll: a short sleep keeps the wait cheap, and the limit is honoured within 5 ms.
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) throw std::runtime_error(std::string("waitpid failed: ") + std::strerror(errno));
        if (std::chrono::duration<double>(Clock::now() - start).count() > limit_seconds) {
            outcome.timed_out = true;
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    end_process_group(pid, children_before);
    outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (!outcome.timed_out) set_outcome_status(outcome, status);
    return outcome;
}

}  // namespace collide::external
