#include <cstdio>
#include <cstdlib>
#include <string>

#include "commands.h"
#include "core/backend_registry.h"
#include "core/io/shell_quote.h"
#include "apps/resource_path.h"

namespace collide::cli {
namespace {

// The engines of engines/ (Node adapters run through the outside-solver protocol, docs/engines.md):
// engines/list.js prints one line each, with the installed package's version or the command
// that installs it. Without Node, one line says how to get it.
void list_outside_engines() {
    const std::string list = resource_path("engines/list.js");
    std::printf("\noutside engines (%s; validation/suites/engines.toml runs them):\n", resource_path("engines").c_str());
    std::fflush(stdout);
    const std::string command = "node " + shell_quote(list) + " 2>&1";
    if (std::system(("command -v node >/dev/null 2>&1 && " + command).c_str()) != 0)
        std::printf("(node not found: install Debian's nodejs and npm, then run `npm ci` in engines/; "
                    "scripts/install-deps.sh does both)\n");
}

}  // namespace

void add_backends_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("backends", "List the backends compiled into this build, and the outside engines of engines/");
    cmd->callback([] {
        std::printf("%-11s %-13s %s\n", "name", "precision", "description");
        for (const auto& b : all_backends())
            std::printf("%-11s %-13s %s\n", b.name.c_str(), b.precision.c_str(), b.description.c_str());
        list_outside_engines();
    });
}

}  // namespace collide::cli
