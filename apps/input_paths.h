// Command-line checks of the files and directories a command reads, naming the system's own
// cause (core/io/output_file.h, input_path_problem): CLI11's ExistingFile says "File does not
// exist" for a loop of symbolic links, a path too long or a directory without permission.
#pragma once

#include <CLI/CLI.hpp>

#include "core/io/output_file.h"

namespace collide {

inline CLI::Validator readable_input(bool directory) {
    return CLI::Validator(
        [directory](std::string& path) {
            const std::string why = input_path_problem(path, directory);
            return why.empty() ? std::string() : path + ": " + why;
        },
        directory ? "DIR" : "FILE", directory ? "readable directory" : "readable file");
}

inline CLI::Validator readable_file() { return readable_input(false); }
inline CLI::Validator readable_directory() { return readable_input(true); }

}  // namespace collide
