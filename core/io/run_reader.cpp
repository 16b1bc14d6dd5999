// RunFile (checks in run_reader.h), on the HDF5 1.10 C API.
#include "core/io/run_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "core/io/input_file.h"
#include "core/io/run_schema.h"
#include "core/io/run_writer.h"

namespace collide {
namespace {

bool has_link(hid_t file, const std::string& name) {
    // H5Lexists fails (< 0) when a parent group is missing: that is "no" too.
    return H5Lexists(file, name.c_str(), H5P_DEFAULT) > 0;
}

std::string shape_text(const std::vector<hsize_t>& shape) {
    std::string text = "(";
    for (std::size_t i = 0; i < shape.size(); ++i) text += (i ? ", " : "") + std::to_string(shape[i]);
    return text + (shape.size() == 1 ? ",)" : ")");
}

bool has_fletcher32(hid_t dataset) {
    Hdf5Handle properties = property_list_handle(H5Dget_create_plist(dataset));
    if (!properties) return false;
    const int count = H5Pget_nfilters(properties.get());
    for (int k = 0; k < count; ++k) {
        unsigned flags = 0;
        std::size_t elements = 0;
        if (H5Pget_filter2(properties.get(), unsigned(k), &flags, &elements, nullptr, 0, nullptr, nullptr) ==
            H5Z_FILTER_FLETCHER32)
            return true;
    }
    return false;
}

// Disks with a NaN or Inf coordinate or velocity, as compute_metrics counts them.
std::size_t count_nonfinite(const ParticleState<double>& s) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < s.size(); ++i) count += !s.is_finite(i);
    return count;
}

// The length of a 1-D dataset, from its shape alone (its other checks follow in read_all).
hsize_t length_of(hid_t file, const std::string& name, const std::string& path) {
    Hdf5Handle dataset = dataset_handle(has_link(file, name) ? H5Dopen2(file, name.c_str(), H5P_DEFAULT) : -1);
    Hdf5Handle space = dataspace_handle(dataset ? H5Dget_space(dataset.get()) : -1);
    hsize_t dims[1] = {0};
    if (!space || H5Sget_simple_extent_ndims(space.get()) != 1 || H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0)
        throw RunFileError(path + ": /" + name + ": missing, or not a 1-D dataset");
    return dims[0];
}

// Every attribute name of `object`, in name order; false when they cannot be listed (damage).
bool attribute_names(hid_t object, std::vector<std::string>& names) {
    auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->push_back(name);
        return 0;
    };
    return H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names) >= 0;
}

// The scalar attribute `name` of `object`, an 8-byte integer (or float) as the writer stores it.
template <typename Number>
Number number_attribute(hid_t object, const std::string& name, const std::string& where) {
    constexpr bool integer = std::is_integral_v<Number>;
    Hdf5Handle attribute = attribute_handle(H5Aexists(object, name.c_str()) > 0 ? H5Aopen(object, name.c_str(), H5P_DEFAULT) : -1);
    Hdf5Handle type = datatype_handle(attribute ? H5Aget_type(attribute.get()) : -1);
    Hdf5Handle space = dataspace_handle(attribute ? H5Aget_space(attribute.get()) : -1);
    Number value{};
    if (!type || H5Tget_class(type.get()) != (integer ? H5T_INTEGER : H5T_FLOAT) || H5Tget_size(type.get()) != 8 ||
        !space || H5Sget_simple_extent_ndims(space.get()) != 0 ||
        H5Aread(attribute.get(), integer ? H5T_NATIVE_INT64 : H5T_NATIVE_DOUBLE, &value) < 0)
        throw RunFileError(where + ": attribute '" + name + "' missing, not one " + (integer ? "int64" : "float64") +
                           " or unreadable (damaged?)");
    return value;
}

}  // namespace

RunFile::RunFile(const std::string& path) : path_(path) {
    // The system's own cause (missing, a link loop, a directory, no permission) before HDF5's.
    if (const std::string why = input_path_problem(path, false); !why.empty()) fail(why);
    silence_hdf5_error_printing();
    const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) {
        const std::string reason = hdf5_error_reason();
        fail("not a readable HDF5 file (damaged or cut short?)" + (reason.empty() ? "" : ": " + reason));
    }
    file_ = file_handle(id);
    check_format();
    read_constants();
    read_metrics();
    has_frames_ = has_link(file_.get(), "frames");
    if (has_frames_) read_frame_times();
}

void RunFile::fail(const std::string& what) const { throw RunFileError(path_ + ": " + what); }

std::string RunFile::attribute(const std::string& name) const {
    if (H5Aexists(file_.get(), name.c_str()) <= 0) fail("no root attribute '" + name + "'");
    Hdf5Handle attribute = attribute_handle(H5Aopen(file_.get(), name.c_str(), H5P_DEFAULT));
    Hdf5Handle type = variable_length_string_type(path_);
    Hdf5Handle stored = datatype_handle(attribute ? H5Aget_type(attribute.get()) : H5I_INVALID_HID);
    if (!stored || H5Tget_class(stored.get()) != H5T_STRING || H5Tis_variable_str(stored.get()) <= 0)
        fail("root attribute '" + name + "' is not a text string");
    char* text = nullptr;
    if (H5Aread(attribute.get(), type.get(), &text) < 0) {
        const std::string reason = hdf5_error_reason();
        fail("cannot read root attribute '" + name + "' (damaged?)" + (reason.empty() ? "" : ": " + reason));
    }
    std::string value(text ? text : "");
    H5free_memory(text);
    return value;
}

// Every root attribute (all are text), by name, for their checksum.
std::map<std::string, std::string> RunFile::root_attributes() const {
    std::vector<std::string> names;
    if (!attribute_names(file_.get(), names)) fail("cannot list the root attributes (damaged?)");
    std::map<std::string, std::string> attributes;
    for (const std::string& name : names) attributes[name] = attribute(name);
    return attributes;
}

SolverStats RunFile::stats() const {
    const std::string where = path_ + ": /stats";
    Hdf5Handle group = group_handle(has_link(file_.get(), "stats") ? H5Gopen2(file_.get(), "stats", H5P_DEFAULT) : -1);
    if (!group) fail("/stats: missing, or not a group");
    SolverStats stats;
    stats.steps = number_attribute<std::int64_t>(group.get(), "steps", where);
    stats.contacts = number_attribute<std::int64_t>(group.get(), "contacts", where);
    for (auto [name, values] : {std::pair{"phase_seconds", &stats.phase_seconds}, {"counters", &stats.counters}}) {
        Hdf5Handle inner = group_handle(has_link(group.get(), name) ? H5Gopen2(group.get(), name, H5P_DEFAULT) : -1);
        std::vector<std::string> keys;
        if (!inner || !attribute_names(inner.get(), keys)) fail(std::string("/stats/") + name + ": missing, or unreadable");
        for (const std::string& key : keys)
            (*values)[key] = number_attribute<double>(inner.get(), key, where + "/" + name);
    }
    return stats;
}

void RunFile::check_format() const {
    if (H5Aexists(file_.get(), "format") <= 0 || attribute("format") != "collide-run")
        fail("not a collide run file (no root attribute format = \"collide-run\")");
    const std::string version = H5Aexists(file_.get(), "format_version") > 0 ? attribute("format_version") : "";
    if (version == "1" || version.empty())
        fail("written by an older collide (run-file format 1, without checksums); run it again");
    if (version != run_format_version)
        fail("run-file format " + version + ", but this collide reads format " + run_format_version +
             " (written by a newer collide?)");
    const std::map<std::string, std::string> attributes = root_attributes();
    const auto stored = attributes.find(attributes_checksum_name);
    if (stored == attributes.end() || stored->second != root_attributes_checksum(attributes))
        fail("the root attributes (provenance, scene text) do not match their checksum (/attributes_checksum): "
             "the file is damaged");
}

// Opens `name` after checking that it is a dataset of 8-byte floats (or integers) of exactly
// `shape`, protected by its checksum filter.
Hdf5Handle RunFile::open_dataset(const std::string& name, bool integer, const std::vector<hsize_t>& shape) const {
    const std::string where = "/" + name;
    if (!has_link(file_.get(), name)) fail(where + ": missing");
    Hdf5Handle dataset = dataset_handle(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT));
    if (!dataset) fail(where + ": not a readable dataset (damaged?)");
    Hdf5Handle type = datatype_handle(H5Dget_type(dataset.get()));
    const H5T_class_t expected = integer ? H5T_INTEGER : H5T_FLOAT;
    if (!type || H5Tget_class(type.get()) != expected || H5Tget_size(type.get()) != 8)
        fail(where + ": stored as the wrong type; expected 8-byte " + (integer ? "integers" : "floats"));
    Hdf5Handle space = dataspace_handle(H5Dget_space(dataset.get()));
    const int rank = space ? H5Sget_simple_extent_ndims(space.get()) : -1;
    std::vector<hsize_t> dims(std::size_t(std::max(rank, 0)));
    if (rank < 0 || H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
        fail(where + ": unreadable shape (damaged?)");
    if (dims != shape) fail(where + ": shape " + shape_text(dims) + ", expected " + shape_text(shape));
    if (!has_fletcher32(dataset.get()))
        fail(where + ": stored without its checksum (Fletcher32 filter); the file was rewritten by another program");
    return dataset;
}

std::vector<double> RunFile::read_all(const std::string& name, bool integer, const std::vector<hsize_t>& shape) const {
    Hdf5Handle dataset = open_dataset(name, integer, shape);
    std::size_t size = 1;
    for (hsize_t extent : shape) size *= std::size_t(extent);
    std::vector<double> values(size);
    if (size && H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
        const std::string reason = hdf5_error_reason();
        fail("/" + name + ": cannot read: the file is damaged (a checksum does not match, or data is missing)" +
             (reason.empty() ? "" : "; HDF5: " + reason));
    }
    return values;
}

void RunFile::read_constants() {
    if (!has_link(file_.get(), "particles") || !has_link(file_.get(), "metrics"))
        fail("not a collide run file (no /particles or /metrics)");
    // N is the length of the radius array; mass and inv_mass must hold exactly as many values.
    const hsize_t n = length_of(file_.get(), "particles/radius", path_);
    if (n == 0) fail("/particles/radius: no disks");
    constants_.radius = read_all("particles/radius", false, {n});
    constants_.mass = read_all("particles/mass", false, {n});
    constants_.inv_mass = read_all("particles/inv_mass", false, {n});
    for (std::size_t i = 0; i < n; ++i) {
        const double r = constants_.radius[i], m = constants_.mass[i], w = constants_.inv_mass[i];
        const std::string disk = "disk " + std::to_string(i) + ": ";
        if (!(std::isfinite(r) && r > 0)) fail("/particles/radius: " + disk + "radius " + std::to_string(r) + ", not > 0");
        if (!(std::isfinite(m) && m > 0)) fail("/particles/mass: " + disk + "mass " + std::to_string(m) + ", not > 0");
        // 1/m, or exactly 0 for a kinematic stone (ParticleState::append_disk).
        if (w != 0 && !(std::fabs(w * m - 1) <= 1e-12))
            fail("/particles/inv_mass: " + disk + "inverse mass " + std::to_string(w) + " is neither 1/mass nor 0");
    }
    constants_.x.assign(n, 0);
    constants_.y.assign(n, 0);
    constants_.vx.assign(n, 0);
    constants_.vy.assign(n, 0);
}

void RunFile::read_metrics() {
    const hsize_t t = length_of(file_.get(), "metrics/time", path_);
    for (const MetricColumn& column : metric_columns)
        metrics_[column.name] = read_all(std::string("metrics/") + column.name, column.integer(), {t});
    const std::vector<double>& time = metrics_["time"];
    for (std::size_t k = 0; k < t; ++k)
        if (!std::isfinite(time[k]) || (k > 0 && time[k] < time[k - 1]))
            fail("/metrics/time: row " + std::to_string(k) + ": time " + std::to_string(time[k]) +
                 " is not finite or runs backwards");
    for (const MetricColumn& column : metric_columns) {
        if (!column.non_negative) continue;
        const std::vector<double>& values = metrics_[column.name];
        for (std::size_t k = 0; k < t; ++k)
            if (values[k] < 0)
                fail(std::string("/metrics/") + column.name + ": row " + std::to_string(k) + ": " +
                     std::to_string(values[k]) + " is negative, which this measure cannot be");
    }
    for (std::size_t k = 0; k < t; ++k)
        if (metrics_["nonfinite"][k] > double(disk_count()))
            fail("/metrics/nonfinite: row " + std::to_string(k) + ": more non-finite disks than disks");
}

const std::vector<double>& RunFile::metric(const std::string& name) const {
    const auto found = metrics_.find(name);
    if (found == metrics_.end()) throw std::logic_error("RunFile::metric: no metric '" + name + "'");
    return found->second;
}

Metrics RunFile::metrics_at(std::size_t k) const {
    if (k >= output_count()) throw std::out_of_range(path_ + ": no output " + std::to_string(k));
    Metrics m;
    for (const MetricColumn& column : metric_columns) column.assign(m, metrics_.at(column.name)[k]);
    return m;
}

void RunFile::read_frame_times() {
    const hsize_t t = output_count(), n = disk_count();
    frame_times_ = read_all("frames/time", false, {t});
    // The writer stores a frame at every output time, the very same double as /metrics/time.
    if (frame_times_ != metric("time")) fail("/frames/time: differs from /metrics/time");
    open_dataset("frames/position", false, {t, n, 2});
    open_dataset("frames/velocity", false, {t, n, 2});
}

void RunFile::read_frame(std::size_t k, ParticleState<double>& out) const {
    if (!has_frames_) fail("written without frames: rerun with `collide run ... --frames`");
    if (k >= frame_times_.size()) throw std::out_of_range(path_ + ": no frame " + std::to_string(k));
    out = constants_;
    const std::size_t n = disk_count();
    std::vector<double> xy(2 * n);
    // One row of a T x N x 2 dataset: frame k.
    auto read_row = [&](const std::string& name) {
        Hdf5Handle dataset = open_dataset(name, false, {frame_times_.size(), n, 2});
        Hdf5Handle file_space = dataspace_handle(H5Dget_space(dataset.get()));
        const hsize_t start[3] = {hsize_t(k), 0, 0}, count[3] = {1, hsize_t(n), 2};
        Hdf5Handle memory = dataspace_handle(H5Screate_simple(3, count, nullptr));
        if (!file_space || !memory ||
            H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0 ||
            H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, memory.get(), file_space.get(), H5P_DEFAULT, xy.data()) < 0) {
            const std::string reason = hdf5_error_reason();
            fail("/" + name + ": cannot read frame " + std::to_string(k) +
                 ": the file is damaged (a checksum does not match, or data is missing)" +
                 (reason.empty() ? "" : "; HDF5: " + reason));
        }
    };
    read_row("frames/position");
    for (std::size_t i = 0; i < n; ++i) out.x[i] = xy[2 * i], out.y[i] = xy[2 * i + 1];
    read_row("frames/velocity");
    for (std::size_t i = 0; i < n; ++i) out.vx[i] = xy[2 * i], out.vy[i] = xy[2 * i + 1];
    check_frame(k, out);
}

// The run counted the non-finite disks of this very state when it wrote it (/metrics/nonfinite).
void RunFile::check_frame(std::size_t k, const ParticleState<double>& state) const {
    const std::size_t found = count_nonfinite(state);
    const double recorded = metric("nonfinite")[k];
    if (double(found) != recorded)
        fail("/frames: frame " + std::to_string(k) + " (t = " + std::to_string(frame_times_[k]) + ") holds " +
             std::to_string(found) + " disks with a NaN or Inf coordinate or velocity, but the run recorded " +
             std::to_string(std::int64_t(recorded)) + " (/metrics/nonfinite): the file is damaged");
}

void RunFile::verify_frames() const {
    ParticleState<double> state;
    for (std::size_t k = 0; k < frame_times_.size(); ++k) read_frame(k, state);
}

}  // namespace collide
