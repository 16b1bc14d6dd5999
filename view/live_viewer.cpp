#include "live_viewer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "image_writers.h"

namespace collide::view {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// Playback speed as a power of two: exponent e >= 0 advances 2^e output steps per frame,
// e < 0 advances one output step every 2^-e frames (slow motion).
struct Playback {
    int exponent = 0;
    bool paused = false;
    bool step_once = false;
    long frame = 0;

    int output_steps() {
        ++frame;
        if (paused) return std::exchange(step_once, false) ? 1 : 0;
        if (exponent >= 0) return 1 << exponent;
        return frame % (1L << -exponent) == 0 ? 1 : 0;
    }
    std::string label() const {
        char text[32];
        if (exponent >= 0) std::snprintf(text, sizeof text, "X%d", 1 << exponent);
        else std::snprintf(text, sizeof text, "X1/%d", 1 << -exponent);
        return paused ? std::string("PAUSED") : std::string(text);
    }
};

struct LoopState {
    Playback playback;
    bool quit = false;
    bool restart = false;
    bool screenshot = false;
};

void handle_key(SDL_Keycode key, LoopState& s) {
    switch (key) {
        case SDLK_SPACE: s.playback.paused = !s.playback.paused; break;
        case SDLK_RIGHT: s.playback.paused = true, s.playback.step_once = true; break;
        case SDLK_PLUS: case SDLK_EQUALS: case SDLK_KP_PLUS:
            s.playback.exponent = std::min(s.playback.exponent + 1, 6); break;
        case SDLK_MINUS: case SDLK_KP_MINUS: s.playback.exponent = std::max(s.playback.exponent - 1, -4); break;
        case SDLK_r: s.restart = true; break;
        case SDLK_s: s.screenshot = true; break;
        case SDLK_q: case SDLK_ESCAPE: s.quit = true; break;
        default: break;
    }
}

void poll_events(LoopState& s) {
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
        if (event.type == SDL_QUIT) s.quit = true;
        if (event.type == SDL_KEYDOWN) handle_key(event.key.keysym.sym, s);
    }
}

std::string speed_hud(double fps, const ViewSession& session, const Playback& playback) {
    char text[128];
    std::snprintf(text, sizeof text, "  %.0f FPS  %.2e PSTEPS/S  %s", fps, session.particle_steps_per_second(),
                  playback.label().c_str());
    return text;
}

std::string screenshot_name(const ViewSession& session) {
    char name[256];
    std::snprintf(name, sizeof name, "collide-%s-t%.3f.png", session.scene().name.c_str(), session.time());
    return name;
}

}  // namespace

FrameTimes draw_frame(ViewSession& session, Canvas& canvas, Geometry& geometry, int output_steps,
                      const std::string& extra_hud) {
    FrameTimes t;
    const auto start = Clock::now();
    if (output_steps > 0) session.advance(output_steps);
    const auto simulated = Clock::now();
    if (output_steps > 0) session.analyse();
    const FrameLayout layout = make_layout(session.scene().world, canvas.width(), canvas.height());
    build_frame(session.frame(extra_hud), layout, geometry, session.threads());
    const auto built = Clock::now();
    canvas.draw(geometry, session.threads());
    canvas.flush();
    t.simulation = seconds_between(start, simulated);
    t.geometry = seconds_between(simulated, built);
    t.draw = seconds_between(built, Clock::now());
    return t;
}

void run_viewer(ViewSession& session, const ViewOptions& options) {
    if (options.headless && options.frames <= 0) throw std::runtime_error("--headless needs --frames N (N > 0)");
    std::unique_ptr<Canvas> canvas =
        options.headless ? std::make_unique<Canvas>(options.width, options.height)
                         : std::make_unique<Canvas>("collide view: " + session.scene().name, options.width,
                                                    options.height, true);
    Geometry geometry;
    LoopState s;
    double fps = 0;
    auto last = Clock::now();
    for (int frame = 0; !s.quit && (options.frames <= 0 || frame < options.frames); ++frame) {
        if (!options.headless) poll_events(s);
        if (std::exchange(s.restart, false)) session.restart();
        // The first frame shows the initial state; every later one advances.
        draw_frame(session, *canvas, geometry, frame == 0 ? 0 : s.playback.output_steps(), speed_hud(fps, session, s.playback));
        if (std::exchange(s.screenshot, false)) write_png(screenshot_name(session), canvas->read_pixels());
        // Read before present: after it, a GPU renderer's back buffer is undefined.
        const bool final_frame = s.quit || (options.frames > 0 && frame + 1 >= options.frames);
        if (final_frame && !options.screenshot.empty()) {
            write_png(options.screenshot, canvas->read_pixels());
            std::printf("screenshot %s (t = %g)\n", options.screenshot.c_str(), session.time());
        }
        if (!options.headless) canvas->present();
        const auto now = Clock::now();
        const double dt = seconds_between(last, now);
        last = now;
        fps = fps == 0 ? 1 / dt : 0.9 * fps + 0.1 / dt;  // smoothed, so the HUD stays readable
    }
}

}  // namespace collide::view
