// Nothing lost, nothing silently wrong: the `collide` program against a hostile user and a
// failing machine (a device as --out, values that overflow, a full disk, a second run into the
// same directory, signals, truncated files). Each test reproduces one failure the program
// once had and checks that it now ends in a clear error or a correct result, leaving no
// temporary file behind.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/collide_program.h"
#include "tests/support/program_runner.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

namespace fs = std::filesystem;
using test::contains;
using test::ProgramResult;
using test::run_collide;
using test::ScratchDirectory;

// `collide ARGS` under a file size limit of `kilobytes`, the way a full disk looks to a
// program (writes fail with EFBIG, "File too large"; SIGXFSZ ignored as a shell may do).
ProgramResult run_collide_with_file_limit(int kilobytes, const std::vector<std::string>& args,
                                          const ScratchDirectory& dir) {
    std::vector<std::string> shell_args{"-c", "trap '' XFSZ; ulimit -f " + std::to_string(kilobytes) +
                                                  "; exec \"$0\" \"$@\"",
                                        COLLIDE_EXECUTABLE};
    shell_args.insert(shell_args.end(), args.begin(), args.end());
    return test::run_program("/bin/sh", shell_args, dir);
}

// head_on_equal.toml with its text edited: each (from, to) replaced once.
std::string edited_scene(const ScratchDirectory& dir, const std::string& name,
                         const std::vector<std::pair<std::string, std::string>>& edits) {
    std::string text = test::read_text_file(test::scene_file("head_on_equal.toml"));
    for (const auto& [from, to] : edits) {
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    const std::string path = dir.file(name);
    test::write_text_file(path, text);
    return path;
}

// A run long enough to be interrupted: 3e7 steps of two disks.
std::string long_scene(const ScratchDirectory& dir) {
    return edited_scene(dir, "long.toml", {{"dt = 1e-3", "dt = 1e-7"}});
}

// A suite of one scene on `step`; with `step` as its own reference, a case per seed. No
// untimed warm-up run: the tests that interrupt a case wait for it to start writing, which
// the warm-up would delay past their patience under the sanitizers (35 s for the long scene).
std::string suite_file(const ScratchDirectory& dir, const std::string& scene_entry, double time_limit = 120,
                       const std::string& reference = "step") {
    const std::string path = dir.file("suite.toml");
    test::write_text_file(path, "name = \"robustness\"\nbackends = [\"step\"]\nreference = \"" + reference +
                                "\"\nseeds = [1]\nwarmup_fraction = 0\n"
                                "time_limit = " + std::to_string(time_limit) + "\n\n[[scene]]\n" + scene_entry);
    return path;
}

std::vector<std::string> temporaries_in(const std::string& directory) {
    std::vector<std::string> found;
    std::error_code error;
    for (const auto& entry : fs::recursive_directory_iterator(directory, error)) {
        const std::string name = entry.path().filename().string();
        if (name.find(".tmp-") != std::string::npos || entry.path().extension() == ".partial") found.push_back(name);
    }
    return found;
}

// Starts `collide ARGS` as a child in its own process group (so that the test can stop it
// and every case process it forked), with its output discarded.
pid_t start_collide(const std::vector<std::string>& args) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::setpgid(0, 0);
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, STDOUT_FILENO);
        ::dup2(null, STDERR_FILENO);
        std::vector<char*> argv{const_cast<char*>(COLLIDE_EXECUTABLE)};
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(COLLIDE_EXECUTABLE, argv.data());
        ::_exit(127);
    }
    return pid;
}

// Waits up to 20 s for `ready()`; false if it never became true.
template <typename Ready>
bool wait_for(Ready ready) {
    for (int i = 0; i < 2000; ++i) {
        if (ready()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
}

// ---- 1. --out never replaces anything but a regular file ---------------------------------

TEST(Robustness, RunRefusesToReplaceAFifo) {
    ScratchDirectory dir;
    const std::string fifo = dir.file("pipe");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    const auto result = run_collide({"run", test::scene_file("head_on_equal.toml"), "--out", fifo}, dir);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_TRUE(contains(result.err, "not a regular file (a FIFO)")) << result.err;
    EXPECT_TRUE(fs::is_fifo(fifo)) << "the FIFO must still be a FIFO";
    EXPECT_TRUE(temporaries_in(dir.path().string()).empty());
}

TEST(Robustness, RunFollowsASymbolicLinkAndKeepsIt) {
    ScratchDirectory dir;
    const std::string real = dir.file("real.h5"), link = dir.file("link.h5");
    test::write_text_file(real, "old");
    fs::create_symlink(real, link);
    const auto result = run_collide({"run", test::scene_file("head_on_equal.toml"), "--out", link}, dir);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(fs::is_symlink(link)) << "the link stays a link";
    EXPECT_GT(fs::file_size(real), 1000u) << "the file it points to holds the new run";
}

// ---- 2. a NaN/Inf metric with finite disks fails the run --------------------------------

TEST(Robustness, RunFailsWhenTheKineticEnergyOverflows) {
    ScratchDirectory dir;
    const std::string scene = edited_scene(dir, "fast.toml", {{"vx = 1.0", "vx = 1e200"}, {"vx = -1.0", "vx = -1e200"}});
    const auto result = run_collide({"run", scene, "--backend", "step"}, dir);
    EXPECT_EQ(result.exit_code, 1);
    // Refused before the start (docs/refusals.md), not found later as a NaN/Inf metric at t = 0.
    EXPECT_TRUE(contains(result.err, "step computes in double: squared relative speed |v_i - v_j|^2 (up to (2 |v|)^2) "
                                     "= 4e+400 for disk 0 overflows double's largest number")) << result.err;
    EXPECT_FALSE(contains(result.out, "nan")) << result.out;
}

TEST(Robustness, ValidateFailsTheRunCheckWhenTheKineticEnergyOverflows) {
    ScratchDirectory dir;
    const std::string scene = edited_scene(dir, "fast.toml", {{"vx = 1.0", "vx = 1e200"}, {"vx = -1.0", "vx = -1e200"}});
    const auto result = run_collide({"validate", suite_file(dir, "path = \"" + scene + "\"\n"), "--out", dir.file("out")}, dir);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_TRUE(contains(result.out, "run: error: step cannot run scene 'fast': step computes in double")) << result.out;
}

// ---- 3. a suite's dt obeys the scene rules -----------------------------------------------

TEST(Robustness, ValidateRefusesASuiteDtThatDoesNotDivideTheRun) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "name = \"head_on_equal\"\npath = \"" +
                                                  test::scene_file("head_on_equal.toml") + "\"\ndt = [3e-4]\n",
                                        120, "event");
    const auto result = run_collide({"validate", suite, "--out", dir.file("out")}, dir);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_TRUE(contains(result.err, suite + ":11: [[scene]] head_on_equal with dt = 0.0003")) << result.err;
    EXPECT_TRUE(contains(result.err, "output_interval: expected a whole multiple of dt = 0.0003")) << result.err;
    EXPECT_FALSE(fs::exists(dir.file("out/cases"))) << "no case ran";
}

// `validate --plan` says what a suite would run, and refuses what the run would refuse, without
// running or writing anything.
TEST(Robustness, ValidatePlanCountsTheCasesAndRefusesWhatTheRunWould) {
    ScratchDirectory dir;
    const std::string scene = "name = \"head_on_equal\"\npath = \"" + test::scene_file("head_on_equal.toml") + "\"\n";
    const auto good = run_collide({"validate", suite_file(dir, scene + "dt = [1e-3, 5e-4]\n", 120, "event"), "--plan",
                                   "--out", dir.file("good")}, dir);
    EXPECT_EQ(good.exit_code, 0) << good.err;
    EXPECT_TRUE(contains(good.out, "2 cases planned on 1 scenes; nothing run")) << good.out;  // two dt, one backend
    EXPECT_TRUE(contains(good.out, "step             2 cases")) << good.out;
    const auto bad = run_collide({"validate", suite_file(dir, scene + "dt = [3e-4]\n", 120, "event"), "--plan",
                                  "--out", dir.file("bad")}, dir);
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_TRUE(contains(bad.err, "output_interval: expected a whole multiple of dt = 0.0003")) << bad.err;
    EXPECT_FALSE(fs::exists(dir.file("good")) || fs::exists(dir.file("bad"))) << "--plan wrote an output directory";
}

// An earlier run's verdicts leave the directory when a new run takes it (they would judge records
// that are no longer theirs, and a run cut short would leave them behind as if its own), and stay
// when the new run is refused before it writes anything.
TEST(Robustness, ValidateRemovesTheEarlierSummaryWhenItStartsAndKeepsItWhenRefused) {
    ScratchDirectory dir;
    const std::string out = dir.file("out");
    fs::create_directories(out);
    for (const char* file : {"/summary.json", "/junit.xml"}) test::write_text_file(out + file, "earlier run\n");
    const std::string refused = suite_file(dir, "name = \"head_on_equal\"\npath = \"" + test::scene_file("head_on_equal.toml") +
                                                    "\"\ndt = [3e-4]\n", 120, "event");  // 3e-4 does not divide 0.1
    EXPECT_EQ(run_collide({"validate", refused, "--out", out}, dir).exit_code, 1);
    EXPECT_TRUE(fs::exists(out + "/summary.json") && fs::exists(out + "/junit.xml")) << "a refused run removed them";
    const pid_t run = start_collide({"validate", suite_file(dir, "path = \"" + long_scene(dir) + "\"\n"), "--out", out});
    const bool removed = wait_for([&] { return !fs::exists(out + "/summary.json") && !fs::exists(out + "/junit.xml"); });
    ::kill(-run, SIGKILL);  // cut short: nothing may stand in for its verdicts
    ::waitpid(run, nullptr, 0);
    EXPECT_TRUE(removed) << "the earlier summary.json and junit.xml were still there while the new run ran";
    EXPECT_FALSE(fs::exists(out + "/summary.json") || fs::exists(out + "/junit.xml")) << "left behind by a killed run";
}

// ---- 4. a second validate into the same directory refuses at once ------------------------

TEST(Robustness, SecondValidateIntoOneDirectoryRefusesNamingTheFirst) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "path = \"" + long_scene(dir) + "\"\n");
    const std::string out = dir.file("out");
    const pid_t first = start_collide({"validate", suite, "--out", out});
    ASSERT_TRUE(wait_for([&] { return fs::exists(out + "/cases"); })) << "the first run never started";
    const auto second = run_collide({"validate", suite, "--out", out}, dir);
    ::kill(-first, SIGKILL);
    ::waitpid(first, nullptr, 0);
    EXPECT_EQ(second.exit_code, 1);
    EXPECT_TRUE(contains(second.err, "another `collide validate` (process " + std::to_string(first) + ")"))
        << second.err;
}

// ---- 5. --resume reruns a case whose HDF5 file was truncated ------------------------------

TEST(Robustness, ResumeRerunsACaseWhoseHdf5FileIsTruncated) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "name = \"head_on_equal\"\npath = \"" +
                                                  test::scene_file("head_on_equal.toml") + "\"\n");
    const std::string out = dir.file("out");
    ASSERT_EQ(run_collide({"validate", suite, "--out", out}, dir).exit_code, 0);
    const std::string h5 = out + "/runs/head_on_equal__step__seed1.h5";
    ASSERT_TRUE(fs::exists(h5));
    fs::resize_file(h5, fs::file_size(h5) / 2);
    const auto report = run_collide({"report", out}, dir);
    EXPECT_NE(report.exit_code, 0);
    EXPECT_TRUE(contains(report.err, h5)) << "report names the unreadable file: " << report.err;
    const auto resumed = run_collide({"validate", suite, "--out", out, "--resume"}, dir);
    EXPECT_EQ(resumed.exit_code, 0) << resumed.out << resumed.err;
    EXPECT_TRUE(contains(resumed.out, "(1 run, 0 resumed)")) << resumed.out;
    EXPECT_TRUE(contains(resumed.err, "running head_on_equal__step__seed1 again: " + h5)) << resumed.err;
}

// ---- 5b. the report checks every case's files, drawn or not -------------------------------

// `collide report` parses in full only the records it draws from (the smallest dt); every
// other record is checked against its checksum and its HDF5 file against the counts in
// summary.json. A changed byte in the record of the case not drawn (`step` at dt = 0.02; `step`
// is held against `event`, so it runs at both time steps), or its run file cut short, is
// still named.
TEST(Robustness, ReportNamesADamagedRecordOrRunFileOfACaseItDoesNotDraw) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "name = \"head_on_equal\"\npath = \"" +
                                                  test::scene_file("head_on_equal.toml") + "\"\ndt = [0.02, 0.01]\n",
                                     120, "event");
    const std::string out = dir.file("out");
    ASSERT_EQ(run_collide({"validate", suite, "--out", out}, dir).exit_code, 0);
    ASSERT_EQ(run_collide({"report", out}, dir).exit_code, 0) << "intact files: the report is written";
    const std::string record = out + "/cases/head_on_equal__step__dt0.02__seed1.toml";
    const std::string h5 = out + "/runs/head_on_equal__step__dt0.02__seed1.h5";
    ASSERT_TRUE(fs::exists(record) && fs::exists(h5));

    const std::string intact = test::read_text_file(record);
    std::string edited = intact;
    const auto at = edited.find("disks = 2");
    ASSERT_NE(at, std::string::npos);
    edited.replace(at, 9, "disks = 3");
    test::write_text_file(record, edited);
    const auto damaged = run_collide({"report", out}, dir);
    EXPECT_NE(damaged.exit_code, 0);
    EXPECT_TRUE(contains(damaged.err, record) && contains(damaged.err, "checksum does not match")) << damaged.err;

    test::write_text_file(record, intact);
    fs::resize_file(h5, fs::file_size(h5) / 2);
    const auto truncated = run_collide({"report", out}, dir);
    EXPECT_NE(truncated.exit_code, 0);
    EXPECT_TRUE(contains(truncated.err, h5)) << truncated.err;
}

// ---- 6. a full disk: a clear message, no crash, no partial file ---------------------------

TEST(Robustness, RunOnAFullDiskFailsWithTheReasonAndLeavesNothing) {
    ScratchDirectory dir;
    const auto result = run_collide_with_file_limit(
        8, {"run", test::scene_file("head_on_equal.toml"), "--frames", "--out", dir.file("run.h5")}, dir);
    EXPECT_EQ(result.exit_code, 1) << "a crash (segfault in HDF5's exit-time cleanup) gives -1: " << result.err;
    EXPECT_TRUE(contains(result.err, "File too large")) << result.err;
    EXPECT_EQ(dir.entry_count(), 0u) << "no output and no temporary file";
}

TEST(Robustness, ValidateOnAFullDiskFailsWithTheReasonAndLeavesNoPartialFile) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "name = \"head_on_equal\"\npath = \"" +
                                                  test::scene_file("head_on_equal.toml") + "\"\n");
    const std::string out = dir.file("out");
    const auto result = run_collide_with_file_limit(8, {"validate", suite, "--out", out}, dir);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_NE(result.exit_code, -1) << "no crash: " << result.err;
    EXPECT_TRUE(contains(result.err + result.out, "File too large")) << result.out << result.err;
    EXPECT_TRUE(temporaries_in(out).empty());
    for (const auto& entry : fs::recursive_directory_iterator(out))
        if (entry.path().extension() == ".toml") {
            EXPECT_GT(fs::file_size(entry.path()), 0u) << entry.path();
        }
}

// ---- 7. box2d refuses values float cannot hold --------------------------------------------

TEST(Robustness, Box2dRefusesAVelocityBeyondFloatAndATinyMass) {
    ScratchDirectory dir;
    const std::string fast = edited_scene(dir, "fast.toml", {{"vx = 1.0", "vx = 1e39"}});
    const auto a = run_collide({"run", fast, "--backend", "box2d"}, dir);
    EXPECT_EQ(a.exit_code, 1) << "a Box2D assertion aborts (-1): " << a.err;
    EXPECT_TRUE(contains(a.err, "vx in Box2D's units (length scale 1) = 1e+39 for disk 0 overflows float's largest "
                                "number 3.4e+38")) << a.err;
    const std::string light = edited_scene(dir, "light.toml", {{"mass = 1.0", "mass = 1e-50"}});
    const auto b = run_collide({"run", light, "--backend", "box2d"}, dir);
    EXPECT_EQ(b.exit_code, 1) << "Box2D would give the disk mass 1 and run on: " << b.out;
    EXPECT_TRUE(contains(b.err, "mass in Box2D's units (length scale 1) = 1e-50 for disk 0 underflows")) << b.err;
}

// ---- 9. signals leave no temporary file ---------------------------------------------------

TEST(Robustness, RunRemovesItsTemporaryFileOnSigintSigtermAndSighup) {
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
        ScratchDirectory dir;
        const pid_t pid = start_collide({"run", long_scene(dir), "--out", dir.file("run.h5")});
        ASSERT_TRUE(wait_for([&] { return !temporaries_in(dir.path().string()).empty(); }));
        ::kill(pid, signal_number);
        int status = 0;
        ::waitpid(pid, &status, 0);
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << strsignal(signal_number);
        EXPECT_TRUE(temporaries_in(dir.path().string()).empty()) << strsignal(signal_number);
        EXPECT_FALSE(fs::exists(dir.file("run.h5")));
    }
}

TEST(Robustness, ValidateRemovesTheTemporariesOfACaseKilledForTime) {
    ScratchDirectory dir;
    // No warm-up (suite_file): the case writes its HDF5 file from the start until it is killed
    // at 2.5 s.
    const std::string suite = suite_file(dir, "path = \"" + long_scene(dir) + "\"\n", 2.5);
    const std::string out = dir.file("out");
    const pid_t pid = start_collide({"validate", suite, "--out", out});
    EXPECT_TRUE(wait_for([&] { return !temporaries_in(out + "/runs").empty(); })) << "the case never wrote";
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1);
    EXPECT_TRUE(contains(test::read_text_file(out + "/summary.json"), "killed after the time limit"));
    EXPECT_TRUE(temporaries_in(out).empty());
}

TEST(Robustness, ValidateInterruptedFromTheTerminalLeavesNoTemporaries) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "path = \"" + long_scene(dir) + "\"\n");
    const std::string out = dir.file("out");
    const pid_t pid = start_collide({"validate", suite, "--out", out});
    ASSERT_TRUE(wait_for([&] { return !temporaries_in(out + "/runs").empty(); })) << "the case never wrote";
    ::kill(-pid, SIGINT);  // Ctrl-C: the terminal signals the whole process group
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT);
    EXPECT_TRUE(temporaries_in(out).empty());
}

TEST(Robustness, ResumeRemovesTemporariesASigkillLeft) {
    ScratchDirectory dir;
    const std::string suite = suite_file(dir, "name = \"head_on_equal\"\npath = \"" +
                                                  test::scene_file("head_on_equal.toml") + "\"\n");
    const std::string out = dir.file("out");
    fs::create_directories(out + "/runs");
    fs::create_directories(out + "/cases");
    test::write_text_file(out + "/runs/.head_on_equal__step__seed1.h5.tmp-99999999-0", "half");
    test::write_text_file(out + "/cases/head_on_equal__step__seed1.toml.partial", "half");
    const auto result = run_collide({"validate", suite, "--out", out, "--resume"}, dir);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(temporaries_in(out).empty());
}

// ---- 10. messages that name the real problem ----------------------------------------------

TEST(Robustness, MessagesNameTheRealProblem) {
    ScratchDirectory dir;
    const std::string base = test::read_text_file(test::scene_file("head_on_equal.toml"));
    const std::string step_key = dir.file("step_key.toml"), typo = dir.file("typo.toml");
    test::write_text_file(step_key, base + "[backend.step]\nfoo = 1\n");
    test::write_text_file(typo, base + "[backend.stpe]\nfoo = 1\n");
    const std::string huge = edited_scene(dir, "huge.toml", {{"duration = 3.0", "duration = 1e300"}});
    const std::string fast = edited_scene(dir, "fast.toml", {{"vx = 1.0", "vx = 1e30"}, {"vx = -1.0", "vx = -1e30"}});
    const std::string beyond_float = edited_scene(dir, "f39.toml", {{"vx = 1.0", "vx = 1e39"}});
    const struct {
        std::vector<std::string> args;
        std::string expected;
    } cases[] = {
        {{"run", step_key}, "the step backend has no options"},
        {{"run", typo}, "unknown key [backend].stpe: expected one of event, step, cpu, opencl, box2d"},
        {{"run", huge}, "expected at most 1000000000000 steps of dt = 0.001"},
        {{"run", fast, "--backend", "event"}, "events cannot finish"},
        {{"run", beyond_float, "--backend", "cpu"}, "cpu computes in float: speed |v| = 1e+39 for disk 0 overflows"},
        {{"run", dir.path().string()}, "is a directory: expected a scene file"},
        {{"validate", step_key, "--jobs", "0"}, "0 is no number of jobs: expected a whole number >= 1"},
    };
    for (const auto& c : cases) {
        const auto result = run_collide(c.args, dir);
        EXPECT_NE(result.exit_code, 0) << c.args[1];
        if (c.args[0] == "run") {
            EXPECT_EQ(result.exit_code, 1) << c.args[1];
        }
        EXPECT_TRUE(contains(result.err, c.expected)) << c.args[1] << ": " << result.err;
        EXPECT_FALSE(contains(result.err, "every disk was finite at t = 0")) << result.err;
    }
}

TEST(Robustness, OutOfMemoryIsNamed) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit allows";
#endif
    ScratchDirectory dir;
    // 5e6 disks need ~2 GiB: beyond an address-space limit of ~800 MB, well within the machine.
    std::string text = test::read_text_file(test::scene_file("box_gas_1000.toml"));
    text.replace(text.find("count = 1000"), 12, "count = 5000000");
    text.replace(text.find("50.0, 50.0]"), 11, "50000.0, 50000.0]");
    const std::string scene = dir.file("big.toml");
    test::write_text_file(scene, text);
    const auto result = test::run_program(
        "/bin/sh", {"-c", "ulimit -v 800000; exec \"$0\" \"$@\"", COLLIDE_EXECUTABLE, "run", scene}, dir);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_TRUE(contains(result.err, "collide: error: out of memory")) << result.err;
}

}  // namespace
}  // namespace collide
