#include "opencl_solver.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "physics/step_schedule.h"
#include "core/scene/option_reader.h"
#include "core/numerics/representability.h"
#include "core/numerics/phase_timer.h"
#include "core/uniform_grid.h"
#include "device_grid.h"
#include "step_params.h"

namespace collide::opencl {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Default grid per device (docs/opencl-backend.md has the measurements). Up to a few
// thousand disks, launches cost more than the work: one work-group runs many steps per launch
// (kernels/group_steps.cl). Beyond that, on a CPU device (PoCL) the "device" memory is host
// memory, so the host build's read-back and upload are plain copies: the serial counting
// sort was faster up to N = 1e4, the grid kernels from 1e5 on. On a GPU the host build would
// cross the bus twice per step and sort on one core while thousands wait, so the grid stays
// on the device.
std::string default_grid_mode(const DeviceEntry& device, std::size_t n) {
    constexpr std::size_t cpu_device_grid_from = 50'000;
    if (n <= group_grid_up_to) return "group";
    if (device.type == "CPU" && n < cpu_device_grid_from) return "host";
    return "device";
}

// Disk-passes one launch of the group kernel may run: a launch is then some tens of
// milliseconds on a CPU core, short enough for a GPU's display watchdog, long enough that
// its own cost (tens of microseconds) is lost in it.
constexpr std::int64_t group_disk_passes_per_launch = std::int64_t(1) << 22;

// Move the disks into cell order at every grid build (docs/opencl-backend.md measures 0, 1
// and larger intervals).
constexpr int default_sort_interval = 1;

template <typename Real>
class OpenclSolver : public Solver {
public:
    using Particle = typename Layout<Real>::Particle;
    using StepParams = typename Layout<Real>::StepParams;

    explicit OpenclSolver(const BackendOptions& options) : requested_(options) {}

    std::string name() const override { return "opencl"; }
    double time() const override { return double(step_count_) * scene_.run.dt; }

    void load(const Scene& scene, const ParticleState<double>& initial) override {
        try {
            load_checked(scene, initial);
        } catch (const cl::Error& e) {
            throw_cl_error(e, "loading the scene onto the device");
        }
    }

    void advance_to(double t) override {
        const std::int64_t target = target_step(scene_, t, step_count_, "opencl");
        try {
            if (grid_mode_ == "group") advance_in_group(target);
            else while (step_count_ < target) step();
        } catch (const cl::Error& e) {
            throw_cl_error(e, "running a step");
        }
    }

    // In the scene's order: slot k holds scene disk scene_index[k] (k itself until a reorder).
    void read_state(ParticleState<double>& out) const override {
        std::vector<Particle> host(n_);
        std::vector<cl_uint> scene_index(n_);
        try {
            if (n_ > 0) {
                session_.queue.enqueueReadBuffer(particles_[current_], CL_TRUE, 0, sizeof(Particle) * n_, host.data());
                session_.queue.enqueueReadBuffer(scene_index_[current_order_], CL_TRUE, 0, sizeof(cl_uint) * n_,
                                                 scene_index.data());
            }
        } catch (const cl::Error& e) {
            throw_cl_error(e, "reading the state back");
        }
        out.resize(n_);
        for (std::size_t k = 0; k < n_; ++k) {
            const std::size_t i = scene_index[k];
            out.x[i] = host[k].x;
            out.y[i] = host[k].y;
            out.vx[i] = host[k].vx;
            out.vy[i] = host[k].vy;
            out.radius[i] = host[k].radius;
            out.mass[i] = host[k].mass;
            out.inv_mass[i] = host[k].inv_mass;
        }
    }

    SolverStats stats() const override {
        SolverStats s = stats_;
        std::vector<cl_uint> counts(n_);
        if (n_ > 0) session_.queue.enqueueReadBuffer(contact_count_, CL_TRUE, 0, sizeof(cl_uint) * n_, counts.data());
        s.contacts = std::accumulate(counts.begin(), counts.end(), std::int64_t(0));
        return s;
    }

    std::map<std::string, std::string> provenance() const override {
        const DeviceEntry& d = session_.device;
        return {{"opencl_platform", d.platform_name}, {"opencl_device", d.device_name}, {"opencl_device_type", d.type},
                {"opencl_device_version", d.device_version}, {"opencl_driver", d.driver_version},
                {"opencl_build_options", session_.build_options}, {"grid", grid_mode_},
                {"sort_interval", std::to_string(sort_interval_)}, {"real", sizeof(Real) == 8 ? "double" : "float"}};
    }

private:
    void load_checked(const Scene& scene, const ParticleState<double>& initial) {
        scene_ = scene;
        read_options(scene);
        n_ = initial.size();
        if (n_ >= std::size_t(UINT32_MAX)) throw std::invalid_argument("opencl: at most 2^32 - 1 disks (32-bit indices)");
        // Before the device is opened: a scene the kernels' precision cannot hold needs no device.
        require_representable(scene, initial, sizeof(Real) == 8 ? Precision::double_ : Precision::single,
                              Method::stepping_rules, "opencl");
        step_count_ = 0;
        grid_builds_ = 0;
        stats_ = SolverStats{};
        const bool real_double = sizeof(Real) == 8;
        const DeviceEntry device = select_device(requested_.device);
        if (real_double && !device.fp64)
            throw std::runtime_error("opencl: --real double needs fp64, which device '" + device.device_name +
                                     "' does not offer; use --real float or another --cl-device");
        session_ = open_session(device, kernel_build_options(scene, initial, real_double, device));
        check_layout();
        grid_mode_ = grid_choice_.empty() ? default_grid_mode(session_.device, n_) : grid_choice_;
        if (grid_mode_ == "group") sort_interval_ = 0;  // the group kernel never reorders the disks

        const double r_max = n_ ? *std::max_element(initial.radius.begin(), initial.radius.end()) : 1.0;
        host_grid_.configure(scene.world, 2 * r_max);
        const bool integrate_first = scene.run.order == StepOrder::integrate_first;
        params_ = make_step_params<Real>(scene, initial, host_grid_, integrate_first ? scene.run.dt / scene.run.substeps : scene.run.dt);
        allocate_buffers();
        upload(initial);
        choose_local_size();
    }

    // The options, the caller's winning over the scene's [backend.opencl] table, read and
    // checked before any device work (core/scene/option_reader.h); choose_local_size checks
    // local_size against the device.
    void read_options(const Scene& scene) {
        OptionReader settings("opencl", &scene, requested_.extra);
        grid_choice_ = settings.get_choice("grid", {"host", "device", "group"}, "");
        sort_interval_ = int(settings.get_int("sort_interval", default_sort_interval, 0, INT_MAX,
                                              "an integer >= 0 (0: never reorder)"));
        local_size_.reset();
        if (settings.has("local_size")) local_size_ = settings.get_string("local_size", "");
        settings.refuse_unknown();
    }

    // The kernel compiler must see the layout the host sees (particle_layout.h).
    void check_layout() {
        cl::Buffer out(session_.context, CL_MEM_WRITE_ONLY, 4 * sizeof(cl_int));
        cl::Kernel probe(session_.program, "layout_probe");
        probe.setArg(0, out);
        session_.queue.enqueueNDRangeKernel(probe, cl::NullRange, cl::NDRange(1));
        cl_int got[4] = {};
        session_.queue.enqueueReadBuffer(out, CL_TRUE, 0, sizeof(got), got);
        if (got[0] != cl_int(sizeof(Particle)) || got[1] != cl_int(alignof(Particle)) ||
            got[2] != cl_int(sizeof(StepParams)) || got[3] != cl_int(sizeof(Real)))
            throw std::runtime_error("opencl: the kernel compiler of '" + session_.device.device_name +
                                     "' lays out the shared structs differently from the host (sizeof Particle " +
                                     std::to_string(got[0]) + " vs " + std::to_string(sizeof(Particle)) +
                                     ", alignment " + std::to_string(got[1]) + " vs " + std::to_string(alignof(Particle)) +
                                     ", sizeof StepParams " + std::to_string(got[2]) + " vs " +
                                     std::to_string(sizeof(StepParams)) + ")");
    }

    void allocate_buffers() {
        const std::uint64_t cells = std::uint64_t(host_grid_.cell_count());
        const std::uint64_t n = std::max<std::uint64_t>(n_, 1);
        const std::uint64_t particle_bytes = sizeof(Particle) * n;
        const bool group = grid_mode_ == "group";
        const std::uint64_t total = 2 * particle_bytes + sizeof(cl_uint) * (cells + 1 + (group ? 6 : 4) * n) +
                                    (grid_mode_ == "device" ? DeviceGrid::work_bytes(n_, host_grid_.cell_count()) : 0);
        const DeviceEntry& d = session_.device;
        constexpr double mib = 1024.0 * 1024.0;
        if (total > d.global_memory || particle_bytes > d.max_allocation)
            throw std::runtime_error("opencl: out of device memory: the scene needs " + std::to_string(total / mib) +
                                     " MiB (largest buffer " + std::to_string(particle_bytes / mib) + " MiB) but device '" +
                                     d.device_name + "' has " + std::to_string(d.global_memory / mib) +
                                     " MiB (largest buffer " + std::to_string(d.max_allocation / mib) + " MiB)");
        for (auto& b : particles_) b = cl::Buffer(session_.context, CL_MEM_READ_WRITE, particle_bytes);
        for (auto& b : scene_index_) b = cl::Buffer(session_.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * n);
        cell_start_ = cl::Buffer(session_.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * (cells + 1));
        sorted_index_ = cl::Buffer(session_.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * n);
        contact_count_ = cl::Buffer(session_.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * n);
        session_.queue.enqueueFillBuffer(contact_count_, cl_uint(0), 0, sizeof(cl_uint) * n);
        device_grid_.reset();
        if (grid_mode_ == "device") device_grid_ = std::make_unique<DeviceGrid>(session_, std::int64_t(n_), host_grid_.cell_count());
        if (group) {
            cell_of_ = cl::Buffer(session_.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * n);
            rank_ = cl::Buffer(session_.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * n);
        }
        integrate_ = cl::Kernel(session_.program, "integrate");
        resolve_ = cl::Kernel(session_.program, "collide_and_correct");
        gather_ = cl::Kernel(session_.program, "gather_cell_order");
        group_ = cl::Kernel(session_.program, "run_steps_in_group");
    }

    void upload(const ParticleState<double>& s) {
        host_particles_.assign(n_, Particle{});
        for (std::size_t i = 0; i < n_; ++i) {
            Particle& p = host_particles_[i];
            p.x = Real(s.x[i]);
            p.y = Real(s.y[i]);
            p.vx = Real(s.vx[i]);
            p.vy = Real(s.vy[i]);
            p.inv_mass = Real(s.inv_mass[i]);
            p.radius = Real(s.radius[i]);
            p.mass = Real(s.mass[i]);
        }
        current_ = 0;
        current_order_ = 0;
        host_scene_index_.resize(n_);
        std::iota(host_scene_index_.begin(), host_scene_index_.end(), cl_uint(0));
        if (n_ > 0) {
            session_.queue.enqueueWriteBuffer(particles_[0], CL_TRUE, 0, sizeof(Particle) * n_, host_particles_.data());
            session_.queue.enqueueWriteBuffer(scene_index_[0], CL_TRUE, 0, sizeof(cl_uint) * n_, host_scene_index_.data());
        }
    }

    // A user-chosen work-group size must fit the device and the compiled kernels.
    void choose_local_size() {
        local_ = cl::NullRange;
        if (!local_size_) return;
        const std::string text = *local_size_;
        std::size_t size = 0, used = 0;
        try {
            size = std::stoul(text, &used);
        } catch (const std::exception&) {
        }
        if (used != text.size()) size = 0;  // trailing text ("64abc") is no size
        const cl::Device& dev = session_.device.device;
        const std::size_t limit = std::min({resolve_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(dev),
                                            integrate_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(dev),
                                            gather_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(dev),
                                            group_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(dev)});
        if (size == 0 || size > limit)
            throw std::invalid_argument("opencl: invalid work-group size local_size = '" + text + "' for device '" +
                                        session_.device.device_name + "': expected 1.." + std::to_string(limit));
        local_ = cl::NDRange(size);
    }

    cl::NDRange global_range() const {
        if (local_.dimensions() == 0) return cl::NDRange(n_);
        const std::size_t l = local_[0];
        return cl::NDRange((n_ + l - 1) / l * l);
    }

    // The size of the one work-group of grid = "group": the user's local_size, else the
    // smallest of 16, 64, 256, 1024 (a few sizes, because a compiler such as PoCL's builds the
    // kernel once per work-group size) that gives each work-item at most `disks_per_item`
    // disks, within the kernel's limit on this device. On a GPU that is one disk per item. On a
    // CPU device the group runs on one core, its work-items the iterations of a loop
    // (vectorised across items) that every barrier restarts, so items beyond a few per vector
    // lane only add loop overhead: four disks per item measured best at N = 1000
    // (docs/opencl-backend.md).
    std::size_t group_size() const {
        if (local_.dimensions() != 0) return local_[0];
        const std::size_t limit = group_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(session_.device.device);
        const std::size_t disks_per_item = session_.device.type == "CPU" ? 4 : 1;
        std::size_t size = 16;
        while (size * disks_per_item < n_ && size < 1024) size *= 4;
        return std::min(size, limit);
    }

    // Whole steps up to `target`, as few launches of run_steps_in_group as the launch budget allows.
    void advance_in_group(std::int64_t target) {
        const std::int64_t passes_per_step =
            scene_.run.order == StepOrder::integrate_first ? std::int64_t(scene_.run.substeps) : 1;
        const std::int64_t steps_per_launch = std::max<std::int64_t>(
            1, group_disk_passes_per_launch / (std::max<std::int64_t>(std::int64_t(n_), 1) * passes_per_step));
        while (step_count_ < target) {
            const std::int64_t steps = std::min(target - step_count_, steps_per_launch);
            if (n_ > 0) run_group_launch(int(steps * passes_per_step));
            step_count_ += steps;
            stats_.steps += steps;
        }
    }

    void run_group_launch(int passes) {
        const auto start = std::chrono::steady_clock::now();
        const std::size_t size = group_size();
        cl_uint arg = 0;
        group_.setArg(arg++, particles_[current_]);
        group_.setArg(arg++, particles_[1 - current_]);
        group_.setArg(arg++, cell_start_);
        group_.setArg(arg++, sorted_index_);
        group_.setArg(arg++, cell_of_);
        group_.setArg(arg++, rank_);
        group_.setArg(arg++, contact_count_);
        group_.setArg(arg++, params_);
        group_.setArg(arg++, cl_int(passes));
        group_.setArg(arg++, cl::Local(sizeof(cl_uint) * size));
        session_.queue.enqueueNDRangeKernel(group_, cl::NullRange, cl::NDRange(size), cl::NDRange(size));
        session_.queue.finish();
        if (passes % 2 == 1) current_ = 1 - current_;  // each pass writes the other buffer
        stats_.phase_seconds[phase::device_steps] += seconds_since(start);
    }

    void step() {
        if (n_ > 0) {
            // The step length lives in the kernels' parameters; only the order is scheduled here.
            step_by_rule<double>(
                scene_.run,
                [this](double) {
                    build_grid();
                    resolve();
                },
                [this](double) {
                    run_kernel_integrate();
                    build_grid();
                    resolve();
                });
        }
        ++step_count_;
        ++stats_.steps;
    }

    // The grid of this build, then, every sort_interval-th build, the disks moved into its order.
    void build_grid() {
        if (device_grid_) build_grid_on_device();  // (set at load iff grid = "device")
        else build_grid_on_host();
        const bool reorder = sort_interval_ > 0 && grid_builds_ % sort_interval_ == 0;
        ++grid_builds_;
        if (reorder) gather_cell_order();
    }

    // When the disks may leave the scene's order, each cell's slots are sorted by scene index,
    // so that neighbours are visited in the order of `step` whether or not the disks moved:
    // reordering changes where a disk lives in memory, never a result. Without reordering the
    // slot is the scene index and a plain counting sort keeps that order.
    bool cells_sorted_by_scene_index() const { return sort_interval_ > 0; }

    void build_grid_on_device() {
        const auto start = std::chrono::steady_clock::now();
        const cl::Buffer* scene_index = cells_sorted_by_scene_index() ? &scene_index_[current_order_] : nullptr;
        device_grid_->build(particles_[current_], &params_, sizeof(params_), cell_start_, sorted_index_, scene_index);
        session_.queue.finish();
        stats_.phase_seconds[phase::grid_on_device] += seconds_since(start);
    }

    // Read the positions back, counting-sort on the host, upload: no grid kernels to launch,
    // the cheapest build for few disks on a CPU device.
    void build_grid_on_host() {
        auto start = std::chrono::steady_clock::now();
        session_.queue.enqueueReadBuffer(particles_[current_], CL_TRUE, 0, sizeof(Particle) * n_, host_particles_.data());
        stats_.phase_seconds[phase::read_back] += seconds_since(start);
        start = std::chrono::steady_clock::now();
        xs_.resize(n_);
        ys_.resize(n_);
        for (std::size_t i = 0; i < n_; ++i) {
            xs_[i] = host_particles_[i].x;
            ys_[i] = host_particles_[i].y;
        }
        host_grid_.build(xs_.data(), ys_.data(), n_);
        const std::vector<std::uint32_t>* slots = &host_grid_.sorted_index();
        if (cells_sorted_by_scene_index()) {
            sort_cells_by_scene_index();
            slots = &host_sorted_index_;
        }
        stats_.phase_seconds[phase::grid_on_host] += seconds_since(start);
        start = std::chrono::steady_clock::now();
        const auto& cs = host_grid_.cell_start();
        session_.queue.enqueueWriteBuffer(cell_start_, CL_FALSE, 0, sizeof(cl_uint) * cs.size(), cs.data());
        session_.queue.enqueueWriteBuffer(sorted_index_, CL_FALSE, 0, sizeof(cl_uint) * n_, slots->data());
        session_.queue.finish();
        stats_.phase_seconds[phase::upload] += seconds_since(start);
    }

    // The host grid's cells list their slots in increasing slot order; the order wanted is
    // increasing scene index (grid_sort_cells_by_scene_index in kernels/grid.cl, on the host).
    void sort_cells_by_scene_index() {
        host_sorted_index_ = host_grid_.sorted_index();
        std::uint32_t* slots = host_sorted_index_.data();
        const cl_uint* scene_index = host_scene_index_.data();
        const auto& cell_start = host_grid_.cell_start();
        for (std::size_t c = 0; c + 1 < cell_start.size(); ++c) {
            const std::uint32_t begin = cell_start[c], end = cell_start[c + 1];
            for (std::uint32_t k = begin + 1; k < end; ++k) {  // insertion sort: a cell holds a few disks
                const std::uint32_t slot = slots[k];
                std::uint32_t m = k;
                for (; m > begin && scene_index[slots[m - 1]] > scene_index[slot]; --m) slots[m] = slots[m - 1];
                slots[m] = slot;
            }
        }
    }

    // Moves the particles and their scene indices into the grid's slot order (into the spare
    // ping-pong buffers), and makes sorted_index the identity so that the grid describes them.
    void gather_cell_order() {
        const auto start = std::chrono::steady_clock::now();
        gather_.setArg(0, particles_[current_]);
        gather_.setArg(1, particles_[1 - current_]);
        gather_.setArg(2, scene_index_[current_order_]);
        gather_.setArg(3, scene_index_[1 - current_order_]);
        gather_.setArg(4, sorted_index_);
        gather_.setArg(5, cl_int(n_));
        session_.queue.enqueueNDRangeKernel(gather_, cl::NullRange, global_range(), local_);
        session_.queue.finish();
        current_ = 1 - current_;
        current_order_ = 1 - current_order_;
        stats_.phase_seconds[phase::reorder] += seconds_since(start);
        if (!device_grid_) follow_reorder_on_host();
    }

    // The host build sorts cells by scene index, so it keeps its own copy of the slots' scene
    // indices, moved as the kernel moved the device's.
    void follow_reorder_on_host() {
        const auto start = std::chrono::steady_clock::now();
        const std::vector<std::uint32_t>& from = host_sorted_index_;
        reordered_scene_index_.resize(n_);
        for (std::size_t k = 0; k < n_; ++k) reordered_scene_index_[k] = host_scene_index_[from[k]];
        host_scene_index_.swap(reordered_scene_index_);
        stats_.phase_seconds[phase::reorder] += seconds_since(start);
    }

    void run_kernel_integrate() {
        const auto start = std::chrono::steady_clock::now();
        integrate_.setArg(0, particles_[current_]);
        integrate_.setArg(1, params_);
        session_.queue.enqueueNDRangeKernel(integrate_, cl::NullRange, global_range(), local_);
        session_.queue.finish();
        stats_.phase_seconds[phase::device_steps] += seconds_since(start);
    }

    // Jacobi pass from particles_[current_] into the other buffer, which becomes current.
    void resolve() {
        const auto start = std::chrono::steady_clock::now();
        resolve_.setArg(0, particles_[current_]);
        resolve_.setArg(1, particles_[1 - current_]);
        resolve_.setArg(2, cell_start_);
        resolve_.setArg(3, sorted_index_);
        resolve_.setArg(4, contact_count_);
        resolve_.setArg(5, params_);
        session_.queue.enqueueNDRangeKernel(resolve_, cl::NullRange, global_range(), local_);
        session_.queue.finish();
        current_ = 1 - current_;
        stats_.phase_seconds[phase::device_steps] += seconds_since(start);
    }

    const BackendOptions requested_;  // as created
    std::string grid_choice_;         // read_options(): "host", "device", "group" or "" (the device's default)
    std::optional<std::string> local_size_;
    Scene scene_;
    std::size_t n_ = 0;
    std::int64_t step_count_ = 0;
    SolverStats stats_;
    ClSession session_;
    std::string grid_mode_;
    int sort_interval_ = default_sort_interval;
    std::int64_t grid_builds_ = 0;
    StepParams params_{};
    UniformGrid<Real> host_grid_;
    std::vector<Particle> host_particles_;
    std::vector<Real> xs_, ys_;
    std::vector<std::uint32_t> host_sorted_index_;                     // host grid, cells sorted by scene index
    std::vector<cl_uint> host_scene_index_, reordered_scene_index_;    // host grid: the slots' scene indices
    cl::Buffer particles_[2];    // ping-pong: the pass (or the reorder) reads one and writes the other
    int current_ = 0;
    cl::Buffer scene_index_[2];  // scene index of the disk in each slot; ping-pong with the reorder
    int current_order_ = 0;
    cl::Buffer cell_start_, sorted_index_, contact_count_;
    cl::Buffer cell_of_, rank_;  // grid = "group": each disk's cell and rank in it
    std::unique_ptr<DeviceGrid> device_grid_;
    cl::Kernel integrate_, resolve_, gather_, group_;
    cl::NDRange local_ = cl::NullRange;
};

}  // namespace

std::string kernel_build_options(const Scene& scene, const ParticleState<double>& initial, bool real_double,
                                 const DeviceEntry& device) {
    // Correctly rounded float division and square root where the device offers them, so
    // that float kernels round as the host's float arithmetic does (OpenCL otherwise allows
    // 2.5 ulp for division and 3 ulp for sqrt). Double arithmetic is always correctly rounded.
    std::string options = feature_flags(scene, initial, real_double);
    const auto fp32 = device.device.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>();
    if (!real_double && (fp32 & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT)) options += " -cl-fp32-correctly-rounded-divide-sqrt";
    return options;
}

std::unique_ptr<Solver> make_opencl_solver(const BackendOptions& options) {
    if (options.real.empty() || options.real == "float") return std::make_unique<OpenclSolver<float>>(options);
    if (options.real == "double") return std::make_unique<OpenclSolver<double>>(options);
    throw std::invalid_argument("opencl: --real '" + options.real + "': expected float or double");
}

}  // namespace collide::opencl
