// The property of docs/refusals.md, "Numbers a backend cannot represent", over random scenes
// with magnitudes from 1e-300 to 1e300 (fixed seed): every backend either refuses before
// starting, naming the quantity, its value and the limit, or runs and keeps the disks intact.
// The opencl backend's part is tests/opencl/test_opencl_extreme_scenes.cpp.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "core/backend_registry.h"
#include "tests/support/extreme_scenes.h"

namespace collide::test {
namespace {

// A fixed seed, so that a failure repeats; EXTREME_SEED=<n> explores other sequences.
std::uint64_t seed() {
    const char* text = std::getenv("EXTREME_SEED");
    return text ? std::strtoull(text, nullptr, 10) : 20261124;
}
constexpr int cases = 600;

class ExtremeScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(ExtremeScenes, RefuseNamingTheLimitOrRunIntact) {
    const BackendInfo& backend = find_backend(GetParam());
    BackendOptions options;
    options.threads = 1;
    int refused = 0, ran = 0;
    for (int k = 0; k < cases; ++k) {
        const ExtremeCase c = extreme_case(seed(), k);
        const ExtremeOutcome outcome = run_extreme_case(backend, options, c);
        EXPECT_EQ(outcome.violation, "") << c.summary;
        (outcome.refused ? refused : ran) += 1;
    }
    // The magnitudes are drawn so that both sides of the property are exercised.
    std::printf("%s: %d of %d cases refused, %d ran\n", GetParam().c_str(), refused, cases, ran);
    EXPECT_GT(refused, cases / 10) << ran << " ran";
    EXPECT_GT(ran, cases / 10) << refused << " refused";
}

INSTANTIATE_TEST_SUITE_P(Backends, ExtremeScenes, ::testing::Values("event", "step", "cpu", "box2d"));

}  // namespace
}  // namespace collide::test
