// An outside solver is untrusted input: every fault of docs/your-solver.md ("What collide
// checks") must end the run with a message that names the solver, the scene and the fault,
// and a correct answer must come through bit for bit. The fake solvers here copy a prepared
// response into the request directory (or misbehave in the shell), so each fault is exact.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/run_driver.h"
#include "external/external_solver.h"
#include "external/npy.h"
#include "external/program_call.h"
#include "external/sha256.h"
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
    EXPECT_NE(request.find("protocol 1\n"), std::string::npos);
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
