// run_scene, the loop every command and the validation runner share: output times, and the
// NaN/Inf guard that stops a run at the first broken output and says where to look.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/run_driver.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

// A solver whose disk 1 gets a NaN position once time passes `breaks_after`; otherwise the
// disks stay where they were loaded.
class BreakingSolver : public Solver {
public:
    explicit BreakingSolver(double breaks_after) : breaks_after_(breaks_after) {}
    std::string name() const override { return "breaking"; }
    void load(const Scene&, const ParticleState<double>& initial) override { state_ = initial; }
    void advance_to(double t) override {
        now_ = t;
        if (t > breaks_after_) state_.x[1] = std::numeric_limits<double>::quiet_NaN();
    }
    void read_state(ParticleState<double>& out) const override { out = state_; }
    double time() const override { return now_; }
    SolverStats stats() const override { return {}; }

private:
    double breaks_after_, now_ = 0;
    ParticleState<double> state_;
};

Scene ten_outputs() {
    Scene scene = test::box_scene(10, 10);
    scene.run.duration = 1.0;
    scene.run.output_interval = 0.1;
    return scene;
}

TEST(RunDriver, OutputTimesCoverTheDurationInEqualIntervals) {
    const auto times = output_times(ten_outputs());
    ASSERT_EQ(times.size(), 11u);
    EXPECT_DOUBLE_EQ(times.front(), 0.0);
    EXPECT_DOUBLE_EQ(times[3], 0.3);
    EXPECT_DOUBLE_EQ(times.back(), 1.0);
}

TEST(RunDriver, NanStopsTheRunNamingTheDiskAndTheLastFiniteOutput) {
    const Scene scene = ten_outputs();
    const auto initial = test::make_state({{2, 2, 1, 0, 0.5, 1}, {6, 6, -1, 0, 0.5, 1}});
    BreakingSolver solver(0.25);
    try {
        run_scene(scene, solver, initial);
        FAIL() << "expected the NaN to stop the run";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("breaking: 1 disk(s) with NaN/Inf state at t = 0.3"), std::string::npos) << message;
        EXPECT_NE(message.find("first: disk 1"), std::string::npos) << message;
        EXPECT_NE(message.find("every disk was finite at t = 0.2"), std::string::npos) << message;
    }
}

TEST(RunDriver, WithoutTheGuardTheRunGoesOnAndCountsTheBrokenDisks) {
    const auto initial = test::make_state({{2, 2, 1, 0, 0.5, 1}, {6, 6, -1, 0, 0.5, 1}});
    BreakingSolver solver(0.25);
    RunOptions options;
    options.stop_on_nonfinite = false;
    const RunResult result = run_scene(ten_outputs(), solver, initial, options);
    ASSERT_EQ(result.series.size(), 11u);
    EXPECT_EQ(result.series[2].nonfinite, 0);
    EXPECT_EQ(result.series[3].nonfinite, 1);
    EXPECT_EQ(result.series.back().nonfinite, 1);
}

}  // namespace
}  // namespace collide
