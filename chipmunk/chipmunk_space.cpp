#include "chipmunk_space.h"

#include <chipmunk/chipmunk.h>
#include <unistd.h>

#include <cstdio>
#include <mutex>

namespace collide {
namespace {

// Makes one space with file descriptor 1 on stderr, then puts stdout back.
void print_banner_to_stderr() {
    std::fflush(stdout);
    const int saved = ::dup(STDOUT_FILENO);
    if (saved < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) return;  // then it goes where it goes
    cpSpaceFree(cpSpaceNew());
    std::fflush(stdout);
    ::dup2(saved, STDOUT_FILENO);
    ::close(saved);
}

}  // namespace

cpSpace* new_chipmunk_space() {
    static std::once_flag banner;
    std::call_once(banner, print_banner_to_stderr);
    return cpSpaceNew();
}

}  // namespace collide
