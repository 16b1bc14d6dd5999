// Every check can fail (docs/validation.md, "Every check can fail"): for each check the plan can
// emit (the check table, check_table.h), a realistic fault of the backend, injected into the
// measurements of a scene where the check runs, fails it under that backend's limits, and the
// same measurements without the fault pass it. The judging is the real one (case_checks,
// compare_with_reference, classify) on measurements of the real scene files: analytic states
// for the two-disk head-on collision, free flight and real `step`/`event` runs for the walled
// gas, replicate draws for the periodic gas. A check added to the table without a fault case
// here fails EveryCheckOfTheTableHasAFaultCase.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "core/metrics.h"
#include "core/scene/scene_features.h"
#include "core/scene/scene_loader.h"
#include "reference/event/event_solver.h"
#include "reference/step_solver.h"
#include "tests/support/recorded_case.h"
#include "validation/compare/reference_comparison.h"
#include "validation/judge/checks.h"
#include "validation/judge/observables.h"
#include "validation/judge/stability.h"
#include "validation/models/energy_loss_model.h"
#include "validation/models/statistics_bias_model.h"
#include "validation/record/check_table.h"
#include "validation/record/exact_limits.h"

namespace collide::validation {
namespace {

Scene scene_file(const std::string& name) {
    return load_scene(std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/" + name + ".toml");
}

Snapshot snapshot_of(const ParticleState<double>& s) { return {s.x, s.y, s.vx, s.vy, s.radius}; }

// A finished case of `backend` on `scene` whose states at the output times were `states`: the
// metrics through compute_metrics, the snapshots as the runner keeps them.
CaseResult case_of(const Scene& scene, const std::string& backend, const std::vector<ParticleState<double>>& states,
                   const std::vector<double>& times, std::uint64_t seed = 1) {
    CaseResult r;
    r.spec.id = scene.name + "__" + backend + "__seed" + std::to_string(seed);
    r.spec.scene = scene.name;
    r.spec.backend = backend;
    r.spec.seed = seed;
    r.disks = states.front().size();
    for (std::size_t i = 0; i < r.disks; ++i) r.total_mass += states.front().mass[i];
    r.duration = times.back();
    r.dt = scene.run.dt;
    r.substeps = scene.run.substeps;
    for (std::size_t k = 0; k < states.size(); ++k) {
        r.series.push_back(compute_metrics(scene, states[k], times[k]));
        r.trajectory.push_back(snapshot_of(states[k]));
    }
    r.trajectory_time = times;
    r.initial = snapshot_of(states.front());
    r.final_state = snapshot_of(states.back());
    return r;
}

// The check named `check` of case_checks on `r`, judged with `backend`'s limits at the case's
// scale (and a suite's [tolerances], `suite`).
CheckResult judged_case(const CaseResult& r, const Scene& scene, const std::string& backend, const std::string& check,
                        const ToleranceTable& suite = {}) {
    const BackendInfo& info = find_backend(backend);
    const ParticleState<double> initial = generate_initial_state(scene);
    const Tolerances tol = suite.for_case(info, rounding_scale(r, scene, nullptr));
    for (const CheckResult& c : case_checks(r, scene_features(scene, initial), tol, info))
        if (c.check == check) return c;
    ADD_FAILURE() << "case_checks made no " << check << " check";
    return {};
}

// --- head_on_equal: two equal disks (r = 0.5) at x = 3 and 7, v = +-1, meet at t = 1.5 --------

enum class HeadOn { honest, missed, restitution_0_999, late_by_one_step };

// The state at time t: velocities exchanged at contact (scaled by e for a restitution e), or
// never (a missed collision: the disks pass through each other). late_by_one_step: the
// collision is found one step after the step in which the disks met (see overlap_after_contact).
ParticleState<double> head_on_state(const Scene& scene, HeadOn fault, double t) {
    ParticleState<double> s = generate_initial_state(scene);
    const double contact_time = 1.5;
    const bool after = t > contact_time && fault != HeadOn::missed;
    const double e = fault == HeadOn::restitution_0_999 ? 0.999 : 1.0;
    const double v = after ? -e : 1.0, since = after ? t - contact_time : t;
    s.x[0] = (after ? 4.5 : 3.0) + v * since;
    s.x[1] = (after ? 5.5 : 7.0) - v * since;
    s.vx[0] = v;
    s.vx[1] = -v;
    return s;
}

// head_on_equal at its output times with `fault`, as a case of `backend`.
CaseResult head_on_case(const Scene& scene, HeadOn fault, const std::string& backend) {
    std::vector<ParticleState<double>> states;
    std::vector<double> times;
    for (int k = 0; k <= 30; ++k) {
        times.push_back(0.1 * k);
        states.push_back(head_on_state(scene, fault, times.back()));
    }
    CaseResult r = case_of(scene, backend, states, times);
    r.contacts = fault == HeadOn::missed ? 0 : 1;
    return r;
}

// The output that falls in the step after the disks met: an honest rule has met them within
// the last step (half a step ago), so they overlap by half a step of their approach; a rule
// that finds the contact one step late has let them press on for a step and a half.
CaseResult overlap_after_contact(const Scene& scene, HeadOn fault, const std::string& backend) {
    const double h = scene.run.dt, steps_in = fault == HeadOn::late_by_one_step ? 1.5 : 0.5;
    std::vector<ParticleState<double>> states = {head_on_state(scene, HeadOn::missed, 0.0),
                                                 head_on_state(scene, HeadOn::missed, 1.5 + steps_in * h)};
    return case_of(scene, backend, states, {0.0, 1.5 + steps_in * h});
}

// --- box_gas_1000: 1000 disks in a reflecting box --------------------------------------------

// A real run of `solver` on the gas for 0.5 time units (no fault), and the same gas in free
// flight for as long with every collision and wall reflection missed (the collision pass and
// the wall law not run: disks pass through each other and out of the box).
Scene short_gas() {
    Scene s = scene_file("box_gas_1000");
    s.run.duration = 0.5;
    s.run.output_interval = 0.1;
    return s;
}

CaseResult honest_gas_run(Solver& solver, const std::string& backend) {
    const Scene s = short_gas();
    return test::recorded_case(solver, s, s, "box_gas_1000__" + backend, backend);
}

CaseResult free_flight_gas(const std::string& backend) {
    const Scene s = short_gas();
    std::vector<ParticleState<double>> states;
    std::vector<double> times;
    const ParticleState<double> initial = generate_initial_state(s);
    for (int k = 0; k <= 5; ++k) {
        ParticleState<double> moved = initial;
        for (std::size_t i = 0; i < moved.size(); ++i) {
            moved.x[i] += moved.vx[i] * 0.1 * k;
            moved.y[i] += moved.vy[i] * 0.1 * k;
        }
        states.push_back(moved);
        times.push_back(0.1 * k);
    }
    return case_of(s, backend, states, times);
}

// --- periodic_gas: 1000 disks, periodic, the statistics against the reference ----------------

// One impulse lost: disk 0 takes a collision's impulse (a thermal momentum sqrt(m kT), kT = K/N)
// and its partner never takes the mirror one (a lost update in the one-sided pass), from the
// middle of the run on. The disks stand still: only the sums matter here.
CaseResult periodic_momentum_case(bool fault, const std::string& backend) {
    const Scene s = scene_file("periodic_gas");
    ParticleState<double> state = generate_initial_state(s);
    const double kt = compute_metrics(s, state, 0).kinetic_energy / double(state.size());
    std::vector<ParticleState<double>> states;
    std::vector<double> times;
    for (int k = 0; k <= 10; ++k) {
        if (fault && k == 5) state.vx[0] += std::sqrt(kt / state.mass[0]);
        states.push_back(state);
        times.push_back(k * s.run.duration / 10);
    }
    return case_of(s, backend, states, times);
}

// The replicates of one group of periodic_gas as the default suite runs it (64 seeds, 4.8 time
// units): Z from the contact-shell estimator, drawn around z_mean with the spread of one
// replicate (1.1 % of Z: the default suite's standard error of 0.14 % over 64 replicates), the
// collision count around nu N T / 2 with Poisson spread, and each disk's final speed from the
// 2D Maxwell (Rayleigh) distribution at kT. The draws are seeded: the test is deterministic.
struct GasDraw {
    double z_mean = 0, rate_factor = 1, kt = 1;
};

std::vector<CaseResult> periodic_group(const Scene& s, const std::string& backend, bool reference, const GasDraw& draw,
                                       std::uint64_t stream) {
    std::mt19937_64 rng(stream);
    std::normal_distribution<double> unit;
    const double n = 1000, duration = 4.8, phi = 0.218;
    const double nu = enskog_collision_frequency(phi, 0.5, 0.25, 1.0);
    std::vector<CaseResult> out;
    for (std::uint64_t seed = 1; seed <= 64; ++seed) {
        CaseResult r;
        r.spec.seed = seed;
        r.spec.scene = s.name;
        r.spec.backend = backend;
        r.spec.reference = reference;
        r.spec.id = s.name + "__" + backend + "__seed" + std::to_string(seed);
        r.disks = std::size_t(n);
        r.duration = duration;
        r.dt = s.run.dt;
        const double pairs = nu * n * duration / 2 * draw.rate_factor;
        r.contacts = std::int64_t(std::llround(pairs + std::sqrt(pairs) * unit(rng)));
        r.compressibility = {draw.z_mean * (1 + 0.011 * unit(rng))};
        for (std::size_t i = 0; i < r.disks; ++i) {
            const double vx = std::sqrt(draw.kt) * unit(rng), vy = std::sqrt(draw.kt) * unit(rng);
            r.final_state.vx.push_back(vx);
            r.final_state.vy.push_back(vy);
        }
        r.series.resize(1);
        out.push_back(r);
    }
    return out;
}

// periodic_gas as the default suite runs it at its coarsest step, and its Z from Henderson's
// g(sigma): 1 + 2 phi g at phi = 0.218.
constexpr double periodic_dt = 6e-3, periodic_z = 1.646;
Scene periodic_scene() {
    Scene s = scene_file("periodic_gas");
    s.run.dt = periodic_dt;
    return s;
}

// What a correct `backend` measures: the reference's means, plus the rule's predicted bias for a
// stepping rule (statistics_bias_model.h), judged so by compare_with_reference.
GasDraw honest_draw(const std::string& backend) {
    if (!find_backend(backend).stepping_rule()) return {periodic_z, 1, 1};
    const double nu = enskog_collision_frequency(0.218, 0.5, 0.25, 1.0);
    return {periodic_z + predicted_pressure_bias(nu, 0, periodic_dt, contact_shell).value,
            1 + predicted_collision_rate_bias(nu, 0, periodic_dt).value / nu, 1};
}

// One collision in 20 missed: the collision part of Z (Z - 1) and the rate 5 % low.
GasDraw one_in_20_missed(GasDraw d) { return {1 + (d.z_mean - 1) * 0.95, d.rate_factor * 0.95, d.kt}; }

// A restitution of 0.99 over the run: the gas loses (1 - e^2)/2 of a collision's energy at
// each of nu T collisions per disk (nu from Enskog), so kT falls by that fraction.
GasDraw restitution_0_99(GasDraw d) {
    const double nu = enskog_collision_frequency(0.218, 0.5, 0.25, 1.0);
    return {d.z_mean, d.rate_factor, d.kt * std::exp(-(1 - 0.99 * 0.99) / 2 * nu * 4.8)};
}

// The check `check` of `backend`'s cases against `event`'s in a one-scene suite comparing by
// `comparison`, judged by the real comparison (compare_with_reference) at the default tolerances.
CheckResult judged_against_event(const Scene& s, Comparison comparison, const std::vector<CaseResult>& results,
                                 const std::string& backend, const std::string& check) {
    Suite suite;
    suite.reference = "event";
    SuiteScene entry;
    entry.name = s.name;
    entry.scene = s;
    entry.comparison = comparison;
    suite.scenes.push_back(entry);
    std::map<std::string, Tolerances> tolerances;
    std::map<std::string, const BackendInfo*> declared;
    for (const std::string& b : {std::string("event"), backend}) {
        tolerances[b] = ToleranceTable{}.for_backend(find_backend(b));
        declared[b] = &find_backend(b);
    }
    const Comparisons c = compare_with_reference(suite, results, {scene_features(s, generate_initial_state(s))},
                                                 tolerances, declared);
    for (const CheckResult& r : c.checks)
        if (r.check == check) return r;
    ADD_FAILURE() << "no " << check << " check";
    return {};
}

// The statistics checks of `backend`'s group against `event`'s on periodic_gas.
CheckResult judged_statistics(const GasDraw& draw, const std::string& backend, const std::string& check) {
    const Scene s = periodic_scene();
    std::vector<CaseResult> results = periodic_group(s, "event", true, {periodic_z, 1, 1}, 1);
    const auto tested = periodic_group(s, backend, false, draw, 2);
    results.insert(results.end(), tested.begin(), tested.end());
    return judged_against_event(s, Comparison::statistics, results, backend, check);
}

// --- trajectories: head_on_equal against the reference run of its seed -----------------------

CheckResult judged_trajectory(const CaseResult& tested) {
    const Scene s = scene_file("head_on_equal");
    CaseResult ref = head_on_case(s, HeadOn::honest, "event");
    ref.spec.reference = true;
    ref.spec.dt = tested.spec.dt;
    // Twins one ulp apart stay within rounding of each other through one collision.
    ref.twin_separation.assign(ref.trajectory_time.size(), 1e-14);
    return judged_against_event(s, Comparison::trajectory, {ref, tested}, tested.spec.backend, "trajectory_error");
}

// The collision resolved one step (dt = 1e-3) after the contact time, as an exact solver whose
// collision time is rounded up to the step would: each disk then runs 1e-3 too long on its
// incoming line and leaves 2e-3 behind the exact solution.
CaseResult head_on_one_step_late(const Scene& scene, const std::string& backend) {
    CaseResult r = head_on_case(scene, HeadOn::honest, backend);
    for (std::size_t k = 0; k < r.trajectory.size(); ++k)
        if (r.trajectory_time[k] > 1.5) {
            r.trajectory[k].x[0] += 2 * scene.run.dt;
            r.trajectory[k].x[1] -= 2 * scene.run.dt;
        }
    return r;
}

// --- stability ----------------------------------------------------------------------------------

// An impulse applied twice in the one collision of head_on_equal (the impulse of e = 3: the
// disks leave at three times their speed, nine times the energy).
Outcome classified(HeadOn fault, bool doubled_impulse) {
    const Scene s = scene_file("head_on_equal");
    CaseResult r = head_on_case(s, fault, "step");
    if (doubled_impulse)
        for (Metrics& m : r.series)
            if (m.time > 1.5) m.kinetic_energy *= 9;
    const CaseResult ref = head_on_case(s, HeadOn::honest, "event");
    const Tolerances tol = ToleranceTable{}.for_backend(find_backend("step"));
    return classify(r, &ref, scene_features(s, generate_initial_state(s)), tol).outcome;
}

CheckResult as_check(Outcome o) {
    CheckResult c;
    c.check = "stability";
    c.status = o == Outcome::stable ? CheckStatus::pass : CheckStatus::fail;
    c.detail = to_string(o);
    return c;
}

// --- the cases ------------------------------------------------------------------------------------

struct FaultCase {
    std::string check, backend, scene, fault;
    std::function<CheckResult(bool faulty)> judge;
};

std::vector<FaultCase> fault_cases() {
    const auto head_on = [](HeadOn fault, const std::string& backend, const std::string& check) {
        return [=](bool faulty) {
            const Scene s = scene_file("head_on_equal");
            return judged_case(head_on_case(s, faulty ? fault : HeadOn::honest, backend), s, backend, check);
        };
    };
    const auto gas = [](const std::string& backend, const std::string& check) {
        return [=](bool faulty) {
            const Scene s = short_gas();
            StepSolver step;
            EventSolver event;
            Solver& solver = find_backend(backend).exact ? static_cast<Solver&>(event) : static_cast<Solver&>(step);
            return judged_case(faulty ? free_flight_gas(backend) : honest_gas_run(solver, backend), s, backend, check);
        };
    };
    const auto momentum = [](const std::string& backend) {
        return [=](bool faulty) {
            return judged_case(periodic_momentum_case(faulty, backend), scene_file("periodic_gas"), backend,
                               "momentum_drift");
        };
    };
    const auto beyond_step = [](HeadOn fault, const std::string& backend) {
        return [=](bool faulty) {
            const Scene s = scene_file("head_on_equal");
            const CaseResult r = fault == HeadOn::late_by_one_step
                                     ? overlap_after_contact(s, faulty ? fault : HeadOn::honest, backend)
                                     : head_on_case(s, faulty ? fault : HeadOn::honest, backend);
            return judged_case(r, s, backend, "overlap_beyond_step");
        };
    };
    const auto statistics = [](const std::string& backend, const std::string& check, GasDraw (*fault)(GasDraw)) {
        return [=](bool faulty) {
            const GasDraw honest = honest_draw(backend);
            return judged_statistics(faulty ? fault(honest) : honest, backend, check);
        };
    };
    const auto trajectory = [](const std::string& backend, bool missed) {
        return [=](bool faulty) {
            const Scene s = scene_file("head_on_equal");
            CaseResult r = !faulty ? head_on_case(s, HeadOn::honest, backend)
                           : missed ? head_on_case(s, HeadOn::missed, backend)
                                    : head_on_one_step_late(s, backend);
            return judged_trajectory(r);
        };
    };
    const std::string missed = "a missed collision (the disks pass through each other)";
    return {
        {"run", "step", "head_on_equal", "a NaN in the kinetic energy (coincident centres divide by zero)",
         [](bool faulty) {
             const Scene s = scene_file("head_on_equal");
             CaseResult r = head_on_case(s, HeadOn::honest, "step");
             if (faulty) r.series[20].kinetic_energy = std::nan("");
             return judged_case(r, s, "step", "run");
         }},
        {"momentum_drift", "step", "periodic_gas", "one impulse without its mirror (a lost update)", momentum("step")},
        {"momentum_drift", "cpu", "periodic_gas", "one impulse without its mirror (a lost update)", momentum("cpu")},
        {"momentum_drift", "event", "periodic_gas", "one impulse without its mirror (a lost update)", momentum("event")},
        {"energy_drift", "step", "head_on_equal", "restitution 0.999 at its one collision",
         head_on(HeadOn::restitution_0_999, "step", "energy_drift")},
        {"energy_drift", "event", "head_on_equal", "restitution 0.999 at its one collision",
         head_on(HeadOn::restitution_0_999, "event", "energy_drift")},
        {"energy_drift", "box2d", "head_on_equal", "restitution 0.999 at its one collision",
         head_on(HeadOn::restitution_0_999, "box2d", "energy_drift")},
        {"max_overlap", "step", "head_on_equal", missed, head_on(HeadOn::missed, "step", "max_overlap")},
        {"max_overlap", "event", "head_on_equal", missed, head_on(HeadOn::missed, "event", "max_overlap")},
        {"mean_overlap", "step", "head_on_equal", missed, head_on(HeadOn::missed, "step", "mean_overlap")},
        {"mean_overlap", "event", "head_on_equal", missed, head_on(HeadOn::missed, "event", "mean_overlap")},
        {"overlapping_pairs", "event", "box_gas_1000", "every collision missed (the collision pass not run)",
         gas("event", "overlapping_pairs")},
        {"overlapping_pairs", "step", "box_gas_1000", "every collision missed (the collision pass not run)",
         gas("step", "overlapping_pairs")},
        {"overlap_beyond_step", "event", "head_on_equal", missed, beyond_step(HeadOn::missed, "event")},
        {"overlap_beyond_step", "step", "head_on_equal", missed, beyond_step(HeadOn::missed, "step")},
        {"overlap_beyond_step", "step", "head_on_equal", "the contact found one step late",
         beyond_step(HeadOn::late_by_one_step, "step")},
        {"overlap_beyond_step", "cpu", "head_on_equal", "the contact found one step late",
         beyond_step(HeadOn::late_by_one_step, "cpu")},
        {"overlap_beyond_step", "box2d", "head_on_equal", missed, beyond_step(HeadOn::missed, "box2d")},
        {"wall_penetration", "step", "box_gas_1000", "the wall law not run (disks leave the box)",
         gas("step", "wall_penetration")},
        {"wall_penetration", "event", "box_gas_1000", "the wall law not run (disks leave the box)",
         gas("event", "wall_penetration")},
        {"trajectory_error", "step", "head_on_equal", missed, trajectory("step", true)},
        {"trajectory_error", "event-plain", "head_on_equal", "the collision resolved one step (1e-3) late",
         trajectory("event-plain", false)},
        {"pressure", "event-plain", "periodic_gas", "one collision in 20 missed (Z - 1 is 5 % low)",
         statistics("event-plain", "pressure", one_in_20_missed)},
        {"pressure", "step", "periodic_gas", "one collision in 20 missed (Z - 1 is 5 % low)",
         statistics("step", "pressure", one_in_20_missed)},
        {"collision_rate", "event-plain", "periodic_gas", "one collision in 20 missed",
         statistics("event-plain", "collision_rate", one_in_20_missed)},
        {"collision_rate", "step", "periodic_gas", "one collision in 20 missed",
         statistics("step", "collision_rate", one_in_20_missed)},
        {"speed_distribution", "event-plain", "periodic_gas", "restitution 0.99 (the gas cools)",
         statistics("event-plain", "speed_distribution", restitution_0_99)},
        {"speed_distribution", "step", "periodic_gas", "restitution 0.99 (the gas cools)",
         statistics("step", "speed_distribution", restitution_0_99)},
        {"stability", "step", "head_on_equal", "the impulse applied twice (the energy grows 9-fold)",
         [](bool faulty) { return as_check(classified(HeadOn::honest, faulty)); }},
    };
}

void PrintTo(const FaultCase& f, std::ostream* os) { *os << f.check << " on " << f.backend << " in " << f.scene; }

class EveryCheckCanFail : public ::testing::TestWithParam<FaultCase> {};

TEST_P(EveryCheckCanFail, TheFaultFailsItAndTheHonestRunPasses) {
    const FaultCase& f = GetParam();
    const CheckResult honest = f.judge(false), faulty = f.judge(true);
    EXPECT_EQ(honest.status, CheckStatus::pass) << f.check << " on " << f.backend << " without the fault: " << honest.detail
                                                << " (value " << honest.value << ", tolerance " << honest.tolerance << ")";
    EXPECT_EQ(faulty.status, CheckStatus::fail) << f.check << " on " << f.backend << " with " << f.fault
                                                << ": value " << faulty.value << ", tolerance " << faulty.tolerance;
    std::printf("%-20s %-12s %-14s honest %.3g, fault %.3g, tolerance %.3g: %s\n", f.check.c_str(), f.backend.c_str(),
                f.scene.c_str(), honest.value, faulty.value, faulty.tolerance, f.fault.c_str());
}

INSTANTIATE_TEST_SUITE_P(Faults, EveryCheckCanFail, ::testing::ValuesIn(fault_cases()), [](const auto& info) {
    std::string name = info.param.check + "_" + info.param.backend + "_" + std::to_string(info.index);
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
});

// The replacement of the two-disk count is judged at rounding: real runs of the exact solver and
// of the stepped rule (both orders) on head_on_equal and glancing, at the default suite's
// coarsest and finest steps, with an output at every step (so the step in which the disks
// overlap is seen), must pass it.
TEST(EveryCheckCanFail, RealTwoDiskRunsPassOverlapBeyondStep) {
    for (const std::string name : {"head_on_equal", "glancing"})
        for (StepOrder order : {StepOrder::collide_first, StepOrder::integrate_first})
            for (double dt : {4e-3, 2.5e-4}) {
                Scene s = scene_file(name);
                s.run.dt = dt;
                s.run.order = order;
                s.run.output_interval = dt;
                StepSolver step;
                EventSolver event;
                for (Solver* solver : {static_cast<Solver*>(&step), static_cast<Solver*>(&event)}) {
                    const std::string backend = solver == &step ? "step" : "event";
                    const CaseResult r = test::recorded_case(*solver, s, s, name, backend);
                    const CheckResult c = judged_case(r, s, backend, "overlap_beyond_step");
                    EXPECT_EQ(c.status, CheckStatus::pass)
                        << name << ", " << to_string(order) << ", dt " << dt << ", " << backend << ": " << c.detail;
                    double deepest = 0;
                    for (const Metrics& m : r.series) deepest = std::max(deepest, m.max_overlap);
                    // glancing meets at t = 4 - sqrt(3)/2, inside a step (head_on_equal at 1.5, on
                    // a step boundary: touching, not overlapping): the check judged a real overlap.
                    if (solver == &step && order == StepOrder::collide_first && name == "glancing") {
                        EXPECT_GT(deepest, 1e-6) << "dt " << dt << ": the output after contact shows the overlap";
                    }
                }
            }
}

// The list cannot fall behind the table: a check added to check_table.h without a fault case
// here fails this test.
// In a two-disk scene box2d's energy is held to the rounding of its one isolated contact, not to
// its general 5e-2; a suite that sets box2d's energy limit keeps the limit it set, even when the
// value equals the backend's own default: what decides is that the suite set it
// (Tolerances::set_by_suite), not whether the value happens to differ from the default.
TEST(EveryCheckCanFail, ASuiteSetEnergyLimitIsKeptForAnIsolatedContact) {
    const Scene s = scene_file("head_on_equal");
    const CaseResult lossy = head_on_case(s, HeadOn::restitution_0_999, "box2d");
    const double own = default_tolerances(find_backend("box2d")).energy_drift;
    ToleranceTable per_backend, all_backends;
    per_backend.per_backend["box2d"]["energy_drift"] = own;
    all_backends.all_backends["energy_drift"] = own;
    for (const ToleranceTable& suite : {per_backend, all_backends}) {
        const CheckResult kept = judged_case(lossy, s, "box2d", "energy_drift", suite);
        EXPECT_EQ(kept.tolerance, own);
        EXPECT_EQ(kept.status, CheckStatus::pass) << kept.detail;
    }
    const CheckResult rounding = judged_case(lossy, s, "box2d", "energy_drift");  // no suite limit
    EXPECT_LT(rounding.tolerance, 1e-5);
    EXPECT_EQ(rounding.status, CheckStatus::fail) << rounding.detail;
}

TEST(EveryCheckCanFail, EveryCheckOfTheTableHasAFaultCase) {
    std::set<std::string> covered;
    for (const FaultCase& f : fault_cases()) covered.insert(f.check);
    for (const CheckDefinition& c : check_table) EXPECT_TRUE(covered.count(c.name)) << "no fault case for " << c.name;
}

}  // namespace
}  // namespace collide::validation
