// The [solver.NAME] tables of a suite file and the joining of outside solvers to a suite's
// backends (validation/plan/external_solvers.h): each mistake is refused with the file, line and key.
#include <gtest/gtest.h>

#include <cstdlib>

#include "validation/plan/external_solvers.h"
#include "validation/models/statistics_bias_model.h"
#include "tests/support/suite_text.h"
#include "validation/plan/suite.h"

namespace collide::validation {
namespace {

using test::parse_suite_text;
using test::suite_refusal;

TEST(SolverTables, ReadCommandPythonAndRule) {
    const Suite s = parse_suite_text("backends = [\"event\"]\n[solver.mine]\ncommand = \"./a.out\"\n"
                                     "[solver.py]\npython = \"m.py:C\"\nrule = \"collide-first\"\n");
    ASSERT_EQ(s.solvers.size(), 2u);
    EXPECT_EQ(s.solvers[0].name, "mine");
    EXPECT_EQ(s.solvers[0].command, "./a.out");
    EXPECT_EQ(s.solvers[1].python_class, "m.py:C");
    EXPECT_EQ(s.solvers[1].rule, "collide-first");
    EXPECT_EQ(s.solvers[0].directory, std::string(COLLIDE_SOURCE_DIR) + "/validation/suites");
    // Each joins the suite's list of backends for this run.
    EXPECT_EQ(s.backends, (std::vector<std::string>{"event", "mine", "py"}));
}

TEST(SolverTables, RefuseEachMistakeWithItsPlace) {
    EXPECT_NE(suite_refusal("[solver.Mine]\ncommand = \"x\"\n").find("s.toml:1: solver.Mine: expected a solver name"),
              std::string::npos);
    EXPECT_NE(suite_refusal("[solver.mine]\n").find("either command"), std::string::npos);
    EXPECT_NE(suite_refusal("[solver.mine]\ncommand = \"x\"\npython = \"m:C\"\n").find("not both"), std::string::npos);
    EXPECT_NE(suite_refusal("[solver.mine]\ncommand = \"x\"\nargs = 1\n").find("solver.mine.args: expected no such key"),
              std::string::npos);
    EXPECT_NE(suite_refusal("[solver.mine]\npython = \"module\"\n").find("\"module:Class\""), std::string::npos);
    EXPECT_NE(suite_refusal("[solver.mine]\ncommand = \"x\"\nrule = \"rk4\"\n").find("solver.mine.rule"), std::string::npos);
    EXPECT_NE(suite_refusal("[solver.mine]\ncommand = 3\n").find("a non-empty string"), std::string::npos);
}

// Protocol 2: what a solver handles, declared once, leaves a scene out before any call; the
// declared files join the hashed provenance; each mistake names its key and line.
TEST(SolverTables, HandlesLeavesOutScenesTheSolverDoesNotDeclare) {
    const Suite s = parse_suite_text("[solver.engine]\ncommand = \"x\"\nhandles = [\"walls\", \"gravity\"]\n"
                                     "files = [\"lock.json\"]\n");
    ASSERT_TRUE(s.solvers.at(0).handles.has_value());
    EXPECT_EQ(s.solvers.at(0).files, (std::vector<std::string>{"lock.json"}));
    const auto backends = backends_with_solvers(s, {}, {"python3", "runner.py"});
    Scene walled;
    walled.name = "walled";
    walled.physics.gravity_y = -1;
    EXPECT_FALSE(backends.at(0).supports(walled).has_value());
    Scene periodic = walled;
    periodic.world.boundary = Boundary::periodic;
    periodic.physics.restitution = 0.9;
    const auto why = backends.at(0).supports(periodic);
    ASSERT_TRUE(why.has_value());
    EXPECT_NE(why->find("the scene needs periodic, restitution too"), std::string::npos) << *why;
    // Without the key, every scene goes to the program (which may refuse it when called).
    const Suite open = parse_suite_text("[solver.engine]\ncommand = \"x\"\n");
    EXPECT_FALSE(backends_with_solvers(open, {}, {"python3", "runner.py"}).at(0).supports(periodic).has_value());
}

TEST(SolverTables, HandlesAndFilesMistakesAreNamedWithTheirLine) {
    EXPECT_NE(suite_refusal("[solver.e]\ncommand = \"x\"\nhandles = [\"walls\", \"wind\"]\n").find("s.toml:3: solver.e.handles: expected capabilities from walls, periodic"),
              std::string::npos);
    EXPECT_NE(suite_refusal("[solver.e]\ncommand = \"x\"\nhandles = [\"walls\", \"walls\"]\n").find("named twice"), std::string::npos);
    EXPECT_NE(suite_refusal("[solver.e]\ncommand = \"x\"\nhandles = \"walls\"\n").find("an array of capability names"),
              std::string::npos);
    EXPECT_NE(suite_refusal("[solver.e]\ncommand = \"x\"\nfiles = [3]\n").find("solver.e.files: expected an array of file paths"),
              std::string::npos);
}

// long_lived = true: one start serves many calls (external/solver_server.h); a program only.
TEST(SolverTables, LongLivedIsReadAndItsMistakesAreNamedWithTheirLine) {
    EXPECT_TRUE(parse_suite_text("[solver.e]\ncommand = \"x\"\nlong_lived = true\n").solvers.at(0).long_lived);
    EXPECT_FALSE(parse_suite_text("[solver.e]\ncommand = \"x\"\n").solvers.at(0).long_lived);
    EXPECT_NE(suite_refusal("[solver.e]\ncommand = \"x\"\nlong_lived = \"yes\"\n").find("s.toml:3: solver.e.long_lived: expected true or false"),
              std::string::npos);
    const std::string python = suite_refusal("[solver.e]\npython = \"m.py:C\"\nlong_lived = true\n");
    EXPECT_NE(python.find("s.toml:3: solver.e.long_lived: expected a program (command = \"...\")"), std::string::npos) << python;
}

TEST(SolverTables, ANameTakenTwiceOrByABackendIsRefused) {
    Suite s = parse_suite_text("[solver.mine]\ncommand = \"x\"\n");
    external::ExternalSolverSpec again = s.solvers.at(0);  // the same name once more
    again.origin = std::string("--solver mine=y");
    EXPECT_THROW(add_solvers(s, {again}), SuiteError);
    Suite t = parse_suite_text("[solver.step]\ncommand = \"x\"\n");
    BackendInfo step;
    step.name = std::string("step");
    EXPECT_THROW(backends_with_solvers(t, {step}, {}), SuiteError);
}

TEST(SolverTables, ARuleMakesTheSolverAStepperForTheChecks) {
    const Suite s = parse_suite_text("[solver.mine]\ncommand = \"x\"\nrule = \"collide-first\"\n[solver.other]\ncommand = \"y\"\n");
    const auto backends = backends_with_solvers(s, {}, {"python3", "runner.py"});
    ASSERT_EQ(backends.size(), 2u);
    EXPECT_TRUE(backends[0].stepping_rule());
    EXPECT_EQ(backends[0].rule, "collide-first");
    EXPECT_FALSE(backends[1].stepping_rule());
    EXPECT_FALSE(backends[1].exact);
    EXPECT_EQ(s.backends, (std::vector<std::string>{"all"}));  // "all" takes them anyway
}

TEST(SolverTables, ShellQuotingKeepsQuotes) {
    EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
}

// Why outside solvers cannot run here, or "" (what backends_with_solvers refuses, if anything).
std::string tmpdir_refusal(const char* tmpdir) {
    const char* old = std::getenv("TMPDIR");
    const std::string saved = old ? old : "";
    tmpdir ? ::setenv("TMPDIR", tmpdir, 1) : ::unsetenv("TMPDIR");
    std::string why;
    try {
        backends_with_solvers(parse_suite_text("[solver.mine]\ncommand = \"x\"\n"), {}, {});
    } catch (const SuiteError& e) {
        why = e.what();
    }
    old ? ::setenv("TMPDIR", saved.c_str(), 1) : ::unsetenv("TMPDIR");
    return why;
}

// A relative TMPDIR named another place in each solver's own directory, and a missing one
// failed every call with an error blamed on the solver; both are refused once, before any
// case, naming TMPDIR. An unset TMPDIR means /tmp.
TEST(RequestRootChecked, ARelativeOrMissingTmpdirIsRefusedUpFrontNamingIt) {
    const std::string relative = tmpdir_refusal("relative/tmp");
    EXPECT_NE(relative.find("TMPDIR=relative/tmp: "), std::string::npos) << relative;
    EXPECT_NE(relative.find("relative path"), std::string::npos) << relative;
    const std::string missing = tmpdir_refusal("/no/such/tmp");
    EXPECT_NE(missing.find("TMPDIR=/no/such/tmp: "), std::string::npos) << missing;
    EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
    EXPECT_EQ(tmpdir_refusal("/tmp"), "");
    EXPECT_EQ(tmpdir_refusal(nullptr), "");
}

}  // namespace
}  // namespace collide::validation
