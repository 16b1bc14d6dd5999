// The backend options of the command line, declared once for every command that runs a
// backend (`run`, `view`): they fill BackendOptions (core/solver.h). A backend's own keys are
// not options here: they are its [backend.NAME] table, or `--set backend.NAME.KEY=VALUE`, read
// by core/scene/option_reader.h.
#include "commands.h"

namespace collide::cli {

void add_backend_options(CLI::App& cmd, BackendOptions& options) {
    cmd.add_option("--threads", options.threads, "Threads for multi-threaded backends (0 = all)");
    cmd.add_option("--real", options.real, "Precision for backends that offer both")
        ->check(CLI::IsMember({"float", "double"}));
    cmd.add_option("--cl-device", options.device, "OpenCL device (index or name substring)");
}

}  // namespace collide::cli
