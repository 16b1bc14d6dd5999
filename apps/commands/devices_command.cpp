// `collide devices`: the OpenCL platforms and devices this machine offers, numbered as
// `--cl-device` counts them.
#include <cstdio>

#include "commands.h"
#include "opencl/cl_devices.h"

namespace collide::cli {

void add_devices_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("devices", "List OpenCL platforms and devices (for --cl-device)");
    cmd->callback([] {
        const auto devices = opencl::list_devices();
        std::string platform;
        for (const auto& d : devices) {
            if (d.platform_name != platform) {
                platform = d.platform_name;
                std::printf("platform  %s\n", platform.c_str());
            }
            std::printf("  [%d] %s (%s, %d compute units, %.0f MiB, %s, fp64 %s)\n      driver %s\n", d.index,
                        d.device_name.c_str(), d.type.c_str(), d.compute_units, double(d.global_memory) / (1 << 20),
                        d.device_version.c_str(), d.fp64 ? "yes" : "no", d.driver_version.c_str());
        }
        std::printf("pick one with --cl-device INDEX or --cl-device NAME-SUBSTRING\n");
    });
}

}  // namespace collide::cli
