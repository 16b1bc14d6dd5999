// `collide export RUN.h5 --out FILE [--format xdmf|gsd|xyz]`: a run's frames for ParaView,
// VisIt, OVITO, ASE or HOOMD (core/io/run_export.h, docs/exporting.md). XDMF and XYZ are written
// here; GSD by python/collide/gsd_export.py (the `gsd` package), run as `collide report` runs
// its renderer.

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "apps/python_script.h"
#include "apps/resource_path.h"
#include "apps/input_paths.h"
#include "commands.h"
#include "core/io/output_file.h"
#include "core/io/run_export.h"
#include "validation/record/case_result.h"

namespace collide::cli {
namespace {

struct ExportArgs {
    std::string run, out, format;
};

// The script names its own errors (apps/python_script.h runs it).
void write_gsd(const std::string& run, const std::string& out) {
    const std::string script = resource_path("python/collide") + "/gsd_export.py";
    if (run_python_script(script, {run, out}) != 0)
        throw std::runtime_error("no GSD file written (" + std::string(python_interpreter()) + " " + script +
                                 ", reason above)");
}

void execute(const ExportArgs& args) {
    const ExportFormat format = export_format(args.format, args.out);
    // A device, a FIFO, a link to nothing, the run file itself: refused before any work.
    check_output_path(args.out);
    if (format == ExportFormat::xdmf) check_output_path(xdmf_frames_path(args.out));
    require_frames(args.run);     // every frame read and checked (core/io/run_reader.h) before writing
    if (format == ExportFormat::gsd) write_gsd(args.run, args.out);
    else if (format == ExportFormat::xdmf) write_xdmf(args.run, args.out);
    else write_file_atomically(args.out, xyz_text(args.run));
    std::printf("output    %s (%s)\n", args.out.c_str(), to_string(format));
    if (format == ExportFormat::xdmf) std::printf("data      %s (keep it beside the XDMF file)\n", xdmf_frames_path(args.out).c_str());
}

}  // namespace

void add_export_command(CLI::App& app) {
    auto args = std::make_shared<ExportArgs>();
    auto* cmd = app.add_subcommand(
        "export", "Write a run's frames for ParaView/VisIt (XDMF), OVITO/freud/HOOMD (GSD) or ASE/OVITO (extended XYZ)");
    cmd->add_option("run", args->run, "Run file (HDF5, written with `collide run ... --frames`)")
        ->required()->check(readable_file());
    cmd->add_option("-o,--out", args->out, "Output file: .xdmf (its data written beside it as NAME.frames.h5), .gsd or .xyz")
        ->required();
    cmd->add_option("-f,--format", args->format, "xdmf, gsd or xyz (default: from the extension of --out)")
        ->check(CLI::IsMember({"xdmf", "gsd", "xyz"}));
    cmd->callback([args] { execute(*args); });
}

}  // namespace collide::cli
