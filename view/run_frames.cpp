#include "run_frames.h"

#include <stdexcept>

#include "core/scene/scene_loader.h"

namespace collide::view {

RunFrames::RunFrames(const std::string& path) : run_(path) {
    if (!run_.has_frames())
        throw std::runtime_error(path + ": written without --frames: rerun with `collide run ... --frames`");
    scene_ = parse_scene(run_.attribute("scene_text"), run_.attribute("scene_path"));
    backend_ = run_.attribute("backend");
}

void RunFrames::read(std::size_t k, ParticleState<double>& out) const {
    run_.read_frame(k, out);  // checked against the run's own record of non-finite disks
    const double nonfinite = run_.metric("nonfinite")[k];
    if (nonfinite > 0)
        throw std::runtime_error(path() + ": frame " + std::to_string(k) + " (t = " + std::to_string(time(k)) +
                                 ") has " + std::to_string(std::size_t(nonfinite)) +
                                 " disks at NaN or Inf (the run failed there): nothing to draw");
}

}  // namespace collide::view
