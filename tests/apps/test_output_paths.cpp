// The output-path guard (core/io/output_file.h) as a property of every writer of the `collide`
// program: whatever a command writes (an HDF5 run, a render, a screenshot, benchmark
// tables, a suite's summary, case records and runs, a report), pointed at a place that is not
// a new or a regular file it
//   - exits with a non-zero status (no crash, no hang),
//   - says which path and what is wrong with it,
//   - leaves the place as it was: a device stays a device, a FIFO a FIFO, a link a link,
//     and no file or temporary file appears;
// and pointed at a symbolic link to a regular file it replaces that file and keeps the link.
//
// Every writer meets every hostile place (one test each, so that a place that cannot be made,
// a device without root, skips alone). Names are drawn from a seeded generator with spaces
// and quotes in them, so that no writer works only for tame names.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <ostream>
#include <random>
#include <string>
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
using test::ScratchDirectory;

// `collide ARGS` under a time limit: a writer that opened a FIFO would wait forever.
ProgramResult run_collide_limited(const std::vector<std::string>& args, const ScratchDirectory& dir) {
    return test::run_collide_within(60, args, dir);
}

const std::string case_id = "head_on_equal__step__seed1";

// The id of a process that has ended (a temporary named after it belongs to no running writer).
pid_t ended_process() {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(0);
    ::waitpid(pid, nullptr, 0);
    return pid;
}

std::string suite_file(const ScratchDirectory& dir) {
    const std::string path = dir.file("suite.toml");
    test::write_text_file(path, "name = \"paths\"\nbackends = [\"step\"]\nreference = \"step\"\nseeds = [1]\n\n"
                                "[[scene]]\nname = \"head_on_equal\"\npath = \"" +
                                    test::scene_file("head_on_equal.toml") + "\"\n");
    return path;
}

// A run with frames for `collide render`, written once for all tests.
const std::string& run_with_frames() {
    static ScratchDirectory dir;
    static const std::string path = [] {
        const std::string h5 = dir.file("frames.h5");
        const auto r = run_collide_limited({"run", test::scene_file("head_on_equal.toml"), "--frames", "--out", h5}, dir);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return h5;
    }();
    return path;
}

// ---- the writers ---------------------------------------------------------------------------

// One writer: the command line that writes the file at `place`, given the scratch directory
// (for its inputs). `named`: the user names the file, so the name itself can be hostile (too
// long, in a missing directory); otherwise the file name is fixed inside an output directory.
struct Writer {
    std::string name;
    std::string suffix;  // how the written file's name ends ("" for a fixed name)
    std::string fixed;   // the fixed file name ("" for a named writer)
    std::function<std::vector<std::string>(const fs::path& place, const ScratchDirectory& dir)> args;
    bool named() const { return fixed.empty(); }
};

std::vector<std::string> render_args(const fs::path& place) {
    return {"render", run_with_frames(), "--out", place.string(), "--frames", "2", "--size", "32x32"};
}

std::string without_suffix(const fs::path& place, const std::string& suffix) {
    const std::string s = place.string();
    return s.substr(0, s.size() - suffix.size());
}

const std::vector<Writer>& writers() {
    static const std::vector<Writer> all = {
        {"run", ".h5", "", [](const fs::path& p, const ScratchDirectory&) -> std::vector<std::string> {
             return {"run", test::scene_file("head_on_equal.toml"), "--out", p.string()};
         }},
        {"render_gif", ".gif", "", [](const fs::path& p, const ScratchDirectory&) { return render_args(p); }},
        {"render_png", ".png", "", [](const fs::path& p, const ScratchDirectory&) { return render_args(p); }},
        {"render_mp4", ".mp4", "", [](const fs::path& p, const ScratchDirectory&) { return render_args(p); }},
        {"view_screenshot", ".png", "", [](const fs::path& p, const ScratchDirectory&) -> std::vector<std::string> {
             return {"view", test::scene_file("head_on_equal.toml"), "--headless", "--frames", "2",
                     "--size", "32x32", "--screenshot", p.string()};
         }},
        {"bench", "-event.csv", "", [](const fs::path& p, const ScratchDirectory&) -> std::vector<std::string> {
             return {"bench", "event", "--quick", "--sizes", "300", "--out", without_suffix(p, "-event.csv")};
         }},
        {"validate_summary", "", "summary.json", [](const fs::path& p, const ScratchDirectory& d) -> std::vector<std::string> {
             return {"validate", suite_file(d), "--out", p.parent_path().string()};
         }},
        {"validate_junit", "", "junit.xml", [](const fs::path& p, const ScratchDirectory& d) -> std::vector<std::string> {
             return {"validate", suite_file(d), "--out", p.parent_path().string()};
         }},
        {"validate_record", "", "cases/" + case_id + ".toml",
         [](const fs::path& p, const ScratchDirectory& d) -> std::vector<std::string> {
             return {"validate", suite_file(d), "--out", p.parent_path().parent_path().string()};
         }},
        {"validate_run", "", "runs/" + case_id + ".h5",
         [](const fs::path& p, const ScratchDirectory& d) -> std::vector<std::string> {
             return {"validate", suite_file(d), "--out", p.parent_path().parent_path().string()};
         }},
        // The files written as they go: a case's log and the output directory's lock.
        {"validate_log", "", "cases/" + case_id + ".log",
         [](const fs::path& p, const ScratchDirectory& d) -> std::vector<std::string> {
             return {"validate", suite_file(d), "--out", p.parent_path().parent_path().string()};
         }},
        {"validate_lock", "", ".lock", [](const fs::path& p, const ScratchDirectory& d) -> std::vector<std::string> {
             return {"validate", suite_file(d), "--out", p.parent_path().string()};
         }},
        // The exports; GSD is written by the Python writer (python/collide/gsd_export.py).
        {"export_gsd", ".gsd", "", [](const fs::path& p, const ScratchDirectory&) -> std::vector<std::string> {
             return {"export", run_with_frames(), "--out", p.string()};
         }},
        {"export_xdmf", ".xdmf", "", [](const fs::path& p, const ScratchDirectory&) -> std::vector<std::string> {
             return {"export", run_with_frames(), "--out", p.string()};
         }},
        {"report_html", "", "report/index.html", [](const fs::path& p, const ScratchDirectory&) -> std::vector<std::string> {
             const fs::path results = p.parent_path().parent_path();
             test::write_text_file((results / "summary.json").string(), "{}\n");
             return {"report", results.string()};
         }},
        {"report_markdown", "", "report/summary.md", [](const fs::path& p, const ScratchDirectory&) -> std::vector<std::string> {
             const fs::path results = p.parent_path().parent_path();
             test::write_text_file((results / "summary.json").string(), "{}\n");
             return {"report", results.string()};
         }},
    };
    return all;
}

// A file name with spaces, quotes and a dash from a seeded generator, ending in `suffix`.
std::string drawn_name(const std::string& writer, const std::string& suffix) {
    std::mt19937 random(unsigned(std::hash<std::string>{}(writer) & 0xffff));
    const std::string alphabet = "abcxyz019 -_'";
    std::string name = "o";
    for (int k = 0; k < 8; ++k) name += alphabet[random() % alphabet.size()];
    return name + suffix;
}

// ---- the hostile places --------------------------------------------------------------------

// Makes the hostile thing at `place` (whose directory exists) and returns the path the
// writer is given; "" with `skip` set when it cannot be made here.
struct Hostile {
    std::string name;
    bool named_only;       // only where the user names the file
    std::string expected;  // the cause the message must name
    std::function<std::string(const fs::path& place, std::string& skip)> make;
    // Whether the place is still what it was (the device a device, ...).
    std::function<bool(const std::string& given)> unchanged;
};

bool is_kind(const std::string& path, mode_t kind) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0 && (st.st_mode & S_IFMT) == kind;
}

const std::vector<Hostile>& hostiles() {
    static const std::vector<Hostile> all = {
        {"character_device", false, "not a regular file (a character device)",
         [](const fs::path& p, std::string& skip) {
             // A twin of /dev/null (major 1, minor 3) inside the scratch directory: the test
             // never goes near the system's own /dev/null.
             if (::mknod(p.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
                 skip = std::string("cannot make a character device here (mknod: ") + std::strerror(errno) +
                        "; it needs root or CAP_MKNOD)";
             return p.string();
         },
         [](const std::string& g) { return is_kind(g, S_IFCHR); }},
        {"fifo", false, "not a regular file (a FIFO)",
         [](const fs::path& p, std::string& skip) {
             if (::mkfifo(p.c_str(), 0644) != 0) skip = std::string("mkfifo: ") + std::strerror(errno);
             return p.string();
         },
         [](const std::string& g) { return is_kind(g, S_IFIFO); }},
        {"dangling_link", false, "a symbolic link to nothing",
         [](const fs::path& p, std::string&) {
             fs::create_symlink("nowhere", p);
             return p.string();
         },
         [](const std::string& g) {
             return is_kind(g, S_IFLNK) && !fs::exists(fs::path(g).parent_path() / "nowhere");
         }},
        {"link_loop", false, "a loop of symbolic links",
         [](const fs::path& p, std::string&) {
             fs::create_symlink(p.filename(), p);  // a link to itself
             return p.string();
         },
         [](const std::string& g) { return is_kind(g, S_IFLNK); }},
        {"directory", false, "a directory of that name exists",
         [](const fs::path& p, std::string&) {
             fs::create_directory(p);
             return p.string();
         },
         [](const std::string& g) { return is_kind(g, S_IFDIR) && fs::is_empty(g); }},
        {"name_too_long", true, "the path is too long (File name too long",
         [](const fs::path& p, std::string&) {
             return (p.parent_path() / (std::string(300, 'n') + p.filename().string())).string();
         },
         [](const std::string& g) { return fs::is_empty(fs::path(g).parent_path()); }},
        {"path_too_long", true, "the path is too long (File name too long",
         [](const fs::path& p, std::string&) {
             fs::path deep = p.parent_path();
             for (int k = 0; k < 24; ++k) deep /= std::string(200, 'd');  // > PATH_MAX in all
             return (deep / p.filename()).string();
         },
         [](const std::string& g) {
             const std::string top = g.substr(0, g.find(std::string(200, 'd')));
             return fs::is_empty(top);
         }},
        {"missing_directory", true, "does not exist",
         [](const fs::path& p, std::string&) { return (p.parent_path() / "no" / "such" / p.filename()).string(); },
         [](const std::string& g) { return !fs::exists(fs::path(g).parent_path().parent_path()); }},
    };
    return all;
}

// ---- the property --------------------------------------------------------------------------

// Printed by name in test names and failures (not as bytes).
void PrintTo(const Writer& writer, std::ostream* out) { *out << writer.name; }
void PrintTo(const Hostile& hostile, std::ostream* out) { *out << hostile.name; }

using Combination = std::tuple<Writer, Hostile>;

// Every writer with every hostile place that applies to it (a fixed file name cannot be too
// long or in a missing directory: collide makes the directory).
std::vector<Combination> combinations() {
    std::vector<Combination> all;
    for (const Writer& writer : writers())
        for (const Hostile& hostile : hostiles())
            if (writer.named() || !hostile.named_only) all.emplace_back(writer, hostile);
    return all;
}

class EveryWriter : public testing::TestWithParam<Combination> {};

bool ffmpeg_missing() { return std::system("command -v ffmpeg >/dev/null 2>&1") != 0; }

std::vector<std::string> temporaries_in(const fs::path& top) {
    std::vector<std::string> found;
    std::error_code error;
    for (auto it = fs::recursive_directory_iterator(top, error); it != fs::recursive_directory_iterator();
         it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.find(".tmp-") != std::string::npos || name.find(".partial") != std::string::npos)
            found.push_back(name);
    }
    return found;
}

TEST_P(EveryWriter, RefusesAPlaceThatIsNotARegularFileAndLeavesItAsItWas) {
    // (MP4 included without ffmpeg: the path is refused before ffmpeg is looked for.)
    const auto& [writer, hostile] = GetParam();
    ScratchDirectory dir;
    const fs::path folder = dir.path() / "out";
    const fs::path place = folder / (writer.named() ? drawn_name(writer.name, writer.suffix) : writer.fixed);
    fs::create_directories(place.parent_path());
    std::string skip;
    const std::string given = hostile.make(place, skip);
    if (!skip.empty()) GTEST_SKIP() << skip;
    const auto result = run_collide_limited(writer.args(given, dir), dir);
    EXPECT_NE(result.exit_code, 0) << result.out;
    EXPECT_NE(result.exit_code, -1) << "no crash: " << result.err;
    EXPECT_NE(result.exit_code, 124) << "no hang";
    EXPECT_TRUE(contains(result.err, "'" + given + "'")) << "the message names the path: " << result.err;
    EXPECT_TRUE(contains(result.err, hostile.expected)) << result.err;
    EXPECT_FALSE(contains(result.err, "Filesystem error")) << "a raw library error: " << result.err;
    EXPECT_TRUE(hostile.unchanged(given)) << given << " is no longer what it was";
    EXPECT_EQ(temporaries_in(folder), std::vector<std::string>{});
}

std::string combination_name(const testing::TestParamInfo<Combination>& info) {
    return std::get<0>(info.param).name + "_" + std::get<1>(info.param).name;
}

INSTANTIATE_TEST_SUITE_P(OutputPaths, EveryWriter, testing::ValuesIn(combinations()), combination_name);

// ---- an output directory (`validate --out DIR`, the report's folder) -----------------------

class EveryOutputDirectory : public testing::TestWithParam<Hostile> {};

TEST_P(EveryOutputDirectory, RefusesAPlaceThatIsNotADirectory) {
    const Hostile& hostile = GetParam();
    for (const bool report : {false, true}) {
        if (report && hostile.named_only) continue;  // the report's folder has a fixed name
        ScratchDirectory dir;
        const fs::path results = dir.path() / "results", spot = dir.path() / "spot";
        fs::create_directory(results);
        fs::create_directory(spot);
        test::write_text_file((results / "summary.json").string(), "{}\n");
        std::string skip;
        const std::string given = hostile.make(report ? results / "report" : spot / "out", skip);
        if (!skip.empty()) GTEST_SKIP() << skip;
        const std::vector<std::string> args =
            report ? std::vector<std::string>{"report", results.string()}
                   : std::vector<std::string>{"validate", suite_file(dir), "--out", given};
        const auto result = run_collide_limited(args, dir);
        EXPECT_NE(result.exit_code, 0) << result.out;
        EXPECT_NE(result.exit_code, -1) << "no crash: " << result.err;
        EXPECT_TRUE(contains(result.err, "'" + given + "'")) << result.err;
        const std::string cause = hostile.expected.find("not a regular file") != std::string::npos
                                      ? "not a directory (it is a " + hostile.expected.substr(hostile.expected.find("(a ") + 3)
                                      : hostile.expected;
        EXPECT_TRUE(contains(result.err, cause)) << cause << ": " << result.err;
        EXPECT_TRUE(hostile.unchanged(given)) << given;
    }
}

// An output directory may exist or be created with its parents; a name too long is the file
// writers' case (the same check).
std::vector<Hostile> hostile_directories() {
    std::vector<Hostile> chosen;
    for (const Hostile& h : hostiles())
        if (h.name != "directory" && h.name != "missing_directory" && h.name != "name_too_long") chosen.push_back(h);
    return chosen;
}

INSTANTIATE_TEST_SUITE_P(OutputPaths, EveryOutputDirectory, testing::ValuesIn(hostile_directories()),
                         [](const testing::TestParamInfo<Hostile>& info) { return info.param.name; });

// ---- a symbolic link to a regular file is followed ------------------------------------------

class EveryWriterFollowingALink : public testing::TestWithParam<Writer> {};

TEST_P(EveryWriterFollowingALink, ReplacesTheFileAndKeepsTheLink) {
    const Writer& writer = GetParam();
    if (writer.name == "render_mp4" && ffmpeg_missing()) GTEST_SKIP() << "MP4 needs ffmpeg, not installed here";
    ScratchDirectory dir;
    const fs::path folder = dir.path() / "out";
    const fs::path place = folder / (writer.named() ? drawn_name(writer.name, writer.suffix) : writer.fixed);
    fs::create_directories(place.parent_path());
    const fs::path real = dir.path() / ("real" + place.extension().string());
    test::write_text_file(real.string(), "old");
    fs::create_symlink(real, place);
    const auto result = run_collide_limited(writer.args(place, dir), dir);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(fs::is_symlink(place)) << "the link stays a link";
    EXPECT_NE(test::read_text_file(real.string()), "old") << "the file it points to holds the new output";
    EXPECT_EQ(temporaries_in(dir.path()), std::vector<std::string>{});
}

// Left out: the report, which needs a whole suite's results to render (its writer follows a
// link in tests/report/test_safe_output.py), a case record, which `validate` removes
// before its case runs, so that a case that dies is not taken for a finished one, and the log
// and the lock, which refuse a link (LogsAndLocksAreNeverWrittenThroughALink).
std::vector<Writer> writers_of_a_followed_link() {
    std::vector<Writer> chosen;
    for (const Writer& w : writers())
        if (w.name.rfind("report", 0) != 0 && w.name != "validate_record" && w.name != "validate_log" &&
            w.name != "validate_lock")
            chosen.push_back(w);
    return chosen;
}

INSTANTIATE_TEST_SUITE_P(OutputPaths, EveryWriterFollowingALink, testing::ValuesIn(writers_of_a_followed_link()),
                         [](const testing::TestParamInfo<Writer>& info) { return info.param.name; });


// collide's own files in its output directory are never written through a link: a `.lock`
// linked out of the directory truncated its target, a log linked elsewhere was written there.
TEST(OutputPaths, LogsAndLocksAreNeverWrittenThroughALink) {
    for (const std::string& name : {std::string(".lock"), "cases/" + case_id + ".log"}) {
        ScratchDirectory dir;
        const fs::path out = dir.path() / "out", precious = dir.path() / "precious.txt";
        fs::create_directories(out / "cases");
        test::write_text_file(precious.string(), "keep me");
        fs::create_symlink(precious, out / name);
        const auto r = run_collide_limited({"validate", suite_file(dir), "--out", out.string()}, dir);
        EXPECT_NE(r.exit_code, 0) << name;
        const std::string quoted = std::string("'").append((out / name).string()).append("'");  // GCC 12 warns falsely on "'" + s
        EXPECT_TRUE(contains(r.err, quoted)) << r.err;
        EXPECT_TRUE(contains(r.err, "symbolic link")) << r.err;
        EXPECT_EQ(test::read_text_file(precious.string()), "keep me") << name;
        EXPECT_TRUE(fs::is_symlink(out / name)) << name;
    }
}

// An output that is the command's input (the same file, or a link to it) is refused before
// anything is written: `collide export run.h5 --out run.h5` destroyed the only copy.
TEST(OutputPaths, OutputIsNotInput) {
    ScratchDirectory dir;
    const std::string run = dir.file("run.h5"), scene = dir.file("scene.toml"), link = dir.file("link.xyz");
    const std::string gif = dir.file("run.gif");  // a run file named as render's output
    fs::copy_file(run_with_frames(), run);
    fs::copy_file(run_with_frames(), gif);
    fs::copy_file(test::scene_file("head_on_equal.toml"), scene);
    fs::create_symlink(run, link);
    const std::string run_bytes = test::read_text_file(run), scene_bytes = test::read_text_file(scene);
    const std::string gif_bytes = test::read_text_file(gif);
    const std::vector<std::vector<std::string>> commands = {
        {"export", run, "--out", run, "--format", "xyz"},
        {"export", run, "--out", link},
        {"render", gif, "--out", gif},
        {"run", scene, "--out", scene},
    };
    for (const auto& args : commands) {
        const auto r = run_collide_limited(args, dir);
        EXPECT_NE(r.exit_code, 0) << args[0] << " " << args[3];
        EXPECT_TRUE(contains(r.err, "it is the input")) << args[0] << ": " << r.err;
    }
    EXPECT_EQ(test::read_text_file(run), run_bytes);
    EXPECT_EQ(test::read_text_file(scene), scene_bytes);
    EXPECT_EQ(test::read_text_file(gif), gif_bytes);
    EXPECT_TRUE(fs::is_symlink(link));
}

// A FIFO given as any command's input is refused at once (every reading command waited on it
// for good).
TEST(InputPaths, NonRegularInputsRefused) {
    ScratchDirectory dir;
    const std::string fifo = dir.file("fifo.toml"), results = dir.file("results"), other = dir.file("other");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    for (const std::string& d : {results, other}) {
        fs::create_directories(d);
        ASSERT_EQ(::mkfifo((d + "/summary.json").c_str(), 0644), 0);
    }
    const std::vector<std::vector<std::string>> commands = {
        {"run", fifo}, {"view", fifo, "--headless"}, {"validate", fifo, "--out", dir.file("v")},
        {"export", fifo, "--out", dir.file("x.xyz")}, {"render", fifo, "--out", dir.file("x.gif")},
        {"report", results}, {"compare", other, results}, {"explain", results, "case"}};
    for (const auto& args : commands) {
        const auto r = run_collide_limited(args, dir);
        EXPECT_NE(r.exit_code, 0) << args[0];
        EXPECT_NE(r.exit_code, 124) << args[0] << " waited on the FIFO";
        EXPECT_TRUE(contains(r.err, "FIFO")) << args[0] << ": " << r.err;
    }
}

// A FIFO named like a case log hung `validate` for good, deaf to SIGINT and SIGTERM (the case
// blocked opening it, and after the case's time limit the runner blocked reading it). Now it is
// refused before any case runs; a SIGTERM after 10 s (timeout(1)) would end it in any case,
// and a KILL 5 s later (exit 137) would mean it ignored the TERM.
TEST(OutputPaths, AFifoPlantedAsACaseLogNeitherHangsNorIgnoresSignals) {
    ScratchDirectory dir;
    const fs::path out = dir.path() / "out";
    fs::create_directories(out / "cases");
    ASSERT_EQ(::mkfifo((out / "cases" / (case_id + ".log")).c_str(), 0644), 0);
    std::string suite = test::read_text_file(suite_file(dir));
    suite.insert(suite.find("[[scene]]"), "time_limit = 1\n");
    test::write_text_file(dir.file("suite.toml"), suite);
    const auto start = std::chrono::steady_clock::now();
    const auto r = test::run_program("timeout", {"--signal=TERM", "--kill-after=5", "10", COLLIDE_EXECUTABLE,
                                                 "validate", dir.file("suite.toml"), "--out", out.string()}, dir);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NE(r.exit_code, 137) << "SIGTERM was ignored";
    EXPECT_LT(seconds, 14.0);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_TRUE(contains(r.err, "a FIFO")) << r.err;
}

// A kill during the summary's rename leaves `.summary.json.tmp-PID-K`: --resume and report remove
// it and say so.
TEST(OutputPaths, ResumeAndReportRemoveAnInterruptedRunsTemporaries) {
    ScratchDirectory dir;
    const fs::path out = dir.path() / "out";
    ASSERT_EQ(run_collide_limited({"validate", suite_file(dir), "--out", out.string()}, dir).exit_code, 0);
    const std::string stale = ".summary.json.tmp-" + std::to_string(ended_process()) + "-0";
    for (const char* command : {"validate", "report"}) {
        test::write_text_file((out / stale).string(), "{");
        const auto r = std::string(command) == "validate"
                           ? run_collide_limited({"validate", suite_file(dir), "--out", out.string(), "--resume"}, dir)
                           : run_collide_limited({"report", out.string()}, dir);
        EXPECT_FALSE(fs::exists(out / stale)) << command;
        EXPECT_TRUE(contains(r.out + r.err, stale)) << command << ": " << r.out << r.err;
    }
}

// Every command's input path (scene, suite, run file, results directory) names the system's
// cause: a loop of links was "File does not exist" (CLI11's ExistingFile), a path too long
// "cannot open scene file".
TEST(InputPaths, EveryReaderNamesALoopOfLinksAndAPathTooLong) {
    ScratchDirectory dir;
    const std::string a = dir.file("a"), b = dir.file("b");
    std::filesystem::create_symlink("b", a);
    std::filesystem::create_symlink("a", b);
    const std::string too_long = dir.file(std::string(300, 'n') + ".toml");
    const std::vector<std::vector<std::string>> commands = {
        {"run", a}, {"view", a, "--headless"}, {"render", a, "--out", dir.file("x.gif")},
        {"validate", a, "--out", dir.file("results")}, {"report", a}, {"export", a, "--out", dir.file("x.xyz")},
        {"explain", a, "case"}};
    for (const auto& args : commands) {
        const auto r = run_collide_limited(args, dir);
        EXPECT_NE(r.exit_code, 0) << args[0];
        EXPECT_TRUE(test::contains(r.err, "loop of symbolic links")) << args[0] << ": " << r.err;
    }
    for (const char* command : {"run", "view", "validate"}) {
        const auto r = run_collide_limited({command, too_long}, dir);
        EXPECT_TRUE(test::contains(r.err, "too long")) << command << ": " << r.err;
    }
}

}  // namespace
}  // namespace collide
