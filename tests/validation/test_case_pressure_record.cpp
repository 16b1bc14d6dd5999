// A validation case of `event` on a periodic gas holds the pressure record in its counters
// (the physics rows read them there); a case with walls holds none.
#include <gtest/gtest.h>

#include "core/backend_registry.h"
#include "core/scene/scene_loader.h"
#include "tests/support/test_scenes.h"
#include "validation/plan/suite.h"
#include "validation/run/case_execution.h"

namespace collide::validation {
namespace {

CaseResult event_case(const std::string& scene_file, double duration) {
    Suite suite;
    SuiteScene entry;
    entry.name = "gas";
    entry.path = test::scene_file(scene_file);
    entry.duration = duration;
    suite.scenes = {entry};
    suite.warmup_fraction = 0;
    suite.output.hdf5 = false;
    const Scene scene = load_scene(entry.path);
    CaseSpec spec;
    spec.id = "gas__event__seed1";
    spec.scene = "gas";
    spec.backend = "event";
    const CaseContext context{&suite, &scene, &find_backend("event"), ""};
    return execute_case(spec, context);
}

TEST(CasePressureRecord, PeriodicGasCaseHoldsTheCounters) {
    const CaseResult r = event_case("periodic_gas.toml", 2);
    ASSERT_TRUE(r.finished()) << r.diagnostic;
    for (const char* name : {"beta_pressure", "beta_pressure_error", "beta_pressure_correlation_time",
                             "beta_pressure_equilibration", "beta_pressure_batches", "psi6_traversals", "psi6_mixed"})
        EXPECT_TRUE(r.counters.count(name)) << name;
    EXPECT_GT(r.counters.at("beta_pressure"), 0);
}

TEST(CasePressureRecord, WalledCaseHoldsNone) {
    const CaseResult r = event_case("head_on_equal.toml", 1);
    ASSERT_TRUE(r.finished()) << r.diagnostic;
    EXPECT_FALSE(r.counters.count("beta_pressure"));
}

}  // namespace
}  // namespace collide::validation
