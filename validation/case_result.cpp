#include "case_result.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <toml++/toml.h>

#include "core/hdf5_handle.h"
#include "core/output_file.h"

namespace collide::validation {

const char* to_string(RunStatus s) {
    switch (s) {
        case RunStatus::completed: return "completed";
        case RunStatus::left_out: return "left_out";
        case RunStatus::error: return "error";
        case RunStatus::crashed: return "crashed";
        case RunStatus::timed_out: return "timed_out";
    }
    return "error";
}

RunStatus run_status_from_string(const std::string& s) {
    for (auto st : {RunStatus::completed, RunStatus::left_out, RunStatus::error, RunStatus::crashed,
                    RunStatus::timed_out})
        if (s == to_string(st)) return st;
    throw std::runtime_error("unknown run status '" + s + "'");
}

namespace {

// TOML has nan and inf; toml++ writes and reads them, so columns round-trip as they are.
toml::array to_array(const std::vector<double>& v) {
    toml::array a;
    for (double x : v) a.push_back(x);
    return a;
}

std::vector<double> from_array(const toml::table& t, const std::string& key) {
    std::vector<double> out;
    if (const toml::array* a = t[key].as_array())
        for (const auto& e : *a) out.push_back(e.value<double>().value_or(std::nan("")));
    return out;
}

toml::table to_table(const Snapshot& s) {
    return toml::table{{"x", to_array(s.x)}, {"y", to_array(s.y)}, {"vx", to_array(s.vx)},
                       {"vy", to_array(s.vy)}, {"radius", to_array(s.radius)}};
}

Snapshot snapshot_from(const toml::table& t) {
    return {from_array(t, "x"), from_array(t, "y"), from_array(t, "vx"), from_array(t, "vy"),
            from_array(t, "radius")};
}

template <typename T>
toml::table to_table(const std::map<std::string, T>& m) {
    toml::table t;
    for (const auto& [k, v] : m) t.insert(k, v);
    return t;
}

}  // namespace

void write_case_result(const CaseResult& r, const std::string& path) {
    toml::table spec{{"id", r.spec.id}, {"scene", r.spec.scene}, {"backend", r.spec.backend},
                     {"reference", r.spec.reference}, {"seed", std::int64_t(r.spec.seed)},
                     {"scene_index", std::int64_t(r.spec.scene_index)}};
    if (r.spec.dt) spec.insert("dt", *r.spec.dt);
    if (r.spec.substeps) spec.insert("substeps", *r.spec.substeps);
    if (r.spec.iterations) spec.insert("iterations", *r.spec.iterations);
    if (!r.spec.parameters.empty()) {
        toml::array parameters;  // an array keeps the sweep order (a table would sort the paths)
        for (const auto& [path, value] : r.spec.parameters) parameters.push_back(toml::table{{"path", path}, {"value", value}});
        spec.insert("parameters", parameters);
    }
    const MetricSeries& m = r.series;
    toml::table series{{"time", to_array(m.time)}, {"kinetic_energy", to_array(m.kinetic_energy)},
                       {"total_energy", to_array(m.total_energy)}, {"momentum_x", to_array(m.momentum_x)},
                       {"momentum_y", to_array(m.momentum_y)}, {"max_overlap", to_array(m.max_overlap)},
                       {"mean_overlap", to_array(m.mean_overlap)},
                       {"overlapping_pairs", to_array(m.overlapping_pairs)},
                       {"wall_penetration", to_array(m.wall_penetration)}, {"nonfinite", to_array(m.nonfinite)}};
    toml::array trajectory;
    for (const auto& s : r.trajectory) trajectory.push_back(to_table(s));
    toml::table root{{"spec", spec},
                     {"status", to_string(r.status)},
                     {"diagnostic", r.diagnostic},
                     {"disks", std::int64_t(r.disks)},
                     {"total_mass", r.total_mass},
                     {"duration", r.duration},
                     {"dt", r.dt},
                     {"substeps", r.substeps},
                     {"wall_seconds", r.wall_seconds},
                     {"warmup_seconds", r.warmup_seconds},
                     {"steps", r.steps},
                     {"contacts", r.contacts},
                     {"phase_seconds", to_table(r.phase_seconds)},
                     {"counters", to_table(r.counters)},
                     {"provenance", to_table(r.provenance)},
                     {"series", series},
                     {"initial", to_table(r.initial)},
                     {"final", to_table(r.final_state)},
                     {"trajectory_time", to_array(r.trajectory_time)},
                     {"trajectory", trajectory},
                     {"overlap_depths", to_array(r.overlap_depths)},
                     {"compressibility", to_array(r.compressibility)},
                     {"hdf5_file", r.hdf5_file}};
    std::ostringstream text;
    text << root << "\n";
    write_file_atomically(path, text.str());  // the guard and rename of every output
}

CaseResult read_case_result(const std::string& path) {
    toml::table root;
    try {
        root = toml::parse_file(path);
    } catch (const toml::parse_error& e) {
        throw std::runtime_error(path + ": unreadable case result: " + std::string(e.description()));
    }
    CaseResult r;
    const toml::table* spec = root["spec"].as_table();
    if (!spec) throw std::runtime_error(path + ": case result without [spec]");
    r.spec.id = (*spec)["id"].value_or(std::string());
    r.spec.scene = (*spec)["scene"].value_or(std::string());
    r.spec.backend = (*spec)["backend"].value_or(std::string());
    r.spec.reference = (*spec)["reference"].value_or(false);
    r.spec.seed = std::uint64_t((*spec)["seed"].value_or(std::int64_t(1)));
    r.spec.scene_index = std::size_t((*spec)["scene_index"].value_or(std::int64_t(0)));
    if (auto v = (*spec)["dt"].value<double>()) r.spec.dt = *v;
    if (auto v = (*spec)["substeps"].value<int>()) r.spec.substeps = *v;
    if (auto v = (*spec)["iterations"].value<int>()) r.spec.iterations = *v;
    if (const toml::array* a = (*spec)["parameters"].as_array())
        for (const auto& e : *a)
            if (const toml::table* p = e.as_table())
                r.spec.parameters.emplace_back((*p)["path"].value_or(std::string()), (*p)["value"].value_or(0.0));
    r.status = run_status_from_string(root["status"].value_or(std::string("error")));
    r.diagnostic = root["diagnostic"].value_or(std::string());
    r.disks = std::size_t(root["disks"].value_or(std::int64_t(0)));
    r.total_mass = root["total_mass"].value_or(0.0);
    r.duration = root["duration"].value_or(0.0);
    r.dt = root["dt"].value_or(0.0);
    r.substeps = root["substeps"].value_or(1);
    r.wall_seconds = root["wall_seconds"].value_or(0.0);
    r.warmup_seconds = root["warmup_seconds"].value_or(0.0);
    r.steps = root["steps"].value_or(std::int64_t(0));
    r.contacts = root["contacts"].value_or(std::int64_t(0));
    if (const toml::table* t = root["phase_seconds"].as_table())
        for (const auto& [k, v] : *t) r.phase_seconds[std::string(k.str())] = v.value_or(0.0);
    if (const toml::table* t = root["counters"].as_table())
        for (const auto& [k, v] : *t) r.counters[std::string(k.str())] = v.value_or(0.0);
    if (const toml::table* t = root["provenance"].as_table())
        for (const auto& [k, v] : *t) r.provenance[std::string(k.str())] = v.value_or(std::string());
    if (const toml::table* s = root["series"].as_table()) {
        MetricSeries& m = r.series;
        m.time = from_array(*s, "time");
        m.kinetic_energy = from_array(*s, "kinetic_energy");
        m.total_energy = from_array(*s, "total_energy");
        m.momentum_x = from_array(*s, "momentum_x");
        m.momentum_y = from_array(*s, "momentum_y");
        m.max_overlap = from_array(*s, "max_overlap");
        m.mean_overlap = from_array(*s, "mean_overlap");
        m.overlapping_pairs = from_array(*s, "overlapping_pairs");
        m.wall_penetration = from_array(*s, "wall_penetration");
        m.nonfinite = from_array(*s, "nonfinite");
    }
    if (const toml::table* t = root["initial"].as_table()) r.initial = snapshot_from(*t);
    if (const toml::table* t = root["final"].as_table()) r.final_state = snapshot_from(*t);
    r.trajectory_time = from_array(root, "trajectory_time");
    if (const toml::array* a = root["trajectory"].as_array())
        for (const auto& e : *a)
            if (const toml::table* t = e.as_table()) r.trajectory.push_back(snapshot_from(*t));
    r.overlap_depths = from_array(root, "overlap_depths");
    r.compressibility = from_array(root, "compressibility");
    r.hdf5_file = root["hdf5_file"].value_or(std::string());
    return r;
}

}  // namespace collide::validation

namespace collide::validation {

namespace {

// This machine's name as MPI reports it (Open MPI's MPI_Get_processor_name is the host name).
std::string this_host() {
    char name[256] = {};
    return ::gethostname(name, sizeof name - 1) == 0 ? std::string(name) : std::string();
}

}  // namespace

std::string case_files_problem(const CaseResult& result, const std::string& output_dir) {
    if (result.hdf5_file.empty()) return "";
    // A case run by an MPI rank on another node keeps its HDF5 file there (without
    // --gather-hdf5); the record says where, and only that node could check the file.
    const auto host = result.provenance.find("hdf5_host");
    if (host != result.provenance.end() && host->second != this_host()) return "";
    const std::string path = output_dir + "/" + result.hdf5_file;
    if (!std::filesystem::is_regular_file(path)) return path + ": missing";
    silence_hdf5_error_printing();
    try {
        // HDF5 refuses a truncated file at open ("truncated file: eof = ..."); a file cut
        // at a chunk boundary still has to hold one /metrics/time row per output in the record.
        Hdf5Handle file = file_handle(checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path, "open"));
        Hdf5Handle time = dataset_handle(checked(H5Dopen2(file.get(), "/metrics/time", H5P_DEFAULT), path,
                                                 "open /metrics/time"));
        Hdf5Handle space = dataspace_handle(checked(H5Dget_space(time.get()), path, "read /metrics/time"));
        hsize_t rows = 0;
        checked(H5Sget_simple_extent_dims(space.get(), &rows, nullptr), path, "read /metrics/time");
        if (rows != result.series.size())
            return path + ": " + std::to_string(rows) + " outputs where the case record has " +
                   std::to_string(result.series.size());
        std::vector<double> values(rows);
        if (rows) checked(H5Dread(time.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
                          path, "read /metrics/time");
    } catch (const Hdf5Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace collide::validation
