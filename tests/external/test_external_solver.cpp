// An outside solver is untrusted input: every fault of docs/your-solver.md ("What collide
// checks") must end the run with a message that names the solver, the scene and the fault,
// and a correct answer must come through bit for bit. The fake solvers here copy a prepared
// response into the request directory (or misbehave in the shell), so each fault is exact.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <sys/resource.h>
#include <cstdlib>

#include "core/run_driver.h"
#include "external/external_solver.h"
#include "external/npy.h"
#include "external/program_call.h"
#include "external/sha256.h"
#include "external/solver_files.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide::external {
namespace {

// Two disks flying apart in a 10 x 10 box; output at 0, 0.5, 1.
struct Fixture {
    Scene scene = test::box_scene(10, 10);
    ParticleState<double> initial = test::make_state({{3, 5, -1, 0, 0.5, 1}, {7, 5, 1, 0, 0.5, 1}});
    test::ScratchDirectory dir;
    Fixture() {
        scene.name = "two_apart";
        scene.run.duration = 1;
        scene.run.output_interval = 0.5;
        scene.run.dt = 0.01;
    }
    // The exact free flight at the requested times 0.5 and 1, as the solver would write it.
    std::vector<double> states(std::size_t disks = 2, std::size_t columns = 4) const {
        std::vector<double> out;
        for (double t : {0.5, 1.0})
            for (std::size_t i = 0; i < disks; ++i)
                for (std::size_t c = 0; c < columns; ++c) {
                    const std::size_t k = i % 2;
                    const double v[4] = {initial.x[k] + initial.vx[k] * t, initial.y[k], initial.vx[k], initial.vy[k]};
                    out.push_back(v[c % 4]);
                }
        return out;
    }
    // A solver that copies `npy` and `result` into the request directory.
    ExternalSolverSpec answering(const std::string& npy, const std::string& result) const {
        test::write_text_file(dir.file("states.npy"), npy);
        test::write_text_file(dir.file("result.txt"), result);
        return shell("cp states.npy result.txt");  // the request directory is appended
    }
    ExternalSolverSpec shell(const std::string& command, double limit = 20) const {
        ExternalSolverSpec spec;
        spec.name = "mine";
        spec.command = command;
        spec.directory = dir.path().string();
        spec.call_time_limit = limit;
        return spec;
    }
    RunResult run(const ExternalSolverSpec& spec) const {
        auto solver = make_external_solver(spec);
        return run_scene(scene, *solver, initial);
    }
    // The message of the run's failure (fails the test when the run succeeds).
    std::string fault(const ExternalSolverSpec& spec) const {
        try {
            run(spec);
        } catch (const std::exception& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("solver 'mine'"), std::string::npos) << message;
            EXPECT_NE(message.find("scene two_apart"), std::string::npos) << message;
            return message;
        }
        ADD_FAILURE() << "the run succeeded";
        return "";
    }
};

const std::string good_times = "times 0.5 1\n";

TEST(ExternalSolver, ACorrectAnswerComesThroughBitForBit) {
    Fixture f;
    const RunResult r = f.run(f.answering(npy_bytes(f.states(), {2, 2, 4}), good_times + "steps 100\ncontacts 0\nversion v1.2\n"));
    EXPECT_EQ(r.final_state.x[0], 2.0);
    EXPECT_EQ(r.final_state.x[1], 8.0);
    EXPECT_EQ(r.final_state.vx[1], 1.0);
    EXPECT_EQ(r.stats.steps, 100);
    EXPECT_EQ(r.stats.counters.at("program_calls"), 1.0);  // one call for the whole run
    auto solver = make_external_solver(f.answering(npy_bytes(f.states(), {2, 2, 4}), good_times + "version v1.2\n"));
    run_scene(f.scene, *solver, f.initial);
    const auto p = solver->provenance();
    EXPECT_EQ(p.at("solver_version"), "v1.2");
    EXPECT_EQ(p.at("solver_command"), "cp states.npy result.txt");
}

// Protocol 2: the solver's own `seconds` summed over its calls, whether it counted contacts, a
// variant's settings as option lines, and a bad `seconds` named with its line.
TEST(ExternalSolver, Protocol2SecondsContactsAndOptionLines) {
    Fixture f;
    const RunResult r = f.run(f.answering(npy_bytes(f.states(), {2, 2, 4}), good_times + "contacts 3\nseconds 0.25\n"));
    EXPECT_EQ(r.stats.counters.at("solver_seconds"), 0.25);
    EXPECT_EQ(r.stats.counters.at("contacts_reported"), 1.0);
    EXPECT_EQ(r.stats.counters.count("solver_seconds_missing"), 0u);
    const RunResult silent = f.run(f.answering(npy_bytes(f.states(), {2, 2, 4}), good_times));
    EXPECT_EQ(silent.stats.counters.at("contacts_reported"), 0.0);
    EXPECT_EQ(silent.stats.counters.at("solver_seconds_missing"), 1.0);
    EXPECT_NE(f.fault(f.answering(npy_bytes(f.states(), {2, 2, 4}), good_times + "seconds -1\n"))
                  .find("result.txt line 2: seconds: expected a number of seconds >= 0"),
              std::string::npos);
    const std::string keep = f.dir.file("kept");
    f.scene.backend_options["mine"] = {{"preset", "shipped"}};
    try {
        f.run(f.shell("cp -r \"$1\" " + keep + "; exit 1"));
    } catch (const std::exception&) {
    }
    EXPECT_NE(test::read_text_file(keep + "/request.txt").find("option preset shipped\n"), std::string::npos);
}

// The files a command names are found as the shell splits its words: a path with a space or a
// quote in it, quoted or escaped, is one file and is hashed (it was left out of the provenance).
TEST(ExternalSolver, ProvenanceHashesEveryFileTheShellWouldRun) {
    Fixture f;
    const std::vector<std::string> names = {"my solver.py", "it's.py", "say \"hi\".py", "back\\slash.py"};
    const std::string command = "python3 'my solver.py' \"it's.py\" 'say \"hi\".py' back\\\\slash.py";
    for (const std::string& name : names) test::write_text_file(f.dir.file(name), "print('" + name + "')\n");
    auto solver = make_external_solver(f.shell(command));
    const std::string hashes = solver->provenance().at("solver_files_sha256");
    for (const std::string& name : names)
        EXPECT_NE(hashes.find(name + " " + sha256_file(f.dir.file(name))), std::string::npos) << name << ": " << hashes;
}

TEST(ExternalSolver, ATimeOffByRoundingIsAccepted) {
    Fixture f;
    EXPECT_NO_THROW(f.run(f.answering(npy_bytes(f.states(), {2, 2, 4}), "times 0.50000000000000011 0.99999999999999989\n")));
}

TEST(ExternalSolver, ACrashFails) {
    Fixture f;
    EXPECT_NE(f.fault(f.shell("kill -SEGV $$")).find("killed by signal 11"), std::string::npos);
}

TEST(ExternalSolver, ANonZeroExitFailsAndQuotesItsOutputEscaped) {
    Fixture f;
    const std::string m = f.fault(f.shell("printf 'Traceback: bad\\033[31m<b>\\n'; exit 3"));
    EXPECT_NE(m.find("exit status 3"), std::string::npos) << m;
    EXPECT_NE(m.find("Traceback: bad\\x1b[31m<b>"), std::string::npos) << m;  // the escape byte shown, not sent
    EXPECT_EQ(m.find('\033'), std::string::npos);
}

TEST(ExternalSolver, AHangIsKilledAtTheLimit) {
    Fixture f;
    const auto start = std::chrono::steady_clock::now();
    const std::string m = f.fault(f.shell("sleep 30; true", 0.5));
    EXPECT_NE(m.find("still running after the limit of 0.5 s"), std::string::npos) << m;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10);
}

TEST(ExternalSolver, AProgramThatDoesNotExistFails) {
    Fixture f;
    const std::string m = f.fault(f.shell("./no-such-solver-program"));
    EXPECT_NE(m.find("exit status 127"), std::string::npos) << m;
}

TEST(ExternalSolver, NoResultFileFails) {
    Fixture f;
    EXPECT_NE(f.fault(f.shell("true")).find("wrote no result.txt"), std::string::npos);
}

TEST(ExternalSolver, NanOrInfFails) {
    Fixture f;
    auto states = f.states();
    states[4 * 3 + 2] = std::nan("");  // t = 1, disk 1, vx
    const std::string m = f.fault(f.answering(npy_bytes(states, {2, 2, 4}), good_times));
    EXPECT_NE(m.find("NaN/Inf) at t = 1, disk 1, vx"), std::string::npos) << m;
    states[4 * 3 + 2] = INFINITY;
    EXPECT_NE(f.fault(f.answering(npy_bytes(states, {2, 2, 4}), good_times)).find("NaN/Inf"), std::string::npos);
}

TEST(ExternalSolver, TheWrongNumberOfDisksFails) {
    Fixture f;
    const std::string m = f.fault(f.answering(npy_bytes(f.states(3), {2, 3, 4}), good_times));
    EXPECT_NE(m.find("shape (2, 3, 4), expected (2, 2, 4)"), std::string::npos) << m;
}

TEST(ExternalSolver, TheWrongShapeFails) {
    Fixture f;
    const std::string m = f.fault(f.answering(npy_bytes(f.states(2, 3), {2, 2, 3}), good_times));
    EXPECT_NE(m.find("shape (2, 2, 3), expected (2, 2, 4)"), std::string::npos) << m;
}

TEST(ExternalSolver, TheWrongTypeFails) {
    Fixture f;
    std::string bytes = npy_bytes(f.states(), {2, 2, 4});
    bytes.replace(bytes.find("<f8"), 3, "<f4");
    const std::string m = f.fault(f.answering(bytes, good_times));
    EXPECT_NE(m.find("dtype '<f4', expected '<f8'"), std::string::npos) << m;
}

TEST(ExternalSolver, TheWrongTimeFails) {
    Fixture f;
    const std::string m = f.fault(f.answering(npy_bytes(f.states(), {2, 2, 4}), "times 0.5 0.9\n"));
    EXPECT_NE(m.find("output time 1 is 0.9, expected 1"), std::string::npos) << m;
    EXPECT_NE(f.fault(f.answering(npy_bytes(f.states(), {2, 2, 4}), "times 0.5\n")).find("lists 1 output times, expected 2"),
              std::string::npos);
}

TEST(ExternalSolver, GarbageFails) {
    Fixture f;
    EXPECT_NE(f.fault(f.answering("\x01garbage", good_times)).find("not a .npy file"), std::string::npos);
    const std::string cut = npy_bytes(f.states(), {2, 2, 4});
    EXPECT_NE(f.fault(f.answering(cut.substr(0, cut.size() - 5), good_times)).find("bytes of data"), std::string::npos);
    EXPECT_NE(f.fault(f.answering(cut, "tims 0.5 1\n")).find("unknown key 'tims'"), std::string::npos);
    EXPECT_NE(f.fault(f.answering(cut, "times 0.5 one\n")).find("'one' is not a number"), std::string::npos);
}

TEST(ExternalSolver, GarbageOnStdoutAloneIsHarmless) {
    Fixture f;  // the program's output goes to the case log; only the files are the answer
    test::write_text_file(f.dir.file("states.npy"), npy_bytes(f.states(), {2, 2, 4}));
    test::write_text_file(f.dir.file("result.txt"), good_times);
    EXPECT_NO_THROW(f.run(f.shell("head -c 300 /dev/urandom; cp states.npy result.txt")));
}

TEST(ExternalSolver, ARefusalLeavesTheSceneOut) {
    Fixture f;
    EXPECT_THROW(f.run(f.answering("", "refuse no walls here\n")), SceneRefused);
}

TEST(ExternalSolver, TheRequestHoldsTheCaseAndTheInitialState) {
    Fixture f;  // a solver that keeps its request for the test to read
    const std::string keep = f.dir.file("kept");
    try {
        f.run(f.shell("cp -r \"$1\" " + keep + "; exit 1"));
    } catch (const std::exception&) {
    }
    const std::string request = test::read_text_file(keep + "/request.txt");
    EXPECT_NE(request.find("protocol " + std::to_string(protocol_version) + "\n"), std::string::npos);
    EXPECT_NE(request.find("output_times 0.5 1\n"), std::string::npos);
    EXPECT_NE(request.find("dt 0.01\n"), std::string::npos);
    EXPECT_NE(request.find("disks 2\n"), std::string::npos);
    const NpyArray initial = read_npy(keep + "/initial.npy");
    EXPECT_EQ(initial.shape, (std::vector<std::size_t>{2, 7}));
    EXPECT_EQ(initial.data[7 + 0], 7.0);   // disk 1: x
    EXPECT_EQ(initial.data[7 + 6], 0.0);   // not a stone
}

TEST(Npy, RoundTripsAndRefusesFortranOrder) {
    const std::vector<double> data = {1, -2.5, 1e-300, 3};
    const NpyArray back = parse_npy(npy_bytes(data, {2, 2}));
    EXPECT_EQ(back.data, data);
    EXPECT_EQ(npy_bytes(data, {4}).find("(4,)") != std::string::npos, true);
    std::string fortran = npy_bytes(data, {2, 2});
    fortran.replace(fortran.find("False"), 5, "True ");
    EXPECT_THROW(parse_npy(fortran), NpyError);
}

// The header is read without std::regex, whose recursion per repeated character overflowed the
// stack on a header of 65,000 spaces (the case worker died by signal 11). Spaces wherever the
// format allows them, and double quotes, read as NumPy reads them.
TEST(Npy, NoRegexOnInputText) {
    // A run of spaces that a backtracking std::regex recursed over once a character (65,000
    // overflowed its stack): within NumPy's 10,000-byte bound it is read, past it refused.
    const std::vector<double> data = {1, 2};
    const auto with_spaces = [&](std::size_t count) {
        const std::string header = "{\"descr\":" + std::string(count, ' ') + "'<f8',\t'fortran_order'  :  False, 'shape':(2,)}\n";
        std::string bytes = std::string("\x93NUMPY\x01\x00", 8) + char(header.size() & 0xff) + char(header.size() >> 8);
        return bytes + header + std::string(reinterpret_cast<const char*>(data.data()), 2 * sizeof(double));
    };
    EXPECT_EQ(parse_npy(with_spaces(9000)).data, data);
    EXPECT_THROW(parse_npy(with_spaces(65000)), NpyError);
    std::string unclosed = npy_bytes(data, {2});  // a key's closing quote missing: named, not searched for
    unclosed.replace(unclosed.find("'shape'"), 7, "'shapes");
    try {
        parse_npy(unclosed);
        ADD_FAILURE() << "no NpyError";
    } catch (const NpyError& e) {
        EXPECT_NE(std::string(e.what()).find("expected the closing quote"), std::string::npos) << e.what();
    }
}

TEST(Sha256, MatchesTheStandardTestVectors) {
    // FIPS 180-4 examples: "abc" and the 448-bit message (two blocks after padding).
    EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
              "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(SolverOption, NamesAndCommandsAreChecked) {
    EXPECT_EQ(parse_solver_option("mine=python3 x.py").command, "python3 x.py");
    EXPECT_THROW(parse_solver_option("mine"), std::invalid_argument);
    EXPECT_THROW(parse_solver_option("Mine=x"), std::invalid_argument);
    EXPECT_THROW(parse_solver_option("a/b=x"), std::invalid_argument);
    EXPECT_THROW(parse_solver_option("mine=  "), std::invalid_argument);
}

}  // namespace
}  // namespace collide::external

namespace collide::external {
namespace {

// A version 1.0 .npy file with the header text given (a newline is added) and the data.
std::string npy_with_header(std::string header, const std::vector<double>& data) {
    header += '\n';
    std::string bytes = std::string("\x93NUMPY\x01\x00", 8) + char(header.size() & 0xff) + char(header.size() >> 8) + header;
    for (double v : data) bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
    return bytes;
}

// A .npy header is untrusted text: a header of 65,000 spaces overflowed std::regex's stack and
// killed the case worker (signal 11, no solver named, its request directory left behind). A
// header longer than NumPy's own limit is refused with the solver and the file named, and the
// request directory is removed.
TEST(NpyHeaderBounds, AHeaderOfSpacesIsRefusedNamingTheSolverAndTheFile) {
    Fixture f;
    const std::string requests = f.dir.file("requests");
    std::filesystem::create_directory(requests);
    const char* old = std::getenv("TMPDIR");
    const std::string saved = old ? old : "";
    ::setenv("TMPDIR", requests.c_str(), 1);
    // The spaces where the regex's \s* recursed once per space.
    const std::string header = "{'descr':" + std::string(65000, ' ') + "'<f8', 'fortran_order': False, 'shape': (2, 2, 4), }";
    const std::string m = f.fault(f.answering(npy_with_header(header, f.states()), good_times));
    old ? ::setenv("TMPDIR", saved.c_str(), 1) : ::unsetenv("TMPDIR");
    EXPECT_NE(m.find("states.npy"), std::string::npos) << m;
    EXPECT_NE(m.find("states.npy: the .npy header is " + std::to_string(header.size() + 1) +
                     " bytes long, more than the 10000 NumPy itself reads"), std::string::npos) << m;
    EXPECT_TRUE(std::filesystem::is_empty(requests)) << "a request directory was left behind";
    // Spaces NumPy accepts (a header padded to its limit, spaces between tokens) still read.
    const std::string padded = "{ 'descr' :" + std::string(9000, ' ') + "'<f8' ,'fortran_order':False,\n'shape':( 2 , 2 , 4 , ) }  ";
    EXPECT_EQ(parse_npy(npy_with_header(padded, f.states())).shape, (std::vector<std::size_t>{2, 2, 4}));
}

// The request fixes the answer's shape and size: an answer of another size is refused from its
// header and its file size, before its data is read (a 2 GiB states.npy for a 128-byte answer
// was read whole: its size in memory, std::bad_alloc under a memory limit).
TEST(AnswerSizeCheckedBeforeReading, AnOversizedAnswerIsRefusedUnread) {
    Fixture f;
    const std::string big = f.dir.file("big.npy");
    test::write_text_file(big, npy_bytes(f.states(), {2, 2, 4}));
    std::filesystem::resize_file(big, std::uintmax_t(2) << 30);  // sparse: no disk space
    struct rusage before {};
    ::getrusage(RUSAGE_SELF, &before);
    try {
        read_npy(big, std::vector<std::size_t>{2, 2, 4});
        ADD_FAILURE() << "a 2 GiB file for a 128-byte answer was accepted";
    } catch (const NpyError& e) {
        EXPECT_NE(std::string(e.what()).find("bytes of data"), std::string::npos) << e.what();
    }
    struct rusage after {};
    ::getrusage(RUSAGE_SELF, &after);
    EXPECT_LT(after.ru_maxrss - before.ru_maxrss, 100 * 1024) << "KiB more peak memory: the data was read";
    // A header that claims another shape is refused before the size is even looked at.
    const std::string m = f.fault(f.answering(npy_bytes(std::vector<double>(8000), {1000, 2, 4}), good_times));
    EXPECT_NE(m.find("shape (1000, 2, 4), expected (2, 2, 4)"), std::string::npos) << m;
}

// Python's dict keeps the last of two equal keys, so NumPy reads {'descr': '<f8', 'descr': '>f8'}
// as big-endian; a reader that kept the first would read another array. Both are refused.
TEST(NpyDuplicateHeaderKeysRefused, TwoDescrKeysAreRefused) {
    Fixture f;
    const std::string twice = "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2, 4), 'descr': '>f8', }";
    const std::string m = f.fault(f.answering(npy_with_header(twice, f.states()), good_times));
    EXPECT_NE(m.find("the header names 'descr' twice"), std::string::npos) << m;
    const std::string extra = "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2, 4), 'x': True}";
    const std::string e = f.fault(f.answering(npy_with_header(extra, f.states()), good_times));
    EXPECT_NE(e.find("the header has the key 'x'; NumPy accepts only descr, fortran_order and shape"), std::string::npos) << e;
}

// An answer file that is there but is no regular file is named for what it is (a FIFO would
// block a reader for good; the message said "wrote no states.npy").
TEST(AnswerFileKindNamed, AFifoOrDirectoryAnswerIsNamedForWhatItIs) {
    Fixture f;
    test::write_text_file(f.dir.file("result.txt"), good_times);
    const std::string fifo = f.fault(f.shell("sh -c 'cp result.txt \"$1\"; mkfifo \"$1/states.npy\"' sh"));
    EXPECT_NE(fifo.find("wrote states.npy as a FIFO, not a regular file"), std::string::npos) << fifo;
    const std::string directory = f.fault(f.shell("sh -c 'cp result.txt \"$1\"; mkdir \"$1/states.npy\"' sh"));
    EXPECT_NE(directory.find("wrote states.npy as a directory, not a regular file"), std::string::npos) << directory;
    const std::string result = f.fault(f.shell("sh -c 'mkdir \"$1/result.txt\"' sh"));
    EXPECT_NE(result.find("wrote result.txt as a directory"), std::string::npos) << result;
}

// A data file named in the solver's command is hashed for the provenance once per process,
// and a file over 256 MiB only in its first 64 MiB beside its size and time, as the text says
// (a 3 GiB file, hashed whole in every call, had every case run into its time limit).
TEST(SolverFileHashingBounded, ALargeFileIsHashedByItsPrefixAndSaysSo) {
    Fixture f;
    const std::string data = f.dir.file("data.bin");
    test::write_text_file(data, "x");
    std::filesystem::resize_file(data, whole_hash_limit_bytes + 1);  // sparse
    ExternalSolverSpec spec = f.shell("true data.bin");
    const std::string files = make_external_solver(spec)->provenance().at("solver_files_sha256");
    const std::string prefix = std::to_string(hashed_prefix_bytes >> 20) + " MiB ";
    EXPECT_EQ(files, "data.bin sha256 of the first " + prefix + sha256_file(data, hashed_prefix_bytes) + ", size " +
                         std::to_string(whole_hash_limit_bytes + 1) + " bytes, modified " + files.substr(files.size() - 20));
    EXPECT_EQ(files.substr(files.size() - 1), "Z");
}

}  // namespace
}  // namespace collide::external
