// Every file collide writes (HDF5 runs, case records, summaries, reports, screenshots, GIF,
// MP4 and PNG strips, benchmark CSV and JSON) goes through this one guard and this one
// atomic write. docs/refusals.md ("Output paths") lists each refusal and its message.
//
// The guard, check_output_path(), runs before any work starts. It accepts a path that does
// not exist yet (in an existing, writable directory), an existing regular file, and a
// symbolic link to an existing regular file. It refuses everything else and says why: the
// directory is missing or is not a directory, the name is a directory, a character or
// block device, a FIFO or a socket, a symbolic link to nothing or a loop of links, the name
// is too long, or the directory cannot be written. Devices and FIFOs matter most: the file is
// renamed into place at the end, and a rename over /dev/null would replace the system's
// /dev/null with a regular file.
//
// The atomic write, AtomicOutputFile: the bytes go to a temporary ".NAME.tmp-PID-K" in the
// target's own directory (the same file system, so the final rename is atomic); commit()
// syncs it to disk and renames it over the target, so a reader sees the old file or the new
// one, never half of one. A symbolic link is followed: the regular file it points to is
// replaced and the link stays a link. Without commit() the temporary is removed. The file is
// created with mode 0666 less the umask, like any file a program creates.
#pragma once

#include <sys/types.h>

#include <stdexcept>
#include <string>

namespace collide {

// Every refusal and every failed write; the message names the path and the cause.
class OutputFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws OutputFileError when `path` is no place collide may write a file (see above).
void check_output_path(const std::string& path);

// For an output directory (`validate --out DIR`, the report's folder): it may be missing (it
// is created, parents too), but what exists under that name must be a directory or a
// symbolic link to one. Throws OutputFileError naming the cause otherwise.
void check_output_directory(const std::string& path);

// The readers' side of the same guard: why `path` cannot be read as an input file
// (`directory` false: a scene, a suite, a run file) or an input directory (`directory` true:
// the results of `collide validate`), from the system's own errno, or "" when it can. The
// causes: it does not exist, a symbolic link to nothing, a loop of links, the path is too
// long, a part of it is not a directory, no permission, or it is a directory / not one.
// (std::filesystem::exists() says "does not exist" for all of these.)
std::string input_path_problem(const std::string& path, bool directory);

// What a file of this stat() mode is, in the refusals' words: "a FIFO", "a directory",
// "a character device", "a regular file", ...
std::string file_kind(mode_t mode);

class AtomicOutputFile {
public:
    // Checks `path` (check_output_path) and creates the empty temporary file.
    explicit AtomicOutputFile(const std::string& path);
    ~AtomicOutputFile();  // removes the temporary file unless commit() renamed it
    AtomicOutputFile(const AtomicOutputFile&) = delete;
    AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

    // Appends `bytes` to the temporary file (for writers that hold their output in memory).
    void write(const std::string& bytes);
    // Syncs the temporary file to disk and renames it over the target.
    void commit();

    const std::string& path() const { return path_; }             // as the user gave it
    const std::string& target() const { return target_; }         // after following a link
    const std::string& temporary_path() const { return temporary_; }

private:
    std::string path_, target_, temporary_;
    bool committed_ = false;
};

// check_output_path, then the whole of `bytes` written atomically.
void write_file_atomically(const std::string& path, const std::string& bytes);

}  // namespace collide
