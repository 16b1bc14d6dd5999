#include "opencl_solver.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <stdexcept>

#include "core/step_schedule.h"
#include "core/uniform_grid.h"
#include "device_grid.h"
#include "step_params.hpp"

namespace collide::opencl {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Default grid per device (docs/opencl-backend.md has the measurements). On a CPU device
// (PoCL) the "device" memory is host memory, so the host build's read-back and upload are
// plain copies: the serial counting sort was faster up to N = 1e4, the grid kernels from
// 1e5 on. On a GPU the host build would cross the bus twice per step and sort on one core
// while thousands wait, so the grid stays on the device.
std::string default_grid_mode(const DeviceEntry& device, std::size_t n) {
    constexpr std::size_t cpu_device_grid_from = 50'000;
    if (device.type == "CPU" && n < cpu_device_grid_from) return "host";
    return "device";
}

template <typename Real>
class OpenclSolver : public Solver {
public:
    using Particle = typename Layout<Real>::Particle;
    using StepParams = typename Layout<Real>::StepParams;

    explicit OpenclSolver(const BackendOptions& options) : requested_(options), options_(options) {}

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
            while (step_count_ < target) step();
        } catch (const cl::Error& e) {
            throw_cl_error(e, "running a step");
        }
    }

    void read_state(ParticleState<double>& out) const override {
        std::vector<Particle> host(n_);
        try {
            if (n_ > 0) session_.queue.enqueueReadBuffer(particles_[current_], CL_TRUE, 0, sizeof(Particle) * n_, host.data());
        } catch (const cl::Error& e) {
            throw_cl_error(e, "reading the state back");
        }
        out.resize(n_);
        for (std::size_t i = 0; i < n_; ++i) {
            out.x[i] = host[i].x;
            out.y[i] = host[i].y;
            out.vx[i] = host[i].vx;
            out.vy[i] = host[i].vy;
            out.radius[i] = host[i].radius;
            out.mass[i] = host[i].mass;
            out.inv_mass[i] = host[i].inv_mass;
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
        return {{"opencl_platform", d.platform_name}, {"opencl_device", d.device_name},
                {"opencl_device_version", d.device_version}, {"opencl_driver", d.driver_version},
                {"opencl_build_options", session_.build_options}, {"grid", grid_mode_},
                {"real", sizeof(Real) == 8 ? "double" : "float"}};
    }

private:
    void load_checked(const Scene& scene, const ParticleState<double>& initial) {
        scene_ = scene;
        options_ = requested_;
        merge_scene_options(scene);
        n_ = initial.size();
        step_count_ = 0;
        stats_ = SolverStats{};
        const bool real_double = sizeof(Real) == 8;
        const DeviceEntry device = select_device(options_.device);
        if (real_double && !device.fp64)
            throw std::runtime_error("opencl: --real double needs fp64, which device '" + device.device_name +
                                     "' does not offer; use --real float or another --cl-device");
        session_ = open_session(device, kernel_build_options(scene, initial, real_double, device));
        check_layout();
        grid_mode_ = options_.extra.count("grid") ? options_.extra.at("grid") : default_grid_mode(session_.device, n_);
        if (grid_mode_ != "host" && grid_mode_ != "device")
            throw std::invalid_argument("opencl: option grid = '" + grid_mode_ + "': expected \"host\" or \"device\"");

        const double r_max = n_ ? *std::max_element(initial.radius.begin(), initial.radius.end()) : 1.0;
        host_grid_.configure(scene.world, 2 * r_max);
        const bool integrate_first = scene.run.order == StepOrder::integrate_first;
        params_ = make_step_params<Real>(scene, initial, host_grid_, integrate_first ? scene.run.dt / scene.run.substeps : scene.run.dt);
        allocate_buffers();
        upload(initial);
        choose_local_size();
    }

    // Keys of the scene's [backend.opencl] table, unless the caller set them already.
    void merge_scene_options(const Scene& scene) {
        const auto table = scene.backend_options.find("opencl");
        if (table == scene.backend_options.end()) return;
        for (const auto& [key, value] : table->second) {
            if (key != "grid" && key != "local_size")
                throw std::invalid_argument("opencl: scene '" + scene.name + "', [backend.opencl]: unknown key '" + key +
                                            "' (expected grid or local_size)");
            options_.extra.emplace(key, value);  // does not replace an explicit option
        }
    }

    // The kernel compiler must see the layout the host sees (particle_layout.hpp).
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
        const std::uint64_t total = 2 * particle_bytes + sizeof(cl_uint) * (cells + 1 + 2 * n) +
                                    (grid_mode_ == "device" ? DeviceGrid::work_bytes(n_, host_grid_.cell_count()) : 0);
        const DeviceEntry& d = session_.device;
        constexpr double mib = 1024.0 * 1024.0;
        if (total > d.global_memory || particle_bytes > d.max_allocation)
            throw std::runtime_error("opencl: out of device memory: the scene needs " + std::to_string(total / mib) +
                                     " MiB (largest buffer " + std::to_string(particle_bytes / mib) + " MiB) but device '" +
                                     d.device_name + "' has " + std::to_string(d.global_memory / mib) +
                                     " MiB (largest buffer " + std::to_string(d.max_allocation / mib) + " MiB)");
        for (auto& b : particles_) b = cl::Buffer(session_.context, CL_MEM_READ_WRITE, particle_bytes);
        cell_start_ = cl::Buffer(session_.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * (cells + 1));
        sorted_index_ = cl::Buffer(session_.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * n);
        contact_count_ = cl::Buffer(session_.context, CL_MEM_READ_WRITE, sizeof(cl_uint) * n);
        session_.queue.enqueueFillBuffer(contact_count_, cl_uint(0), 0, sizeof(cl_uint) * n);
        device_grid_.reset();
        if (grid_mode_ == "device") device_grid_ = std::make_unique<DeviceGrid>(session_, std::int64_t(n_), host_grid_.cell_count());
        integrate_ = cl::Kernel(session_.program, "integrate_motion");
        resolve_ = cl::Kernel(session_.program, "resolve_collisions");
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
        if (n_ > 0)
            session_.queue.enqueueWriteBuffer(particles_[0], CL_TRUE, 0, sizeof(Particle) * n_, host_particles_.data());
    }

    // A user-chosen work-group size must fit the device and the compiled kernels.
    void choose_local_size() {
        local_ = cl::NullRange;
        if (!options_.extra.count("local_size")) return;
        const std::string text = options_.extra.at("local_size");
        std::size_t size = 0;
        try {
            size = std::stoul(text);
        } catch (const std::exception&) {
        }
        const cl::Device& dev = session_.device.device;
        const std::size_t limit = std::min(resolve_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(dev),
                                           integrate_.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(dev));
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

    void build_grid() {
        if (grid_mode_ == "device") {
            const auto start = std::chrono::steady_clock::now();
            device_grid_->build(particles_[current_], &params_, sizeof(params_), cell_start_, sorted_index_);
            session_.queue.finish();
            stats_.phase_seconds["grid (device)"] += seconds_since(start);
            return;
        }
        // Seed 000's design: read the positions back, counting-sort on the host, upload.
        auto start = std::chrono::steady_clock::now();
        session_.queue.enqueueReadBuffer(particles_[current_], CL_TRUE, 0, sizeof(Particle) * n_, host_particles_.data());
        stats_.phase_seconds["read-back"] += seconds_since(start);
        start = std::chrono::steady_clock::now();
        xs_.resize(n_);
        ys_.resize(n_);
        for (std::size_t i = 0; i < n_; ++i) {
            xs_[i] = host_particles_[i].x;
            ys_[i] = host_particles_[i].y;
        }
        host_grid_.build(xs_.data(), ys_.data(), n_);
        stats_.phase_seconds["grid (host)"] += seconds_since(start);
        start = std::chrono::steady_clock::now();
        const auto& cs = host_grid_.cell_start();
        session_.queue.enqueueWriteBuffer(cell_start_, CL_FALSE, 0, sizeof(cl_uint) * cs.size(), cs.data());
        session_.queue.enqueueWriteBuffer(sorted_index_, CL_FALSE, 0, sizeof(cl_uint) * n_, host_grid_.sorted_index().data());
        session_.queue.finish();
        stats_.phase_seconds["upload"] += seconds_since(start);
    }

    void run_kernel_integrate() {
        const auto start = std::chrono::steady_clock::now();
        integrate_.setArg(0, particles_[current_]);
        integrate_.setArg(1, params_);
        session_.queue.enqueueNDRangeKernel(integrate_, cl::NullRange, global_range(), local_);
        session_.queue.finish();
        stats_.phase_seconds["kernels"] += seconds_since(start);
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
        stats_.phase_seconds["kernels"] += seconds_since(start);
    }

    const BackendOptions requested_;  // as created
    BackendOptions options_;          // requested_ plus the scene's [backend.opencl] keys
    Scene scene_;
    std::size_t n_ = 0;
    std::int64_t step_count_ = 0;
    SolverStats stats_;
    ClSession session_;
    std::string grid_mode_;
    StepParams params_{};
    UniformGrid<Real> host_grid_;
    std::vector<Particle> host_particles_;
    std::vector<Real> xs_, ys_;
    cl::Buffer particles_[2];  // ping-pong: the pass reads one and writes the other
    int current_ = 0;
    cl::Buffer cell_start_, sorted_index_, contact_count_;
    std::unique_ptr<DeviceGrid> device_grid_;
    cl::Kernel integrate_, resolve_;
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
