// The output-path guard and the atomic write (output_file.h). The checks use lstat/stat and
// their errno rather than std::filesystem's exists(), which says only "no" where the system
// says why: ENOENT (missing), ENAMETOOLONG (too long), ELOOP (a loop of symbolic links),
// ENOTDIR (a file where a directory should be), EACCES (no permission).
#include "core/io/output_file.h"

#include "core/io/fd_io.h"
#include "core/io/input_file.h"
#include "core/io/path_causes.h"

#include <fcntl.h>
#include <signal.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

namespace collide {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw OutputFileError("cannot write '" + path + "': " + why);
}

using path_causes::kind_of;
using path_causes::link_loop;
using path_causes::too_long;

// Why `directory` (the folder a file goes into, or an output directory itself) cannot be
// reached, from the errno of a failed stat(); "" where the caller decides (ENOENT).
std::string unreachable_directory(const std::string& directory, int error) {
    switch (error) {
        case ENAMETOOLONG: return too_long();
        case ELOOP: return link_loop("directory '" + directory + "'");
        case ENOTDIR: return "a part of '" + directory + "' is not a directory";
        case EACCES: return "directory '" + directory + "' cannot be searched (" + std::strerror(error) + ")";
        default: return "directory '" + directory + "': " + std::strerror(error);
    }
}

std::string directory_of(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? "." : parent.string();
}

// The directory that will hold the file must exist, be a directory and take new files
// (the temporary file is created there).
void check_directory_of(const std::string& path, const std::string& directory) {
    struct stat st {};
    if (::stat(directory.c_str(), &st) != 0) {
        if (errno == ENOENT) refuse(path, "directory '" + directory + "' does not exist");
        refuse(path, unreachable_directory(directory, errno));
    }
    if (!S_ISDIR(st.st_mode)) refuse(path, "'" + directory + "' is not a directory (it is " + kind_of(st.st_mode) + ")");
    if (::access(directory.c_str(), W_OK | X_OK) != 0)
        refuse(path, "cannot create a file in directory '" + directory + "' (" + std::strerror(errno) + ")");
}

// Writing over an input would destroy it before (or while) it is read.
[[noreturn]] void refuse_input(const std::string& path, const std::string& input) {
    refuse(path, "it is the input '" + input +
                     "' (the same file); writing it would destroy the input: choose another output");
}

// What a symbolic link at `path` leads to; refuses a link to nothing and a loop of links.
struct stat follow_link(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) return st;
    const int error = errno;
    if (error == ELOOP) refuse(path, link_loop("it"));
    if (error == ENAMETOOLONG) refuse(path, too_long());
    std::error_code ignored;
    const std::string pointee = fs::read_symlink(path, ignored).string();
    if (error == ENOENT) refuse(path, "it is a symbolic link to nothing ('" + pointee + "' does not exist)");
    refuse(path, "it is a symbolic link to '" + pointee + "', which cannot be reached (" + std::strerror(error) + ")");
}

// The existing file at `path`, if any, must be a regular file (or a link to one): the new
// file is renamed over it, which would turn a device, a FIFO or a socket into a plain file.
void check_existing(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) {
        if (errno == ENOENT) return;  // a new file
        if (errno == ENAMETOOLONG) refuse(path, too_long());
        refuse(path, std::strerror(errno));
    }
    if (S_ISLNK(st.st_mode)) st = follow_link(path);
    if (S_ISDIR(st.st_mode)) refuse(path, "a directory of that name exists");
    if (!S_ISREG(st.st_mode))
        refuse(path, "it exists and is not a regular file (" + kind_of(st.st_mode) +
                         "); collide writes only to a new or a regular file");
    if (const std::string input = remembered_input_at(path); !input.empty()) refuse_input(path, input);
}

// A symbolic link is followed, so that the rename replaces the file it points to and the
// link stays a link (a rename onto the link itself would replace the link).
std::string followed(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
    return fs::canonical(path).string();
}

std::string temporary_path_for(const std::string& target) {
    static std::atomic<unsigned> counter{0};
    std::string name = ".";  // built with append: GCC 12 warns falsely on "." + std::string
    name.append(fs::path(target).filename().string()).append(".tmp-").append(std::to_string(::getpid()));
    name.append("-").append(std::to_string(counter++));
    return (fs::path(directory_of(target)) / name).string();
}

}  // namespace

void check_output_path(const std::string& path) {
    if (path.empty()) throw OutputFileError("cannot write the output: the file name is empty");
    if (!fs::path(path).has_filename()) refuse(path, "the path names a directory, not a file");
    check_directory_of(path, directory_of(path));
    check_existing(path);
    const std::string target = followed(path);
    if (target != path) check_directory_of(path, directory_of(target));
}

void check_output_is_not_input(const std::string& output, const std::string& input) {
    if (same_file(output, input)) refuse_input(output, input);
}

void check_output_stream_path(const std::string& path) {
    check_output_path(path);
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
        refuse(path, "it is a symbolic link; collide writes its own logs and locks only as regular files, "
                     "never through a link");
}

int open_output_stream(const std::string& path, StreamStart start) {
    check_output_stream_path(path);
    struct stat st {};
    // O_NOFOLLOW and O_NONBLOCK: what was put at the path after the check (a link, a FIFO
    // without a reader) is refused below, not followed or waited on.
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC, 0666);
    if (fd < 0) {
        const int error = errno;
        refuse(path, error == ELOOP ? std::string("it is a symbolic link; collide never writes through one")
                                    : std::string(std::strerror(error)));
    }
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        refuse(path, "it exists and is not a regular file (" + kind_of(st.st_mode) +
                         "); collide writes only to a new or a regular file");
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    if (start == StreamStart::empty && ::ftruncate(fd, 0) != 0) {
        const int error = errno;
        ::close(fd);
        refuse(path, std::strerror(error));
    }
    return fd;
}

void check_output_directory(const std::string& path) {
    if (path.empty()) throw OutputFileError("cannot write into the output directory: its name is empty");
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        struct stat link {};
        const int error = errno;
        if (error == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
            refuse(path, "it is a symbolic link to nothing ('" + fs::read_symlink(path).string() + "' does not exist)");
        if (error == ENOENT) return;  // created with its parents
        refuse(path, unreachable_directory(path, error));
    }
    if (!S_ISDIR(st.st_mode))
        refuse(path, "it exists and is not a directory (it is " + kind_of(st.st_mode) + "); expected an output directory");
    if (::access(path.c_str(), W_OK | X_OK) != 0)
        refuse(path, "cannot create files in directory '" + path + "' (" + std::strerror(errno) + ")");
}

namespace {

// The writer's process id in a temporary's name ".NAME.tmp-PID-K"; 0 when it is none.
pid_t writer_of_temporary(const std::string& name) {
    const std::size_t mark = name.rfind(".tmp-");
    if (name.empty() || name[0] != '.' || mark == std::string::npos) return 0;
    const std::size_t dash = name.find('-', mark + 5);
    if (dash == std::string::npos || dash == mark + 5 || dash + 1 == name.size()) return 0;
    const std::string digits = name.substr(mark + 5, dash - mark - 5);
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return 0;
    return pid_t(std::stol(digits));
}

}  // namespace

std::vector<std::string> remove_stale_temporaries(const std::string& dir) {
    std::vector<std::string> removed;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(dir, error)) {
        const std::string name = entry.path().filename().string();
        const pid_t writer = writer_of_temporary(name);
        // A writer that still runs may still rename its temporary into place.
        if (writer == 0 || writer == ::getpid() || ::kill(writer, 0) == 0 || errno != ESRCH) continue;
        if (!entry.is_regular_file(error) || entry.is_symlink(error)) continue;
        if (fs::remove(entry.path(), error)) removed.push_back(name);
    }
    return removed;
}

AtomicOutputFile::AtomicOutputFile(const std::string& path) : path_(path) {
    check_output_path(path);
    target_ = followed(path);
    temporary_ = temporary_path_for(target_);
    // Created here, O_EXCL, with 0666 less the umask: the system's own reason ("Permission
    // denied", "Read-only file system") shows before any work, and no other file is reused.
    const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) refuse(path, "cannot create '" + temporary_ + "' (" + std::strerror(errno) + ")");
    ::close(fd);
}

AtomicOutputFile::~AtomicOutputFile() {
    if (!committed_) ::unlink(temporary_.c_str());
}

void AtomicOutputFile::write(const std::string& bytes) {
    const int fd = ::open(temporary_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd < 0) refuse(path_, "cannot open '" + temporary_ + "' (" + std::strerror(errno) + ")");
    const bool written = write_fully(fd, bytes.data(), bytes.size());  // (core/io/fd_io.h)
    const int error = errno;
    // A full disk may show only at close (NFS, quotas): both results count.
    const bool closed = ::close(fd) == 0;
    if (!written || !closed) refuse(path_, std::strerror(written ? errno : error));
}

void AtomicOutputFile::commit() {
    // Forced to the disk first, so that after the rename the target is complete even if the
    // machine loses power.
    const int fd = ::open(temporary_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || ::fsync(fd) != 0) {
        const std::string reason = std::strerror(errno);
        if (fd >= 0) ::close(fd);
        refuse(path_, "cannot sync '" + temporary_ + "' to disk (" + reason + ")");
    }
    ::close(fd);
    // Checked again: during a long run something else may have been put at the path.
    check_existing(path_);
    // rename() replaces an existing target atomically (POSIX): a reader sees the old file or
    // the new one, never a mixture.
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0)
        refuse(path_, "cannot rename '" + temporary_ + "' into place (" + std::strerror(errno) + ")");
    committed_ = true;
}

void write_file_atomically(const std::string& path, const std::string& bytes) {
    AtomicOutputFile file(path);
    file.write(bytes);
    file.commit();
}

}  // namespace collide
