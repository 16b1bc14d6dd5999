#include "cl_programs.h"

#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "kernel_sources.h"

namespace collide::opencl {
namespace {

struct Cache {
    std::mutex mutex;
    std::map<cl_device_id, cl::Context> contexts;
    std::map<std::pair<cl_device_id, std::string>, cl::Program> programs;
};

// Never destroyed: releasing OpenCL objects from a static destructor can run after the
// driver has shut down. The cache stays reachable, so leak checkers do not report it.
Cache& cache() {
    static Cache* instance = new Cache;
    return *instance;
}

cl::Program build(const cl::Context& context, const cl::Device& device, const std::string& options) {
    cl::Program program(context, program_text());
    try {
        program.build({device}, options.c_str());
    } catch (const cl::Error& e) {
        std::string log;
        try {
            log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
        } catch (const cl::Error&) {
            log = "(the driver gave no build log)";
        }
        throw std::runtime_error("opencl: building the kernels failed with " + error_name(e.err()) +
                                 "\nbuild options: " + options + "\nbuild log:\n" + log);
    }
    return program;
}

}  // namespace

ClSession open_session(const DeviceEntry& device, const std::string& build_options) {
    ClSession s;
    s.device = device;
    s.build_options = build_options;
    Cache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    const cl_device_id id = s.device.device();
    try {
        auto context = c.contexts.find(id);
        if (context == c.contexts.end()) context = c.contexts.emplace(id, cl::Context(s.device.device)).first;
        s.context = context->second;
        s.queue = cl::CommandQueue(s.context, s.device.device);
    } catch (const cl::Error& e) {
        throw_cl_error(e, "opening device '" + s.device.device_name + "'");
    }
    const auto key = std::make_pair(id, build_options);
    auto program = c.programs.find(key);
    if (program == c.programs.end()) program = c.programs.emplace(key, build(s.context, s.device.device, build_options)).first;
    s.program = program->second;
    return s;
}

}  // namespace collide::opencl

#if defined(__SANITIZE_ADDRESS__)
// PoCL 3.1 loses 16 bytes inside its compiler when a process compiles a kernel that is not
// yet in PoCL's disk cache (no frame of ours is on the allocating stack; a cached build does
// not allocate them). LeakSanitizer would fail every
// sanitized process that builds kernels, so that one library's leaks are suppressed. This is
// LeakSanitizer's documented hook for built-in suppressions; it applies only to sanitized
// builds (the `dev` preset) and to every binary that links this library.
extern "C" const char* __lsan_default_suppressions() { return "leak:libpocl.so\n"; }
#endif
