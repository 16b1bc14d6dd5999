// One OpenCL context per device and one built program per (device, build options), shared
// by every solver of the process: a compiler such as PoCL's takes a second or more per
// build, and a scene's features change only the -D flags, not the text.
#pragma once

#include <string>

#include "cl_devices.h"

namespace collide::opencl {

struct ClSession {
    DeviceEntry device;
    cl::Context context;
    cl::CommandQueue queue;   // in order, one per session
    cl::Program program;
    std::string build_options;
};

// Opens `device` (see select_device) with the program built with `build_options` (the -D
// flags of a scene). A build failure throws std::runtime_error carrying the compiler's full
// build log.
ClSession open_session(const DeviceEntry& device, const std::string& build_options);

}  // namespace collide::opencl
