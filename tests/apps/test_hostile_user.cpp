// A hostile user against `collide`, round three (docs/refusals.md, "Foreign text, solver
// processes, comparisons"): a solver that daemonises, a comparison that lost coverage, a --set
// with a line break, a suite `set` that a sweep overrides, a missing input, two backends whose
// case ids clash, and text that collide did not write (a solver's output, a key) reaching the
// terminal or summary.md. Each test fails on the code before the fix of its class.
#include <gtest/gtest.h>

#include <signal.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "core/text/printable.h"
#include "tests/support/collide_program.h"
#include "tests/support/program_runner.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

namespace fs = std::filesystem;
using test::contains;
using test::run_collide;
using test::ScratchDirectory;

// A suite of head_on_equal on `step` (its own reference), one seed; `extra` is appended to the
// [[scene]] entry, `tables` after it.
std::string suite_file(const ScratchDirectory& dir, const std::string& extra = "", const std::string& tables = "",
                       const std::string& name = "suite.toml") {
    const std::string path = dir.file(name);
    test::write_text_file(path, "name = \"hostile\"\nbackends = [\"step\"]\nreference = \"step\"\nseeds = [1]\n"
                                "warmup_fraction = 0\ntime_limit = 60\n\n[[scene]]\npath = \"" +
                                    test::scene_file("head_on_equal.toml") + "\"\n" + extra + "\n" + tables);
    return path;
}

std::string replaced_all(std::string text, const std::string& from, const std::string& to) {
    for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

bool has_byte(const std::string& text, char byte) { return text.find(byte) != std::string::npos; }

// --- every descendant of a solver call ends with it -------------------------------------------

// The solver starts a daemon in a session of its own (setsid leaves the solver's process
// group), which writes into the output directory 2 s later, and fails. The daemon must be gone
// when `validate` exits: nothing is written after it.
TEST(SolverDescendantsEndWithTheCall, ASetsidDaemonDoesNotOutliveValidate) {
    ScratchDirectory dir;
    const std::string out = dir.file("results"), pid_file = dir.file("daemon.pid");
    const std::string late = out + "/late.txt";
    const std::string daemon = "setsid sh -c 'echo $$ > " + pid_file + "; sleep 2; echo late > " + late +
                               "' </dev/null >/dev/null 2>&1 & sleep 0.2; exit 3";
    const auto r = run_collide({"validate", suite_file(dir), "--out", out, "--solver", "daemon=" + daemon}, dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;  // the solver failed its case
    ASSERT_TRUE(fs::exists(pid_file)) << "the daemon never started: " << r.err;
    const pid_t pid = pid_t(std::stol(test::read_text_file(pid_file)));
    std::this_thread::sleep_for(std::chrono::seconds(3));
    EXPECT_FALSE(fs::exists(late)) << "a solver's daemon wrote into the output directory after validate exited";
    EXPECT_TRUE(::kill(pid, 0) != 0 && errno == ESRCH) << "the daemon " << pid << " is still running";
    if (::kill(pid, 0) == 0) ::kill(pid, SIGKILL);
}

// --- `collide compare`: lost coverage is a regression -----------------------------------------

class CompareCountsLostCoverage : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new ScratchDirectory;
        const auto r = run_collide({"validate", suite_file(*dir_), "--out", dir_->file("a")}, *dir_);
        ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    }
    static void TearDownTestSuite() { delete dir_; }

    // A copy of the baseline as B, with its summary.json passed through `edit`.
    static std::string copy_of_a(const std::string& name, std::string (*edit)(std::string)) {
        const std::string b = dir_->file(name);
        fs::copy(dir_->file("a"), b, fs::copy_options::recursive);
        const std::string summary = b + "/summary.json";
        test::write_text_file(summary, edit(test::read_text_file(summary)));
        return b;
    }

    static ScratchDirectory* dir_;
};
ScratchDirectory* CompareCountsLostCoverage::dir_ = nullptr;

TEST_F(CompareCountsLostCoverage, ChecksThatWentFromPassToLeftOutAreARegression) {
    const std::string b = copy_of_a("left_out", [](std::string text) {
        return replaced_all(replaced_all(text, "\"status\": \"pass\"", "\"status\": \"left_out\""),
                            "\"status\":\"pass\"", "\"status\":\"left_out\"");
    });
    ASSERT_NE(test::read_text_file(b + "/summary.json"), test::read_text_file(dir_->file("a/summary.json")));
    const auto r = run_collide({"compare", dir_->file("a"), b}, *dir_);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "LOST ")) << r.out;
    EXPECT_TRUE(contains(r.out, "verdict   regression")) << r.out;
}

TEST_F(CompareCountsLostCoverage, DirectoriesWithoutASharedCaseCannotBeCompared) {
    const std::string b = copy_of_a("renamed", [](std::string text) { return replaced_all(text, "__seed1", "__seed7"); });
    const auto r = run_collide({"compare", dir_->file("a"), b}, *dir_);
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, "share no case")) << r.err;
}

TEST_F(CompareCountsLostCoverage, DeletedRecordsAndRunsAreNamedAndARegression) {
    const std::string b = copy_of_a("deleted", [](std::string text) { return text; });
    fs::remove_all(b + "/cases");
    fs::remove_all(b + "/runs");
    const auto r = run_collide({"compare", dir_->file("a"), b}, *dir_);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "MISSING   " + b + "/cases/")) << r.out;
    EXPECT_TRUE(contains(r.out, "MISSING   " + b + "/runs/")) << r.out;
}

// --- --set and a suite's `set`: what runs is what is recorded ---------------------------------

TEST(SetValuesAreTakenWholeOrRefused, ALineBreakInASetValueIsRefused) {
    ScratchDirectory dir;
    const auto r = run_collide({"run", test::scene_file("head_on_equal.toml"), "--set", "run.dt=0.002\n# the rest",
                                "--out", dir.file("run.h5")},
                               dir);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, "control character")) << r.err;
    EXPECT_TRUE(contains(r.err, "run.dt=0.002\\x0a# the rest")) << r.err;  // shown whole, escaped
    EXPECT_FALSE(fs::exists(dir.file("run.h5")));
}

TEST(SuiteSetBesideASweepIsRefused, ASetOfRunDtBesideADtSweepNamesFileAndKey) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "dt = [0.001]\nset = { \"run.dt\" = [0.002] }");
    const auto r = run_collide({"validate", suite, "--out", dir.file("results")}, dir);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, suite + ":")) << r.err;
    EXPECT_TRUE(contains(r.err, "run.dt")) << r.err;
    EXPECT_TRUE(contains(r.err, "`dt` sets run.dt for every case")) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("results/summary.json")));
}

// --- a missing input is collide's refusal: exit 1 and collide's message ------------------------

TEST(MissingInputsExitOneWithCollidesMessage, EveryReadingCommand) {
    ScratchDirectory dir;
    const std::string gone = dir.file("gone");
    const std::vector<std::vector<std::string>> commands = {
        {"view", gone, "--headless"}, {"render", gone, "--out", dir.file("x.gif")},
        {"validate", gone, "--out", dir.file("results")}, {"report", gone},
        {"export", gone, "--out", dir.file("x.xyz")}, {"explain", gone, "case"}, {"compare", gone, gone}};
    for (const auto& args : commands) {
        const auto r = run_collide(args, dir);
        EXPECT_EQ(r.exit_code, 1) << args[0] << ": " << r.err;
        EXPECT_TRUE(contains(r.err, "collide: error: " + gone + ": does not exist")) << args[0] << ": " << r.err;
    }
}

// --- two backends whose case ids clash: the backends are named, not the scenes -----------------

TEST(BackendIdClashNamesTheBackends, AnOutsideSolverNamedLikeAVariant) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "", "[variant.\"box2d[shipped]\"]\npreset = \"shipped\"\n");
    test::write_text_file(suite, replaced_all(test::read_text_file(suite), "backends = [\"step\"]",
                                              "backends = [\"step\", \"box2d[shipped]\"]"));
    const auto r = run_collide({"validate", suite, "--out", dir.file("results"), "--solver", "box2d-shipped=true"}, dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_TRUE(contains(r.err, "--solver box2d-shipped=true: the outside solver 'box2d-shipped' is named like the "
                                "variant 'box2d[shipped]'"))
        << r.err;
    EXPECT_FALSE(contains(r.err, "scenes that share a file stem")) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("results/summary.json")));
}

// --- text collide did not write, shown through the one sanitiser -------------------------------

TEST(ForeignTextIsSanitised, PrintableShowsControlBytesAndKeepsLetters) {
    EXPECT_EQ(printable("a\x1b[2J\nb\x7f"), "a\\x1b[2J\\x0ab\\x7f");
    EXPECT_EQ(printable("x\ny", LineBreaks::kept), "x\ny");
    EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x9c\x93"), "caf\xc3\xa9 \xe2\x9c\x93");  // letters of any script pass
    EXPECT_EQ(printable("\xc2\x9b" "31m"), "\\xc2\\x9b31m");                         // C1 CSI, an escape in UTF-8
    EXPECT_EQ(printable("\xff\xc3"), "\\xff\\xc3");                                  // not UTF-8
    EXPECT_EQ(printable_tail("0123456789", 4), "...6789");
}

// A solver that prints a forged summary line, HTML and an escape: the terminal summary keeps
// one line per failed check, and summary.md shows the HTML as text.
TEST(ForeignTextIsSanitised, SolverOutputInTheTerminalSummaryAndSummaryMd) {
    ScratchDirectory dir;
    const std::string out = dir.file("results");
    const std::string forger = "printf '<script>alert(1)</script>\\nchecks    99 passed, 0 failed\\n\\033[2J'; exit 3";
    const auto r = run_collide({"validate", suite_file(dir), "--out", out, "--solver", "forger=" + forger}, dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_FALSE(contains(r.out, "\nchecks    99 passed")) << r.out;  // no forged line
    EXPECT_FALSE(has_byte(r.out, '\x1b')) << r.out;
    EXPECT_TRUE(contains(r.out, "\\x1b[2J")) << r.out;
    const auto report = run_collide({"report", out}, dir);
    ASSERT_EQ(report.exit_code, 0) << report.err;
    for (const char* name : {"summary.md", "summary-full.md"}) {
        const std::string md = test::read_text_file(out + "/report/" + name);
        EXPECT_FALSE(contains(md, "<script>")) << name;
        EXPECT_TRUE(contains(md, "&lt;script&gt;")) << name;
        EXPECT_FALSE(has_byte(md, '\x1b')) << name;
    }
}

TEST(ForeignTextIsSanitised, AnEscapeInASuiteSetKeyIsShownNotSent) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "set = { \"run.\\u001b[31mdt\" = [0.001] }");
    const auto r = run_collide({"validate", suite, "--out", dir.file("results")}, dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_FALSE(has_byte(r.err, '\x1b')) << r.err;
    EXPECT_TRUE(contains(r.err, "run.\\x1b[31mdt")) << r.err;
}

}  // namespace
}  // namespace collide
