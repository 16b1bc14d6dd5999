#include "python_script.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace collide::cli {

const char* python_interpreter() { return COLLIDE_PYTHON; }

int run_python_script(const std::string& script, const std::vector<std::string>& arguments) {
    std::vector<std::string> words{COLLIDE_PYTHON, script};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        std::error_code error;
        const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
        if (!error) ::setenv("COLLIDE_EXECUTABLE", self.c_str(), 0);
        ::execv(COLLIDE_PYTHON, argv.data());
        std::perror(COLLIDE_PYTHON);
        ::_exit(127);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace collide::cli
