// Cases run by worker processes (case_isolation.h, IsolationOptions::in_worker): several cases
// share a process, and a case that crashes, throws or hangs still fails alone and is recorded
// as a case's own process would record it; the worker is replaced.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "test_backends.h"
#include "validation/plan/backend_variant.h"
#include "validation/run/case_isolation.h"
#include "validation/suite_runner.h"

namespace collide::test {
namespace {

using validation::CaseResult;
using validation::CaseSpec;
using validation::RunStatus;

std::vector<CaseSpec> specs_named(const std::vector<std::string>& ids) {
    std::vector<CaseSpec> specs;
    for (const auto& id : ids) {
        CaseSpec s;
        s.id = id;
        s.backend = "opencl";
        specs.push_back(s);
    }
    return specs;
}

// A case prints its id, then does what its id says; its result records the process it ran in.
CaseResult run_case(const CaseSpec& spec) {
    std::fprintf(stderr, "running %s\n", spec.id.c_str());  // unbuffered: in the log before an abort
    if (spec.id.find("crash") != std::string::npos) std::abort();
    if (spec.id.find("throw") != std::string::npos) throw std::runtime_error("deliberate failure");
    if (spec.id.find("hang") != std::string::npos) std::this_thread::sleep_for(std::chrono::seconds(60));
    CaseResult r;
    r.spec = spec;
    r.diagnostic = std::to_string(::getpid());
    return r;
}

std::map<std::string, CaseResult> run_all(const std::vector<std::string>& ids, int jobs, bool in_worker,
                                          const std::string& dir, double time_limit = 30) {
    validation::IsolationOptions options;
    options.jobs = jobs;
    options.time_limit_seconds = time_limit;
    options.result_dir = dir;
    if (in_worker) options.in_worker = [](const CaseSpec&) { return true; };
    std::map<std::string, CaseResult> results;
    validation::run_isolated(specs_named(ids), options, run_case,
                             [&](const CaseResult& r) { results[r.spec.id] = r; });
    return results;
}

std::string file_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(CaseWorkers, CasesShareAWorkerAndEachKeepsItsOwnLog) {
    const std::string dir = fresh_output_dir("workers_share");
    const std::vector<std::string> ids = {"a", "b", "c", "d", "e", "f"};
    const auto results = run_all(ids, 2, true, dir);
    ASSERT_EQ(results.size(), ids.size());
    std::set<std::string> processes;
    for (const auto& id : ids) {
        EXPECT_EQ(results.at(id).status, RunStatus::completed) << id;
        processes.insert(results.at(id).diagnostic);
        EXPECT_EQ(file_text(dir + "/" + id + ".log"), "running " + id + "\n") << id;
    }
    EXPECT_LE(processes.size(), 2u) << "at most one worker per job";
    EXPECT_FALSE(processes.count(std::to_string(::getpid()))) << "cases never run in the runner";
}

TEST(CaseWorkers, WithoutWorkersEveryCaseHasAProcessOfItsOwn) {
    const std::vector<std::string> ids = {"a", "b", "c", "d"};
    const auto results = run_all(ids, 2, false, fresh_output_dir("workers_none"));
    std::set<std::string> processes;
    for (const auto& id : ids) processes.insert(results.at(id).diagnostic);
    EXPECT_EQ(processes.size(), ids.size());
}

TEST(CaseWorkers, ACrashFailsOnlyItsCaseAndTheWorkerIsReplaced) {
    const auto results = run_all({"before", "crash", "after"}, 1, true, fresh_output_dir("workers_crash"));
    EXPECT_EQ(results.at("before").status, RunStatus::completed);
    EXPECT_EQ(results.at("crash").status, RunStatus::crashed);
    EXPECT_NE(results.at("crash").diagnostic.find("signal"), std::string::npos) << results.at("crash").diagnostic;
    EXPECT_NE(results.at("crash").diagnostic.find("running crash"), std::string::npos) << "the log's tail";
    EXPECT_EQ(results.at("after").status, RunStatus::completed);
    EXPECT_NE(results.at("after").diagnostic, results.at("before").diagnostic) << "a new worker";
}

TEST(CaseWorkers, AThrowingCaseIsRecordedAsInAProcessOfItsOwn) {
    const auto alone = run_all({"throw"}, 1, false, fresh_output_dir("workers_throw_alone"));
    const auto worker = run_all({"throw", "after"}, 1, true, fresh_output_dir("workers_throw"));
    EXPECT_EQ(worker.at("throw").status, alone.at("throw").status);
    EXPECT_NE(worker.at("throw").diagnostic.find("deliberate failure"), std::string::npos) << worker.at("throw").diagnostic;
    EXPECT_EQ(worker.at("after").status, RunStatus::completed);
}

TEST(CaseWorkers, ACaseOverTheTimeLimitIsKilledAndTheNextOneRuns) {
    const auto results = run_all({"hang", "after"}, 1, true, fresh_output_dir("workers_hang"), 1.0);
    EXPECT_EQ(results.at("hang").status, RunStatus::timed_out);
    EXPECT_EQ(results.at("after").status, RunStatus::completed);
}

TEST(CaseWorkers, EveryCaseGoesToAWorkerALeftOutOneToo) {
    CaseSpec spec;
    for (const char* backend : {"opencl", "opencl[fast]", "cpu", "step", "event", "box2d[shipped]"}) {
        spec.backend = backend;
        EXPECT_TRUE(validation::runs_in_worker(spec)) << backend;
    }
    spec.left_out = "the backend refuses the scene";
    EXPECT_TRUE(validation::runs_in_worker(spec));
}

TEST(CaseWorkers, ASpecSurvivesItsRequestText) {
    CaseSpec spec;
    spec.id = "gas__opencl__dt0.001__seed3";
    spec.scene = "gas";
    spec.backend = "opencl";
    spec.scene_index = 4;
    spec.seed = 3;
    spec.dt = 1e-3;
    spec.substeps = 2;
    spec.parameters = {{"particles.0.radius", 0.25}, {"physics.restitution", 0.9}};
    spec.left_out = "why";
    const CaseSpec back = validation::case_spec_from_text(validation::case_spec_text(spec));
    EXPECT_EQ(back.id, spec.id);
    EXPECT_EQ(back.scene_index, spec.scene_index);
    EXPECT_EQ(back.seed, spec.seed);
    EXPECT_EQ(back.dt, spec.dt);
    EXPECT_EQ(back.substeps, spec.substeps);
    EXPECT_FALSE(back.iterations);
    EXPECT_EQ(back.parameters, spec.parameters);
    EXPECT_EQ(back.left_out, spec.left_out);
    EXPECT_THROW(validation::case_spec_from_text("spec = 1"), std::runtime_error);
}

}  // namespace
}  // namespace collide::test
