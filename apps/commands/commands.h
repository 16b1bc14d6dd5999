// The subcommands of the `collide` program, one file each.
#pragma once

#include <CLI/CLI.hpp>

#include "core/backend_registry.h"
#include "core/scene/scene_overrides.h"
#include "validation/plan/external_solvers.h"

namespace collide::cli {

void add_run_command(CLI::App& app);       // run one scene on one backend -> HDF5
void add_backends_command(CLI::App& app);  // list the backends
void add_scenes_command(CLI::App& app);    // list the scene library
void add_bench_command(CLI::App& app);     // benchmark suites
void add_validate_command(CLI::App& app);  // validation suites -> summary.json, junit.xml
void add_report_command(CLI::App& app);    // validation results -> HTML and Markdown report
void add_devices_command(CLI::App& app);   // list OpenCL platforms and devices
void add_view_command(CLI::App& app);      // watch a scene run (SDL2 window or headless)
void add_render_command(CLI::App& app);    // run file with frames -> GIF, MP4 or PNG strip
void add_explain_command(CLI::App& app);   // the step of a validated case that changed the energy most
void add_export_command(CLI::App& app);    // run file with frames -> XDMF, GSD or extended XYZ
void add_compare_command(CLI::App& app);   // two validation results side by side; exit 1 on a regression

// Throws "backend 'NAME' cannot run scene 'SCENE': REASON" when the backend does not support
// the scene; every command that runs a scene says it in these words (run_command.cpp).
void require_support(const BackendInfo& backend, const Scene& scene);

// --threads, --real and --cl-device, the options of a command that runs a backend
// (backend_cli_options.cpp).
void add_backend_options(CLI::App& cmd, BackendOptions& options);

// `--set PATH=VALUE` (repeatable) on a command that reads a scene (core/scene/scene_overrides.h);
// each word is checked as PATH=VALUE when parsed, the paths and values when applied.
void add_set_option(CLI::App& cmd, std::vector<SceneOverride>& overrides);
// The scene file with the overrides applied (load_scene alone without any).
Scene load_scene_with_overrides(const std::string& path, const std::vector<SceneOverride>& overrides);

// Outside solvers named on the command line (solver_option.cpp, docs/your-solver.md).
struct SolverArgs {
    std::vector<std::string> programs;  // --solver NAME=COMMAND
    std::vector<std::string> classes;   // --python-solver NAME=MODULE:CLASS
    std::vector<std::string> rules;     // --solver-rule NAME=RULE
    std::vector<std::string> exact;     // --solver-exact NAME
    std::vector<std::string> long_lived;  // --solver-long-lived NAME
    std::vector<std::string> precisions;  // --solver-precision NAME=PRECISION
};
void add_solver_options(CLI::App& cmd, SolverArgs& args);
// The specs the options name; throws std::invalid_argument for a malformed one.
std::vector<external::ExternalSolverSpec> solver_specs(const SolverArgs& args);
// The interpreter and runner script that run a Python class (this build's Python).
validation::PythonRunner python_runner();

}  // namespace collide::cli
