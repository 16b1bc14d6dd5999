// "Reference against physics" (validation/compare/physics_rows.h): the published references read from
// data/references, each row's computation against a hand-worked example, and injected errors
// (pressure scaled by 1.01, one collision in a thousand dropped, restitution 0.999 where 1 is
// claimed) that must make the right row fail while the exact solver passes.
#include <gtest/gtest.h>
#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "core/metrics.h"
#include "core/scene/scene_loader.h"
#include "core/thermo/kinetic_temperature.h"
#include "core/thermo/velocity_sphere.h"
#include "reference/event/event_solver.h"
#include "test_backends.h"
#include "tests/support/test_scenes.h"
#include "validation/compare/physics_rows.h"
#include "validation/judge/statistics.h"
#include "validation/suite_runner.h"

namespace collide::validation {
namespace {

std::string references() { return std::string(COLLIDE_SOURCE_DIR) + "/data/references"; }

// Taylor coefficient of eta^k in Z(eta) = sum c eta^a (1 - eta)^-b: c binom(k - a + b - 1, k - a).
double virial_coefficient(const PublishedReference& eos, int k) {
    double sum = 0;
    for (const EquationOfStateTerm& t : eos.terms) {
        if (k < t.eta_power) continue;
        const int n = k - t.eta_power;  // coefficient of x^n in (1 - x)^-b
        double binom = t.one_minus_eta_power == 0 ? (n == 0 ? 1 : 0) : 1;
        for (int i = 1; i <= n && t.one_minus_eta_power > 0; ++i) binom *= double(t.one_minus_eta_power - 1 + i) / i;
        sum += t.coefficient * binom;
    }
    return sum;
}

TEST(PublishedReference, KolafaRottnerHasTheExactVirialCoefficientsAndItsTableValue) {
    const PublishedReference kr = load_reference(references(), "kolafa_rottner_2006");
    EXPECT_EQ(virial_coefficient(kr, 0), 1.0);
    EXPECT_NEAR(virial_coefficient(kr, 1), 2.0, 1e-12);                                   // B2 = 2 (in eta)
    EXPECT_NEAR(virial_coefficient(kr, 2), 4 * (4.0 / 3 - std::sqrt(3.0) / M_PI), 1e-6);  // B3, exact
    EXPECT_NEAR(virial_coefficient(kr, 3), 4.257854, 1e-5);                              // B4
    EXPECT_NEAR(compressibility_factor(kr, M_PI * 0.80 / 4), 7.476491, 1e-5 * 7.476491);  // Table 1, rho = 0.80
    EXPECT_THROW(compressibility_factor(kr, 0.75), std::runtime_error);                   // beyond the fit
}

TEST(PublishedReference, HendersonDiffersFromKolafaRottnerByTwoPercentAtSixtyFive) {
    const PublishedReference h = load_reference(references(), "henderson_1975");
    const PublishedReference kr = load_reference(references(), "kolafa_rottner_2006");
    EXPECT_NEAR(compressibility_factor(h, 0.5), (1 + 0.25 / 8) / 0.25, 1e-12);
    const double ratio = compressibility_factor(h, 0.65) / compressibility_factor(kr, 0.65);
    EXPECT_GT(ratio, 1.015);
    EXPECT_LT(ratio, 1.03);
}

TEST(PublishedReference, BadFilesNameTheFileAndTheKey) {
    EXPECT_THROW(load_reference(references(), "no_such_reference"), std::runtime_error);
    const auto dir = test::fresh_output_dir("bad_reference");
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/bad.toml") << "name = \"x\"\ncitation = \"y\"\nquantity = \"compressibility_factor\"\n"
                                        "terms = [ { coefficient = 1.0, eta_power = -1, one_minus_eta_power = 0 } ]\n";
    try {
        load_reference(dir, "bad");
        ADD_FAILURE() << "accepted a negative power";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.toml:4"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("eta_power"), std::string::npos) << e.what();
    }
}

TEST(PhysicsRows, EnskogRateAndContactValueByHand) {
    // Z = 3 at eta = 0.5: g = (3 - 1) / (2 * 0.5) = 2; nu = 2 * 0.25 * 2 * 2 * sqrt(pi * 0.5).
    EXPECT_DOUBLE_EQ(contact_value(3.0, 0.5), 2.0);
    EXPECT_NEAR(enskog_collision_rate(0.25, 2.0, 2.0, 0.5), 2.0 * std::sqrt(M_PI * 0.5), 1e-14);
}

TEST(PhysicsRows, VirialCompressibilityAndRatesByHand) {
    CaseResult r;
    r.disks = 10;
    r.total_mass = 10;
    r.duration = 4;
    r.contacts = 300;
    for (int k = 0; k <= 4; ++k) {  // K0 = 5 sets kT, whatever K does later
        Metrics m;
        m.time = k;
        m.kinetic_energy = 5 - k;
        r.series.push_back(m);
    }
    r.counters = {{"virial_sum", 100.0}, {"virial_sum_at_half", 40.0}, {"contacts_at_half", 100.0}, {"time_at_half", 2.0}};
    // W = (100 - 40) / (2 * 2) = 15. Walls: Z = 1 + W / K = 4. Periodic (N - 1 = 9 degrees of
    // freedom): Z = 1 + (9 / 10) W / K_int = 3.7 (before issue 47 both read 4: kT = K / N).
    EXPECT_DOUBLE_EQ(virial_compressibility(r, case_temperature(r, 10, false)), 4.0);
    EXPECT_DOUBLE_EQ(virial_compressibility(r, case_temperature(r, 10, true)), 3.7);
    // nu = 2 * (300 - 100) / (10 * 2) = 20.
    EXPECT_DOUBLE_EQ(second_half_collision_rate(r), 20.0);
}

// Moving the centre of mass of a periodic gas adds |P|^2 / (2 M) to K and nothing to K_int,
// the heat: Z, Haff's tau and the scaled speeds read the same temperature as before.
TEST(PhysicsRows, ACentreOfMassDriftChangesNoEstimatorByHand) {
    CaseResult r;
    r.total_mass = 10;
    r.duration = 4;
    r.counters = {{"virial_sum", 100.0}, {"virial_sum_at_half", 40.0}, {"time_at_half", 2.0}};
    for (int i = 0; i <= 20; ++i) {
        Metrics m;
        m.time = i;
        m.kinetic_energy = 100.0 / std::pow(1 + i / 8.0, 2);  // K_int, tau = 8
        r.series.push_back(m);
    }
    const double z = virial_compressibility(r, case_temperature(r, 10, true));
    const double tau = haff_cooling_time(r, 20, 10, true);
    CaseResult drifting = r;
    for (Metrics& m : drifting.series) {  // P = M V with V = (3, -4): K grows by M |V|^2 / 2 = 125
        m.momentum_x = 30, m.momentum_y = -40;
        m.kinetic_energy += 125;
    }
    EXPECT_NEAR(virial_compressibility(drifting, case_temperature(drifting, 10, true)), z, 1e-12);
    EXPECT_NEAR(haff_cooling_time(drifting, 20, 10, true), tau, 1e-9);
    EXPECT_NEAR(tau, 8.0, 1e-9);

    Snapshot s;
    s.vx = {1, -1, 0.5, -0.5}, s.vy = {0.2, 0.3, -0.1, -0.4};
    const std::vector<double> u = scaled_speeds(s, 2.0, true);
    for (double& v : s.vx) v += 3;
    for (double& v : s.vy) v -= 4;
    const std::vector<double> moved = scaled_speeds(s, 2.0, true);
    for (std::size_t i = 0; i < u.size(); ++i) EXPECT_NEAR(moved[i], u[i], 1e-12);
}

TEST(PhysicsRows, HaffFitRecoversTheCoolingTime) {
    CaseResult r;
    for (int i = 0; i <= 20; ++i) {
        Metrics m;
        m.time = i;
        m.kinetic_energy = 100.0 / std::pow(1 + i / 8.0, 2);  // T0 / (1 + t/tau)^2, tau = 8
        r.series.push_back(m);
    }
    EXPECT_NEAR(haff_cooling_time(r, 20, 10, false), 8.0, 1e-9);
    EXPECT_TRUE(std::isnan(haff_cooling_time(r, 1, 10, false)));  // two points only
}

// The smallest periodic gas, two disks, is exactly solvable: their relative position is
// uniform over the box less one excluded disk of radius sigma (the uniform configurational
// measure of hard disks; the box is wider than 2 sigma, so one image at most is excluded).
// With Q(A) = A (A - pi sigma^2): beta P A = A d ln Q / dA = 2 + pi sigma^2 / (A - pi sigma^2),
//     Z = 1 + pi sigma^2 / (2 (A - pi sigma^2)),
// and the relative motion is a Sinai billiard at fixed speed (ergodic), colliding
// 2 s sigma / (A - pi sigma^2) times per unit time (Santalo's mean free path pi A_free / perimeter).
// The estimator of pressure_estimator.h must give this Z; without its (N - 1) / N factor it
// would read 2 (Z - 1) too high, and with kT = K / N (the drift of the centre of mass counted as
// heat) lower still. Enskog's rate at this N (g(sigma) = A / (2 (A - pi sigma^2)), the pair
// density of the uniform measure) needs the velocity sphere's factor 2 / sqrt(pi) = 1.128.
TEST(PhysicsRows, TwoDisksInAPeriodicBoxGiveTheExactPressureAndCollisionRate) {
    const double side = 5, sigma = 1, duration = 1e6;
    Scene scene = test::box_scene(side, side, Boundary::periodic);
    ParticleGenerator g;
    g.kind = "list";
    g.disks = {{1.0, 1.0, 0.3, 0.7, sigma / 2, 1.0, false}, {3.2, 2.9, -0.6, 0.1, sigma / 2, 1.0, false}};
    scene.generators = {g};
    scene.run.duration = duration;
    const ParticleState<double> initial = generate_initial_state(scene);
    EventSolver solver;
    solver.load(scene, initial);
    solver.advance_to(duration);

    CaseResult r;
    r.total_mass = 2;
    r.duration = duration;
    r.contacts = solver.stats().contacts;
    r.counters = {{"virial_sum", solver.stats().counters.at("virial_sum")}, {"virial_sum_at_half", 0.0},
                  {"contacts_at_half", 0.0}, {"time_at_half", 0.0}};
    r.series = {compute_metrics(scene, initial, 0)};  // drifting: total momentum (-0.3, 0.8)
    const KineticTemperature t = case_temperature(r, 2, true);
    const double area = side * side, excluded = M_PI * sigma * sigma;
    EXPECT_GT(r.contacts, 90000);
    EXPECT_NEAR(virial_compressibility(r, t), 1 + excluded / (2 * (area - excluded)), 1e-3);

    const double speed = std::hypot(0.3 + 0.6, 0.7 - 0.1);
    const double rate = second_half_collision_rate(r);  // per disk: 2 collisions / (2 disks t)
    EXPECT_NEAR(rate, 2 * speed * sigma / (area - excluded), 0.01 * rate);
    const double g_contact = area / (2 * (area - excluded));
    const double enskog = enskog_collision_rate(2 / area, sigma, g_contact, t.kT() / 1.0);
    EXPECT_NEAR(rate, enskog * collision_rate_finite_n_factor(t.degrees_of_freedom), 0.01 * rate);
}

TEST(PhysicsRows, ChiSquareAcceptsRayleighAndRejectsOneSpeed) {
    std::vector<double> rayleigh, one_speed(4000, std::sqrt(2.0));
    for (int i = 0; i < 4000; ++i) rayleigh.push_back(std::sqrt(-2 * std::log(1 - (i + 0.5) / 4000)));  // quantiles
    EXPECT_GT(maxwell_boltzmann_chi_square(rayleigh, 20).p_value, 0.99);
    EXPECT_LT(maxwell_boltzmann_chi_square(one_speed, 20).p_value, 1e-10);
    EXPECT_EQ(maxwell_boltzmann_chi_square(rayleigh, 20).dof, 18);
}

// --- The rows on real runs of `event`, and with injected errors ---------------------------

enum class Injected { none, virial_times_1_01, drop_one_in_a_thousand, centre_of_mass_moving };

// The velocity added to every disk by Injected::centre_of_mass_moving: its kinetic energy per
// unit mass, |V|^2 / 2 = 1.04, about kT / m of the fluid scene, so K about doubles and K_int stays.
constexpr double drift_x = 1.2, drift_y = -0.8;

// `event` reporting its statistics with one injected error.
class FaultyEvent : public Solver {
public:
    explicit FaultyEvent(Injected fault) : fault_(fault) {}
    std::string name() const override { return "event"; }
    void load(const Scene& s, const ParticleState<double>& initial) override {
        ParticleState<double> state = initial;
        if (fault_ == Injected::centre_of_mass_moving)
            for (std::size_t i = 0; i < state.size(); ++i) state.vx[i] += drift_x, state.vy[i] += drift_y;
        solver_.load(s, state);
    }
    void advance_to(double t) override { solver_.advance_to(t); }
    void read_state(ParticleState<double>& out) const override { solver_.read_state(out); }
    double time() const override { return solver_.time(); }
    SolverStats stats() const override {
        SolverStats s = solver_.stats();
        if (fault_ == Injected::virial_times_1_01) s.counters["virial_sum"] *= 1.01;
        if (fault_ == Injected::drop_one_in_a_thousand) s.contacts -= s.contacts / 1000;
        return s;
    }

private:
    EventSolver solver_;
    Injected fault_;
};

BackendInfo event_backend(Injected fault) {
    BackendInfo b;
    b.name = "event";
    b.precision = "double";
    b.supports = [](const Scene&) { return std::optional<std::string>(); };
    b.create = [fault](const BackendOptions&) { return std::make_unique<FaultyEvent>(fault); };
    return b;
}

SuiteScene physics_scene(const std::string& file, std::vector<std::string> rows, SceneParameter set) {
    SuiteScene s;
    s.name = file;
    s.path = test::scene_file("physics/" + file + ".toml");
    s.physics = std::move(rows);
    s.set = {std::move(set)};
    return s;
}

std::vector<PhysicsRow> run_rows(Suite suite, Injected fault, const std::string& name) {
    suite.name = name;
    suite.source_path = "test-physics";
    suite.reference_dir = references();
    suite.backends = {"event"};
    suite.warmup_fraction = 0;
    suite.output.hdf5 = false;
    suite.time_limit_seconds = 60;
    RunnerOptions options;
    options.output_dir = test::fresh_output_dir(name);
    options.jobs = 2;
    return run_suite(suite, {event_backend(fault)}, options).physics.rows;
}

const PhysicsRow& only_row(const std::vector<PhysicsRow>& rows, const std::string& kind, double parameter) {
    for (const PhysicsRow& r : rows)
        if (r.row == kind && std::abs(r.parameter - parameter) <= 1e-6 * parameter) return r;
    throw std::runtime_error("no row " + kind);
}

Suite fluid_suite() {
    Suite suite;
    suite.seeds = {1, 2, 3};
    // eta = 0.6 (the radius), 24 time units: Z to about 0.1 %.
    suite.scenes = {physics_scene("hard_disk_fluid", {"equation_of_state", "collision_rate"},
                                  {"particles.0.radius", {0.416378530658203}})};
    suite.scenes[0].duration = 24;
    return suite;
}

TEST(PhysicsRows, EventPassesTheFluidRowsAndAPressureScaledByOnePercentFails) {
    const auto good = run_rows(fluid_suite(), Injected::none, "physics_fluid");
    const PhysicsRow& z = only_row(good, "equation_of_state", 0.6);
    EXPECT_EQ(z.verdict, PhysicsVerdict::pass) << z.value << " +- " << z.standard_error << " vs " << z.reference;
    EXPECT_EQ(z.estimator, "collision virial, batch means per replicate, pooled by inverse variance");
    EXPECT_EQ(z.score_from.degrees_of_freedom, 0);
    EXPECT_TRUE(z.resolved) << "at 0.6 Henderson is 1.2 % above Kolafa & Rottner";
    EXPECT_EQ(only_row(good, "collision_rate", 0.6).verdict, PhysicsVerdict::pass);

    const auto bad = run_rows(fluid_suite(), Injected::virial_times_1_01, "physics_fluid_bad");
    const PhysicsRow& zb = only_row(bad, "equation_of_state", 0.6);
    EXPECT_EQ(zb.verdict, PhysicsVerdict::fail) << zb.value << " +- " << zb.standard_error << " vs " << zb.reference;
    EXPECT_GT(zb.score, physics_z_max);
}

// Galilean invariance: a periodic fluid whose centre of mass moves (all disks given the same
// extra velocity) has the same pressure, collision rate and speed distribution in its rest
// frame. Before the rows read K_int, the drift was counted as heat and Z - 1 read half its value.
TEST(PhysicsRows, MovingTheCentreOfMassOfTheFluidChangesNoRow) {
    Suite suite = fluid_suite();
    suite.scenes[0].physics = {"equation_of_state", "collision_rate", "speed_distribution"};
    const auto rest = run_rows(suite, Injected::none, "physics_fluid_rest");
    const auto moving = run_rows(suite, Injected::centre_of_mass_moving, "physics_fluid_moving");
    for (const char* kind : {"equation_of_state", "collision_rate"}) {
        const PhysicsRow& a = only_row(rest, kind, 0.6);
        const PhysicsRow& b = only_row(moving, kind, 0.6);
        EXPECT_LE(std::abs(a.value - b.value), 3 * std::hypot(a.standard_error, b.standard_error))
            << kind << ": " << a.value << " +- " << a.standard_error << " at rest, " << b.value << " +- "
            << b.standard_error << " moving";
        EXPECT_EQ(b.verdict, PhysicsVerdict::pass) << kind;
    }
    const auto speeds = std::find_if(moving.begin(), moving.end(), [](const PhysicsRow& r) { return r.row == "speed_distribution"; });
    ASSERT_NE(speeds, moving.end());
    EXPECT_EQ(speeds->verdict, PhysicsVerdict::pass) << speeds->detail;
}

Suite billiard_suite() {
    Suite suite;
    suite.seeds = {1};
    suite.scenes = {physics_scene("pi_billiard", {"galperin"}, {"particles.0.disks.1.mass", {1e6}})};
    return suite;
}

TEST(PhysicsRows, GalperinCountsPiAndCatchesOneCollisionInAThousandDropped) {
    const auto good = run_rows(billiard_suite(), Injected::none, "physics_pi");
    EXPECT_EQ(only_row(good, "galperin", 1e6).value, 3141);
    EXPECT_EQ(only_row(good, "galperin", 1e6).verdict, PhysicsVerdict::pass);

    const auto dropped = run_rows(billiard_suite(), Injected::drop_one_in_a_thousand, "physics_pi_drop");
    EXPECT_EQ(only_row(dropped, "galperin", 1e6).verdict, PhysicsVerdict::fail);

}

// A solver that loses 0.1 % of the normal relative speed's energy where e = 1 is claimed: the
// gas cools, and Z measured against the conserved energy's kT reads low. (Galperin's count
// does not see it: at mass ratio 1e6 and e = 0.999 it is still 3141.)
TEST(PhysicsRows, RestitutionBelowOneWhereOneIsClaimedFailsTheEquationOfState) {
    Suite suite = fluid_suite();
    suite.scenes[0].set.push_back({"physics.restitution", {0.999}});
    const auto lossy = run_rows(suite, Injected::none, "physics_fluid_lossy");
    const PhysicsRow& z = only_row(lossy, "equation_of_state", 0.6);
    EXPECT_EQ(z.verdict, PhysicsVerdict::fail) << z.value << " +- " << z.standard_error << " vs " << z.reference;
}

// --- The statistics a row is judged by, on synthesized results ------------------------------

// Student's t on 3 dof against the normal: Q_t3(3) = 0.0288 (two-sided 5.8 %, against 0.27 % for
// a normal z of 3), whose normal quantile is 1.899; a normal score stays itself (dof 0).
TEST(PhysicsRows, StudentTConvertsToTheNormalScoreOfEqualTailByHand) {
    // Q_t3(t) = 1/2 - (1/pi) (atan(t / sqrt 3) + sqrt(3) t / (t^2 + 3)), closed form for 3 dof.
    const double t = 3, q = 0.5 - (std::atan(t / std::sqrt(3.0)) + std::sqrt(3.0) * t / (t * t + 3)) / M_PI;
    EXPECT_NEAR(q, 0.02883, 1e-5);
    EXPECT_NEAR(gsl_cdf_ugaussian_Q(normal_equivalent_of_t(t, 3)), q, 1e-12);  // the same upper tail
    EXPECT_NEAR(normal_equivalent_of_t(t, 3), 1.8986, 1e-3);
    EXPECT_DOUBLE_EQ(normal_equivalent_of_t(-2.5, 0), 2.5);
    EXPECT_NEAR(normal_equivalent_of_t(3, 1e6), 3, 1e-4);
    // t's heavy tail: t = 60 on 3 dof is as rare as a normal 4.41, not 60.
    const double far = 60, q_far = 0.5 - (std::atan(far / std::sqrt(3.0)) + std::sqrt(3.0) * far / (far * far + 3)) / M_PI;
    EXPECT_NEAR(gsl_cdf_ugaussian_Q(normal_equivalent_of_t(far, 3)), q_far, 1e-3 * q_far);
}

// Four replicates of the fluid whose second-half virial scatters wildly (Z 1 and 20), while each
// replicate's pressure record (beta_pressure +- beta_pressure_error, batch means) and
// collision-rate record sit on the references within their errors: the rows must judge the
// pooled records (pass, dof 0) and print the numbers z recomputes from.
TEST(PhysicsRows, TheRowsJudgeEachReplicatesBatchMeansPooledByInverseVariance) {
    Suite suite;
    suite.reference_dir = references();
    suite.scenes = {physics_scene("hard_disk_fluid", {"equation_of_state", "collision_rate"},
                                  {"particles.0.radius", {0.416378530658203}})};
    const Scene scene = load_scene(suite.scenes[0].path);
    const ParticleState<double> initial = generate_initial_state(scene);
    const double area = scene.world.width() * scene.world.height(), sigma = 2 * initial.radius[0];
    const double rho_d2 = double(initial.size()) / area * sigma * sigma, eta = rho_d2 * M_PI / 4;
    const PublishedReference kr = load_reference(references(), "kolafa_rottner_2006");
    const double z_ref = compressibility_factor(kr, eta);
    // The collision rate the row predicts at the initial state's temperature.
    const KineticTemperature kt = kinetic_temperature(scene, initial);
    const double nu_ref = enskog_collision_rate(double(initial.size()) / area, sigma,
                                                contact_value(z_ref, eta), kt.kT() / initial.mass[0]) *
                          collision_rate_finite_n_factor(kt.degrees_of_freedom);
    std::vector<CaseResult> results(4);
    const double offsets[] = {+1, -1, +0.5, -0.5};  // in units of each replicate's own error
    for (std::size_t k = 0; k < results.size(); ++k) {
        CaseResult& r = results[k];
        r.spec.scene = "hard_disk_fluid", r.spec.backend = "event", r.spec.seed = k + 1, r.spec.id = "fluid__seed" + std::to_string(k + 1);
        r.disks = initial.size(), r.duration = 10, r.contacts = 1000 * (k % 2 ? 1 : 20);
        r.total_mass = initial.mass[0] * double(initial.size());
        Metrics m;
        m.kinetic_energy = kt.internal_kinetic_energy;
        r.series = {m};
        r.counters = {{"virial_sum", k % 2 ? 1.0 : 1e6}, {"virial_sum_at_half", 0.0}, {"time_at_half", 5.0}, {"contacts_at_half", 0.0},
                      {"beta_pressure", z_ref * rho_d2 * (1 + 1e-3 * offsets[k])}, {"beta_pressure_error", z_ref * rho_d2 * 1e-3},
                      {"collision_rate_mean", nu_ref * (1 + 2e-3 * offsets[k])}, {"collision_rate_error", nu_ref * 2e-3}};
    }
    const auto rows = compare_with_physics(suite, results, [&](const CaseSpec&) -> const Scene& { return scene; }).rows;
    for (const char* kind : {"equation_of_state", "collision_rate"}) {
        const PhysicsRow& row = only_row(rows, kind, eta);
        EXPECT_EQ(row.verdict, PhysicsVerdict::pass) << kind << " " << row.estimator << ": " << row.score;
        EXPECT_EQ(row.score_from.degrees_of_freedom, 0) << kind;
        EXPECT_NE(row.estimator.find("batch means"), std::string::npos) << row.estimator;
        const auto& f = row.score_from;  // z recomputes from the printed numbers
        EXPECT_NEAR(row.score, std::abs(f.value - f.reference) / std::hypot(f.standard_error, f.reference_uncertainty), 1e-12);
    }
    // Pooled Z: errors equal, so the plain mean of 1 +- 1e-3 offsets {1, -1, 0.5, -0.5} = Z_ref, SE 5e-4 Z_ref.
    const PhysicsRow& z = only_row(rows, "equation_of_state", eta);
    EXPECT_NEAR(z.value, z_ref, 1e-12 * z_ref);
    EXPECT_NEAR(z.standard_error, 5e-4 * z_ref, 1e-12 * z_ref);

    // Without the records, the same results fall back on the replicates' scatter: Student's t.
    for (CaseResult& r : results)
        for (const char* name : {"beta_pressure", "beta_pressure_error", "collision_rate_mean", "collision_rate_error"}) r.counters.erase(name);
    const auto fallback = compare_with_physics(suite, results, [&](const CaseSpec&) -> const Scene& { return scene; }).rows;
    const PhysicsRow& zt = only_row(fallback, "equation_of_state", eta);
    EXPECT_EQ(zt.score_from.degrees_of_freedom, 3);
    EXPECT_NE(zt.estimator.find("Student t"), std::string::npos) << zt.estimator;
    const auto& f = zt.score_from;
    EXPECT_NEAR(zt.score, normal_equivalent_of_t(std::abs(f.value - f.reference) / std::hypot(f.standard_error, f.reference_uncertainty), 3), 1e-12);
}

}  // namespace
}  // namespace collide::validation

namespace collide::validation {
namespace {

// Bonferroni by hand: Q(3) = 1.3499e-3; over 56 rows each row's one-sided tail is 2.4105e-5,
// whose normal quantile is 4.066 (tables of the normal distribution).
TEST(PhysicsRows, FamilyThresholdKeepsOneRowsFalseAlarmRateForTheWholeSuite) {
    EXPECT_DOUBLE_EQ(family_z_max(0), 3.0);
    EXPECT_DOUBLE_EQ(family_z_max(1), 3.0);
    EXPECT_NEAR(family_z_max(56), 4.066, 2e-3);
    EXPECT_GT(family_z_max(10), family_z_max(2));
}

}  // namespace
}  // namespace collide::validation
