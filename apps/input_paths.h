// Command-line checks of the files and directories a command reads, naming the system's own
// cause (core/io/output_file.h, input_path_problem): CLI11's ExistingFile says "File does not
// exist" for a loop of symbolic links, a path too long or a directory without permission.
// A refused input is collide's error, not a usage error: the validator throws (CLI11 passes
// anything but its own ValidationError through), so main() prints "collide: error: PATH: why"
// and exits 1 as docs/refusals.md says, for every command, instead of CLI11's exit 105.
#pragma once

#include <stdexcept>

#include <CLI/CLI.hpp>

#include "core/io/output_file.h"

namespace collide {

inline CLI::Validator readable_input(bool directory) {
    return CLI::Validator(
        [directory](std::string& path) {
            const std::string why = input_path_problem(path, directory);
            if (!why.empty()) throw std::runtime_error(path + ": " + why);
            return std::string();
        },
        directory ? "DIR" : "FILE", directory ? "readable directory" : "readable file");
}

inline CLI::Validator readable_file() { return readable_input(false); }
inline CLI::Validator readable_directory() { return readable_input(true); }

}  // namespace collide
