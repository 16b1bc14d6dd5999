// A finished case whose metrics hold NaN or Inf while every disk stayed finite (the kinetic
// energy of |v| = 1e200 overflows double) must fail: the run check, every check that reads
// the metric, and the stability classification. std::max(m, NaN) returns m, which would let
// such a case pass with an energy drift of 0.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "validation/judge/checks.h"
#include "validation/judge/stability.h"

namespace collide::validation {
namespace {

CaseResult case_with_kinetic_energy(double k0, double k1) {
    CaseResult r;
    r.spec.id = "overflow";
    r.spec.backend = "step";
    r.disks = 2;
    r.total_mass = 2;
    r.series.resize(2);
    r.series[0].kinetic_energy = k0;
    r.series[1].time = 1;
    r.series[1].kinetic_energy = k1;
    return r;
}

const CheckResult& find(const std::vector<CheckResult>& checks, const std::string& name) {
    for (const auto& c : checks)
        if (c.check == name) return c;
    throw std::runtime_error("no check " + name);
}

TEST(NonfiniteMetrics, FailTheRunCheckAndTheEnergyCheck) {
    SceneFeatures features;  // no walls, no gravity: kinetic energy and momentum are checked
    const Tolerances tolerances;
    for (double bad : {std::numeric_limits<double>::infinity(), std::nan("")}) {
        const auto checks = case_checks(case_with_kinetic_energy(bad, bad), features, tolerances, BackendInfo{});
        EXPECT_EQ(find(checks, "run").status, CheckStatus::fail) << bad;
        EXPECT_EQ(find(checks, "energy_drift").status, CheckStatus::fail) << bad;
        EXPECT_EQ(find(checks, "max_overlap").status, CheckStatus::pass) << "a check that does not read it";
    }
    const auto healthy = case_checks(case_with_kinetic_energy(1, 1), features, tolerances, BackendInfo{});
    EXPECT_EQ(find(healthy, "run").status, CheckStatus::pass);
    EXPECT_EQ(find(healthy, "energy_drift").status, CheckStatus::pass);
}

TEST(NonfiniteMetrics, AreNotStable) {
    const auto c = classify(case_with_kinetic_energy(1, std::numeric_limits<double>::infinity()), nullptr,
                            SceneFeatures{}, Tolerances{});
    EXPECT_EQ(c.outcome, Outcome::nan) << c.reason;
}

}  // namespace
}  // namespace collide::validation
