#include "resource_path.h"

#include <filesystem>

namespace collide::cli {

std::string resource_path(const std::string& relative) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path self = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
        // `cmake --install` mirrors the source tree's layout under share/collide (apps/CMakeLists.txt).
        const fs::path installed = self.parent_path().parent_path() / "share" / "collide" / relative;
        if (fs::exists(installed, error)) return installed.string();
    }
    return std::string(COLLIDE_SOURCE_DIR) + "/" + relative;
}

}  // namespace collide::cli
