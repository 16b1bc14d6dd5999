#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "core/text/printable.h"
#include "apps/resource_path.h"
#include "commands.h"
#include "core/scene/scene_loader.h"

namespace collide::cli {

// Lists every scene file below a directory (default: the scene library, apps/resource_path.h).
void add_scenes_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("scenes", "List the scene library with a one-line description");
    static std::string dir = resource_path("data/scenes");
    cmd->add_option("--dir", dir, "Scene directory")->capture_default_str();
    cmd->callback([] {
        namespace fs = std::filesystem;
        if (!fs::is_directory(dir)) throw std::runtime_error("scene directory not found: " + dir);
        std::vector<fs::path> files;
        for (const auto& entry : fs::recursive_directory_iterator(dir))
            if (entry.path().extension() == ".toml") files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        for (const auto& f : files) {
            const std::string rel = fs::relative(f, dir).string();
            try {
                std::printf("%-40s %s\n", printable(rel).c_str(),
                            printable(load_scene(f.string()).description).c_str());
            } catch (const std::exception& e) {
                std::printf("%-40s (invalid: %s)\n", printable(rel).c_str(), printable(e.what()).c_str());
            }
        }
    });
}

}  // namespace collide::cli
