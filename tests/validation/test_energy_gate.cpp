// The energy check of the stepped rules compares the measured drift with the drift the rule
// itself predicts (validation/models/energy_loss_model.h). A bound derived that way must still catch
// defects: here the `step` solver runs a gas with a defect injected through the scene it is
// given, while the check judges it as the scene the suite declares (e = 1). The honest rule
// must pass the same check on the same scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/run_driver.h"
#include "core/scene/scene_loader.h"
#include "reference/step_solver.h"
#include "tests/support/recorded_case.h"
#include "validation/judge/applicability.h"
#include "validation/judge/checks.h"
#include "validation/record/tolerances.h"

namespace collide::validation {
namespace {

// box_gas_1000 (area fraction 0.31, kT = 1, nu = 2.6) at dt = 1.25e-4 for 10 time units: few
// multi-contact steps (the model expects 0.28 nu^2 dt T N ~ 2.3), so the honest rule's bound
// (which grows as sqrt(dt T)) is small, while a defect acting at every collision grows as T.
Scene gas_scene(double duration = 10.0) {
    Scene s = load_scene(std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/box_gas_1000.toml");
    s.run.dt = 1.25e-4;
    s.run.duration = duration;
    s.run.output_interval = 0.1;
    return s;
}

// Runs `step` on `solver_scene` and judges the run as a case of `declared`.
CheckResult energy_check_of(const Scene& declared, const Scene& solver_scene) {
    StepSolver solver;
    const CaseResult r = test::recorded_case(solver, declared, solver_scene, "energy_gate", "step");
    const ParticleState<double> initial = generate_initial_state(declared);
    for (const auto& c : case_checks(r, scene_features(declared, initial), default_tolerances(find_backend("step")),
                                      find_backend("step")))
        if (c.check == "energy_drift") {
            std::printf("drift %.3g, predicted %.3g +- %.3g, bound %.3g\n", c.value, c.predicted,
                        c.predicted_uncertainty, c.tolerance);
            return c;
        }
    ADD_FAILURE() << "no energy_drift check";
    return {};
}

TEST(EnergyGate, HonestRulePassesWithThePredictionReported) {
    const Scene s = gas_scene();
    const CheckResult c = energy_check_of(s, s);
    EXPECT_EQ(c.status, CheckStatus::pass) << c.detail;
    EXPECT_FALSE(std::isnan(c.predicted));
    EXPECT_GT(c.predicted_uncertainty, 0);
    EXPECT_GT(c.tolerance, c.predicted);
}

// A restitution of 0.999 in place of 1: every collision removes (1 - e^2)/2 of the reduced
// mass times u_n^2 (docs/stepping-rules.md, eq. 3), ~1e-3 of a disk's energy, nu = 2.6 of them
// per disk per time unit: a systematic loss of order nu T 1e-3 ~ 2.6e-2, twice the bound.
TEST(EnergyGate, RestitutionSlightlyBelowOneFails) {
    const Scene s = gas_scene();
    Scene defect = s;
    defect.physics.restitution = 0.999;
    const CheckResult c = energy_check_of(s, defect);
    EXPECT_EQ(c.status, CheckStatus::fail) << "drift " << c.value << " within " << c.tolerance;
}

// An impulse applied twice: J = -(1 + e) u_n / (w_i + w_j) doubled at e = 1 is the impulse of
// e = 3, which multiplies the normal relative speed by -3 and gains energy at every collision
// (the gas heats without bound; a tenth of a time unit, 0.26 collisions per disk, each gaining
// of the order of a disk's energy, already exceeds the bound many times over; longer runs heat
// the gas until every step is crowded with contacts and cost minutes under the sanitizers).
TEST(EnergyGate, ImpulseAppliedTwiceFails) {
    const Scene s = gas_scene(0.1);
    Scene defect = s;
    defect.physics.restitution = 3.0;
    const CheckResult c = energy_check_of(s, defect);
    EXPECT_EQ(c.status, CheckStatus::fail) << "drift " << c.value << " within " << c.tolerance;
}

}  // namespace
}  // namespace collide::validation
