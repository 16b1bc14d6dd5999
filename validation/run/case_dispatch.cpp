#include "validation/run/case_dispatch.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <stdexcept>

namespace collide::validation {

bool launched_by_mpi_launcher() {
    // Open MPI's mpirun, PMIx launchers (Slurm's srun --mpi=pmix, prrte) and PMI-1/2 launchers
    // (MPICH's hydra, srun --mpi=pmi2) each set one of these in every rank's environment.
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
        if (std::getenv(name)) return true;
    return false;
}

std::string this_host() {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
    return name;
}

std::map<std::string, std::string> serial_execution(int jobs) {
    return {{"ranks", "1"}, {"jobs_per_rank", std::to_string(jobs)}, {"hosts", this_host()}, {"launcher", "none"}};
}

#ifndef COLLIDE_HAVE_MPI
std::unique_ptr<CaseDispatch> start_case_dispatch(int, bool) {
    const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
    if (!size) size = std::getenv("PMI_SIZE");
    if (launched_by_mpi_launcher() && (!size || std::string(size) != "1"))
        throw std::runtime_error("this collide was built without MPI (find_package(MPI) found none), so it "
                                 "cannot share a suite across ranks; run it without mpirun/srun, or rebuild "
                                 "with libopenmpi-dev installed");
    return nullptr;
}
#endif

namespace {

std::int64_t disk_count(const Scene& scene) {
    std::int64_t n = 0;
    for (const ParticleGenerator& g : scene.generators) n += g.kind == "list" ? std::int64_t(g.disks.size()) : g.count;
    return n;
}

// Disk-steps of a finished case, from what it recorded (the same measure as the estimate).
double recorded_work(const CaseResult& r) {
    const double steps = r.dt > 0 ? r.duration / r.dt * std::max(1, r.substeps) : 1.0;
    return double(std::max<std::size_t>(r.disks, 1)) * std::max(steps, 1.0);
}

// Seconds per disk-step over the finished cases that `match` selects (0 when none).
template <typename Match>
double measured_speed(const std::map<std::string, CaseResult>& finished, Match match) {
    double seconds = 0, work = 0;
    for (const auto& [id, r] : finished)
        if (r.finished() && match(r)) seconds += r.wall_seconds + r.warmup_seconds, work += recorded_work(r);
    return work > 0 ? seconds / work : 0;
}

}  // namespace

double estimated_cost(const CaseSpec& spec, const Scene& scene, const std::map<std::string, CaseResult>& finished) {
    if (!spec.left_out.empty()) return 0;  // the backend refuses it: the case only says why
    // The event solver has no time step; its work grows like the stepped solvers' at the
    // scene's own dt (collisions per unit time), which is what this counts for it.
    const double steps = double(scene.steps_for(scene.run.duration)) * std::max(1, scene.run.substeps);
    const double work = double(std::max<std::int64_t>(disk_count(scene), 1)) * std::max(steps, 1.0);
    double speed = measured_speed(finished, [&](const CaseResult& r) {
        return r.spec.scene == spec.scene && r.spec.backend == spec.backend;
    });
    if (speed == 0) speed = measured_speed(finished, [&](const CaseResult& r) { return r.spec.backend == spec.backend; });
    if (speed == 0) speed = measured_speed(finished, [](const CaseResult&) { return true; });
    return work * (speed > 0 ? speed : 1.0);
}

std::vector<int> longest_first(const std::vector<CaseSpec>& specs, const std::map<std::string, CaseResult>& finished,
                               const std::function<double(const CaseSpec&)>& cost) {
    std::vector<int> order;
    std::vector<double> costs(specs.size(), 0.0);
    for (std::size_t k = 0; k < specs.size(); ++k)
        if (!finished.count(specs[k].id)) {
            order.push_back(int(k));
            costs[k] = cost(specs[k]);
        }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return costs[a] > costs[b]; });
    return order;
}

}  // namespace collide::validation
