#include "core/process/descendants.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace collide {
namespace {

namespace fs = std::filesystem;

// The pids listed in /proc/self/task/TID/children (CONFIG_PROC_CHILDREN); false where the
// kernel has no such file.
bool read_task_children(std::set<pid_t>& out) {
    std::error_code error;
    bool found = false;
    for (const auto& task : fs::directory_iterator("/proc/self/task", error)) {
        std::ifstream in(task.path() / "children");
        if (!in) continue;
        found = true;
        for (long pid = 0; in >> pid;) out.insert(pid_t(pid));
    }
    return found;
}

// The parent pid in /proc/PID/stat: "PID (COMM) STATE PPID ...", where COMM may hold spaces
// and parentheses, so the fields are counted from the last ')'.
pid_t parent_of(const fs::path& stat_file) {
    std::ifstream in(stat_file);
    std::string text;
    std::getline(in, text);
    const auto close = text.rfind(')');
    if (close == std::string::npos) return -1;
    char state = 0;
    long parent = -1;
    std::istringstream fields(text.substr(close + 1));
    fields >> state >> parent;
    return pid_t(parent);
}

void scan_proc_for_children(std::set<pid_t>& out) {
    const pid_t self = ::getpid();
    std::error_code error;
    for (const auto& entry : fs::directory_iterator("/proc", error)) {
        const std::string name = entry.path().filename().string();
        if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
        if (parent_of(entry.path() / "stat") == self) out.insert(pid_t(std::stol(name)));
    }
}

}  // namespace

SubreaperScope::SubreaperScope() {
    ::prctl(PR_GET_CHILD_SUBREAPER, &previous_, 0, 0, 0);
    ::prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
}

SubreaperScope::~SubreaperScope() { ::prctl(PR_SET_CHILD_SUBREAPER, previous_, 0, 0, 0); }

std::set<pid_t> child_processes() {
    std::set<pid_t> children;
    if (!read_task_children(children)) scan_proc_for_children(children);
    return children;
}

std::size_t end_children_except(const std::set<pid_t>& keep) {
    std::size_t ended = 0;
    for (int round = 0; round < 10000; ++round) {
        std::set<pid_t> strays;
        for (pid_t pid : child_processes())
            if (!keep.count(pid)) strays.insert(pid);
        if (strays.empty()) break;
        for (pid_t pid : strays) ::kill(pid, SIGKILL);
        for (pid_t pid : strays)
            while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
            }
        ended += strays.size();
    }
    return ended;
}

}  // namespace collide
