#include "external/solver_files.h"

#include <sys/stat.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

#include "core/io/shell_quote.h"
#include "external/sha256.h"

namespace collide::external {
namespace fs = std::filesystem;
namespace {

// The words of the command that may name files; for a Python class, its module's file (the
// command is then the interpreter and collide's runner: the class's own file is what counts).
std::vector<std::string> candidate_words(const ExternalSolverSpec& spec) {
    // The words as the shell splits them: a quoted path with a space or a quote is one file.
    if (spec.python_class.empty()) {
        std::vector<std::string> words = shell_words(spec.command);
        words.insert(words.end(), spec.files.begin(), spec.files.end());  // declared: lock file, library
        return words;
    }
    std::string file = spec.python_class.substr(0, spec.python_class.rfind(':'));
    if (file.size() < 3 || file.compare(file.size() - 3, 3, ".py") != 0) {
        std::replace(file.begin(), file.end(), '.', '/');
        file += ".py";
    }
    std::vector<std::string> words = {file};
    words.insert(words.end(), spec.files.begin(), spec.files.end());
    return words;
}

std::string utc_text(std::time_t t) {
    char buf[32] = {};
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
    return buf;
}

// The digest text of one regular file, made once per process for each version of the file.
std::string file_digest(const std::string& path, const struct stat& st, std::FILE* progress) {
    static std::mutex mutex;
    static std::map<std::string, std::string> made;  // key: device, inode, size, mtime
    const std::lock_guard<std::mutex> lock(mutex);
    const std::string key = std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" +
                            std::to_string(st.st_size) + ":" + std::to_string(st.st_mtim.tv_sec) + "." +
                            std::to_string(st.st_mtim.tv_nsec);
    if (const auto found = made.find(key); found != made.end()) return found->second;
    const auto size = std::uintmax_t(st.st_size);
    if (progress && size > hashed_prefix_bytes) {
        const std::string part = size > whole_hash_limit_bytes
                                     ? ": its first " + std::to_string(hashed_prefix_bytes >> 20) + " MiB, with its size and time"
                                     : "";
        std::fprintf(progress, "hashing %s (%ju MiB) for the solver's provenance%s\n", path.c_str(), size >> 20, part.c_str());
    }
    std::string text;
    if (size <= whole_hash_limit_bytes)
        text = sha256_file(path);
    else
        text = "sha256 of the first " + std::to_string(hashed_prefix_bytes >> 20) + " MiB " +
               sha256_file(path, hashed_prefix_bytes) + ", size " + std::to_string(size) + " bytes, modified " +
               utc_text(st.st_mtim.tv_sec);
    made.emplace(key, text);
    return text;
}

}  // namespace

std::string solver_files_digest(const ExternalSolverSpec& spec, std::FILE* progress) {
    std::string out;
    for (const std::string& w : candidate_words(spec)) {  // unquoted already (shell_words)
        if (w.empty()) continue;
        fs::path p(w);
        if (p.is_relative() && !spec.directory.empty()) p = fs::path(spec.directory) / p;
        struct stat st {};
        if (::stat(p.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
        try {
            out += (out.empty() ? "" : "; ") + w + " " + file_digest(p.string(), st, progress);
        } catch (const std::exception&) {
            // An unreadable file is left out of the provenance, as one the command does not name.
        }
    }
    return out;
}

}  // namespace collide::external
