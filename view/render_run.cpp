#include "render_run.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "canvas.h"
#include "core/metrics.h"
#include "core/io/output_file.h"
#include "image_writers.h"
#include "run_frames.h"
#include "view_session.h"

namespace collide::view {
namespace {

// K indices spread evenly over T stored frames, first and last included.
std::vector<std::size_t> chosen_frames(const RunFrames& run, int asked, const std::string& format) {
    const std::size_t total = run.frame_count();
    if (total == 0) throw std::runtime_error(run.path() + ": the run file holds no frames");
    const std::size_t k = asked > 0 ? std::size_t(asked) : (format == "png" ? std::min<std::size_t>(6, total) : total);
    if (k > total)
        throw std::runtime_error("--frames " + std::to_string(k) + ": " + run.path() + " holds only " +
                                 std::to_string(total) + " frames");
    std::vector<std::size_t> indices;
    for (std::size_t j = 0; j < k; ++j)
        indices.push_back(k == 1 ? 0 : std::size_t(std::llround(double(j) * double(total - 1) / double(k - 1))));
    return indices;
}

// The reference frame whose time is nearest to t (runs of one scene share output times).
std::size_t nearest_frame(const RunFrames& ref, double t) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < ref.frame_count(); ++k)
        if (std::fabs(ref.time(k) - t) < std::fabs(ref.time(best) - t)) best = k;
    return best;
}

void check_compatible(const RunFrames& run, const RunFrames& ref) {
    if (run.disk_count() != ref.disk_count())
        throw std::runtime_error("--compare: " + run.path() + " has " + std::to_string(run.disk_count()) +
                                 " disks but " + ref.path() + " has " + std::to_string(ref.disk_count()) +
                                 " (compare runs of the same scene)");
}

// Reads every frame that will be drawn before anything is written, so a damaged file leaves
// no half-written animation behind.
void check_frames(const RunFrames& run, const RunFrames* ref, const std::vector<std::size_t>& frames) {
    ParticleState<double> state;
    for (std::size_t k : frames) {
        run.read(k, state);
        if (ref) ref->read(nearest_frame(*ref, run.time(k)), state);
    }
}

// Copies `panel` into `strip` at column offset x0.
void paste(Image& strip, const Image& panel, int x0) {
    for (int y = 0; y < panel.height; ++y)
        std::copy_n(panel.rgba.begin() + std::ptrdiff_t(y) * panel.width * 4, std::size_t(panel.width) * 4,
                    strip.rgba.begin() + (std::ptrdiff_t(y) * strip.width + x0) * 4);
}

class FramePainter {
public:
    FramePainter(const RunFrames& run, const RunFrames* ref, int width, int height)
        : run_(run), ref_(ref), canvas_(width, height) {
        run_.read(0, state_);
        speed_max_ = default_speed_max(run_.scene(), state_);
        initial_ = compute_metrics(run_.scene(), state_, run_.time(0));
    }

    Image paint(std::size_t k) {
        run_.read(k, state_);
        if (ref_) ref_->read(nearest_frame(*ref_, run_.time(k)), ref_state_);
        finder_.find(run_.scene().world, state_, overlaps_);
        FrameContent c;
        c.state = &state_;
        c.compare = ref_ ? &ref_state_ : nullptr;
        c.overlaps = &overlaps_;
        c.speed_max = speed_max_;
        c.hud = physics_hud(run_.scene(), initial_, frame_metrics(run_.scene(), state_, run_.time(k), overlaps_)) + "  " +
                run_.backend() + (ref_ ? " (OUTLINES " + ref_->backend() + ")" : "");
        build_frame(c, make_layout(run_.scene().world, canvas_.width(), canvas_.height()), geometry_);
        canvas_.draw(geometry_);
        return canvas_.read_pixels();
    }

private:
    const RunFrames& run_;
    const RunFrames* ref_;
    Canvas canvas_;
    Geometry geometry_;
    ParticleState<double> state_, ref_state_;
    OverlapFinder finder_;
    std::vector<OverlapMark> overlaps_;
    Metrics initial_;
    double speed_max_ = 1;
};

}  // namespace

void render_run(const RenderOptions& o) {
    const std::string format = output_format(o.out);
    check_output_path(o.out);  // before any frame is read or drawn (core/io/output_file.h)
    if (o.width < 16 || o.height < 16) throw std::runtime_error("--size: a frame needs at least 16x16 pixels");
    const RunFrames run(o.run);
    std::unique_ptr<RunFrames> ref;
    if (!o.compare.empty()) {
        ref = std::make_unique<RunFrames>(o.compare);
        check_compatible(run, *ref);
    }
    const std::vector<std::size_t> frames = chosen_frames(run, o.frames, format);
    check_frames(run, ref.get(), frames);
    FramePainter painter(run, ref.get(), o.width, o.height);
    if (format == "png") {
        Image strip{o.width * int(frames.size()), o.height, {}};
        strip.rgba.resize(std::size_t(strip.width) * std::size_t(strip.height) * 4);
        for (std::size_t j = 0; j < frames.size(); ++j) {
            paste(strip, painter.paint(frames[j]), int(j) * o.width);
            if (o.on_frame) o.on_frame(run.time(frames[j]), run.time(frames.back()));
        }
        write_png(o.out, strip);
    } else {
        auto writer = format == "gif" ? open_gif(o.out, o.width, o.height, o.fps) : open_mp4(o.out, o.width, o.height, o.fps);
        for (std::size_t k : frames) {
            writer->add(painter.paint(k));
            if (o.on_frame) o.on_frame(run.time(k), run.time(frames.back()));
        }
        writer->finish();
    }
    std::printf("wrote %s (%zu frames of %dx%d, t = %g .. %g)\n", o.out.c_str(), frames.size(), o.width, o.height,
                run.time(frames.front()), run.time(frames.back()));
}

}  // namespace collide::view
