// The output-path guard and the atomic write (output_file.h). The checks use lstat/stat and
// their errno rather than std::filesystem's exists(), which says only "no" where the system
// says why: ENOENT (missing), ENAMETOOLONG (too long), ELOOP (a loop of symbolic links),
// ENOTDIR (a file where a directory should be), EACCES (no permission).
#include "core/io/output_file.h"

#include "core/io/fd_io.h"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace collide {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw OutputFileError("cannot write '" + path + "': " + why);
}

std::string kind_of(mode_t mode) {
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISREG(mode)) return "a regular file";
    return "not a regular file";
}

std::string too_long() {
    return "the path is too long (" + std::string(std::strerror(ENAMETOOLONG)) + ": at most " +
           std::to_string(NAME_MAX) + " bytes a name and " + std::to_string(PATH_MAX - 1) + " bytes a path)";
}

std::string link_loop(const std::string& what) {
    return what + " is a loop of symbolic links (" + std::strerror(ELOOP) + "): it never reaches a file";
}

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

std::string input_path_problem(const std::string& path, bool directory) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        const int error = errno;
        struct stat link {};
        if (error == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
            std::error_code ignored;
            return "a symbolic link to nothing ('" + fs::read_symlink(path, ignored).string() + "' does not exist)";
        }
        switch (error) {
            case ENOENT: return "does not exist";
            case ENAMETOOLONG: return too_long();
            case ELOOP: return link_loop("it");
            case ENOTDIR: return "a part of the path is not a directory";
            default: return std::strerror(error);
        }
    }
    if (directory && !S_ISDIR(st.st_mode)) return "not a directory (it is " + kind_of(st.st_mode) + ")";
    if (!directory && S_ISDIR(st.st_mode)) return "a directory, not a file";
    if (::access(path.c_str(), R_OK) != 0) return "cannot be read (" + std::string(std::strerror(errno)) + ")";
    return "";
}

std::string file_kind(mode_t mode) { return kind_of(mode); }

void check_output_path(const std::string& path) {
    if (path.empty()) throw OutputFileError("cannot write the output: the file name is empty");
    if (!fs::path(path).has_filename()) refuse(path, "the path names a directory, not a file");
    check_directory_of(path, directory_of(path));
    check_existing(path);
    const std::string target = followed(path);
    if (target != path) check_directory_of(path, directory_of(target));
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
