#include "solver_server.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

#include "core/io/fd_io.h"
#include "core/process/descendants.h"
#include "core/text/printable.h"

namespace collide::external {
namespace {

using Clock = std::chrono::steady_clock;

// A reply is one short line; a longer one without a line break is garbage, not a reply to wait for.
constexpr std::size_t max_reply_bytes = 64 * 1024;
// What a call's output may hold (the rest of a larger one is cut: the case's log is no archive).
constexpr off_t max_output_bytes = 64 << 20;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Writes `line` to a pipe whose reader may be gone: with SIGPIPE blocked in this thread, so a
// dead server makes the write fail with EPIPE instead of ending collide (a case process keeps
// SIGPIPE's default action); a SIGPIPE that became pending is taken back before unblocking.
bool write_line(int fd, const std::string& line) {
    sigset_t pipe_signal, previous;
    sigemptyset(&pipe_signal);
    sigaddset(&pipe_signal, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_signal, &previous);
    const bool written = write_fully(fd, line.data(), line.size());
    if (!written && errno == EPIPE) {
        const timespec now{0, 0};
        while (sigtimedwait(&pipe_signal, nullptr, &now) < 0 && errno == EINTR) {
        }
    }
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    return written;
}

// An anonymous in-memory file for the server's stderr (no path to clean up, none a fork could
// remove), opened for appending so that emptying it after a call starts the next at 0.
int output_file() {
    const int fd = ::memfd_create("collide-solver-output", MFD_CLOEXEC);
    if (fd < 0) throw std::runtime_error(std::string("memfd_create failed: ") + std::strerror(errno));
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_APPEND);
    return fd;
}

void close_fd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

}  // namespace

std::string ServedCall::problem(double limit_seconds) const {
    switch (reply) {
    case Reply::done: return "";
    case Reply::failed: return "it answered failed: " + text;
    case Reply::garbage:
        return "it answered '" + text + "' instead of 'done' or 'failed REASON' (its server was ended; the next call starts a new one)";
    case Reply::ended: break;
    }
    if (process.timed_out) return process.describe(limit_seconds) + "; the next call starts a new server";
    return "its server ended before answering: " + process.describe(limit_seconds);
}

SolverServer::SolverServer(const std::string& command, const std::string& directory) {
    int requests[2], replies[2];
    if (::pipe2(requests, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe failed: ") + std::strerror(errno));
    if (::pipe2(replies, O_CLOEXEC) != 0) {
        ::close(requests[0]), ::close(requests[1]);
        throw std::runtime_error(std::string("pipe failed: ") + std::strerror(errno));
    }
    requests_ = requests[1];
    replies_ = replies[0];
    try {
        log_ = output_file();
        pid_ = start_program(command, "--serve", directory, ChildStreams{requests[0], replies[1], log_});
    } catch (...) {
        ::close(requests[0]), ::close(replies[1]);
        close_fd(requests_), close_fd(replies_), close_fd(log_);
        throw;
    }
    ::close(requests[0]), ::close(replies[1]);
    fresh_ = true;
}

SolverServer::~SolverServer() {
    close();
    close_fd(log_);
}

void SolverServer::send_end() { close_fd(requests_); }

void SolverServer::close(double grace_seconds) {
    if (pid_ > 0) end(false, grace_seconds);
}

void SolverServer::forget() {
    close_fd(requests_), close_fd(replies_), close_fd(log_);
    pid_ = 0;
}

// Ends the server: end of file on its stdin, up to `grace_seconds` for it to exit (none when
// `kill_now`), then its process group killed, its orphans ended and every process reaped.
ProgramOutcome SolverServer::end(bool kill_now, double grace_seconds) {
    const SubreaperScope adopt_orphans;
    std::set<pid_t> others = child_processes();  // other servers of this process stay
    others.erase(pid_);
    send_end();
    const auto start = Clock::now();
    while (!kill_now && !reaped_ && seconds_since(start) < grace_seconds) {
        reaped_ = ::waitpid(pid_, &status_, WNOHANG) == pid_;
        if (!reaped_) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (!reaped_) {
        ::kill(-pid_, SIGKILL);
        while (::waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
        }
    }
    end_process_group(pid_, others);  // what it started, in its group or orphaned
    ProgramOutcome outcome;
    set_outcome_status(outcome, status_);
    close_fd(replies_);  // its output file stays: the call reads what it wrote last
    pid_ = 0;
    return outcome;
}

bool SolverServer::still_running() {
    if (pid_ > 0 && ::waitpid(pid_, &status_, WNOHANG) == pid_) {
        reaped_ = true;
        end(true, 0);
    }
    if (pid_ > 0) drain_replies();
    if (!pending_.empty()) end(true, 0);  // it wrote while idle: out of step with the protocol
    return alive();
}

// What it wrote on stderr since the last call; the file is emptied for the next.
std::string SolverServer::take_output() {
    struct stat st {};
    if (log_ < 0 || ::fstat(log_, &st) != 0) return "";
    std::string text(std::size_t(std::min<off_t>(st.st_size, max_output_bytes)), '\0');
    const ssize_t n = ::pread(log_, text.data(), text.size(), 0);
    text.resize(n > 0 ? std::size_t(n) : 0);
    if (::ftruncate(log_, 0) != 0) text += "\n(collide could not empty this output for the next call)";
    return text;
}

// The first whole line of what it wrote (without the line break); a long run without one is
// taken as a line too, to be refused.
bool SolverServer::take_pending_line(std::string& line) {
    const auto eol = pending_.find('\n');
    if (eol == std::string::npos && pending_.size() <= max_reply_bytes) return false;
    line = pending_.substr(0, std::min(eol, pending_.size()));
    pending_.erase(0, eol == std::string::npos ? pending_.size() : eol + 1);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
}

// Appends to pending_ what it wrote and has not been read, without waiting.
void SolverServer::drain_replies() {
    char buffer[4096];
    pollfd p{replies_, POLLIN, 0};
    while (pending_.size() <= max_reply_bytes && ::poll(&p, 1, 0) > 0) {
        const ssize_t n = ::read(replies_, buffer, sizeof buffer);
        if (n <= 0) break;
        pending_.append(buffer, std::size_t(n));
    }
}

// One line of its stdout, waiting at most `limit_seconds`. False when no line came: it ended
// (`ended` says how), or it ran out of time and was killed.
bool SolverServer::read_line(std::string& line, double limit_seconds, ProgramOutcome& ended) {
    const auto start = Clock::now();
    for (;;) {
        if (take_pending_line(line)) return true;
        if (!alive()) return false;
        const double left = limit_seconds - seconds_since(start);
        if (left <= 0) {
            ended = end(true, 0);
            ended.timed_out = true;
            continue;
        }
        // Short polls: a server that died while a descendant holds its stdout open gives no end
        // of file, so its exit is looked for between them.
        pollfd p{replies_, POLLIN, 0};
        if (::poll(&p, 1, int(std::min(left * 1000.0, 50.0)) + 1) > 0) {
            char buffer[4096];
            const ssize_t n = ::read(replies_, buffer, sizeof buffer);
            if (n > 0) pending_.append(buffer, std::size_t(n));
            else if (n == 0 || errno != EINTR) ended = end(false, 1);  // it closed its stdout: it is exiting
            continue;
        }
        if (::waitpid(pid_, &status_, WNOHANG) == pid_) {
            reaped_ = true;
            drain_replies();  // a reply written just before it exited still counts
            ended = end(true, 0);
        }
    }
}

ServedCall SolverServer::call(const std::string& request_dir, double limit_seconds) {
    ServedCall served;
    served.started = std::exchange(fresh_, false);
    const auto start = Clock::now();
    std::string line;
    if (request_dir.find('\n') != std::string::npos) {
        served.reply = ServedCall::Reply::failed;
        served.text = "the request directory's path holds a line break (TMPDIR?); it cannot be sent as one line";
    } else if (!write_line(requests_, request_dir + "\n")) {
        served.process = end(false, 1);  // its stdin is closed: it has ended, or is ending
    } else if (read_line(line, limit_seconds, served.process)) {
        if (line == "done") served.reply = ServedCall::Reply::done;
        else if (line == "failed" || line.rfind("failed ", 0) == 0) {
            served.reply = ServedCall::Reply::failed;
            served.text = line.size() > 7 ? printable_tail(line.substr(7), 300) : "(no reason given)";
        } else {
            served.reply = ServedCall::Reply::garbage;
            served.text = printable_tail(line, 200);
        }
    }
    // Out of step with the protocol: a line that is no reply, or more than one reply to one
    // request (the extra line would be taken as the next request's reply). The reply it gave
    // stands; the next call starts a new server.
    if (served.reply == ServedCall::Reply::garbage || !pending_.empty()) end(true, 0);
    served.output = take_output();
    served.process.seconds = seconds_since(start);
    return served;
}

namespace {

// The idle servers of this process. A fork copies them into the child, which must neither use
// nor end them (they are the parent's children): `owner` tells the copy apart.
struct ServerPool {
    std::mutex mutex;
    pid_t owner = ::getpid();
    std::multimap<std::pair<std::string, std::string>, std::unique_ptr<SolverServer>> idle;

    void forget_if_forked() {
        if (owner == ::getpid()) return;
        for (auto& [key, server] : idle) server->forget();
        idle.clear();
        owner = ::getpid();
    }
    void close_all() {
        forget_if_forked();
        for (auto& [key, server] : idle) server->send_end();  // all at once: they exit in parallel
        for (auto& [key, server] : idle) server->close();
        idle.clear();
    }
    ~ServerPool() { close_all(); }
};

ServerPool& pool() {
    static ServerPool servers;
    return servers;
}

}  // namespace

std::unique_ptr<SolverServer> take_idle_server(const std::string& command, const std::string& directory) {
    ServerPool& p = pool();
    const std::lock_guard lock(p.mutex);
    p.forget_if_forked();
    // One that ended while idle (killed from outside) is reaped here, and a new one started instead.
    for (auto found = p.idle.find({command, directory}); found != p.idle.end(); found = p.idle.find({command, directory})) {
        std::unique_ptr<SolverServer> server = std::move(found->second);
        p.idle.erase(found);
        if (server->still_running()) return server;
    }
    return nullptr;
}

void give_back_server(const std::string& command, const std::string& directory, std::unique_ptr<SolverServer> server) {
    ServerPool& p = pool();
    const std::lock_guard lock(p.mutex);
    p.forget_if_forked();
    p.idle.emplace(std::make_pair(command, directory), std::move(server));
}

void close_solver_servers() {
    ServerPool& p = pool();
    const std::lock_guard lock(p.mutex);
    p.close_all();
}

}  // namespace collide::external
