// Published finite-N rows (validation/compare/published_rows.h): the reference files li_2022.toml
// and engel_2013.toml read with their N and box, a malformed row refused with its key named, the
// inverse-variance pooling by hand, and the rows judged from synthesized case results with the
// pressure counters the runs record (beta_pressure, beta_pressure_error, psi6_mixed, ...):
// a pass, a pressure 10 standard errors off, an error bar too wide, a run that has not mixed, a
// backend without the counters, a scene that is not the published system, and the suite key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/scene/scene_loader.h"
#include "test_backends.h"
#include "tests/support/test_scenes.h"
#include "validation/compare/published_rows.h"
#include "validation/judge/statistics.h"
#include "validation/plan/suite.h"

namespace collide::validation {
namespace {

std::string references() { return std::string(COLLIDE_SOURCE_DIR) + "/data/references"; }

TEST(PublishedFiniteN, LiAndEngelRowsStateTheirNAndBox) {
    const PublishedReference li = load_reference(references(), "li_2022");
    EXPECT_EQ(li.quantity, "beta_pressure_d2");
    EXPECT_EQ(li.finite_n.size(), 26u);
    const FiniteNPoint& p = li.finite_n_point("N72_crystal_0.670");
    EXPECT_EQ(p.disks, 72);
    EXPECT_DOUBLE_EQ(p.beta_pressure_d2, 7.82314);
    EXPECT_DOUBLE_EQ(p.standard_error, 0.00025);
    EXPECT_NEAR(p.aspect_ratio, 8 * std::sqrt(3.0) / 2 / 9, 1e-15);
    EXPECT_EQ(p.boundary, "periodic");
    EXPECT_EQ(li.finite_n_point("N870_crystal_0.670").beta_pressure_d2, 7.986735);
    const FiniteNPoint& square224 = li.finite_n_point("N224_square_0.670");   // ThisWork.csv, N = 224, (1 : 1)
    EXPECT_EQ(square224.disks, 224);
    EXPECT_DOUBLE_EQ(square224.beta_pressure_d2, 7.979479);
    EXPECT_DOUBLE_EQ(square224.standard_error, 0.000058);
    EXPECT_EQ(square224.aspect_ratio, 1.0);
    EXPECT_FALSE(li.text("provenance").find("ThisWork.csv") == std::string::npos);
    try {
        li.finite_n_point("N72_crystal_0.671");
        ADD_FAILURE() << "found a row that does not exist";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("li_2022.toml"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("N72_crystal_0.670"), std::string::npos) << "lists the ids: " << e.what();
    }
    const PublishedReference engel = load_reference(references(), "engel_2013");
    ASSERT_EQ(engel.finite_n.size(), 13u);
    EXPECT_EQ(engel.finite_n_point("N1048576_square_0.698_MPMC").disks, 1024 * 1024);
    EXPECT_EQ(engel.finite_n_point("N65536_square_0.698_EDMD").method, "EDMD");
}

// A reference file with one [[rows]] table whose `body` is given; the loader's error message.
std::string load_error(const std::string& body) {
    const auto dir = test::fresh_output_dir("bad_finite_n");
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/bad.toml") << "name = \"x\"\ncitation = \"y\"\nquantity = \"beta_pressure_d2\"\n[[rows]]\n" << body;
    try {
        load_reference(dir, "bad");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

const char* good_row =
    "id = \"a\"\ndisks = 72\nbox = \"1 : 1\"\naspect_ratio = 1.0\nboundary = \"periodic\"\neta = 0.67\n"
    "beta_pressure_d2 = 7.9\nstandard_error = 0.001\n";

TEST(PublishedFiniteN, AMalformedRowIsRefusedWithItsKeyNamed) {
    EXPECT_EQ(load_error(good_row), "");
    auto with = [](const std::string& from, const std::string& to) {
        std::string row = good_row;
        row.replace(row.find(from), from.size(), to);
        return row;
    };
    const std::string missing = load_error(with("standard_error = 0.001\n", ""));
    EXPECT_NE(missing.find("bad.toml"), std::string::npos) << missing;
    EXPECT_NE(missing.find("rows[0].standard_error"), std::string::npos) << missing;
    const std::string zero_n = load_error(with("disks = 72", "disks = 0"));
    EXPECT_NE(zero_n.find("bad.toml:6"), std::string::npos) << "the line of the key: " << zero_n;
    EXPECT_NE(zero_n.find("rows[0].disks"), std::string::npos) << zero_n;
    EXPECT_NE(load_error(with("eta = 0.67", "eta = 0.95")).find("rows[0].eta"), std::string::npos);
    EXPECT_NE(load_error(with("boundary = \"periodic\"", "boundary = \"round\"")).find("rows[0].boundary"), std::string::npos);
    EXPECT_NE(load_error(with("beta_pressure_d2 = 7.9", "beta_pressure_d2 = \"7.9\"")).find("rows[0].beta_pressure_d2"),
              std::string::npos);
    EXPECT_NE(load_error(with("box = ", "shape = ")).find("rows[0].shape"), std::string::npos);
    const std::string twice = load_error(std::string(good_row) + "[[rows]]\n" + good_row);
    EXPECT_NE(twice.find("rows[1].id"), std::string::npos) << twice;
}

TEST(PublishedFiniteN, ReplicatesArePooledByInverseVarianceWeights) {
    // w = 100 and 25: mean (100 * 1 + 25 * 2) / 125 = 1.2, se 1 / sqrt(125), chi2 = 0.04 / 0.01 + 0.64 / 0.04.
    const PooledEstimate p = pool_inverse_variance({{1.0, 0.1}, {2.0, 0.2}});
    EXPECT_DOUBLE_EQ(p.mean, 1.2);
    EXPECT_DOUBLE_EQ(p.standard_error, 1 / std::sqrt(125.0));
    EXPECT_NEAR(p.chi2, 4 + 16, 1e-12);
    EXPECT_TRUE(std::isnan(pool_inverse_variance({}).mean));
}

// --- Rows from synthesized case results -----------------------------------------------------

// Li et al.'s N = 72 crystal box at area fraction `eta`.
Scene crystal_72(double eta) {
    Scene scene = load_scene(test::scene_file("physics/li2022_n72_crystal.toml"));
    scene.generators[0].radius = std::sqrt(eta * scene.world.width() * scene.world.height() / (72 * M_PI));
    return scene;
}

Suite published_suite(const Scene& scene, const std::string& published) {
    Suite suite;
    suite.reference_dir = references();
    SuiteScene s;
    s.name = "n72_crystal";
    s.scene = scene;
    s.published = published;
    suite.scenes = {s};
    return suite;
}

CaseResult finished_case(int seed, std::map<std::string, double> counters) {
    CaseResult r;
    r.spec.scene = "n72_crystal";
    r.spec.backend = "event";
    r.spec.seed = std::uint64_t(seed);
    r.spec.id = "n72_crystal__event__seed" + std::to_string(seed);
    r.status = RunStatus::completed;
    r.disks = 72;
    r.counters = std::move(counters);
    return r;
}

// Two replicates at `value` +- `error` each (pooled: value +- error / sqrt 2), with the
// estimate's facts and psi6 mixed unless `mixed` is false.
std::vector<CaseResult> two_replicates(double value, double error, bool mixed = true) {
    std::vector<CaseResult> results;
    for (int seed : {1, 2})
        results.push_back(finished_case(seed, {{"beta_pressure", value}, {"beta_pressure_error", error},
                                               {"beta_pressure_correlation_time", 0.5},
                                               {"beta_pressure_equilibration", 20.0 + seed},
                                               {"beta_pressure_batches", 32}, {"psi6_traversals", mixed ? 7 : 1},
                                               {"psi6_mixed", mixed ? 1 : 0}}));
    return results;
}

PhysicsRow only_row(const Suite& suite, const std::vector<CaseResult>& results) {
    const Scene scene = *suite.scenes[0].scene;
    // Through the physics section's entry point: the hook in compare_with_physics.
    const PhysicsComparison c = compare_with_physics(suite, results, [&](const CaseSpec&) -> const Scene& { return scene; });
    EXPECT_EQ(c.rows.size(), 1u);
    return c.rows.empty() ? PhysicsRow{} : c.rows[0];
}

const Suite& crystal_suite() {
    static const Suite suite = published_suite(crystal_72(0.670), "li_2022:N72_crystal_0.670");
    return suite;
}

TEST(PublishedFiniteN, ARunWithinItsErrorBarsPassesWithItsFacts) {
    // 7.8228 +- 0.0005 / sqrt 2 against 7.82314 +- 0.00025: z = 0.00034 / 0.00043 = 0.79.
    const PhysicsRow row = only_row(crystal_suite(), two_replicates(7.8228, 0.0005));
    EXPECT_EQ(row.row, "published_finite_n");
    EXPECT_EQ(row.verdict, PhysicsVerdict::pass) << row.detail;
    EXPECT_EQ(row.published, "li_2022:N72_crystal_0.670");
    EXPECT_EQ(row.box, "9 : 8 sqrt(3)/2 periodic");
    EXPECT_NEAR(row.standard_error, 0.0005 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(row.score, 0.00034 / std::hypot(0.0005 / std::sqrt(2.0), 0.00025), 1e-9);
    EXPECT_NEAR(row.parameter, 0.670, 1e-12);
    EXPECT_EQ(row.facts.at("disks"), 72);
    EXPECT_EQ(row.facts.at("equilibration"), 21.5);
    EXPECT_EQ(row.facts.at("correlation_time"), 0.5);
    EXPECT_EQ(row.facts.at("mixed"), 1);
    EXPECT_NE(row.detail.find("inverse-variance"), std::string::npos) << row.detail;
}

TEST(PublishedFiniteN, APressureTenErrorsOffFails) {
    const PhysicsRow row = only_row(crystal_suite(), two_replicates(7.82314 + 0.0043, 0.0005));
    EXPECT_EQ(row.verdict, PhysicsVerdict::fail) << row.detail;
    EXPECT_GT(row.score, 9);
}

TEST(PublishedFiniteN, AnErrorBarWiderThanTwoInTenThousandFailsEvenWhenClose) {
    const PhysicsRow row = only_row(crystal_suite(), two_replicates(7.82314, 0.004));  // 3.6e-4 relative pooled
    EXPECT_EQ(row.verdict, PhysicsVerdict::fail) << row.detail;
    EXPECT_LT(row.score, 1);
    EXPECT_NE(row.detail.find("run longer"), std::string::npos) << row.detail;
}

TEST(PublishedFiniteN, ARunWhosePsi6HasNotMixedIsShownNotJudged) {
    const PhysicsRow row = only_row(crystal_suite(), two_replicates(7.9, 0.0005, false));  // far off, but not mixed
    EXPECT_EQ(row.verdict, PhysicsVerdict::shown) << row.detail;
    EXPECT_EQ(row.facts.at("mixed"), 0);
    EXPECT_EQ(row.detail.rfind("not mixed", 0), 0u) << row.detail;
}

TEST(PublishedFiniteN, ABackendWithoutThePressureCountersFails) {
    const PhysicsRow row = only_row(crystal_suite(), {finished_case(1, {}), finished_case(2, {})});
    EXPECT_EQ(row.verdict, PhysicsVerdict::fail);
    EXPECT_NE(row.detail.find("beta_pressure"), std::string::npos) << row.detail;
}

TEST(PublishedFiniteN, ASceneThatIsNotThePublishedSystemFails) {
    // The right pressure, but the scene at eta = 0.650 is held to the 0.670 row.
    const Suite suite = published_suite(crystal_72(0.650), "li_2022:N72_crystal_0.670");
    const PhysicsRow row = only_row(suite, two_replicates(7.82314, 0.0005));
    EXPECT_EQ(row.verdict, PhysicsVerdict::fail);
    EXPECT_NE(row.detail.find("area fraction"), std::string::npos) << row.detail;
    // and the right eta in the wrong box (the square row): the aspect ratio is named.
    const PhysicsRow box = only_row(published_suite(crystal_72(0.670), "li_2022:N72_square_0.670"),
                                    two_replicates(7.85637, 0.0005));
    EXPECT_EQ(box.verdict, PhysicsVerdict::fail);
    EXPECT_NE(box.detail.find("height / width"), std::string::npos) << box.detail;
}

// --- Two routes on one point: `event` and a sampler ----------------------------------------

// The replicates of `two_replicates`, run by `backend`.
std::vector<CaseResult> by_backend(std::vector<CaseResult> results, const std::string& backend) {
    for (CaseResult& r : results) {
        r.spec.backend = backend;
        r.spec.id = "n72_crystal__" + backend + "__seed" + std::to_string(r.spec.seed);
    }
    return results;
}

std::vector<PhysicsRow> rows_of(const Suite& suite, const std::vector<CaseResult>& results) {
    const Scene scene = *suite.scenes[0].scene;
    return compare_with_physics(suite, results, [&](const CaseSpec&) -> const Scene& { return scene; }).rows;
}

const PhysicsRow& row_of(const std::vector<PhysicsRow>& rows, const std::string& kind, const std::string& backend) {
    for (const PhysicsRow& r : rows)
        if (r.row == kind && r.backend == backend) return r;
    throw std::runtime_error("no " + kind + " row of " + backend);
}

std::vector<CaseResult> event_and_ecmc(double event, double ecmc, double ecmc_error) {
    std::vector<CaseResult> results = two_replicates(event, 0.0005);
    for (CaseResult& r : by_backend(two_replicates(ecmc, ecmc_error), "ecmc")) {
        r.counters["lifts"] = 1e8;  // what event chains record
        results.push_back(r);
    }
    return results;
}

TEST(PublishedFiniteN, EachRouteNamesTheEstimatorItsCasesRecorded) {
    const std::vector<PhysicsRow> rows = rows_of(crystal_suite(), event_and_ecmc(7.8228, 7.8236, 0.0008));
    EXPECT_NE(row_of(rows, "published_finite_n", "ecmc").estimator.find("lifts"), std::string::npos);
    std::vector<CaseResult> results = two_replicates(7.8228, 0.0005);
    for (CaseResult& r : by_backend(two_replicates(7.8228, 0.002), "metropolis")) {
        r.counters["contact_window"] = 0.043;
        results.push_back(r);
    }
    const std::vector<PhysicsRow> with_metropolis = rows_of(crystal_suite(), results);  // kept: the row refers into it
    const PhysicsRow& metropolis = row_of(with_metropolis, "published_finite_n", "metropolis");
    EXPECT_NE(metropolis.estimator.find("pair-gap histogram"), std::string::npos) << metropolis.estimator;
    EXPECT_NE(metropolis.estimator.find("0.043"), std::string::npos) << metropolis.estimator;
}

TEST(PublishedFiniteN, TheRoutesRowHoldsEcmcToEventOnTheirDifference) {
    // ecmc 7.8236 +- 0.0008 / sqrt 2 against event 7.8228 +- 0.0005 / sqrt 2: z = 0.0008 / 0.000667 = 1.2.
    const std::vector<PhysicsRow> rows = rows_of(crystal_suite(), event_and_ecmc(7.8228, 7.8236, 0.0008));
    ASSERT_EQ(rows.size(), 3u);  // event's and ecmc's published rows, and event vs ecmc
    const PhysicsRow& routes = row_of(rows, "routes_agree", "ecmc");
    EXPECT_EQ(routes.verdict, PhysicsVerdict::pass) << routes.detail;
    EXPECT_NEAR(routes.reference, 7.8228, 1e-12);
    EXPECT_NEAR(routes.score, 0.0008 / std::hypot(0.0008, 0.0005) * std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(routes.score_from.value - routes.score_from.reference, 0.0008, 1e-12);
    EXPECT_EQ(routes.published, "li_2022:N72_crystal_0.670");
    // Each route names its estimator, read from what the cases recorded.
    EXPECT_NE(row_of(rows, "published_finite_n", "event").estimator.find("collision virial"), std::string::npos);
    // Ten combined errors apart, each still within 3 of the published value's wide bar: the routes row fails.
    const std::vector<PhysicsRow> apart = rows_of(crystal_suite(), event_and_ecmc(7.8228, 7.8228 + 0.0067, 0.0008));
    EXPECT_EQ(row_of(apart, "routes_agree", "ecmc").verdict, PhysicsVerdict::fail);
    EXPECT_GT(row_of(apart, "routes_agree", "ecmc").score, 9);
}

TEST(PublishedFiniteN, ARouteThatHasNotMixedIsShownNotJudged) {
    std::vector<CaseResult> results = two_replicates(7.8228, 0.0005);
    for (CaseResult& r : by_backend(two_replicates(7.9, 0.0005, false), "ecmc")) results.push_back(r);
    EXPECT_EQ(row_of(rows_of(crystal_suite(), results), "routes_agree", "ecmc").verdict, PhysicsVerdict::shown);
}

TEST(PublishedFiniteN, ABackendIsHeldToThePrecisionTheSuiteNamesForIt) {
    // 3.6e-4 relative pooled: above event's 2e-4, within the 5e-4 the suite asks of ecmc.
    Suite suite = crystal_suite();
    suite.published_precision["ecmc"] = 5e-4;
    std::vector<CaseResult> results = two_replicates(7.82314, 0.004);
    for (CaseResult& r : by_backend(two_replicates(7.82314, 0.004), "ecmc")) results.push_back(r);
    const std::vector<PhysicsRow> rows = rows_of(suite, results);
    EXPECT_EQ(row_of(rows, "published_finite_n", "event").verdict, PhysicsVerdict::fail);
    EXPECT_EQ(row_of(rows, "published_finite_n", "ecmc").verdict, PhysicsVerdict::pass) << row_of(rows, "published_finite_n", "ecmc").detail;
    EXPECT_EQ(row_of(rows, "published_finite_n", "ecmc").facts.at("relative_error_max"), 5e-4);
}

// A suite's `published` key is checked when the suite is read: a row that does not exist stops it.
std::string suite_error(const std::string& published) {
    const std::string text = "reference_dir = \"" + references() + "\"\n[[scene]]\npath = \"" +
                             test::scene_file("physics/li2022_n72_crystal.toml") +
                             "\"\nbackends = [\"event\"]\npublished = \"" + published + "\"\n";
    try {
        const Suite s = parse_suite(text, "physics.toml", "/");
        EXPECT_EQ(s.scenes[0].published, published);
    } catch (const SuiteError& e) {
        return e.what();
    }
    return "";
}

std::string precision_error(const std::string& table) {
    const std::string text = "reference_dir = \"" + references() + "\"\nbackends = [\"event\"]\n" + table + "\n[[scene]]\npath = \"" +
                             test::scene_file("physics/li2022_n72_crystal.toml") +
                             "\"\nbackends = [\"event\", \"ecmc\"]\n";
    try {
        EXPECT_EQ(parse_suite(text, "physics.toml", "/").published_precision.at("ecmc"), 5e-4);
    } catch (const SuiteError& e) {
        return e.what();
    }
    return "";
}

TEST(PublishedFiniteN, ThePrecisionTableNamesBackendsTheSuiteRuns) {
    EXPECT_EQ(precision_error("[published_precision]\necmc = 5e-4"), "");
    const std::string typo = precision_error("[published_precision]\necmx = 5e-4");
    EXPECT_NE(typo.find("published_precision.ecmx"), std::string::npos) << typo;
    EXPECT_NE(typo.find("no [[scene]] runs ecmx"), std::string::npos) << typo;
    EXPECT_NE(precision_error("[published_precision]\necmc = 2").find("(0, 1)"), std::string::npos);
    EXPECT_NE(precision_error("published_precision = 5e-4").find("a table"), std::string::npos);
}

TEST(PublishedFiniteN, TheSuiteKeyNamesAnExistingRow) {
    EXPECT_EQ(suite_error("li_2022:N72_crystal_0.670"), "");
    EXPECT_NE(suite_error("li_2022:N72_crystal_0.671").find("published"), std::string::npos);
    EXPECT_NE(suite_error("li_2022").find("KEY:ID"), std::string::npos);
    EXPECT_NE(suite_error("kolafa_rottner_2006:x").find("beta_pressure_d2"), std::string::npos);
}

}  // namespace
}  // namespace collide::validation
