// The words the input and the output guards (core/io/input_file.h, core/io/output_file.h) use
// for what is wrong with a path, from the system's own stat(2) mode and errno, so that both
// guards name a cause the same way.
#pragma once

#include <limits.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace collide::path_causes {

inline std::string kind_of(mode_t mode) {
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISREG(mode)) return "a regular file";
    return "not a regular file";
}

inline std::string too_long() {
    return "the path is too long (" + std::string(std::strerror(ENAMETOOLONG)) + ": at most " +
           std::to_string(NAME_MAX) + " bytes a name and " + std::to_string(PATH_MAX - 1) + " bytes a path)";
}

inline std::string link_loop(const std::string& what) {
    return what + " is a loop of symbolic links (" + std::strerror(ELOOP) + "): it never reaches a file";
}

}  // namespace collide::path_causes
