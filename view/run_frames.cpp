#include "run_frames.h"

#include <stdexcept>

#include "core/scene_loader.h"

namespace collide::view {
namespace {

bool has_link(hid_t file, const std::string& name) { return H5Lexists(file, name.c_str(), H5P_DEFAULT) > 0; }

}  // namespace

RunFrames::RunFrames(const std::string& path) : path_(path) {
    silence_hdf5_error_printing();
    file_ = file_handle(checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path, "open the run file"));
    if (!has_link(file_.get(), "particles") || !has_link(file_.get(), "metrics"))
        throw std::runtime_error(path + ": not a collide run file (no /particles or /metrics)");
    if (!has_link(file_.get(), "frames"))
        throw std::runtime_error(path + ": written without --frames: rerun with `collide run ... --frames`");
    scene_ = parse_scene(root_attribute("scene_text"), root_attribute("scene_path"));
    backend_ = root_attribute("backend");
    times_ = read_vector("frames/time");
    constants_.radius = read_vector("particles/radius");
    constants_.mass = read_vector("particles/mass");
    constants_.inv_mass = read_vector("particles/inv_mass");
    const std::size_t n = constants_.radius.size();
    constants_.x.resize(n);
    constants_.y.resize(n);
    constants_.vx.resize(n);
    constants_.vy.resize(n);
}

std::vector<double> RunFrames::read_vector(const std::string& name) const {
    Hdf5Handle d = dataset_handle(checked(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), path_, "open " + name));
    Hdf5Handle space = dataspace_handle(checked(H5Dget_space(d.get()), path_, "get the shape of " + name));
    std::vector<double> values(std::size_t(checked(H5Sget_simple_extent_npoints(space.get()), path_, "size " + name)));
    checked(H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), path_, "read " + name);
    return values;
}

std::string RunFrames::root_attribute(const std::string& name) const {
    Hdf5Handle attribute = attribute_handle(
        checked(H5Aopen_by_name(file_.get(), "/", name.c_str(), H5P_DEFAULT, H5P_DEFAULT), path_, "open /" + name));
    Hdf5Handle type = variable_length_string_type(path_);
    char* text = nullptr;
    checked(H5Aread(attribute.get(), type.get(), &text), path_, "read /" + name);
    std::string value(text ? text : "");
    H5free_memory(text);
    return value;
}

void RunFrames::read(std::size_t k, ParticleState<double>& out) const {
    out = constants_;
    const std::size_t n = disk_count();
    std::vector<double> xy(2 * n);
    // One T x N x 2 hyperslab row: frame k of a dataset.
    auto read_frame = [&](const char* name) {
        Hdf5Handle d = dataset_handle(checked(H5Dopen2(file_.get(), name, H5P_DEFAULT), path_, std::string("open ") + name));
        Hdf5Handle file_space = dataspace_handle(checked(H5Dget_space(d.get()), path_, "get a dataspace"));
        const hsize_t start[3] = {hsize_t(k), 0, 0}, count[3] = {1, hsize_t(n), 2};
        checked(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr), path_, "select");
        Hdf5Handle memory = dataspace_handle(checked(H5Screate_simple(3, count, nullptr), path_, "make a dataspace"));
        checked(H5Dread(d.get(), H5T_NATIVE_DOUBLE, memory.get(), file_space.get(), H5P_DEFAULT, xy.data()), path_,
                std::string("read ") + name);
    };
    read_frame("frames/position");
    for (std::size_t i = 0; i < n; ++i) out.x[i] = xy[2 * i], out.y[i] = xy[2 * i + 1];
    read_frame("frames/velocity");
    for (std::size_t i = 0; i < n; ++i) out.vx[i] = xy[2 * i], out.vy[i] = xy[2 * i + 1];
}

}  // namespace collide::view
