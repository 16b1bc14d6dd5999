// Numbers a backend cannot represent (docs/refusals.md): the representability check, the
// overlap test that cannot underflow, round-trip number text, and one test per case of the
// issue that found them.
#include <gtest/gtest.h>

#include <charconv>
#include <cfloat>
#include <random>
#include <stdexcept>
#include <string>

#include "core/backend_registry.h"
#include "core/numerics/disk_overlap.h"
#include "core/metrics.h"
#include "core/numerics/number_text.h"
#include "core/io/provenance.h"
#include "core/numerics/representability.h"
#include "core/scene/scene_loader.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

using test::DiskSpec;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The message a backend's load() throws ("" if it loads).
std::string load_error(const std::string& backend, const Scene& scene, const ParticleState<double>& state,
                       const BackendOptions& options = {}) {
    try {
        find_backend(backend).create(options)->load(scene, state);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

// Two disks of radius r and mass m in a box of side 20 r, moving towards each other at `speed`.
struct Pair {
    Scene scene;
    ParticleState<double> state;
};
Pair head_on(double r, double m, double speed = 1.0) {
    Pair p{test::box_scene(20 * r, 20 * r), {}};
    p.scene.name = "pair";
    p.state = test::make_state({{5 * r, 10 * r, speed, 0, r, m}, {15 * r, 10 * r, -speed, 0, r, m}});
    return p;
}

// ---- the check itself --------------------------------------------------------------------

TEST(Representability, OrdinaryScenesPassInBothPrecisions) {
    const Pair p = head_on(0.5, 1.0);
    for (Precision precision : {Precision::single, Precision::double_})
        for (Method method : {Method::stepping_rules, Method::event_driven, Method::metrics_only})
            EXPECT_FALSE(representability_problem(p.scene, p.state, precision, method, "x")) << to_string(precision);
}

TEST(Representability, MessageNamesQuantityValueDiskAndLimit) {
    const Pair p = head_on(0.5, 1e38);  // 1/m = 1e-38 < FLT_MIN = 1.18e-38
    const auto problem = representability_problem(p.scene, p.state, Precision::single, Method::stepping_rules, "cpu");
    ASSERT_TRUE(problem);
    EXPECT_EQ(*problem, "cpu computes in float: inverse mass 1/m = 1e-38 for disk 0 underflows below float's "
                        "smallest normal number 1.18e-38");
    EXPECT_FALSE(representability_problem(p.scene, p.state, Precision::double_, Method::stepping_rules, "step"));
}

TEST(Representability, ValuesBeyondDoubleAreNamedWithTheirSize) {
    const Pair p = head_on(0.5, 1e300, 1e5);  // m v = 1e305, m v^2 / 2 = 5e309 per disk
    const auto problem = representability_problem(p.scene, p.state, Precision::double_, Method::metrics_only, "box2d");
    ASSERT_TRUE(problem);
    EXPECT_TRUE(contains(*problem, "kinetic energy m |v|^2 / 2 = 5e+309 for disk 0 overflows double's largest number "
                                   "1.8e+308")) << *problem;
}

TEST(Representability, ARestingSceneIsNotRefusedForItsZeroSpeeds) {
    const Pair p = head_on(0.5, 1.0, 0.0);
    EXPECT_FALSE(representability_problem(p.scene, p.state, Precision::single, Method::stepping_rules, "cpu"));
}

TEST(Representability, ADisplacementPerStepThatUnderflowsIsRefused) {
    Pair p = head_on(0.5, 1.0, 1e-20);
    p.scene.run.dt = 1e-20;  // |v| dt = 1e-40: the disk would never move in float
    const auto problem = representability_problem(p.scene, p.state, Precision::single, Method::stepping_rules, "cpu");
    ASSERT_TRUE(problem);
    EXPECT_TRUE(contains(*problem, "displacement per step |v| dt = 1e-40")) << *problem;
}

// ---- the overlap test --------------------------------------------------------------------

TEST(DiskOverlap, HoldsAtBothEndsOfDoublesRange) {
    EXPECT_TRUE(centres_closer_than(0, 0, 2e-170));       // (2e-170)^2 underflows to 0
    EXPECT_TRUE(centres_closer_than(1e-170, 1e-170, 2e-170));
    EXPECT_FALSE(centres_closer_than(3e-170, 0, 2e-170));
    EXPECT_TRUE(centres_closer_than(1e200, 1e200, 2e200));  // (2e200)^2 overflows to inf
    EXPECT_FALSE(centres_closer_than(2e200, 1e200, 2e200));
    EXPECT_FALSE(centres_closer_than(1.2, 1.6, 2.0));       // exactly touching (3-4-5)
    EXPECT_TRUE(centres_closer_than(1.2, 1.6, 2.0000001));
    EXPECT_FALSE(centres_closer_than(std::nan(""), 0, 1));
}

// ---- round-trip number text --------------------------------------------------------------

TEST(NumberText, EveryDoubleReadsBackIdentically) {
    EXPECT_EQ(round_trip_text(0.1), "0.1");
    EXPECT_EQ(round_trip_text(5e-101), "5e-101");
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> exponent(-300, 300), mantissa(1, 10);
    for (int k = 0; k < 1000; ++k) {
        const double v = mantissa(rng) * std::pow(10.0, exponent(rng));
        const std::string text = round_trip_text(v);
        double back = 0;
        std::from_chars(text.data(), text.data() + text.size(), back);
        ASSERT_EQ(back, v) << text;
    }
}

// ---- issue item 6: float backends and huge masses -----------------------------------------

TEST(NumbersIssue, CpuRefusesMassesFloatCannotHoldAndNamesFloat) {
    for (const auto& [m, text] : {std::pair{1e46, "1e+46"}, std::pair{1e39, "1e+39"}}) {
        const Pair p = head_on(0.5, m);
        const std::string error = load_error("cpu", p.scene, p.state);
        EXPECT_TRUE(contains(error, std::string("cpu computes in float: mass m = ") + text +
                                        " for disk 0 overflows float's largest number 3.4e+38"))
            << error;
        EXPECT_FALSE(contains(error, "double")) << error;
    }
    const Pair p = head_on(0.5, 1e38);
    EXPECT_TRUE(contains(load_error("cpu", p.scene, p.state), "inverse mass 1/m = 1e-38"));
}

// ---- issue item 7: box2d scales and provenance --------------------------------------------

TEST(NumbersIssue, Box2dRefusesVelocitiesItsScaleWouldZero) {
    for (double r : {1e100, 1e299}) {
        const Pair p = head_on(r, 1.0);  // default scale 0.5 / r maps vx = 1 to 5e-101 m/s: 0 in float
        const std::string error = load_error("box2d", p.scene, p.state);
        EXPECT_TRUE(contains(error, "box2d computes in float: speed |v| in Box2D's units")) << error;
        EXPECT_TRUE(contains(error, "underflows below float's smallest normal number 1.18e-38")) << error;
    }
}

TEST(NumbersIssue, Box2dProvenanceNumbersRoundTrip) {
    Pair p = head_on(3.0, 1.0);  // scale 0.5 / 3 = 0.16666666666666666
    auto solver = find_backend("box2d").create({});
    solver->load(p.scene, p.state);
    const std::string scale = solver->provenance().at("box2d_length_scale");
    EXPECT_EQ(scale, "0.16666666666666666");
    p.scene.backend_options["box2d"]["length_scale"] = "1e-7";
    p.scene.run.dt = 1e-7;
    p.scene.run.duration = p.scene.run.output_interval = 1e-6;
    solver->load(p.scene, p.state);
    EXPECT_EQ(solver->provenance().at("box2d_length_scale"), "1e-07");  // was "0.000000"
    EXPECT_EQ(solver->provenance().at("box2d_time_step"), "1e-07");
    EXPECT_EQ(run_provenance(p.scene, "box2d", *solver).at("dt"), "1e-07");
}

// ---- issue item 8: one overlap test that cannot underflow ---------------------------------

TEST(NumbersIssue, SceneReaderRefusesDisksAtOneCentreWithTinyRadii) {
    const std::string text = R"(description = "two disks at one centre"
[world]
box = [0.0, 0.0, 1.0, 1.0]
[[particles]]
kind = "list"
disks = [ { x = 0.5, y = 0.5, vx = 1.0, vy = 0.0, radius = 1e-170, mass = 1.0 },
          { x = 0.5, y = 0.5, vx = -1.0, vy = 0.0, radius = 1e-170, mass = 1.0 } ]
)";
    try {
        parse_scene(text, "same_centre.toml");
        FAIL() << "accepted two disks at the same centre";
    } catch (const SceneError& e) {
        EXPECT_TRUE(contains(e.what(), "disks[2] overlaps [[particles]][1].disks[1]")) << e.what();
    }
}

TEST(NumbersIssue, SceneReaderRefusesOverlappingHugeDisks) {
    const std::string text = R"(description = "two huge disks overlapping"
[world]
box = [0.0, 0.0, 1e202, 1e202]
[[particles]]
kind = "list"
disks = [ { x = 3e201, y = 5e201, vx = 0.0, vy = 0.0, radius = 1e200, mass = 1.0 },
          { x = 3.1e201, y = 5e201, vx = 0.0, vy = 0.0, radius = 1e200, mass = 1.0 } ]
)";
    EXPECT_THROW(parse_scene(text, "huge.toml"), SceneError);
}

TEST(NumbersIssue, EveryBackendAndTheMetricsSeeTheSameOverlap) {
    Scene scene = test::box_scene(1, 1);
    scene.name = "same_centre";
    const auto state = test::make_state({{0.5, 0.5, 1, 0, 1e-170, 1}, {0.5, 0.5, -1, 0, 1e-170, 1}});
    EXPECT_EQ(compute_metrics(scene, state, 0).overlapping_pairs, 1);
    for (const char* backend : {"event", "step", "cpu", "box2d"})
        EXPECT_NE(load_error(backend, scene, state), "") << backend << " accepted two disks at one centre";
}

// ---- issue item 12: messages that name what is wrong --------------------------------------

TEST(NumbersIssue, CpuOnATinyBoxNamesTheRadius) {
    const Pair p = head_on(1e-301, 1.0);  // box 2e-300
    const std::string error = load_error("cpu", p.scene, p.state);
    EXPECT_TRUE(contains(error, "radius r = 1e-301 for disk 0 underflows below float's smallest normal")) << error;
    EXPECT_FALSE(contains(error, "largest radius > 0")) << error;
}

TEST(NumbersIssue, Box2dOnATinyRadiusNamesTheScale) {
    const Pair p = head_on(1e-310, 1.0);
    const std::string error = load_error("box2d", p.scene, p.state);
    EXPECT_TRUE(contains(error, "length scale s = inf (0.5 / mean radius 1e-310) is not a finite number")) << error;
    EXPECT_FALSE(contains(error, "gravity")) << error;
}

TEST(NumbersIssue, EventWithHugeMassesNamesTheInverseMass) {
    const Pair p = head_on(0.5, 1e308);
    const std::string error = load_error("event", p.scene, p.state);
    EXPECT_TRUE(contains(error, "event computes in double: inverse mass 1/m = 1e-308 for disk 0 underflows below "
                                "double's smallest normal number 2.23e-308")) << error;
    EXPECT_FALSE(contains(error, "inelastic collapse")) << error;
}

}  // namespace
}  // namespace collide
