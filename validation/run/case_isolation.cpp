#include "validation/run/case_isolation.h"

#include "core/io/fd_io.h"
#include "core/process/descendants.h"
#include "core/io/input_file.h"
#include "core/io/output_file.h"
#include "external/solver_server.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

namespace collide::validation {

std::string result_path(const std::string& result_dir, const std::string& id) {
    return result_dir + "/" + id + ".toml";
}

std::string case_log_path(const std::string& result_dir, const std::string& id) {
    return result_dir + "/" + id + ".log";
}

namespace {

using Clock = std::chrono::steady_clock;

struct Child {
    CaseSpec spec;
    pid_t pid = 0;
    Clock::time_point start;
    bool killed_for_time = false;
    int exit_fd = -1;  // a pidfd: readable from the moment the process ends (-1: none)
};

// A descriptor that poll(2) reports readable once process `pid` has ended (pidfd_open,
// Linux 5.3), so the runner wakes the moment a case ends instead of at its next polling turn.
// -1 where the kernel has none; the runner then falls back to polling every few milliseconds.
int open_exit_fd(pid_t pid) {
#ifdef SYS_pidfd_open
    return int(::syscall(SYS_pidfd_open, pid, 0));
#else
    (void)pid;
    return -1;
#endif
}

// A process that runs cases one after another (in_worker): it reads a request (the case's
// spec as text, after its length) from `requests` and writes one byte to `replies` when the
// case's result file is written.
struct Worker {
    pid_t pid = 0;
    int requests = -1;              // the runner's write end
    int replies = -1;               // the runner's read end
    std::optional<Child> current;   // the case it runs, none while it waits
};

using Workers = std::map<pid_t, Worker>;

// The last lines a child printed: usually the sanitizer report or the abort message. Read
// through the input guard (core/io/input_file.h): a FIFO planted as the log is refused, not
// waited on for good.
std::string log_tail(const std::string& path, std::size_t max_chars = 1500) {
    int fd = -1;
    try {
        fd = open_input_file(path);
    } catch (const InputFileError& e) {
        return ::access(path.c_str(), F_OK) == 0 ? "(the log is not read: " + e.cause() + ")" : "";
    }
    const off_t size = ::lseek(fd, 0, SEEK_END);
    const off_t start = size > off_t(max_chars) ? size - off_t(max_chars) : 0;
    std::string s(std::size_t(std::max<off_t>(size - start, 0)), '\0');
    const ssize_t n = ::pread(fd, s.data(), s.size(), start);
    ::close(fd);
    s.resize(n > 0 ? std::size_t(n) : 0);
    return start > 0 ? "..." + s : s;
}

// SIGINT, SIGTERM and SIGHUP end the suite, but not before the parent has stopped its cases
// and removed their temporary files (a terminal's Ctrl-C reaches the children too; they die
// without cleaning up). The handler only records the signal; the wait loop acts on it.
volatile std::sig_atomic_t stop_signal = 0;
// A second stop signal ends collide at once, whatever it is doing (the cases die with it:
// PR_SET_PDEATHSIG): a stop must never depend on the runner reaching its loop.
extern "C" void record_stop_signal(int signal_number) {
    if (stop_signal) {
        ::signal(signal_number, SIG_DFL);
        ::raise(signal_number);
    }
    stop_signal = signal_number;
}
constexpr int stop_signals[] = {SIGINT, SIGTERM, SIGHUP};

void stop_cases_and_die(std::map<pid_t, Child>& running, Workers& workers, const IsolationOptions& options,
                        const std::set<pid_t>& children_before) {
    std::vector<pid_t> pids;
    for (const auto& [pid, child] : running) pids.push_back(pid);
    for (const auto& [pid, worker] : workers) pids.push_back(pid);
    for (pid_t pid : pids) ::kill(pid, SIGKILL);
    for (pid_t pid : pids) {
        ::waitpid(pid, nullptr, 0);
        remove_temporaries(options.runs_dir, options.result_dir, pid);
    }
    end_children_except(children_before);  // what the killed cases' solvers left running
    const int signal_number = stop_signal;
    ::signal(signal_number, SIG_DFL);
    ::raise(signal_number);
    std::_Exit(128 + signal_number);  // not reached: the signal ends the program
}

// What every process that runs cases does first: the stop signals and SIGPIPE back to their
// defaults (a case just ends; the parent cleans up), no pipe of a worker but its own, and death
// with the runner. A case must not outlive the runner that waits for it: when the runner is
// killed (an MPI job stopped by mpirun or at the end of its allocation), an orphan would go on
// writing into the output directory while a --resume run starts the same case again.
void become_case_process(pid_t runner, const Workers& workers) {
    for (int s : stop_signals) ::signal(s, SIG_DFL);
    ::signal(SIGPIPE, SIG_DFL);
    for (const auto& [pid, worker] : workers) ::close(worker.requests), ::close(worker.replies);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != runner) ::_exit(4);  // the runner died before the line above took effect
}

// The case's output goes to its own log so that parallel cases do not interleave. The log is
// opened through the output guard (core/io/output_file.h): a link to a device or a FIFO
// planted there is refused, not written into (the runner checked the path before the suite
// started; this refusal is for one planted since).
void redirect_output_to_log(const CaseSpec& spec, const IsolationOptions& options) {
    std::fflush(nullptr);
    const std::string log = case_log_path(options.result_dir, spec.id);
    int fd = -1;
    try {
        fd = open_output_stream(log);
    } catch (const OutputFileError& e) {
        std::fprintf(stderr, "case %s: %s\n", spec.id.c_str(), e.what());
        ::_exit(3);
    }
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
}

// Runs the case and writes its result file; 0, or 3 when it threw (its message in the log).
int run_and_record(const CaseSpec& spec, const IsolationOptions& options,
                   const std::function<CaseResult(const CaseSpec&)>& run_case) {
    int code = 0;
    try {
        CaseResult result = run_case(spec);
        write_case_result(result, result_path(options.result_dir, spec.id));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "case %s: %s\n", spec.id.c_str(), e.what());
        code = 3;
    }
    std::fflush(nullptr);
    return code;
}

// Ends a process that ran cases. _exit, not exit: it must not run the parent's atexit handlers
// or flush its stdio buffers twice; so the long-lived outside solvers it started
// (external/solver_server.h) are closed here: end of file on their stdin, then reaped.
[[noreturn]] void end_case_process(int code) {
    external::close_solver_servers();
    ::_exit(code);
}

[[noreturn]] void child_main(const CaseSpec& spec, const IsolationOptions& options,
                             const std::function<CaseResult(const CaseSpec&)>& run_case, pid_t runner,
                             const Workers& workers) {
    become_case_process(runner, workers);
    redirect_output_to_log(spec, options);
    end_case_process(run_and_record(spec, options, run_case));
}

// A worker's life: a case per request until the runner closes the pipe. A case that throws
// ends the worker with the status a case's own process ends with, so the runner records it
// the same way.
[[noreturn]] void worker_main(int requests, int replies, const IsolationOptions& options,
                              const std::function<CaseResult(const CaseSpec&)>& run_case) {
    for (;;) {
        std::uint64_t size = 0;
        if (!read_fully(requests, &size, sizeof size)) end_case_process(0);  // no case left
        std::string text(size, '\0');
        if (!read_fully(requests, text.data(), text.size())) end_case_process(0);
        const CaseSpec spec = case_spec_from_text(text);
        redirect_output_to_log(spec, options);
        const int code = run_and_record(spec, options, run_case);
        if (code != 0) end_case_process(code);
        const char done = 1;
        if (!write_fully(replies, &done, 1)) end_case_process(0);  // the runner is gone
    }
}

Worker start_worker(const IsolationOptions& options, const std::function<CaseResult(const CaseSpec&)>& run_case,
                    const Workers& workers) {
    int requests[2], replies[2];
    if (::pipe2(requests, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe failed: ") + std::strerror(errno));
    if (::pipe2(replies, O_CLOEXEC) != 0) {
        ::close(requests[0]), ::close(requests[1]);
        throw std::runtime_error(std::string("pipe failed: ") + std::strerror(errno));
    }
    std::fflush(nullptr);
    const pid_t runner = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
    if (pid == 0) {
        ::close(requests[1]), ::close(replies[0]);
        become_case_process(runner, workers);
        worker_main(requests[0], replies[1], options, run_case);
    }
    ::close(requests[0]), ::close(replies[1]);
    return Worker{pid, requests[1], replies[0], std::nullopt};
}

// Hands `spec` to an idle worker, started if there is none. A request the worker cannot take
// (it died) is noticed when the runner reaps it: the case is then recorded as its death.
void start_in_worker(const CaseSpec& spec, Workers& workers, const IsolationOptions& options,
                     const std::function<CaseResult(const CaseSpec&)>& run_case) {
    auto idle = std::find_if(workers.begin(), workers.end(), [](const auto& w) { return !w.second.current; });
    if (idle == workers.end()) {
        Worker started = start_worker(options, run_case, workers);
        idle = workers.emplace(started.pid, started).first;
    }
    Worker& worker = idle->second;
    worker.current = Child{spec, worker.pid, Clock::now()};
    const std::string text = case_spec_text(spec);
    const std::uint64_t size = text.size();
    if (write_fully(worker.requests, &size, sizeof size)) write_fully(worker.requests, text.data(), text.size());
}

// Whether the worker has written a reply (a finished case), without waiting.
bool take_reply(const Worker& worker) {
    pollfd p{worker.replies, POLLIN, 0};
    if (::poll(&p, 1, 0) != 1 || !(p.revents & POLLIN)) return false;
    char done = 0;
    return ::read(worker.replies, &done, 1) == 1;
}

void close_worker(const Worker& worker) {
    ::close(worker.requests);
    ::close(worker.replies);
}

// Waits up to `ms` for a busy worker's reply or a case process's end, and returns as soon as
// one comes.
void wait_for_case_end(const std::map<pid_t, Child>& running, const Workers& workers, int ms) {
    std::vector<pollfd> fds;
    for (const auto& [pid, worker] : workers)
        if (worker.current) fds.push_back(pollfd{worker.replies, POLLIN, 0});
    for (const auto& [pid, child] : running)
        if (child.exit_fd >= 0) fds.push_back(pollfd{child.exit_fd, POLLIN, 0});
    ::poll(fds.data(), fds.size(), ms);
}

CaseResult death_result(const Child& child, int wait_status, const IsolationOptions& options) {
    const std::string path = result_path(options.result_dir, child.spec.id);
    const std::string log = case_log_path(options.result_dir, child.spec.id);
    const bool ended_cleanly = !child.killed_for_time && WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0;
    // A child that died without cleaning up (a signal, the time limit, an error exit) leaves its
    // temporaries. One that exited 0 committed or removed its own, and listing both folders
    // after every case would cost time growing with the number of cases already written.
    if (!ended_cleanly) remove_temporaries(options.runs_dir, options.result_dir, child.pid);
    if (ended_cleanly && std::filesystem::exists(path)) {
        try {
            return read_case_result(path);
        } catch (const std::exception& e) {
            CaseResult r;
            r.spec = child.spec;
            r.status = RunStatus::crashed;
            r.diagnostic = e.what();
            return r;
        }
    }
    CaseResult r;
    r.spec = child.spec;
    std::ostringstream why;
    if (child.killed_for_time) {
        r.status = RunStatus::timed_out;
        why << "killed after the time limit of " << options.time_limit_seconds << " s";
    } else if (WIFSIGNALED(wait_status)) {
        r.status = RunStatus::crashed;
        why << "killed by signal " << WTERMSIG(wait_status) << " (" << strsignal(WTERMSIG(wait_status)) << ")";
    } else {
        r.status = RunStatus::crashed;
        why << "exited with status " << (WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1)
            << " without a result";
    }
    const std::string tail = log_tail(log);
    if (!tail.empty()) why << "; last output:\n" << tail;
    r.diagnostic = why.str();
    // The parent records the death, so --resume will not mistake the case for finished work
    // of a previous run that was never judged.
    write_case_result(r, path);
    return r;
}

}  // namespace

void remove_temporaries(const std::string& runs_dir, const std::string& result_dir, int pid) {
    namespace fs = std::filesystem;
    const std::string writer_mark = pid ? ".tmp-" + std::to_string(pid) + "-" : ".tmp-";
    std::error_code error;
    for (const std::string& dir : {runs_dir, result_dir}) {
        if (dir.empty()) continue;
        for (const auto& entry : fs::directory_iterator(dir, error)) {
            const std::string name = entry.path().filename().string();
            if (name.rfind('.', 0) == 0 && name.find(writer_mark) != std::string::npos) fs::remove(entry.path(), error);
        }
    }
    if (pid) return;
    // Records of older versions were written as NAME.partial: --resume removes those too.
    for (const auto& entry : fs::directory_iterator(result_dir, error))
        if (entry.path().extension() == ".partial") fs::remove(entry.path(), error);
}

void run_isolated(const std::vector<CaseSpec>& specs, const IsolationOptions& options,
                  const std::function<CaseResult(const CaseSpec&)>& run_case,
                  const std::function<void(const CaseResult&)>& on_done) {
    std::size_t next = 0;
    auto claim = [&]() -> std::optional<CaseSpec> {
        if (next == specs.size()) return std::nullopt;
        return specs[next++];
    };
    run_isolated_claiming(options, claim, run_case, on_done);
}

void run_isolated_claiming(const IsolationOptions& options, const std::function<std::optional<CaseSpec>()>& claim,
                           const std::function<CaseResult(const CaseSpec&)>& run_case,
                           const std::function<void(const CaseResult&)>& on_done,
                           const std::function<void()>& idle) {
    std::filesystem::create_directories(options.result_dir);
    std::map<pid_t, Child> running;  // cases in processes of their own
    Workers workers;
    auto busy = [&] {
        return running.size() + std::size_t(std::count_if(workers.begin(), workers.end(),
                                                          [](const auto& w) { return bool(w.second.current); }));
    };
    bool claimed_all = false;
    // A case killed at its time limit orphans what its solver left running (a daemon outside
    // its process group): adopted here, it is ended below before the summary is written.
    const SubreaperScope adopt_orphans;
    // Children the caller had before (a Python interpreter's own subprocesses, an MPI helper)
    // are not the suite's: only what appears from here on is ended as a stray.
    const std::set<pid_t> children_before = child_processes();
    stop_signal = 0;
    for (int s : stop_signals) ::signal(s, record_stop_signal);
    // A worker that died leaves its request pipe without a reader: writing to it must fail
    // with EPIPE (the death is recorded when the worker is reaped), not end the runner.
    const auto previous_sigpipe = ::signal(SIGPIPE, SIG_IGN);
    const auto limit = std::chrono::duration<double>(options.time_limit_seconds);
    constexpr int exited_cleanly = 0;  // the wait status of a process that called exit(0)
    while (!claimed_all || busy() > 0) {
        if (stop_signal) stop_cases_and_die(running, workers, options, children_before);
        while (!claimed_all && busy() < std::size_t(std::max(1, options.jobs))) {
            const std::optional<CaseSpec> spec = claim();
            if (!spec) {
                claimed_all = true;
                break;
            }
            std::filesystem::remove(result_path(options.result_dir, spec->id));
            if (options.in_worker && options.in_worker(*spec)) {
                start_in_worker(*spec, workers, options, run_case);
                continue;
            }
            std::fflush(nullptr);  // or the child would print the parent's buffered output again
            const pid_t runner = ::getpid();
            const pid_t pid = ::fork();
            if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
            if (pid == 0) child_main(*spec, options, run_case, runner, workers);
            running[pid] = Child{*spec, pid, Clock::now(), false, open_exit_fd(pid)};
        }
        bool replied = false;
        for (auto& [pid, worker] : workers)
            if (worker.current && take_reply(worker)) {
                const Child child = *worker.current;
                worker.current.reset();
                on_done(death_result(child, exited_cleanly, options));
                replied = true;
            }
        if (replied) continue;  // hand the idle worker its next case now, not after a polling turn
        int status = 0;
        const pid_t done = ::waitpid(-1, &status, WNOHANG);
        if (done > 0 && running.count(done)) {
            const Child child = running[done];
            running.erase(done);
            if (child.exit_fd >= 0) ::close(child.exit_fd);
            on_done(death_result(child, status, options));
            continue;
        }
        if (done > 0 && workers.count(done)) {
            const Worker worker = workers[done];
            workers.erase(done);
            // A reply written just before it died still counts: the case's result is complete.
            const int case_status = take_reply(worker) ? exited_cleanly : status;
            close_worker(worker);
            if (worker.current) on_done(death_result(*worker.current, case_status, options));
            continue;
        }
        auto enforce_limit = [&](Child& child) {
            if (!child.killed_for_time && Clock::now() - child.start > limit) {
                child.killed_for_time = true;
                ::kill(child.pid, SIGKILL);
            }
        };
        for (auto& [pid, child] : running) enforce_limit(child);
        for (auto& [pid, worker] : workers)
            if (worker.current) enforce_limit(*worker.current);
        idle();
        wait_for_case_end(running, workers, 20);
    }
    // No case left: each worker reads the end of its requests and exits.
    for (const auto& [pid, worker] : workers) close_worker(worker);
    for (const auto& [pid, worker] : workers) ::waitpid(pid, nullptr, 0);
    end_children_except(children_before);  // every case is over: any new process still here is a stray
    ::signal(SIGPIPE, previous_sigpipe);
    for (int s : stop_signals) ::signal(s, SIG_DFL);
}

}  // namespace collide::validation
