#include "test_backends.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

namespace collide::test {
namespace {

class FaultySolver : public Solver {
public:
    FaultySolver(std::string name, Fault fault) : name_(std::move(name)), fault_(fault) {}
    std::string name() const override { return name_; }
    void load(const Scene& scene, const ParticleState<double>& initial) override {
        scene_ = scene;
        state_ = initial;
        time_ = 0;
    }
    void advance_to(double t) override {
        switch (fault_) {
            case Fault::throws: throw std::runtime_error("deliberate failure in advance_to");
            case Fault::crashes: std::abort();
            case Fault::hangs: std::this_thread::sleep_for(std::chrono::hours(1)); break;
            default: break;
        }
        const double h = t - time_;
        const World& w = scene_.world;
        for (std::size_t i = 0; i < state_.size(); ++i) {
            state_.x[i] += state_.vx[i] * h;
            state_.y[i] += state_.vy[i] * h;
            if (state_.x[i] - state_.radius[i] < w.xmin || state_.x[i] + state_.radius[i] > w.xmax) state_.vx[i] = -state_.vx[i];
            if (state_.y[i] - state_.radius[i] < w.ymin || state_.y[i] + state_.radius[i] > w.ymax) state_.vy[i] = -state_.vy[i];
            if (fault_ == Fault::adds_energy) state_.vx[i] *= 1.01, state_.vy[i] *= 1.01;
        }
        if (fault_ == Fault::produces_nan && t > 0.5 * scene_.run.duration)
            state_.x[0] = std::numeric_limits<double>::quiet_NaN();
        time_ = t;
    }
    void read_state(ParticleState<double>& out) const override { out = state_; }
    double time() const override { return time_; }
    SolverStats stats() const override { return {}; }

private:
    std::string name_;
    Fault fault_;
    Scene scene_;
    ParticleState<double> state_;
    double time_ = 0;
};

}  // namespace

BackendInfo test_backend(const std::string& name, Fault fault, const std::string& refuses) {
    return {name, "double", "test double",
            [refuses](const Scene&) -> std::optional<std::string> {
                if (refuses.empty()) return std::nullopt;
                return refuses;
            },
            [name, fault](const BackendOptions&) -> std::unique_ptr<Solver> {
                return std::make_unique<FaultySolver>(name, fault);
            }};
}

Scene two_disk_scene(const std::string& name) {
    Scene s;
    s.name = name;
    s.world = World{0, 0, 10, 10, Boundary::reflect};
    s.run.duration = 0.2;
    s.run.output_interval = 0.05;
    s.run.dt = 0.01;
    ParticleGenerator g;
    g.kind = "list";
    g.disks = {{2, 2, 1, 0.5, 0.5, 1, false}, {7, 7, -0.5, 1, 0.5, 2, false}};
    s.generators.push_back(g);
    return s;
}

validation::Suite test_suite(const Scene& scene, const std::vector<std::string>& backends) {
    validation::Suite suite;
    suite.name = "test";
    suite.source_path = "test-suite";
    suite.backends = backends;
    suite.seeds = {1, 2};
    suite.time_limit_seconds = 2;
    suite.warmup_fraction = 0;
    suite.output.hdf5 = false;
    validation::SuiteScene entry;
    entry.name = scene.name;
    entry.scene = scene;
    suite.scenes.push_back(entry);
    return suite;
}

std::string fresh_output_dir(const std::string& name) {
    // The process id keeps apart tests that ctest runs at the same time (each test is a
    // process of its own, and several tests of one file ask for the same name); the
    // directories go when the test process ends.
    struct Made {
        std::vector<std::filesystem::path> dirs;
        ~Made() {
            std::error_code ignored;
            for (const auto& d : dirs) std::filesystem::remove_all(d, ignored);
        }
    };
    static Made made;
    const auto dir = std::filesystem::path(::testing::TempDir()) /
                     ("collide_validation_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    made.dirs.push_back(dir);
    return dir.string();
}

}  // namespace collide::test
