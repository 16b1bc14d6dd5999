// Whole reads and writes on a file descriptor: read(2) and write(2) may move fewer bytes than
// asked (a pipe, a signal), so both loop until all is moved, retrying on EINTR. Used by the
// atomic output file (core/io/output_file.cpp) and the suite's worker pipes
// (validation/run/case_isolation.cpp).
#pragma once

#include <unistd.h>

#include <cerrno>
#include <cstddef>

namespace collide {

// True when all `size` bytes were written; false on an error (errno set, e.g. ENOSPC) or a
// write that moved nothing.
inline bool write_fully(int fd, const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = ::write(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n, size -= std::size_t(n);
    }
    return true;
}

// True when all `size` bytes were read; false on an error or end of file first.
inline bool read_fully(int fd, void* data, std::size_t size) {
    char* p = static_cast<char*>(data);
    while (size > 0) {
        const ssize_t n = ::read(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n, size -= std::size_t(n);
    }
    return true;
}

}  // namespace collide
