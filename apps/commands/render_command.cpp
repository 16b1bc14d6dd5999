// `collide render RUN.h5 --out FILE [--compare REF.h5] [--frames K]`: a run's frames as an
// animated GIF, an MP4 (with ffmpeg) or a PNG strip, drawn as `collide view` draws them.
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "core/io/progress_line.h"
#include "apps/input_paths.h"
#include "commands.h"
#include "view/render_run.h"

namespace collide::cli {

void add_render_command(CLI::App& app) {
    struct Args {
        view::RenderOptions render;
        std::string size = "640x360";
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("render", "Draw a run written with --frames into a GIF, MP4 or PNG strip");
    cmd->add_option("run", args->render.run, "Run file (HDF5, written with `collide run ... --frames`)")
        ->required()->check(readable_file());
    cmd->add_option("-o,--out", args->render.out, "Output: .gif (animated), .mp4 (needs ffmpeg) or .png (strip)")
        ->required();
    cmd->add_option("--compare", args->render.compare, "Reference run of the same scene, drawn as outlines")
        ->check(readable_file());
    cmd->add_option("--frames", args->render.frames, "Frames to draw, evenly spaced (default: all; 6 for .png)");
    cmd->add_option("--size", args->size, "Pixels of one frame, WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--fps", args->render.fps, "Frames per second of an animation")->capture_default_str()
        ->check(CLI::Range(1.0, 100.0));
    cmd->callback([args] {
        int w = 0, h = 0;
        char x = 0, extra = 0;
        if (std::sscanf(args->size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 16 || h < 16 ||
            w > 16384 || h > 16384)
            throw std::runtime_error("--size " + args->size + ": expected WIDTHxHEIGHT, each 16..16384 pixels");
        if (args->render.frames < 0) throw std::runtime_error("--frames must be positive");
        args->render.width = w;
        args->render.height = h;
        // A long animation: the time left on a terminal, a line every 10 s in a log.
        ProgressLine progress;
        args->render.on_frame = [&progress](double t, double last) { progress.update_time(t, last); };
        view::render_run(args->render);
    });
}

}  // namespace collide::cli
