#include "case_isolation.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

namespace collide::validation {

std::string result_path(const std::string& result_dir, const std::string& id) {
    return result_dir + "/" + id + ".toml";
}

namespace {

using Clock = std::chrono::steady_clock;

struct Child {
    CaseSpec spec;
    pid_t pid = 0;
    Clock::time_point start;
    bool killed_for_time = false;
};

// The last lines a child printed: usually the sanitizer report or the abort message.
std::string log_tail(const std::string& path, std::size_t max_chars = 1500) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    if (s.size() > max_chars) s = "..." + s.substr(s.size() - max_chars);
    return s;
}

// SIGINT, SIGTERM and SIGHUP end the suite, but not before the parent has stopped its cases
// and removed their temporary files (a terminal's Ctrl-C reaches the children too; they die
// without cleaning up). The handler only records the signal; the wait loop acts on it.
volatile std::sig_atomic_t stop_signal = 0;
extern "C" void record_stop_signal(int signal_number) { stop_signal = signal_number; }
constexpr int stop_signals[] = {SIGINT, SIGTERM, SIGHUP};

void stop_cases_and_die(std::map<pid_t, Child>& running, const IsolationOptions& options) {
    for (const auto& [pid, child] : running) ::kill(pid, SIGKILL);
    for (const auto& [pid, child] : running) {
        ::waitpid(pid, nullptr, 0);
        remove_temporaries(options.runs_dir, options.result_dir, pid);
    }
    const int signal_number = stop_signal;
    ::signal(signal_number, SIG_DFL);
    ::raise(signal_number);
    std::_Exit(128 + signal_number);  // not reached: the signal ends the program
}

[[noreturn]] void child_main(const CaseSpec& spec, const IsolationOptions& options,
                             const std::function<CaseResult(const CaseSpec&)>& run_case, pid_t runner) {
    for (int s : stop_signals) ::signal(s, SIG_DFL);  // a case just ends; the parent cleans up
    // The child's output goes to its own log so that parallel cases do not interleave.
    const std::string log = options.result_dir + "/" + spec.id + ".log";
    // A case must not outlive the runner that waits for it: when the runner is killed (an MPI
    // job stopped by mpirun or at the end of its allocation), an orphan would go on writing
    // into the output directory while a --resume run starts the same case again.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != runner) ::_exit(4);  // the runner died before the line above took effect
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        ::dup2(fd, STDOUT_FILENO);
        ::dup2(fd, STDERR_FILENO);
        ::close(fd);
    }
    int code = 0;
    try {
        CaseResult result = run_case(spec);
        write_case_result(result, result_path(options.result_dir, spec.id));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "case %s: %s\n", spec.id.c_str(), e.what());
        code = 3;
    }
    std::fflush(nullptr);
    // _exit: the child must not run the parent's atexit handlers or flush its stdio buffers twice.
    ::_exit(code);
}

CaseResult death_result(const Child& child, int wait_status, const IsolationOptions& options) {
    // A child that died without cleaning up (a signal, the time limit) leaves its temporaries.
    remove_temporaries(options.runs_dir, options.result_dir, child.pid);
    const std::string path = result_path(options.result_dir, child.spec.id);
    const std::string log = options.result_dir + "/" + child.spec.id + ".log";
    if (!child.killed_for_time && WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0 &&
        std::filesystem::exists(path)) {
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
    std::map<pid_t, Child> running;
    bool claimed_all = false;
    stop_signal = 0;
    for (int s : stop_signals) ::signal(s, record_stop_signal);
    const auto limit = std::chrono::duration<double>(options.time_limit_seconds);
    while (!claimed_all || !running.empty()) {
        if (stop_signal) stop_cases_and_die(running, options);
        while (!claimed_all && running.size() < std::size_t(std::max(1, options.jobs))) {
            const std::optional<CaseSpec> spec = claim();
            if (!spec) {
                claimed_all = true;
                break;
            }
            std::filesystem::remove(result_path(options.result_dir, spec->id));
            std::fflush(nullptr);  // or the child would print the parent's buffered output again
            const pid_t runner = ::getpid();
            const pid_t pid = ::fork();
            if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
            if (pid == 0) child_main(*spec, options, run_case, runner);
            running[pid] = Child{*spec, pid, Clock::now()};
        }
        int status = 0;
        const pid_t done = ::waitpid(-1, &status, WNOHANG);
        if (done > 0 && running.count(done)) {
            const Child child = running[done];
            running.erase(done);
            on_done(death_result(child, status, options));
            continue;
        }
        for (auto& [pid, child] : running)
            if (!child.killed_for_time && Clock::now() - child.start > limit) {
                child.killed_for_time = true;
                ::kill(pid, SIGKILL);
            }
        idle();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    for (int s : stop_signals) ::signal(s, SIG_DFL);
}

}  // namespace collide::validation
