// `collide explain` as a user runs it: validate a one-case suite, then name the step of the
// case's largest energy change (the worked example of docs/stepping-rules.md), as text and as
// JSON; and the refusals: an unknown case, the exact solvers, an interval without a whole step,
// a case whose scene file was edited since the run.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "tests/support/program_runner.h"
#include "tests/support/scratch_directory.h"

namespace collide {
namespace {

using test::contains;
using test::run_program;
using test::ScratchDirectory;

// box_gas_1000 on `step` for 1.1 time units, its own reference; validated into DIR/out.
// Returns (output directory, the case's id as summary.json records it).
std::pair<std::string, std::string> validated(const ScratchDirectory& dir) {
    const std::string suite = dir.file("suite.toml");
    test::write_text_file(suite, "name = \"explain\"\nbackends = [\"event\", \"event-plain\", \"step\"]\nreference = \"event\"\nseeds = [1]\n"
                                 "scene_dir = \"" + std::string(COLLIDE_SOURCE_DIR) + "/data/scenes\"\n\n"
                                 "[[scene]]\nname = \"box_gas_1000\"\nduration = 1.1\ndt = [1e-3]\n");
    const auto r = run_program(COLLIDE_EXECUTABLE, {"validate", suite, "--out", dir.file("out")}, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const auto summary = nlohmann::json::parse(test::read_text_file(dir.file("out/summary.json")));
    for (const auto& c : summary.at("cases"))
        if (c.at("backend") == "step") return {dir.file("out"), c.at("id").get<std::string>()};
    ADD_FAILURE() << "no step case in " << dir.file("out/summary.json");
    return {};
}

TEST(ExplainCommand, NamesTheStepTheDisksAndTheKindOfContact) {
    ScratchDirectory dir;
    const auto [out, case_id] = validated(dir);
    const auto text = run_program(COLLIDE_EXECUTABLE, {"explain", out, case_id, "--from", "1.0", "--to", "1.1"}, dir);
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_TRUE(contains(text.out, "step      1035: t = 1.035 -> 1.036")) << text.out;
    EXPECT_TRUE(contains(text.out, "3 disks in contact at once (disk 72 touches 545 and 839)")) << text.out;

    const auto json = run_program(COLLIDE_EXECUTABLE, {"explain", out, case_id, "--json"}, dir);
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const auto found = nlohmann::json::parse(json.out);
    EXPECT_EQ(found.at("case"), case_id);
    const auto& group = found.at("groups").at(0);
    EXPECT_EQ(group.at("kind"), "3 disks in contact at once");
    EXPECT_EQ(group.at("disks").size(), 3u);
    // Its energy change is the step's, to rounding: the other groups of that step are pairs.
    EXPECT_NEAR(group.at("energy_change").get<double>(), found.at("energy_change").get<double>(), 1e-9);
}

TEST(ExplainCommand, RefusesWhatItCannotExplain) {
    ScratchDirectory dir;
    const auto [out, case_id] = validated(dir);
    const auto unknown = run_program(COLLIDE_EXECUTABLE, {"explain", out, "no_such_case"}, dir);
    EXPECT_NE(unknown.exit_code, 0);
    EXPECT_TRUE(contains(unknown.err, "the suite plans no case 'no_such_case'")) << unknown.err;
    const auto reversed = run_program(COLLIDE_EXECUTABLE, {"explain", out, case_id, "--from", "0.5", "--to", "0.4"}, dir);
    EXPECT_NE(reversed.exit_code, 0);
    EXPECT_TRUE(contains(reversed.err, "expected 0 <= from < to")) << reversed.err;
    const auto no_step = run_program(COLLIDE_EXECUTABLE, {"explain", out, case_id, "--from", "0.5", "--to", "0.5004"}, dir);
    EXPECT_NE(no_step.exit_code, 0);
    EXPECT_TRUE(contains(no_step.err, "no whole step of dt = 0.001")) << no_step.err;
    const auto exact = run_program(COLLIDE_EXECUTABLE, {"explain", out, "box_gas_1000__event__seed1"}, dir);
    EXPECT_NE(exact.exit_code, 0);
    EXPECT_TRUE(contains(exact.err, "ran on 'event', which has no time steps")) << exact.err;
    // The rule is the backend's property (BackendInfo::exact), not a list of names.
    const auto plain = run_program(COLLIDE_EXECUTABLE, {"explain", out, "box_gas_1000__event-plain__dt0.001__seed1"}, dir);
    EXPECT_NE(plain.exit_code, 0);
    EXPECT_TRUE(contains(plain.err, "ran on 'event-plain', which has no time steps")) << plain.err;
    const auto missing = run_program(COLLIDE_EXECUTABLE, {"explain", dir.file("nowhere"), case_id}, dir);
    EXPECT_NE(missing.exit_code, 0);
    EXPECT_TRUE(contains(missing.err, "nowhere")) << missing.err;
}

// A scene file edited after the run: the rebuilt case starts elsewhere, and explain refuses to
// replay it under the old id rather than explain another run.
TEST(ExplainCommand, RefusesACaseWhoseFilesChangedSinceTheRun) {
    ScratchDirectory dir;
    std::string scene = test::read_text_file(std::string(COLLIDE_SOURCE_DIR) + "/data/scenes/glancing.toml");
    test::write_text_file(dir.file("glancing.toml"), scene);
    const std::string suite = dir.file("suite.toml");
    test::write_text_file(suite, "name = \"edited\"\nbackends = [\"step\"]\nreference = \"step\"\nseeds = [2]\n"
                                 "[[scene]]\npath = \"glancing.toml\"\ncompare = \"trajectory\"\n");
    ASSERT_EQ(run_program(COLLIDE_EXECUTABLE, {"validate", suite, "--out", dir.file("out")}, dir).exit_code, 0);
    const auto summary = nlohmann::json::parse(test::read_text_file(dir.file("out/summary.json")));
    const std::string id = summary.at("cases").at(0).at("id");
    // Unchanged, the replay (seed 2: a phase-shifted start) retraces the run.
    const auto same = run_program(COLLIDE_EXECUTABLE, {"explain", dir.file("out"), id}, dir);
    EXPECT_EQ(same.exit_code, 0) << same.err;
    const auto at = scene.find("vx = 1.0");
    ASSERT_NE(at, std::string::npos);
    scene = scene.substr(0, at) + "vx = 1.5" + scene.substr(at + 8);  // the first disk starts faster
    test::write_text_file(dir.file("glancing.toml"), scene);
    const auto edited = run_program(COLLIDE_EXECUTABLE, {"explain", dir.file("out"), id}, dir);
    EXPECT_NE(edited.exit_code, 0);
    EXPECT_TRUE(contains(edited.err, "edited since the run")) << edited.err;
}

// A case of an outside solver given on `validate`'s command line: the suite file cannot rebuild
// it, and explain said the suite file was edited. It names the solver and how to give it again,
// and with the solver given again it explains the case.
TEST(ExplainNamesCommandLineSolvers, ACaseOfACommandLineSolverAsksForTheSolverAgain) {
    ScratchDirectory dir;
    const std::string scenes = std::string(COLLIDE_SOURCE_DIR) + "/data/scenes";
    const std::string suite = dir.file("suite.toml");
    test::write_text_file(suite, "name = \"cli_solver\"\nbackends = [\"step\"]\nreference = \"step\"\n"
                                 "warmup_fraction = 0\n[[scene]]\npath = \"" + scenes + "/glancing.toml\"\n"
                                 "compare = \"trajectory\"\n");
    // A class, run by collide's own interpreter (the one with NumPy).
    const std::string solver = "mine=" + std::string(COLLIDE_SOURCE_DIR) + "/docs/examples/solvers/numpy_stepper.py:NumPyStepper";
    const auto run = run_program(COLLIDE_EXECUTABLE, {"validate", suite, "--out", dir.file("out"), "--python-solver", solver}, dir);
    std::string id;
    const auto summary = nlohmann::json::parse(test::read_text_file(dir.file("out/summary.json")));
    for (const auto& c : summary.at("cases"))
        if (c.at("backend").get<std::string>() == "mine" && c.at("status").get<std::string>() == "completed")
            id = c.at("id").get<std::string>();
    ASSERT_FALSE(id.empty()) << run.out << run.err;
    const auto refused = run_program(COLLIDE_EXECUTABLE, {"explain", dir.file("out"), id}, dir);
    EXPECT_NE(refused.exit_code, 0);
    EXPECT_TRUE(contains(refused.err, "ran on the outside solver 'mine', which the suite file does not name")) << refused.err;
    EXPECT_TRUE(contains(refused.err, "--python-solver '" + solver + "'")) << refused.err;
    EXPECT_FALSE(contains(refused.err, "edited")) << refused.err;
    const auto again = run_program(COLLIDE_EXECUTABLE, {"explain", dir.file("out"), id, "--to", "0.01", "--python-solver", solver}, dir);
    EXPECT_EQ(again.exit_code, 0) << again.err;
}

}  // namespace
}  // namespace collide
