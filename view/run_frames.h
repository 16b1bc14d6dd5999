// Reading the frames of a run file (docs/output-format.md): the scene (from the stored scene
// text), the disks' constants, and the state at any stored output time, one frame at a time
// (a long run's frames need not fit in memory).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/hdf5_handle.h"
#include "core/particle_state.h"
#include "core/scene.h"

namespace collide::view {

class RunFrames {
public:
    // Throws with the file name when the file is not a run file, or was written without
    // frames (then the message says how to get them).
    explicit RunFrames(const std::string& path);

    const std::string& path() const { return path_; }
    const Scene& scene() const { return scene_; }
    const std::string& backend() const { return backend_; }
    std::size_t frame_count() const { return times_.size(); }
    std::size_t disk_count() const { return constants_.size(); }
    double time(std::size_t k) const { return times_[k]; }
    // The state at output k: positions and velocities of frame k, the disks' constants.
    void read(std::size_t k, ParticleState<double>& out) const;

private:
    std::vector<double> read_vector(const std::string& dataset) const;
    std::string root_attribute(const std::string& name) const;

    std::string path_;
    Hdf5Handle file_;
    Scene scene_;
    std::string backend_;
    std::vector<double> times_;
    ParticleState<double> constants_;  // radius, mass, inv_mass filled; x, y, vx, vy sized
};

}  // namespace collide::view
