// collide: the command-line program. Each subcommand lives in apps/commands/.
#include <iostream>
#include <new>
#include <stdexcept>

#include "commands/commands.h"
#include "core/io/hdf5_handle.h"
#include "core/io/provenance.h"
#include "core/text/printable.h"

int main(int argc, char** argv) {
    collide::skip_hdf5_cleanup_at_exit();
    collide::set_command_line(argc, argv);
    CLI::App app{"collide: cross-validated 2D hard-disk collision solvers"};
    app.require_subcommand(1);
    collide::cli::add_run_command(app);
    collide::cli::add_backends_command(app);
    collide::cli::add_scenes_command(app);
    collide::cli::add_bench_command(app);
    collide::cli::add_validate_command(app);
    collide::cli::add_report_command(app);
    collide::cli::add_devices_command(app);
    collide::cli::add_view_command(app);
    collide::cli::add_render_command(app);
    collide::cli::add_explain_command(app);
    collide::cli::add_export_command(app);
    collide::cli::add_compare_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::bad_alloc&) {
        // Named, since what() is only "std::bad_alloc".
        std::cerr << "collide: error: out of memory (a memory allocation failed; the scene may be too large "
                     "for the memory available, or a limit such as `ulimit -v` is set)\n";
        return 1;
    } catch (const std::exception& e) {
        // A message quotes what collide read (a key, a path, a program's output): shown through
        // the one sanitiser, so no terminal escape in it reaches the terminal.
        std::cerr << "collide: error: " << collide::printable(e.what(), collide::LineBreaks::kept) << "\n";
        return 1;
    }
    return 0;
}
