// The one guard for every file collide reads (scenes, suites, run files, case records and
// logs, a solver's files): the readers' side of core/io/output_file.h. docs/refusals.md
// ("What collide never does") lists its refusals and their messages.
//
// An input must be a regular file (or a symbolic link to one). A FIFO, a device or a socket
// is refused, never opened for reading: opening a FIFO waits until something writes into it,
// so `collide validate` hung for good on a FIFO planted where a case log belongs, and every
// reading command hung on a FIFO given as its input. The check and the open are one step
// (open_input_file): the file is opened without waiting (O_NONBLOCK) and what was opened is
// checked, so a FIFO put in place after a check is refused too.
//
// The command line also remembers its inputs (remember_input), so that the output guard can
// refuse to write over one: `collide export run.h5 --out run.h5` would otherwise destroy the
// only copy of the run before reading it.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace collide {

// An input that cannot be read; the message names the path and the cause.
class InputFileError : public std::runtime_error {
public:
    InputFileError(const std::string& path, const std::string& cause)
        : std::runtime_error(path + ": " + cause), cause_(cause) {}
    const std::string& cause() const { return cause_; }  // the message without the path

private:
    std::string cause_;
};

// Why `path` cannot be read as an input file (`directory` false: a scene, a suite, a run
// file) or an input directory (`directory` true: the results of `collide validate`), from the
// system's own errno, or "" when it can. The causes: it does not exist, a symbolic link to
// nothing, a loop of links, the path is too long, a part of it is not a directory, no
// permission, it is a directory / not one, or it is no regular file (a FIFO, a device, a
// socket). (std::filesystem::exists() says "does not exist" for most of these.)
std::string input_path_problem(const std::string& path, bool directory);

// A text input read whole (summary.json, a case record, a suite): beyond this it is taken for
// a mistaken path (a disk image), not read into memory.
constexpr std::size_t max_text_input_bytes = std::size_t(1) << 30;

// A descriptor open for reading on the regular file `path` (O_CLOEXEC, blocking again after
// the check); throws InputFileError naming the path and the cause otherwise.
int open_input_file(const std::string& path);

// At most `max_bytes` + 1 bytes of the regular file `path` (one more than the limit, so a
// caller can tell a file that is too long); throws InputFileError as open_input_file does.
std::string read_input_file(const std::string& path, std::size_t max_bytes);

// Remembers `path` as an input of this command (a command-line program's run: the `collide`
// program remembers every file its command line names as an input).
void remember_input(const std::string& path);

// The remembered input that `path` names (the same file: device and inode, through links),
// or "" when it names none or does not exist.
std::string remembered_input_at(const std::string& path);

// Forgets every remembered input (a test, or a process that goes on to other work: an inode
// freed by a deleted input may be reused by a new file).
void forget_remembered_inputs();

// Whether `a` and `b` name the same existing file (device and inode, links followed).
bool same_file(const std::string& a, const std::string& b);

}  // namespace collide
