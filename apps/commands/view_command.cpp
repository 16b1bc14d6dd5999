// `collide view SCENE --backend NAME [--compare event] [--headless --frames N --screenshot F]`:
// watch a scene run, one output step per frame (docs/viewer.md).
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "apps/input_paths.h"
#include "commands.h"
#include "core/io/output_file.h"
#include "core/scene/scene_loader.h"
#include "view/live_viewer.h"

namespace collide::cli {
namespace {

struct ViewArgs {
    std::string scene_path;
    std::string backend = "step";
    std::string compare;
    std::string size = "1280x720";
    BackendOptions options;
    view::ViewOptions view;
    std::vector<SceneOverride> overrides;
};

// "WIDTHxHEIGHT" -> pixels; shared by view and render.
void parse_size(const std::string& text, int& width, int& height) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 16 || h < 16 || w > 16384 ||
        h > 16384)
        throw std::runtime_error("--size " + text + ": expected WIDTHxHEIGHT, each 16..16384 pixels");
    width = w;
    height = h;
}

// The same checks, in the same order and words, as `collide run`: backend name, scene,
// support; then the comparison backend the same way.
void execute(ViewArgs& args) {
    parse_size(args.size, args.view.width, args.view.height);
    // The screenshot's path is checked before anything runs (core/io/output_file.h): a device, a
    // FIFO or a link to nothing fails now, with nothing written, not after the last frame.
    if (!args.view.screenshot.empty()) check_output_path(args.view.screenshot);
    const BackendInfo& backend = find_backend(args.backend);
    const BackendInfo* compare = args.compare.empty() ? nullptr : &find_backend(args.compare);
    const Scene scene = load_scene_with_overrides(args.scene_path, args.overrides);
    require_support(backend, scene);
    if (compare) require_support(*compare, scene);
    const ParticleState<double> initial = generate_initial_state(scene);
    view::ViewSession session(scene, initial, backend, compare, args.options);
    view::run_viewer(session, args.view);
}

}  // namespace

void add_view_command(CLI::App& app) {
    auto args = std::make_shared<ViewArgs>();
    auto* cmd = app.add_subcommand("view", "Watch a scene run (SDL2 window; --headless renders off-screen)");
    cmd->add_option("scene", args->scene_path, "Scene file (TOML)")->required()->check(readable_file());
    cmd->add_option("-b,--backend", args->backend, "Backend name (see `collide backends`)")->capture_default_str();
    cmd->add_option("--compare", args->compare, "Second backend drawn as outlines (e.g. event, the exact solution)");
    cmd->add_flag("--headless", args->view.headless, "No window: draw off-screen (needs --frames)");
    cmd->add_option("--frames", args->view.frames, "Stop after N frames (frame 0 is the initial state)");
    cmd->add_option("--screenshot", args->view.screenshot, "Write the last frame as PNG");
    cmd->add_option("--size", args->size, "Window or image size WIDTHxHEIGHT")->capture_default_str();
    add_backend_options(*cmd, args->options);
    add_set_option(*cmd, args->overrides);
    cmd->callback([args] { execute(*args); });
}

}  // namespace collide::cli
