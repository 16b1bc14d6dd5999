// `collide devices [--cl-device TEXT]`: the OpenCL platforms and devices this machine offers, numbered
// as `--cl-device` counts them, or only the one a selector picks.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "opencl/cl_devices.h"

namespace collide::cli {
namespace {

const char* yes_no(bool b) { return b ? "yes" : "no"; }

}  // namespace

void add_devices_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("devices", "List OpenCL platforms and devices (for --cl-device)");
    auto selector = std::make_shared<std::string>();
    cmd->add_option("--cl-device", *selector,
                    "Show only the device this picks (index or name substring), as `collide run --cl-device` "
                    "would; an error lists the devices when none matches");
    cmd->callback([selector] {
        const auto devices = selector->empty() ? opencl::list_devices()
                                               : std::vector<opencl::DeviceEntry>{opencl::select_device(*selector)};
        std::string platform;
        for (const auto& d : devices) {
            if (d.platform_name != platform) {
                platform = d.platform_name;
                std::printf("platform  %s\n", platform.c_str());
            }
            std::printf("  [%d] %s (%s, %d compute units, %.0f MiB, %s, fp64 %s)\n      driver %s\n", d.index,
                        d.device_name.c_str(), d.type.c_str(), d.compute_units, double(d.global_memory) / (1 << 20),
                        d.device_version.c_str(), yes_no(d.fp64), d.driver_version.c_str());
            // The float properties that decide whether `opencl` can give `cpu`'s bits
            // (docs/opencl-backend.md, "Float and double").
            std::printf("      float: denormals %s, fma %s, correctly rounded divide/sqrt %s\n", yes_no(d.fp32_denormals),
                        yes_no(d.fp32_fma), yes_no(d.fp32_correctly_rounded_divide_sqrt));
        }
        std::printf("pick one with --cl-device INDEX or --cl-device NAME-SUBSTRING\n");
    });
}

}  // namespace collide::cli
