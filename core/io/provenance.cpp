#include "core/io/provenance.h"

#include "core/numerics/number_text.h"

#include <H5public.h>
#include <gsl/gsl_version.h>
#include <unistd.h>

#include <chrono>
#include <ctime>

namespace collide {

std::map<std::string, std::string> compiled_build_info();  // generated/build_info.cpp

namespace {
std::string g_command_line;

std::string utc_now() {
    const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
    return buf;
}

std::string host_name() {
    char buf[256] = {};
    return gethostname(buf, sizeof buf - 1) == 0 ? std::string(buf) : std::string("unknown");
}
}  // namespace

std::map<std::string, std::string> build_provenance() {
    auto info = compiled_build_info();
    unsigned major = 0, minor = 0, release = 0;
    H5get_libversion(&major, &minor, &release);
    info["hdf5_version"] = std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release);
    info["gsl_version"] = gsl_version;
    info["host"] = host_name();
    info["run_date_utc"] = utc_now();
    return info;
}

std::map<std::string, std::string> run_provenance(const Scene& scene, const std::string& backend,
                                                  const Solver& solver) {
    auto attributes = build_provenance();
    for (const auto& [key, value] : solver.provenance()) attributes["backend_" + key] = value;
    attributes["backend"] = backend;
    attributes["scene_name"] = scene.name;
    attributes["scene_path"] = scene.source_path;
    attributes["scene_text"] = scene.source_text;
    attributes["scene_overrides"] = scene.overrides;
    attributes["seed"] = std::to_string(scene.seed);
    attributes["dt"] = round_trip_text(scene.run.dt);
    attributes["substeps"] = std::to_string(scene.run.substeps);
    attributes["command_line"] = command_line();
    return attributes;
}

void set_command_line(int argc, char** argv) {
    g_command_line.clear();
    for (int i = 0; i < argc; ++i) {
        if (i) g_command_line += ' ';
        g_command_line += argv[i];
    }
}

const std::string& command_line() { return g_command_line; }

}  // namespace collide
