// `collide explain` as a user runs it: validate a one-case suite, then name the step of the
// case's largest energy change (the worked example of docs/stepping-rules.md), as text and as
// JSON; and the refusals: an unknown case, the exact solver, an interval without a whole step.
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
    test::write_text_file(suite, "name = \"explain\"\nbackends = [\"step\"]\nreference = \"step\"\nseeds = [1]\n"
                                 "scene_dir = \"" + std::string(COLLIDE_SOURCE_DIR) + "/data/scenes\"\n\n"
                                 "[[scene]]\nname = \"box_gas_1000\"\nduration = 1.1\ndt = [1e-3]\n");
    const auto r = run_program(COLLIDE_EXECUTABLE, {"validate", suite, "--out", dir.file("out")}, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const auto summary = nlohmann::json::parse(test::read_text_file(dir.file("out/summary.json")));
    return {dir.file("out"), summary.at("cases").at(0).at("id").get<std::string>()};
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
    EXPECT_NEAR(group.at("kinetic_change").get<double>(), found.at("kinetic_change").get<double>(), 1e-9);
}

TEST(ExplainCommand, RefusesWhatItCannotExplain) {
    ScratchDirectory dir;
    const auto [out, case_id] = validated(dir);
    const auto unknown = run_program(COLLIDE_EXECUTABLE, {"explain", out, "no_such_case"}, dir);
    EXPECT_NE(unknown.exit_code, 0);
    EXPECT_TRUE(contains(unknown.err, "the suite plans no case 'no_such_case'")) << unknown.err;
    const auto empty = run_program(COLLIDE_EXECUTABLE, {"explain", out, case_id, "--from", "0.5", "--to", "0.5"}, dir);
    EXPECT_NE(empty.exit_code, 0);
    EXPECT_TRUE(contains(empty.err, "expected 0 <= from < to")) << empty.err;
    const auto missing = run_program(COLLIDE_EXECUTABLE, {"explain", dir.file("nowhere"), case_id}, dir);
    EXPECT_NE(missing.exit_code, 0);
}

}  // namespace
}  // namespace collide
