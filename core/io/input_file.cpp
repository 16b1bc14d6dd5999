// The input guard (input_file.h). stat(2)'s errno names the cause where std::filesystem says
// only "does not exist"; the open is O_NONBLOCK so that a FIFO is refused rather than waited on.
#include "core/io/input_file.h"

#include "core/io/path_causes.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <utility>
#include <vector>

namespace collide {
namespace {

namespace fs = std::filesystem;
using path_causes::kind_of;

std::string cause_of_failed_stat(const std::string& path, int error) {
    struct stat link {};
    if (error == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
        std::error_code ignored;
        return "a symbolic link to nothing ('" + fs::read_symlink(path, ignored).string() + "' does not exist)";
    }
    switch (error) {
        case ENOENT: return "does not exist";
        case ENAMETOOLONG: return path_causes::too_long();
        case ELOOP: return path_causes::link_loop("it");
        case ENOTDIR: return "a part of the path is not a directory";
        default: return std::strerror(error);
    }
}

// What a file input must be: a FIFO would block the reader, a device never end.
std::string not_regular(mode_t mode) {
    return "not a regular file (it is " + kind_of(mode) + "); collide reads only regular files";
}

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw InputFileError(path, why);
}

// The inputs of this command, by identity (device, inode): a rename or a link cannot hide one.
struct RememberedInput {
    dev_t device;
    ino_t inode;
    std::string path;
};

std::vector<RememberedInput>& remembered() {
    static std::vector<RememberedInput> inputs;
    return inputs;
}

std::mutex remembered_mutex;

}  // namespace

std::string input_path_problem(const std::string& path, bool directory) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return cause_of_failed_stat(path, errno);
    if (directory && !S_ISDIR(st.st_mode)) return "not a directory (it is " + kind_of(st.st_mode) + ")";
    if (!directory && S_ISDIR(st.st_mode)) return "a directory, not a file";
    if (!directory && !S_ISREG(st.st_mode)) return not_regular(st.st_mode);
    if (::access(path.c_str(), R_OK) != 0) return "cannot be read (" + std::string(std::strerror(errno)) + ")";
    return "";
}

int open_input_file(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        const int error = errno;
        const std::string why = input_path_problem(path, false);
        refuse(path, why.empty() ? std::strerror(error) : why);
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        const mode_t mode = st.st_mode;
        ::close(fd);
        refuse(path, S_ISDIR(mode) ? "a directory, not a file" : not_regular(mode));
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // a regular file: plain reads from here
    return fd;
}

std::string read_input_file(const std::string& path, std::size_t max_bytes) {
    const int fd = open_input_file(path);
    std::string text;
    // Room for the whole file at once: grown by doubling, a record of a few hundred kilobytes
    // was allocated, copied and unmapped three or four times (the report reads 200 MB of them).
    // The loop below still reads to the end, so a file that grew since fstat is read whole.
    struct stat st {};
    if (::fstat(fd, &st) == 0 && st.st_size > 0) text.reserve(std::min(std::size_t(st.st_size), max_bytes) + 1);
    char chunk[1 << 16];
    while (text.size() <= max_bytes) {
        const ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int error = errno;
            ::close(fd);
            refuse(path, std::string("cannot be read (") + std::strerror(error) + ")");
        }
        if (n == 0) break;
        text.append(chunk, std::size_t(n));
    }
    ::close(fd);
    if (text.size() > max_bytes + 1) text.resize(max_bytes + 1);
    return text;
}

void remember_input(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return;
    const std::lock_guard<std::mutex> lock(remembered_mutex);
    remembered().push_back({st.st_dev, st.st_ino, path});
}

std::string remembered_input_at(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return "";
    const std::lock_guard<std::mutex> lock(remembered_mutex);
    for (const RememberedInput& input : remembered())
        if (input.device == st.st_dev && input.inode == st.st_ino) return input.path;
    return "";
}

void forget_remembered_inputs() {
    const std::lock_guard<std::mutex> lock(remembered_mutex);
    remembered().clear();
}

bool same_file(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

}  // namespace collide
