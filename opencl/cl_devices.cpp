#include "cl_devices.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <stdexcept>

namespace collide::opencl {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string type_name(cl_device_type type) {
    if (type & CL_DEVICE_TYPE_GPU) return "GPU";
    if (type & CL_DEVICE_TYPE_CPU) return "CPU";
    if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
    return "other";
}

const char* const install_hint =
    "install an OpenCL driver (scripts/install-deps.sh installs PoCL, a CPU device; "
    "`clinfo -l` shows what the ICD loader finds)";

std::string device_table(const std::vector<DeviceEntry>& devices) {
    std::string text;
    for (const auto& d : devices)
        text += "\n  " + std::to_string(d.index) + ": " + d.platform_name + ": " + d.device_name;
    return text;
}

}  // namespace

std::vector<DeviceEntry> list_devices() {
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error& e) {
        // The ICD loader reports CL_PLATFORM_NOT_FOUND_KHR (-1001) when no driver is installed.
        throw std::runtime_error("opencl: no OpenCL platform found (" + error_name(e.err()) + "); " + install_hint);
    }
    if (platforms.empty()) throw std::runtime_error(std::string("opencl: no OpenCL platform found; ") + install_hint);
    std::vector<DeviceEntry> devices;
    for (const auto& platform : platforms) {
        std::vector<cl::Device> found;
        try {
            platform.getDevices(CL_DEVICE_TYPE_ALL, &found);
        } catch (const cl::Error&) {
            continue;  // CL_DEVICE_NOT_FOUND: a platform without devices
        }
        for (const auto& device : found) {
            DeviceEntry d;
            d.index = int(devices.size());
            d.platform = platform;
            d.device = device;
            d.platform_name = platform.getInfo<CL_PLATFORM_NAME>();
            d.device_name = device.getInfo<CL_DEVICE_NAME>();
            d.device_version = device.getInfo<CL_DEVICE_VERSION>();
            d.driver_version = device.getInfo<CL_DRIVER_VERSION>();
            d.type = type_name(device.getInfo<CL_DEVICE_TYPE>());
            d.fp64 = device.getInfo<CL_DEVICE_DOUBLE_FP_CONFIG>() != 0;
            const cl_device_fp_config fp32 = device.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>();
            d.fp32_denormals = (fp32 & CL_FP_DENORM) != 0;
            d.fp32_fma = (fp32 & CL_FP_FMA) != 0;
            d.fp32_correctly_rounded_divide_sqrt = (fp32 & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0;
            d.compute_units = int(device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>());
            d.global_memory = device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
            d.max_allocation = device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
            devices.push_back(d);
        }
    }
    if (devices.empty())
        throw std::runtime_error("opencl: OpenCL platforms were found but no device; " + std::string(install_hint));
    return devices;
}

DeviceEntry select_device(const std::string& requested) {
    const auto devices = list_devices();
    std::string selector = requested;
    if (selector.empty())
        if (const char* env = std::getenv("COLLIDE_CL_DEVICE")) selector = env;
    if (selector.empty()) return devices.front();
    const bool numeric = std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); });
    if (numeric) {
        const std::size_t index = std::stoul(selector);
        if (index < devices.size()) return devices[index];
        throw std::runtime_error("opencl: --cl-device " + selector + ": there are only " +
                                 std::to_string(devices.size()) + " devices:" + device_table(devices));
    }
    for (const auto& d : devices)
        if (lower(d.platform_name + ": " + d.device_name).find(lower(selector)) != std::string::npos) return d;
    throw std::runtime_error("opencl: --cl-device '" + selector + "' matches no device name:" + device_table(devices));
}

std::string error_name(int code) {
    const char* name = "unknown OpenCL error";
    switch (code) {
        case CL_DEVICE_NOT_FOUND: name = "CL_DEVICE_NOT_FOUND"; break;
        case CL_DEVICE_NOT_AVAILABLE: name = "CL_DEVICE_NOT_AVAILABLE"; break;
        case CL_MEM_OBJECT_ALLOCATION_FAILURE: name = "CL_MEM_OBJECT_ALLOCATION_FAILURE"; break;
        case CL_OUT_OF_RESOURCES: name = "CL_OUT_OF_RESOURCES"; break;
        case CL_OUT_OF_HOST_MEMORY: name = "CL_OUT_OF_HOST_MEMORY"; break;
        case CL_BUILD_PROGRAM_FAILURE: name = "CL_BUILD_PROGRAM_FAILURE"; break;
        case CL_INVALID_VALUE: name = "CL_INVALID_VALUE"; break;
        case CL_INVALID_BUFFER_SIZE: name = "CL_INVALID_BUFFER_SIZE"; break;
        case CL_INVALID_BUILD_OPTIONS: name = "CL_INVALID_BUILD_OPTIONS"; break;
        case CL_INVALID_KERNEL_ARGS: name = "CL_INVALID_KERNEL_ARGS"; break;
        case CL_INVALID_WORK_GROUP_SIZE: name = "CL_INVALID_WORK_GROUP_SIZE"; break;
        case CL_INVALID_WORK_ITEM_SIZE: name = "CL_INVALID_WORK_ITEM_SIZE"; break;
        case CL_INVALID_GLOBAL_WORK_SIZE: name = "CL_INVALID_GLOBAL_WORK_SIZE"; break;
        case -1001: name = "CL_PLATFORM_NOT_FOUND_KHR"; break;
        default: break;
    }
    return std::string(name) + " (" + std::to_string(code) + ")";
}

void throw_cl_error(const cl::Error& e, const std::string& what) {
    const int code = e.err();
    std::string message = "opencl: " + what + " failed: " + e.what() + " returned " + error_name(code);
    if (code == CL_MEM_OBJECT_ALLOCATION_FAILURE || code == CL_OUT_OF_RESOURCES || code == CL_INVALID_BUFFER_SIZE)
        message += "; the device is out of memory for this scene (try fewer particles or another --cl-device)";
    if (code == CL_INVALID_WORK_GROUP_SIZE)
        message += "; the work-group size is invalid for this device (see `collide devices`)";
    throw std::runtime_error(message);
}

}  // namespace collide::opencl
