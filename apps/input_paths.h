// Command-line checks of the files and directories a command reads, naming the system's own
// cause (core/io/input_file.h, input_path_problem): CLI11's ExistingFile says "File does not
// exist" for a loop of symbolic links, a path too long or a directory without permission, and
// lets a FIFO through (the command then waits on it for good). Each input is remembered, so
// that the output guard refuses to write over it (`collide export run.h5 --out run.h5`).
// A refused input is collide's error, not a usage error: the validator throws (CLI11 passes
// anything but its own ValidationError through), so main() prints "collide: error: PATH: why"
// and exits 1 as docs/refusals.md says, for every command, instead of CLI11's exit 105.
#pragma once

#include <stdexcept>

#include <CLI/CLI.hpp>

#include "core/io/input_file.h"

namespace collide {

inline CLI::Validator readable_input(bool directory) {
    return CLI::Validator(
        [directory](std::string& path) {
            const std::string why = input_path_problem(path, directory);
            if (!why.empty()) throw std::runtime_error(path + ": " + why);
            remember_input(path);
            return std::string();
        },
        directory ? "DIR" : "FILE", directory ? "readable directory" : "readable file");
}

inline CLI::Validator readable_file() { return readable_input(false); }
inline CLI::Validator readable_directory() { return readable_input(true); }

}  // namespace collide
