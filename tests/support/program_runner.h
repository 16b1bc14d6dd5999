// Runs a built program as a user would, from a test: the command line goes through the
// shell with every word quoted, and stdout and stderr are captured in files of a scratch
// directory (removed again, so they do not count as files the program left behind).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "core/io/shell_quote.h"
#include "tests/support/scratch_directory.h"

namespace collide::test {

struct ProgramResult {
    int exit_code = -1;  // -1 when the program did not exit normally (a crash, a signal)
    std::string out, err;
};

inline ProgramResult run_program(const std::string& program, const std::vector<std::string>& args,
                                 const ScratchDirectory& dir) {
    const std::string out_file = dir.file(".stdout"), err_file = dir.file(".stderr");
    std::string command = shell_quote(program);
    for (const auto& arg : args) command.append(" ").append(shell_quote(arg));
    command.append(" >").append(shell_quote(out_file)).append(" 2>").append(shell_quote(err_file));
    const int status = std::system(command.c_str());
    ProgramResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_text_file(out_file);
    result.err = read_text_file(err_file);
    std::filesystem::remove(out_file);
    std::filesystem::remove(err_file);
    return result;
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace collide::test
