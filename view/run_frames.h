// Reading the frames of a run file (docs/output-format.md) for drawing: the scene (from the
// stored scene text), the disks' constants, and the state at any stored output time, one frame
// at a time (a long run's frames need not fit in memory). Every check is core/io/run_reader.h's:
// a damaged file is refused with its name, never drawn.
#pragma once

#include <cstddef>
#include <string>

#include "core/particle_state.h"
#include "core/io/run_reader.h"
#include "core/scene/scene.h"

namespace collide::view {

class RunFrames {
public:
    // Throws with the file name when the file is not a run file, is damaged, or was written
    // without frames (then the message says how to get them).
    explicit RunFrames(const std::string& path);

    const std::string& path() const { return run_.path(); }
    const Scene& scene() const { return scene_; }
    const std::string& backend() const { return backend_; }
    std::size_t frame_count() const { return run_.frame_times().size(); }
    std::size_t disk_count() const { return run_.disk_count(); }
    double time(std::size_t k) const { return run_.frame_times()[k]; }
    // The state at output k: positions and velocities of frame k, the disks' constants.
    // Throws when the frame is damaged, or holds disks the run itself recorded as NaN or Inf
    // (there is nothing to draw for them: the run failed there).
    void read(std::size_t k, ParticleState<double>& out) const;

private:
    RunFile run_;
    Scene scene_;
    std::string backend_;
};

}  // namespace collide::view
