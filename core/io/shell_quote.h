// A word quoted for /bin/sh: '...' with every ' written '\'' (the one form that needs no other
// escapes). For the commands collide builds: ffmpeg pipes, outside solvers, tests' programs.
#pragma once

#include <string>

namespace collide {

inline std::string shell_quote(const std::string& word) {
    std::string quoted = "'";
    for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

}  // namespace collide
