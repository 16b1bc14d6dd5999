// The opencl part of tests/core/test_extreme_scenes.cpp (docs/refusals.md): random scenes with
// magnitudes from 1e-300 to 1e300 are refused with the limit named, or run intact, in float
// and, where the device has fp64, in double. Plus the case of the issue that found it: float
// kernels turned disks of mass 1e46 into stones that others passed through.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "opencl/cl_devices.h"
#include "opencl_test_scenes.h"
#include "tests/support/extreme_scenes.h"
#include "tests/support/test_scenes.h"

namespace collide::test {
namespace {

// A fixed seed, so that a failure repeats; EXTREME_SEED=<n> explores other sequences.
std::uint64_t seed() {
    const char* text = std::getenv("EXTREME_SEED");
    return text ? std::strtoull(text, nullptr, 10) : 20261124;
}
constexpr int cases = 120;  // kernels are built once per feature set and cached

void expect_property(const BackendOptions& options) {
    int refused = 0, ran = 0;
    for (int k = 0; k < cases; ++k) {
        const ExtremeCase c = extreme_case(seed(), k);
        const ExtremeOutcome outcome = run_extreme_case(backend("opencl"), options, c);
        EXPECT_EQ(outcome.violation, "") << c.summary;
        (outcome.refused ? refused : ran) += 1;
    }
    std::printf("opencl %s: %d of %d cases refused, %d ran\n", options.real.empty() ? "float" : options.real.c_str(),
                refused, cases, ran);
    EXPECT_GT(refused, 0);
    EXPECT_GT(ran, 0);
}

TEST(OpenclExtremeScenes, FloatKernelsRefuseNamingTheLimitOrRunIntact) { expect_property({}); }

TEST(OpenclExtremeScenes, DoubleKernelsRefuseNamingTheLimitOrRunIntact) {
    BackendOptions options;
    options.real = "double";
    try {
        Scene scene = box_scene(10, 10);
        backend("opencl").create(options)->load(scene, make_state({{5, 5, 1, 0, 0.5, 1}}));
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no fp64 device: " << e.what();
    }
    expect_property(options);
}

TEST(OpenclExtremeScenes, HeavyDisksAreRefusedInFloatNotTurnedIntoStones) {
    Scene scene = box_scene(10, 4);
    scene.name = "heavy";
    const auto state = make_state({{3, 2, 1, 0, 0.5, 1e46}, {7, 2, -1, 0, 0.5, 1e46}});
    std::string error;
    try {
        backend("opencl").create({})->load(scene, state);
    } catch (const std::exception& e) {
        error = e.what();
    }
    EXPECT_NE(error.find("opencl computes in float: mass m = 1e+46 for disk 0 overflows float's largest number"),
              std::string::npos)
        << error;
}

}  // namespace
}  // namespace collide::test
