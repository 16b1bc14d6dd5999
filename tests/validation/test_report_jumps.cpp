// The cases the report draws (validation/summary/drawn_cases.h) and the energy jumps `collide
// report` explains in them (validation/explain/report_jumps.h): only drawn cases, only backends
// with time steps, and a case whose numbers equal another's, bit for bit, explained once.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/scratch_directory.h"
#include "validation/explain/report_jumps.h"
#include "validation/summary/drawn_cases.h"

namespace collide::validation {
namespace {

CaseResult record(const std::string& scene, const std::string& backend, double dt, std::uint64_t seed,
                  double energy_after_jump = 0.9) {
    CaseResult r;
    r.spec.scene = scene;
    r.spec.backend = backend;
    r.spec.seed = seed;
    r.spec.dt = r.dt = dt;
    r.spec.id = scene + "__" + backend + "__dt" + std::to_string(dt) + "__seed" + std::to_string(seed);
    r.disks = 1;
    r.duration = 0.5;
    for (int k = 0; k < 6; ++k) {  // the energy drops once, between t = 0.2 and 0.3
        Metrics m;
        m.time = 0.1 * k;
        m.kinetic_energy = k < 3 ? 1.0 : energy_after_jump;
        r.series.push_back(m);
    }
    r.initial = r.final_state = Snapshot{{0.5}, {0.5}, {1.0}, {0.0}, {0.1}};
    return r;
}

TEST(DrawnCases, SmallestDtThenFirstSeedPerSceneAndBackend) {
    std::vector<CaseResult> cases = {record("gas", "step", 2e-3, 1), record("gas", "step", 1e-3, 2),
                                     record("gas", "step", 1e-3, 1), record("gas", "cpu", 1e-3, 1),
                                     record("pair", "step", 4e-3, 1), record("gas", "cpu", 5e-4, 1)};
    cases[5].status = RunStatus::error;  // not finished: never drawn, however small its dt
    EXPECT_EQ(drawn_cases(cases), (std::vector<bool>{false, false, true, true, true, false}));
}

TEST(ReportJumps, DrawnSteppedCasesOnlyAndTwinsExplainedOnce) {
    test::ScratchDirectory dir;
    std::filesystem::create_directories(dir.path() / "cases");
    const std::vector<CaseResult> records = {
        record("gas", "cpu", 1e-3, 1), record("gas", "opencl", 1e-3, 1),  // the same numbers
        record("gas", "step", 1e-3, 1, 0.8),                               // other numbers
        record("gas", "event-plain", 1e-3, 1),                             // event-driven
        record("gas", "cpu", 2e-3, 1),                                     // not drawn
        record("calm", "step", 1e-3, 1)};                                  // energy drift not judged
    nlohmann::json summary = {{"checks", nlohmann::json::array()}, {"cases", nlohmann::json::array()},
                              {"backends", {{"event-plain", {{"exact", true}}}, {"cpu", {{"exact", false}}}}}};
    for (const CaseResult& r : records) {
        write_case_result(r, dir.file("cases/" + r.spec.id + ".toml"));
        summary["cases"].push_back({{"id", r.spec.id}, {"scene", r.spec.scene}, {"backend", r.spec.backend},
                                    {"drawn", r.dt == 1e-3}});
        summary["checks"].push_back({{"check", "energy_drift"}, {"scene", r.spec.scene},
                                     {"status", r.spec.scene == "gas" ? "pass" : "left_out"}});
    }
    const nlohmann::json jumps = report_energy_jumps(dir.path().string(), summary, nullptr, "no suite", {}, 2)["jumps"];
    ASSERT_EQ(jumps.size(), 3u) << jumps.dump(1);
    EXPECT_EQ(jumps[0]["case"], records[0].spec.id);
    EXPECT_EQ(jumps[0]["problem"], "no suite");
    EXPECT_FALSE(jumps[0].contains("same_as"));
    EXPECT_EQ(jumps[1]["case"], records[1].spec.id);
    EXPECT_EQ(jumps[1]["same_as"], records[0].spec.id);  // not rerun: cpu's explanation is its own
    EXPECT_EQ(jumps[1]["problem"], "no suite");
    EXPECT_DOUBLE_EQ(jumps[1]["t0"].get<double>(), 0.2);
    EXPECT_EQ(jumps[2]["case"], records[2].spec.id);
    EXPECT_FALSE(jumps[2].contains("same_as"));
    EXPECT_NEAR(jumps[2]["change"].get<double>(), -0.2, 1e-12);
}

}  // namespace
}  // namespace collide::validation
