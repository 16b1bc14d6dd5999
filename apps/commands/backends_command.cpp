#include <cstdio>

#include "commands.h"
#include "core/backend_registry.h"

namespace collide::cli {

void add_backends_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("backends", "List the backends compiled into this build");
    cmd->callback([] {
        std::printf("%-11s %-13s %s\n", "name", "precision", "description");
        for (const auto& b : all_backends())
            std::printf("%-11s %-13s %s\n", b.name.c_str(), b.precision.c_str(), b.description.c_str());
    });
}

}  // namespace collide::cli
