// The validation runner as `collide validate` runs it under mpirun, on test doubles whose
// timing and faults the MPI tests control (test_mpi_validate.py):
//
//   mpi_validate_driver slow  OUT [--resume] [--jobs J]   12 cases that each sleep 0.4 s
//   mpi_validate_driver crash OUT [--gather-hdf5]         8 cases; those run by rank 1 abort
//
// The sleeps give a test time to kill a run part-way without spending CPU; a case aborts
// only on rank 1 (the launcher tells each rank its number in its environment), so the crash
// test knows where each case died.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/io/provenance.h"
#include "tests/validation/test_backends.h"
#include "validation/suite_runner.h"

namespace {

using namespace collide;

bool on_rank_1() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
        if (const char* v = std::getenv(name)) return std::string(v) == "1";
    return false;
}

// A correct test double with a fault added when the case's solver is made (in the case's
// own process, so the runner sees what a real case doing the same would show).
BackendInfo with_fault(const std::string& name, bool sleeps, bool aborts_on_rank_1) {
    BackendInfo info = test::test_backend(name, test::Fault::none);
    auto create = info.create;
    info.create = [=](const BackendOptions& options) {
        if (aborts_on_rank_1 && on_rank_1()) std::abort();
        if (sleeps) std::this_thread::sleep_for(std::chrono::milliseconds(400));
        return create(options);
    };
    return info;
}

int run(const std::string& kind, const std::string& out, int jobs, bool resume, bool gather) {
    const bool crash = kind == "crash";
    if (!crash && kind != "slow") throw std::invalid_argument("unknown kind '" + kind + "' (slow or crash)");
    std::vector<BackendInfo> backends = {with_fault("sleepy_a", true, crash), with_fault("sleepy_b", true, false)};
    validation::Suite suite = test::test_suite(test::two_disk_scene(), {"sleepy_a", "sleepy_b"});
    suite.seeds = crash ? std::vector<std::uint64_t>{1, 2, 3, 4} : std::vector<std::uint64_t>{1, 2, 3, 4, 5, 6};
    suite.output.hdf5 = true;
    suite.time_limit_seconds = 30;

    // The same hook as apps/commands/validate_command.cpp.
    const auto dispatch = validation::start_case_dispatch(jobs, gather);
    const bool reports = !dispatch || dispatch->is_root();
    validation::RunnerOptions options;
    options.output_dir = out;
    options.jobs = jobs;
    options.resume = resume;
    options.progress = reports ? stderr : nullptr;
    options.dispatch = dispatch.get();
    const auto outcome = validation::run_suite(suite, backends, options);
    return reports && !outcome.passed() ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    collide::set_command_line(argc, argv);
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s slow|crash OUT [--resume] [--jobs J] [--gather-hdf5]\n", argv[0]);
        return 2;
    }
    int jobs = 1;
    bool resume = false, gather = false;
    for (int k = 3; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--resume") resume = true;
        else if (arg == "--gather-hdf5") gather = true;
        else if (arg == "--jobs" && k + 1 < argc) jobs = std::atoi(argv[++k]);
        else return std::fprintf(stderr, "unknown argument '%s'\n", arg.c_str()), 2;
    }
    try {
        return run(argv[1], argv[2], jobs, resume, gather);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mpi_validate_driver: %s\n", e.what());
        return 2;
    }
}
