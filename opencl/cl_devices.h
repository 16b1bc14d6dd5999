// Finding OpenCL platforms and devices, choosing one (`--cl-device`), and turning OpenCL
// error codes into messages a user can act on.
#pragma once

#include <CL/opencl.hpp>

#include <string>
#include <vector>

namespace collide::opencl {

struct DeviceEntry {
    int index = 0;               // position in list_devices(), counted over all platforms
    cl::Platform platform;
    cl::Device device;
    std::string platform_name, device_name, device_version, driver_version;
    std::string type;            // "CPU", "GPU", "accelerator", ...
    bool fp64 = false;           // double precision available (cl_khr_fp64)
    // What the device's float arithmetic offers (CL_DEVICE_SINGLE_FP_CONFIG): where a float
    // kernel's bits differ from the host's, these name the usual causes.
    bool fp32_denormals = false;           // denormals kept, not flushed to zero
    bool fp32_fma = false;                 // a fused multiply-add in hardware
    bool fp32_correctly_rounded_divide_sqrt = false;  // the build option is then honoured
    int compute_units = 0;
    std::uint64_t global_memory = 0, max_allocation = 0;
};

// Every device of every platform, in platform order. Throws std::runtime_error if there is
// no OpenCL platform or no device at all, saying how to install one.
std::vector<DeviceEntry> list_devices();

// The device picked by `selector`: "" = the device named by the environment variable
// COLLIDE_CL_DEVICE if set (for programs without --cl-device, such as `collide bench`), else
// the first device; a number = that index of
// list_devices(), otherwise the first device whose "platform: device" name contains the text
// (case-insensitive). Throws, listing the devices, if nothing matches.
DeviceEntry select_device(const std::string& selector);

// "CL_OUT_OF_RESOURCES (-5)" for an OpenCL error code.
std::string error_name(int code);

// A clear message for an OpenCL error raised while doing `what`; device memory
// exhaustion is said in words.
[[noreturn]] void throw_cl_error(const cl::Error& e, const std::string& what);

}  // namespace collide::opencl
