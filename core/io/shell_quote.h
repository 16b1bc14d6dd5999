// A word quoted for /bin/sh: '...' with every ' written '\'' (the one form that needs no other
// escapes). For the commands collide builds: ffmpeg pipes, outside solvers, tests' programs.
// And the way back, shell_words: a command's words as the shell splits them, for the files an
// outside solver's command names (their hashes go into the provenance).
#pragma once

#include <string>
#include <vector>

namespace collide {

inline std::string shell_quote(const std::string& word) {
    std::string quoted = "'";
    for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

// The words of `command` as /bin/sh splits them (POSIX 2.2 quoting): blanks separate words;
// '...' keeps everything; "..." keeps everything but a backslash before $ ` " \ or a newline;
// a backslash outside quotes keeps the next character. So `python3 'my solver.py'` and
// `./my\ solver` each name one file with a space. Expansions ($VAR, globs) are not made.
inline std::vector<std::string> shell_words(const std::string& command) {
    std::vector<std::string> words;
    std::string word;
    bool in_word = false;
    for (std::size_t i = 0; i < command.size(); ++i) {
        const char c = command[i];
        if (c == ' ' || c == '\t' || c == '\n') {
            if (in_word) words.push_back(word), word.clear(), in_word = false;
            continue;
        }
        in_word = true;
        if (c == '\\' && i + 1 < command.size()) {
            word += command[++i];
        } else if (c == '\'') {
            const std::size_t end = command.find('\'', i + 1);
            word += command.substr(i + 1, end == std::string::npos ? std::string::npos : end - i - 1);
            i = end == std::string::npos ? command.size() : end;
        } else if (c == '"') {
            for (++i; i < command.size() && command[i] != '"'; ++i) {
                if (command[i] == '\\' && i + 1 < command.size() && std::string("$`\"\\\n").find(command[i + 1]) != std::string::npos) ++i;
                word += command[i];
            }
        } else {
            word += c;
        }
    }
    if (in_word) words.push_back(word);
    return words;
}

}  // namespace collide
