#include "validation/run/mpi_dispatch.h"

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <thread>

#include "core/io/input_file.h"
#include "core/io/output_file.h"

namespace collide::validation {

std::unique_ptr<CaseDispatch> start_case_dispatch(int jobs_per_rank, bool gather_hdf5) {
    if (!launched_by_mpi_launcher()) return nullptr;  // a plain run never initialises MPI
    return std::make_unique<MpiDispatch>(jobs_per_rank, gather_hdf5);
}

namespace {

constexpr int record_tag = 1, hdf5_tag = 2;

// Waiting in Open MPI spins a core. On a machine whose cores run the cases, a rank waiting for
// others must not take one of them, so every wait polls and sleeps between polls.
void nap() { std::this_thread::sleep_for(std::chrono::milliseconds(20)); }

void wait_for_all_ranks() {
    MPI_Request barrier;
    MPI_Ibarrier(MPI_COMM_WORLD, &barrier);
    for (int done = 0; MPI_Test(&barrier, &done, MPI_STATUS_IGNORE), !done;) nap();
}

// A case's record or run file, through the input guard (core/io/input_file.h): whole, however
// large (a run with frames), but never a FIFO or a device put in its place.
std::string read_bytes(const std::string& path) {
    return read_input_file(path, std::numeric_limits<std::size_t>::max() / 2);
}

std::string receive_bytes(int source, int tag) {
    MPI_Status status;
    MPI_Probe(source, tag, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    std::string bytes(std::size_t(count), '\0');
    MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return bytes;
}

void send_bytes(const std::string& bytes, int tag) {
    MPI_Send(bytes.data(), int(bytes.size()), MPI_BYTE, 0, tag, MPI_COMM_WORLD);
}

std::string joined(const std::vector<std::string>& words) {
    std::string out;
    for (const auto& w : words) {
        if (!out.empty()) out += ' ';
        out += w;
    }
    return out;
}

// mpirun binds each rank to one core by default (Slurm to its --cpus-per-task), and a rank's
// cases inherit the binding: --jobs J on fewer than J cores makes J cases share them, and a
// multi-threaded backend (cpu, opencl on a CPU device) gets only the rank's cores.
void warn_if_jobs_outnumber_cores(int rank, int jobs) {
    cpu_set_t cores;
    if (::sched_getaffinity(0, sizeof cores, &cores) != 0 || CPU_COUNT(&cores) >= jobs) return;
    std::fprintf(stderr,
                 "collide: rank %d may use %d core(s) but runs %d cases at a time (--jobs); give each rank "
                 "more cores (mpirun --map-by slot:PE=%d, srun --cpus-per-task=%d) or use --bind-to none\n",
                 rank, CPU_COUNT(&cores), jobs, jobs, jobs);
}

bool failed(const CaseResult& r) { return r.status != RunStatus::completed && r.status != RunStatus::left_out; }

}  // namespace

struct MpiDispatch::Run {
    CaseWork* work = nullptr;
    std::vector<int> order;  // indices into work->specs, in hand-out order
    MPI_Win window = MPI_WIN_NULL;
    std::size_t done = 0, failed = 0;          // rank 0's tallies over all ranks
    std::vector<std::size_t> cases_per_rank;  // rank 0's
};

MpiDispatch::MpiDispatch(int jobs_per_rank, bool gather_hdf5) : jobs_(jobs_per_rank), gather_hdf5_(gather_hdf5) {
    MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    char name[MPI_MAX_PROCESSOR_NAME] = {};
    int length = 0;
    MPI_Get_processor_name(name, &length);
    std::vector<char> all(std::size_t(size_) * MPI_MAX_PROCESSOR_NAME);
    MPI_Allgather(name, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, all.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR, MPI_COMM_WORLD);
    for (int r = 0; r < size_; ++r) hosts_.emplace_back(&all[std::size_t(r) * MPI_MAX_PROCESSOR_NAME]);
    warn_if_jobs_outnumber_cores(rank_, jobs_);
}

MpiDispatch::~MpiDispatch() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
}

// Rank 0 alone knows which cases are finished (their records are in its directory); it
// decides the order and every rank receives it, so resuming works on any number of ranks.
std::vector<int> MpiDispatch::agreed_order(const CaseWork& work) const {
    std::vector<int> order;
    if (is_root()) order = longest_first(*work.specs, *work.results, work.expected_cost);
    int n = int(order.size());
    MPI_Bcast(&n, 1, MPI_INT, 0, MPI_COMM_WORLD);
    order.resize(std::size_t(n));
    MPI_Bcast(order.data(), n, MPI_INT, 0, MPI_COMM_WORLD);
    return order;
}

// The record as rank 0 keeps it: where the case ran and where its HDF5 file lies.
void MpiDispatch::record(Run& run, CaseResult r, int from_rank) {
    r.provenance["host"] = hosts_[std::size_t(from_rank)];
    r.provenance["rank"] = std::to_string(from_rank);
    if (!r.hdf5_file.empty() && !r.provenance.count("hdf5_host")) r.provenance["hdf5_host"] = hosts_[std::size_t(from_rank)];
    write_case_result(r, result_path(run.work->isolation.result_dir, r.spec.id));
    ++run.done;
    run.failed += failed(r);
    ++run.cases_per_rank[std::size_t(from_rank)];
    if (run.work->progress)
        run.work->progress->update(run.done, run.failed, r.spec.id + " (rank " + std::to_string(from_rank) + ")");
    (*run.work->results)[r.spec.id] = std::move(r);
}

void MpiDispatch::send_result(const CaseResult& r, const CaseWork& work) const {
    // Written again so that every outcome, a death the runner could not read back included,
    // travels as the same file text the serial runner keeps.
    const std::string path = result_path(work.isolation.result_dir, r.spec.id);
    write_case_result(r, path);
    send_bytes(read_bytes(path), record_tag);
    if (!gather_hdf5_ || r.hdf5_file.empty()) return;
    std::string file = read_bytes(work.output_dir + "/" + r.hdf5_file);
    if (file.size() > std::size_t(INT_MAX)) {  // one MPI message holds at most INT_MAX bytes
        std::fprintf(stderr, "collide: rank %d: %s is over 2 GiB; it stays on %s\n", rank_, r.hdf5_file.c_str(),
                     hosts_[std::size_t(rank_)].c_str());
        file.clear();
    }
    send_bytes(file, hdf5_tag);
}

void MpiDispatch::receive_result(Run& run, const MPI_Status& probed) {
    const int from = probed.MPI_SOURCE;
    const std::string text = receive_bytes(from, record_tag);
    const std::string incoming = run.work->isolation.result_dir + "/.incoming-from-rank-" + std::to_string(from);
    write_file_atomically(incoming, text);
    CaseResult r = read_case_result(incoming);
    std::filesystem::remove(incoming);
    if (gather_hdf5_ && !r.hdf5_file.empty()) {
        const std::string file = receive_bytes(from, hdf5_tag);
        if (!file.empty()) {
            std::filesystem::create_directories(std::filesystem::path(run.work->output_dir + "/" + r.hdf5_file).parent_path());
            // The guard and rename of every output: no reader sees half a file.
            write_file_atomically(run.work->output_dir + "/" + r.hdf5_file, file);
            r.provenance["hdf5_host"] = hosts_[0];
        }
    }
    record(run, std::move(r), from);
}

// The hand-out cursor: a counter in rank 0's memory that every rank advances atomically.
void MpiDispatch::open_cursor(Run& run) const {
    long* counter = nullptr;
    MPI_Win_allocate(is_root() ? MPI_Aint(sizeof(long)) : 0, sizeof(long), MPI_INFO_NULL, MPI_COMM_WORLD, &counter,
                     &run.window);
    if (is_root()) {  // a local store into a window belongs in an access epoch of its own
        MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, run.window);
        *counter = 0;
        MPI_Win_unlock(0, run.window);
    }
    MPI_Barrier(MPI_COMM_WORLD);  // no rank claims before the cursor is zero
}

std::optional<CaseSpec> MpiDispatch::claim(Run& run) const {
    const long one = 1;
    long ticket = 0;
    MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, run.window);
    MPI_Fetch_and_op(&one, &ticket, MPI_LONG, 0, 0, MPI_SUM, run.window);
    MPI_Win_unlock(0, run.window);
    if (ticket >= long(run.order.size())) return std::nullopt;
    return (*run.work->specs)[std::size_t(run.order[std::size_t(ticket)])];
}

// Rank 0 takes in whatever results the other ranks have sent, without waiting for more.
void MpiDispatch::receive_pending(Run& run) {
    for (int flag = 1; is_root() && flag;) {
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, record_tag, MPI_COMM_WORLD, &flag, &status);
        if (flag) receive_result(run, status);
    }
}

std::size_t MpiDispatch::run(CaseWork& work) {
    Run run;
    run.work = &work;
    run.cases_per_rank.assign(std::size_t(size_), 0);
    try {
        run.order = agreed_order(work);
        open_cursor(run);
        auto on_done = [&](const CaseResult& r) {
            if (is_root()) record(run, r, 0);
            else send_result(r, work);
        };
        run_isolated_claiming(work.isolation, [&] { return claim(run); }, work.run_case, on_done,
                              [&] { receive_pending(run); });
        while (is_root() && run.done < run.order.size()) receive_pending(run), nap();
        wait_for_all_ranks();
        MPI_Win_free(&run.window);
    } catch (const std::exception& e) {
        // The other ranks would wait for this one forever: stop the whole job. Finished
        // cases are kept; --resume runs the rest.
        std::fprintf(stderr, "collide: rank %d (%s): %s\n", rank_, hosts_[std::size_t(rank_)].c_str(), e.what());
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    cases_per_rank_ = run.cases_per_rank;
    return run.order.size();
}

std::map<std::string, std::string> MpiDispatch::execution() const {
    const std::set<std::string> distinct(hosts_.begin(), hosts_.end());
    std::vector<std::string> counts;
    for (std::size_t n : cases_per_rank_) counts.push_back(std::to_string(n));
    const std::string hosts = joined(std::vector<std::string>(distinct.begin(), distinct.end()));
    const std::string per_rank = joined(counts);
    char library[MPI_MAX_LIBRARY_VERSION_STRING] = {};
    int length = 0;
    MPI_Get_library_version(library, &length);
    std::string version(library);
    version = version.substr(0, version.find_first_of(",\n"));
    return {{"ranks", std::to_string(size_)}, {"jobs_per_rank", std::to_string(jobs_)}, {"hosts", hosts},
            {"launcher", "mpi"}, {"mpi_library", version}, {"cases_per_rank", per_rank},
            {"hdf5_gathered", gather_hdf5_ ? "true" : "false"}};
}

}  // namespace collide::validation
