// The predictability horizon (validation/compare/predictability_horizon.h): the horizon of an
// analytic exponential separation, the limits judged before it, the twins' starting states, and
// the chaotic suite: event-plain passes it against event, a solver 1e-9 off does not.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <set>

#include "core/scene/scene_loader.h"
#include "reference/event/event_solver.h"
#include "reference/plain_event_solver.h"
#include "test_backends.h"
#include "validation/compare/predictability_horizon.h"
#include "validation/suite_runner.h"
#include "validation/run/twin_runs.h"

namespace collide::validation {
namespace {

std::vector<double> output_grid(double interval, int count) {
    std::vector<double> t;
    for (int k = 0; k <= count; ++k) t.push_back(k * interval);
    return t;
}

// s(t) = s0 e^(lambda t): twins of a chaotic run part exponentially (Lyapunov exponent lambda).
std::vector<double> exponential(const std::vector<double>& times, double s0, double lambda, double factor = 1) {
    std::vector<double> s;
    for (double t : times) s.push_back(factor * s0 * std::exp(lambda * t));
    return s;
}

TEST(PredictabilityHorizon, ExponentialSeparationCrossesWhereTheLogarithmSays) {
    const double s0 = 1e-14, lambda = 2.0, tolerance = 0.5, margin = 1e3, interval = 0.1;
    const auto times = output_grid(interval, 200);
    const auto h = predictability_horizon(times, exponential(times, s0, lambda), tolerance, margin);
    // s0 e^(lambda t) = tolerance / margin at t* = ln(tolerance / (margin s0)) / lambda = 12.3176...
    const double crossing = std::log(tolerance / (margin * s0)) / lambda;
    const auto last_within = std::size_t(std::floor(crossing / interval));
    EXPECT_DOUBLE_EQ(h.threshold, 5e-4);
    EXPECT_TRUE(h.reached);
    EXPECT_EQ(h.judged, last_within + 1);  // outputs 0 .. 123
    EXPECT_DOUBLE_EQ(h.time, times[last_within]);
    EXPECT_DOUBLE_EQ(h.first_unjudged, times[last_within + 1]);
    EXPECT_NEAR(h.time, 12.3, 1e-12);
    EXPECT_TRUE(h.judges_anything(times));
}

TEST(PredictabilityHorizon, TwinsThatNeverPartJudgeTheWholeRun) {
    const auto times = output_grid(0.1, 30);
    const auto h = predictability_horizon(times, std::vector<double>(times.size(), 1e-14), 0.5);
    EXPECT_FALSE(h.reached);
    EXPECT_EQ(h.judged, times.size());
    EXPECT_DOUBLE_EQ(h.time, 3.0);
    EXPECT_TRUE(std::isnan(h.first_unjudged));
}

TEST(PredictabilityHorizon, AHorizonShorterThanTheFirstOutputJudgesNothing) {
    const auto times = output_grid(1.0, 10);
    // Parted by the first output after the start: only t = 0, where every solver starts alike.
    const auto h = predictability_horizon(times, exponential(times, 1e-14, 40.0), 0.5);
    EXPECT_EQ(h.judged, 1u);
    EXPECT_FALSE(h.judges_anything(times));
    const auto j = judge_trajectory(times, std::vector<double>(times.size(), 30.0), exponential(times, 1e-14, 40.0),
                                    0.5, false);
    EXPECT_FALSE(j.judged());
}

TEST(PredictabilityHorizon, ATwinThatDidNotFinishEndsTheHorizon) {
    auto times = output_grid(0.1, 10);
    std::vector<double> s(times.size(), 1e-14);
    s[4] = std::nan("");
    EXPECT_EQ(predictability_horizon(times, s, 0.5).judged, 4u);
}

// A correct exact solver parts from the reference like a twin does (here 10 times faster);
// one whose collisions are 1e-9 late starts 1e-9 / 1e-15 = 1e6 times further off.
TEST(PredictabilityHorizon, ACorrectSolverIsExcusedAfterTheHorizonALateOneIsNotBeforeIt) {
    const auto times = output_grid(0.1, 200);
    const auto twins = exponential(times, 1e-14, 2.0);
    auto saturated = [](std::vector<double> e) {  // disks cannot part by more than the box: 20 r_min
        for (double& x : e) x = std::min(x, 20.0);
        return e;
    };
    const auto correct = saturated(exponential(times, 1e-14, 2.0, 10.0));
    const auto late = saturated(exponential(times, 1e-14, 2.0, 1e6));
    for (bool exact : {false, true}) {
        const auto ok = judge_trajectory(times, correct, twins, 0.5, exact);
        EXPECT_TRUE(ok.passed()) << "exact = " << exact;
        EXPECT_LT(ok.ratio(), 1.0);
        const auto bad = judge_trajectory(times, late, twins, 0.5, exact);
        EXPECT_FALSE(bad.passed()) << "exact = " << exact;
        EXPECT_LT(bad.times[bad.worst], bad.horizon.time);  // caught before the horizon
    }
    // Without the horizon the correct solver fails: 20 r_min at the end against 0.5.
    EXPECT_GT(correct.back(), 0.5);
}

TEST(PredictabilityHorizon, AnExactSolverIsHeldToTheTwinsRoundingLevel) {
    const auto times = output_grid(0.1, 50);
    const auto twins = exponential(times, 1e-14, 2.0);
    // 1e4 times the twins: well inside the stepped tolerance, far above rounding.
    const auto error = exponential(times, 1e-14, 2.0, 1e4);
    EXPECT_TRUE(judge_trajectory(times, error, twins, 0.5, false).passed());
    const auto exact = judge_trajectory(times, error, twins, 0.5, true);
    EXPECT_FALSE(exact.passed());
    EXPECT_DOUBLE_EQ(exact.limit[3], horizon_margin * twins[3]);
}

TEST(PredictabilityHorizon, WithoutTwinsEveryOutputIsJudgedWithTheTolerance) {
    const auto times = output_grid(0.1, 10);
    const auto j = judge_trajectory(times, std::vector<double>(times.size(), 0.4), {}, 0.5, true);
    EXPECT_FALSE(j.measured);
    EXPECT_EQ(j.limit.size(), times.size());
    EXPECT_TRUE(j.passed());
}

double ulp(double x) { return std::nextafter(std::fabs(x), HUGE_VAL) - std::fabs(x); }

TEST(TwinRuns, EveryCoordinateMovesByOneRoundingErrorOfTheBox) {
    const Scene scene = load_scene(std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/chaotic_random_sizes.toml");
    const ParticleState<double> initial = generate_initial_state(scene);
    const double delta = std::numeric_limits<double>::epsilon() * 6.0;  // box 6 x 6 at the origin
    std::set<int> signs;
    for (int twin = 1; twin <= 3; ++twin) {
        const auto t = twin_initial_state(scene, initial, 1, twin);
        EXPECT_EQ(t.x.size(), initial.x.size());
        for (std::size_t i = 0; i < t.size(); ++i) {
            // x + delta rounds to the nearest double: within half an ulp of x, and never x itself.
            EXPECT_NEAR(std::fabs(t.x[i] - initial.x[i]), delta, 0.5 * ulp(initial.x[i]));
            EXPECT_NEAR(std::fabs(t.y[i] - initial.y[i]), delta, 0.5 * ulp(initial.y[i]));
            EXPECT_NE(t.x[i], initial.x[i]);
            EXPECT_NE(t.y[i], initial.y[i]);
            signs.insert(t.x[i] > initial.x[i] ? 1 : -1);
            EXPECT_EQ(t.vx[i], initial.vx[i]);
        }
        // The same twin every time (a hash of seed, twin, disk, coordinate).
        EXPECT_EQ(twin_initial_state(scene, initial, 1, twin).x, t.x);
    }
    EXPECT_EQ(signs.size(), 2u);
    EXPECT_NE(twin_initial_state(scene, initial, 1, 1).x, twin_initial_state(scene, initial, 1, 2).x);
}

// event-plain with every disk moved by 1e-9 of its velocity when it loads: the position error a
// collision 1e-9 late leaves (the disks fly on for 1e-9 with their old velocities), once.
class LateSolver : public PlainEventSolver {
public:
    std::string name() const override { return "late-1e-9"; }
    void load(const Scene& scene, const ParticleState<double>& initial) override {
        ParticleState<double> late = initial;
        for (std::size_t i = 0; i < late.size(); ++i) {
            late.x[i] += 1e-9 * late.vy[i];  // across the velocity: a time shift alone would not grow
            late.y[i] -= 1e-9 * late.vx[i];
        }
        PlainEventSolver::load(scene, late);
    }
};

BackendInfo exact_backend(const std::string& name, std::function<std::unique_ptr<Solver>()> make,
                          bool event_driven = true) {
    return {.name = name, .precision = "double", .description = name,
            .supports = [](const Scene&) -> std::optional<std::string> { return std::nullopt; },
            .create = [make](const BackendOptions&) { return make(); }, .exact = event_driven};
}

TEST(PredictabilityHorizon, EventPlainPassesTheChaoticSuiteALateSolverFailsBeforeTheHorizon) {
    Suite suite = load_suite(COLLIDE_SOURCE_DIR "/validation/suites/chaotic.toml");
    // The late solver twice: claiming exact dynamics (held to the twins' rounding level) and
    // not (held to the stepped tolerance 0.5 r_min): neither claim excuses it before T_h.
    suite.backends = {"event", "event-plain", "late-1e-9", "late-1e-9-stepped"};
    suite.warmup_fraction = 0;
    suite.output.hdf5 = false;
    const std::vector<BackendInfo> backends = {
        exact_backend("event", [] { return std::make_unique<EventSolver>(); }),
        exact_backend("event-plain", [] { return std::make_unique<PlainEventSolver>(); }),
        exact_backend("late-1e-9", [] { return std::make_unique<LateSolver>(); }),
        exact_backend("late-1e-9-stepped", [] { return std::make_unique<LateSolver>(); }, false)};
    RunnerOptions options;
    options.output_dir = test::fresh_output_dir("chaotic");
    options.jobs = 2;
    const SuiteOutcome outcome = run_suite(suite, backends, options);
    std::set<std::string> plain_scenes, late_failures, late_stepped_failures;
    std::size_t horizons_reached = 0;
    for (const CheckResult& c : outcome.checks) {
        if (c.check != "trajectory_error") continue;
        if (c.backend == "event-plain") {
            EXPECT_EQ(c.status, CheckStatus::pass) << c.subject << ": " << c.detail;
            plain_scenes.insert(c.scene);
        }
        if (c.backend == "late-1e-9" && c.status == CheckStatus::fail) late_failures.insert(c.scene);
        if (c.backend == "late-1e-9-stepped" && c.status == CheckStatus::fail) {
            late_stepped_failures.insert(c.scene);
            EXPECT_DOUBLE_EQ(c.tolerance, 0.5) << c.subject;
        }
    }
    for (const auto& [id, j] : outcome.trajectories) {
        horizons_reached += j.horizon.reached;
        if (id.find("late-1e-9") != std::string::npos) {
            EXPECT_FALSE(j.passed()) << id;
            EXPECT_LE(j.times[j.worst], j.horizon.time) << id;  // not excused: caught up to T_h
        }
    }
    EXPECT_EQ(plain_scenes.size(), 3u);
    EXPECT_EQ(late_failures.size(), 3u);
    EXPECT_EQ(late_stepped_failures.size(), 3u);
    // The scenes are chaotic: the twins part within every run (else nothing here tests a horizon).
    EXPECT_EQ(horizons_reached, 3u * 9u);  // three judged backends, three scenes, three seeds
}

}  // namespace
}  // namespace collide::validation
