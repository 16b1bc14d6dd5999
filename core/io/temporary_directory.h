// A directory of its own under `parent`, made with mkdtemp (POSIX: a fresh name, mode 0700, so
// no other run shares or replaces it) and removed with everything in it when the object goes.
// For the files a child program answers in: an outside solver's request, a Python class's
// declarations.
#pragma once

#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace collide {

class TemporaryDirectory {
public:
    // Throws std::runtime_error "cannot create <what> in <parent> (<cause>)".
    TemporaryDirectory(const std::filesystem::path& parent, const std::string& prefix, const std::string& what) {
        std::string pattern = (parent / (prefix + "-XXXXXX")).string();
        if (!::mkdtemp(pattern.data()))
            throw std::runtime_error("cannot create " + what + " in " + parent.string() + " (" +
                                     std::strerror(errno) + ")");
        path_ = pattern;
    }
    ~TemporaryDirectory() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

    std::string file(const std::string& name) const { return (std::filesystem::path(path_) / name).string(); }
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

}  // namespace collide
