// A long-lived outside solver (docs/your-solver.md, "A solver that serves many calls"): started
// once for many calls, and whatever it does in one call (dies, hangs, answers garbage) fails
// that call alone, naming the solver, while the next call starts it again. The server here is a
// shell script that counts its starts and ends in starts.txt and misbehaves by the scene's seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <sstream>

#include "core/process/descendants.h"
#include "core/run_driver.h"
#include "external/external_solver.h"
#include "external/npy.h"
#include "external/solver_server.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide::external {
namespace {

// Seed 2: it kills itself (SIGSEGV); 3: it hangs; 4: it answers garbage; 5: it answers
// "failed"; 6: it answers twice; any other: it copies the prepared answer (free flight of two
// disks) and says done.
const char* const server_script = R"(echo "start $$" >> starts.txt
[ "$1" = --serve ] || { echo "expected --serve, got $1" >&2; exit 9; }
while IFS= read -r request; do
  seed=$(sed -n 's/^seed //p' "$request/request.txt")
  echo "request seed $seed" >&2
  case "$seed" in
    2) kill -SEGV $$ ;;
    3) sleep 30 ;;
    4) echo hello ;;
    5) echo "failed no answer for seed 5" ;;
    6) cp states.npy result.txt "$request/"; echo done; echo done ;;
    *) cp states.npy result.txt "$request/"; echo done ;;
  esac
done
echo "exit $$" >> starts.txt
)";

struct Fixture {
    Scene scene = test::box_scene(10, 10);
    ParticleState<double> initial = test::make_state({{3, 5, -1, 0, 0.5, 1}, {7, 5, 1, 0, 0.5, 1}});
    test::ScratchDirectory dir;
    ExternalSolverSpec spec;

    explicit Fixture(double limit = 20) {
        scene.name = "two_apart";
        scene.run.duration = 1;
        scene.run.output_interval = 0.5;
        scene.run.dt = 0.01;
        std::vector<double> states;
        for (double t : {0.5, 1.0})
            for (std::size_t i = 0; i < 2; ++i)
                for (double v : {initial.x[i] + initial.vx[i] * t, initial.y[i], initial.vx[i], initial.vy[i]}) states.push_back(v);
        test::write_text_file(dir.file("states.npy"), npy_bytes(states, {2, 2, 4}));
        test::write_text_file(dir.file("result.txt"), "times 0.5 1\nseconds 0.125\n");
        test::write_text_file(dir.file("serve.sh"), server_script);
        spec.name = "mine";
        spec.command = "exec sh serve.sh";
        spec.directory = dir.path().string();
        spec.call_time_limit = limit;
        spec.long_lived = true;
    }
    ~Fixture() { close_solver_servers(); }

    RunResult run(int seed) {
        scene.seed = seed;
        auto solver = make_external_solver(spec);
        return run_scene(scene, *solver, initial);
    }
    // The fault of a run that must fail (fails the test when it succeeds).
    std::string fault(int seed) {
        try {
            run(seed);
        } catch (const std::exception& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("solver 'mine', scene two_apart (seed " + std::to_string(seed)), std::string::npos) << message;
            return message;
        }
        ADD_FAILURE() << "the run with seed " << seed << " succeeded";
        return "";
    }
    // How many lines of starts.txt begin with `word` ("start", "exit").
    int count(const std::string& word) const {
        std::istringstream lines(test::read_text_file(dir.file("starts.txt")));
        int n = 0;
        for (std::string line; std::getline(lines, line);) n += line.rfind(word + " ", 0) == 0;
        return n;
    }
};

double counter(const RunResult& r, const std::string& name) {
    const auto found = r.stats.counters.find(name);
    return found == r.stats.counters.end() ? 0 : found->second;
}

TEST(LongLivedSolver, OneStartServesManyCallsAndEndsAtEndOfFile) {
    Fixture f;
    for (int k = 0; k < 4; ++k) {
        const RunResult r = f.run(1);  // a new Solver each time, as each case makes one
        EXPECT_EQ(r.final_state.x[1], 8.0);
        EXPECT_EQ(counter(r, "solver_seconds"), 0.125);
        EXPECT_EQ(counter(r, "server_starts"), k == 0 ? 1.0 : 0.0);
    }
    EXPECT_EQ(f.count("start"), 1);
    EXPECT_EQ(f.count("exit"), 0);
    close_solver_servers();  // what a worker does before it exits
    EXPECT_EQ(f.count("exit"), 1);  // it read end of file and left its loop
    EXPECT_TRUE(child_processes().empty());  // reaped: no zombie
}

TEST(LongLivedSolver, ACrashFailsThatCallAloneAndTheNextCallStartsItAgain) {
    Fixture f;
    EXPECT_NO_THROW(f.run(1));
    const std::string m = f.fault(2);
    EXPECT_NE(m.find("its server ended before answering: killed by signal 11"), std::string::npos) << m;
    EXPECT_NE(m.find("request seed 2"), std::string::npos) << m;  // its output of this call, quoted
    EXPECT_EQ(m.find("request seed 1"), std::string::npos) << m;  // not that of the call before
    EXPECT_EQ(f.run(1).final_state.x[0], 2.0);
    EXPECT_EQ(f.count("start"), 2);
    EXPECT_TRUE(child_processes().size() == 1);  // the new server alone; the dead one reaped
}

TEST(LongLivedSolver, AHangIsKilledAtTheLimitWithWhatItStartedAndTheNextCallPasses) {
    Fixture f(1.0);
    EXPECT_NO_THROW(f.run(1));
    const auto start = std::chrono::steady_clock::now();
    const std::string m = f.fault(3);
    EXPECT_NE(m.find("still running after the limit of 1 s (killed)"), std::string::npos) << m;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10);
    EXPECT_NO_THROW(f.run(1));
    EXPECT_EQ(f.count("start"), 2);
    close_solver_servers();
    EXPECT_TRUE(child_processes().empty());  // the `sleep 30` it started was ended with it
}

TEST(LongLivedSolver, GarbageEndsTheServerAndFailedFailsTheCallAlone) {
    Fixture f;
    const std::string garbage = f.fault(4);
    EXPECT_NE(garbage.find("it answered 'hello' instead of 'done' or 'failed REASON'"), std::string::npos) << garbage;
    EXPECT_NO_THROW(f.run(1));
    EXPECT_EQ(f.count("start"), 2);  // out of step with the protocol: a new server
    const std::string failed = f.fault(5);
    EXPECT_NE(failed.find("it answered failed: no answer for seed 5"), std::string::npos) << failed;
    EXPECT_NO_THROW(f.run(1));
    EXPECT_EQ(f.count("start"), 2);  // a "failed" reply keeps the server
}

TEST(LongLivedSolver, TwoRepliesToOneRequestEndTheServerBeforeTheNextCall) {
    Fixture f;
    EXPECT_NO_THROW(f.run(6));  // its first reply stands
    for (int k = 0; k < 3; ++k) EXPECT_NO_THROW(f.run(1));  // the extra "done" is never taken as their reply
    EXPECT_EQ(f.count("start"), 2);
}

TEST(LongLivedSolver, AProgramThatIgnoresServeFailsNamingItsExit) {
    Fixture f;
    f.spec.command = "exec sh serve.sh oneshot";  // --serve comes last, as its second word here
    test::write_text_file(f.dir.file("serve.sh"), "echo \"got $1 $2\" >&2; exit 9\n");
    const std::string m = f.fault(1);
    EXPECT_NE(m.find("its server ended before answering: exit status 9"), std::string::npos) << m;
    EXPECT_NE(m.find("got oneshot --serve"), std::string::npos) << m;
}

TEST(LongLivedSolver, APythonClassCannotBeLongLived) {
    ExternalSolverSpec spec;
    spec.name = "mine";
    spec.python_class = "solver.py:Mine";
    spec.long_lived = true;
    EXPECT_NE(spec_problem(spec).find("long_lived: expected a program"), std::string::npos) << spec_problem(spec);
}

}  // namespace
}  // namespace collide::external
