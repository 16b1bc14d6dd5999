// RunWriter (layout in run_writer.h and docs/output-format.md), on the HDF5 1.10 C API.
//
// Writing happens in three places, one per kind of data:
//   - constants (root attributes, /particles, /stats) are written once, whole;
//   - time series (/metrics/*, /frames/*) are extendible datasets that grow by one row per
//     output time (append_row), so a long run never holds its history in memory;
//   - the file itself lives under a temporary name until commit() renames it into place
//     (AtomicOutputFile, core/io/output_file.h: the guard and the rename every writer shares).
#include "core/io/run_writer.h"

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <vector>

#include "core/numerics/crc32.h"
#include "core/io/hdf5_handle.h"
#include "core/io/output_file.h"
#include "core/io/run_schema.h"

namespace collide {
namespace {

// What goes into /metrics: one dataset per column of the run schema (core/io/run_schema.h).

constexpr hsize_t metrics_chunk_rows = 256;
constexpr std::size_t frame_chunk_target_bytes = 256 * 1024;
constexpr hsize_t constants_chunk_values = 64 * 1024;  // 512 KiB of doubles per chunk
constexpr unsigned gzip_level = 4;  // little slower than 1, clearly smaller; 9 is rarely worth it

// ---------------------------------------------------------------------------------------
// Attributes

void write_string_attribute(hid_t object, const std::string& name, const std::string& value,
                            const std::string& context) {
    const std::string where = context + ": attribute '" + name + "'";
    if (checked(H5Aexists(object, name.c_str()), where, "look up") > 0)
        checked(H5Adelete(object, name.c_str()), where, "replace");
    Hdf5Handle type = variable_length_string_type(where);
    Hdf5Handle space = dataspace_handle(checked(H5Screate(H5S_SCALAR), where, "create a dataspace"));
    Hdf5Handle attribute = attribute_handle(checked(
        H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), where, "create"));
    const char* text = value.c_str();
    checked(H5Awrite(attribute.get(), type.get(), &text), where, "write");
}

// A scalar number attribute: file_type is the portable on-disk type, memory_type the native one.
void write_number_attribute(hid_t object, const std::string& name, hid_t file_type, hid_t memory_type,
                            const void* value, const std::string& context) {
    const std::string where = context + ": attribute '" + name + "'";
    if (checked(H5Aexists(object, name.c_str()), where, "look up") > 0)
        checked(H5Adelete(object, name.c_str()), where, "replace");
    Hdf5Handle space = dataspace_handle(checked(H5Screate(H5S_SCALAR), where, "create a dataspace"));
    Hdf5Handle attribute = attribute_handle(checked(
        H5Acreate2(object, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), where, "create"));
    checked(H5Awrite(attribute.get(), memory_type, value), where, "write");
}

void write_double_attribute(hid_t object, const std::string& name, double value, const std::string& context) {
    write_number_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value, context);
}

void write_int64_attribute(hid_t object, const std::string& name, std::int64_t value, const std::string& context) {
    write_number_attribute(object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value, context);
}

void describe(hid_t object, const std::string& units, const std::string& meaning, const std::string& context) {
    write_string_attribute(object, "units", units, context);
    write_string_attribute(object, "description", meaning, context);
}

// ---------------------------------------------------------------------------------------
// Groups and datasets

Hdf5Handle create_group(hid_t parent, const std::string& name, const std::string& context) {
    return group_handle(checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                context, "create group '" + name + "'"));
}

Hdf5Handle open_or_create_group(hid_t parent, const std::string& name, const std::string& context) {
    if (checked(H5Lexists(parent, name.c_str(), H5P_DEFAULT), context, "look up group '" + name + "'") > 0)
        return group_handle(checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), context, "open group '" + name + "'"));
    return create_group(parent, name, context);
}

// Every dataset carries HDF5's Fletcher32 checksum filter: HDF5 stores a checksum with each
// chunk and verifies it on every read, so a damaged file (a flipped bit on a disk, a copy
// gone wrong) fails to read instead of handing back wrong numbers. The filter needs chunked
// storage. Added last, so the checksum covers the bytes as stored (after compression).
void add_checksum_filter(hid_t properties, const std::string& where) {
    checked(H5Pset_fletcher32(properties), where, "enable the Fletcher32 checksum filter");
}

// A fixed-size 1-D dataset of doubles, written whole (chunked, for its checksums).
void write_double_array(hid_t group, const std::string& name, const std::vector<double>& values,
                        const std::string& context) {
    const std::string where = context + ": dataset '" + name + "'";
    const hsize_t size = values.size();
    const hsize_t chunk = std::clamp<hsize_t>(size, 1, constants_chunk_values);
    Hdf5Handle space = dataspace_handle(checked(H5Screate_simple(1, &size, nullptr), where, "create a dataspace"));
    Hdf5Handle properties = property_list_handle(checked(H5Pcreate(H5P_DATASET_CREATE), where, "create properties"));
    if (size > 0) {  // HDF5 allows no chunk larger than a fixed, empty extent
        checked(H5Pset_chunk(properties.get(), 1, &chunk), where, "set the chunk shape");
        add_checksum_filter(properties.get(), where);
    }
    Hdf5Handle dataset = dataset_handle(checked(
        H5Dcreate2(group, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT),
        where, "create"));
    checked(H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), where, "write");
}

// An empty dataset of shape (0, row_shape...) that can grow without limit in its first
// dimension. HDF5 needs chunked storage for that; `rows_per_chunk` rows form one chunk.
Hdf5Handle create_growing_dataset(hid_t group, const std::string& name, hid_t file_type,
                                  const std::vector<hsize_t>& row_shape, hsize_t rows_per_chunk,
                                  bool compress, const std::string& context) {
    const std::string where = context + ": dataset '" + name + "'";
    std::vector<hsize_t> dims{0}, max_dims{H5S_UNLIMITED}, chunk{rows_per_chunk};
    for (hsize_t extent : row_shape) {
        dims.push_back(extent);
        max_dims.push_back(extent);
        chunk.push_back(extent);
    }
    const int rank = int(dims.size());
    Hdf5Handle space = dataspace_handle(
        checked(H5Screate_simple(rank, dims.data(), max_dims.data()), where, "create a dataspace"));
    Hdf5Handle properties = property_list_handle(checked(H5Pcreate(H5P_DATASET_CREATE), where, "create properties"));
    checked(H5Pset_chunk(properties.get(), rank, chunk.data()), where, "set the chunk shape");
    if (compress) {
        // Shuffling the bytes of the doubles first groups their similar high-order bytes,
        // which gzip then compresses far better.
        checked(H5Pset_shuffle(properties.get()), where, "enable the shuffle filter");
        checked(H5Pset_deflate(properties.get(), gzip_level), where, "enable gzip compression");
    }
    add_checksum_filter(properties.get(), where);
    return dataset_handle(checked(H5Dcreate2(group, name.c_str(), file_type, space.get(), H5P_DEFAULT,
                                             properties.get(), H5P_DEFAULT),
                                  where, "create"));
}

// Writes row number `row` (shape row_shape) of a growing dataset, extending it to row + 1 rows.
void append_row(hid_t dataset, hid_t memory_type, hsize_t row, const std::vector<hsize_t>& row_shape,
                const void* data, const std::string& where) {
    std::vector<hsize_t> new_dims{row + 1}, start{row}, count{1};
    for (hsize_t extent : row_shape) {
        new_dims.push_back(extent);
        start.push_back(0);
        count.push_back(extent);
    }
    const int rank = int(new_dims.size());
    checked(H5Dset_extent(dataset, new_dims.data()), where, "extend");
    Hdf5Handle file_space = dataspace_handle(checked(H5Dget_space(dataset), where, "get the dataspace"));
    checked(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
            where, "select the new row");
    Hdf5Handle memory_space = dataspace_handle(checked(H5Screate_simple(rank, count.data(), nullptr), where,
                                                       "create a dataspace"));
    checked(H5Dwrite(dataset, memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT, data), where,
            "write row " + std::to_string(row));
}

// x, y arrays (structure of arrays) as one interleaved N x 2 array (x0, y0, x1, y1, ...).
std::vector<double> interleave(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<double> xy(2 * x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        xy[2 * i] = x[i];
        xy[2 * i + 1] = y[i];
    }
    return xy;
}

// File access with the object-header format of HDF5 1.8 (readable by every HDF5 >= 1.8):
// its headers, which hold the attributes (provenance, /stats), carry checksums that HDF5
// verifies when it reads them; the older default format has none.
Hdf5Handle checksummed_metadata_access(const std::string& context) {
    Hdf5Handle access = property_list_handle(checked(H5Pcreate(H5P_FILE_ACCESS), context, "create file properties"));
    checked(H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_V18), context,
            "choose the HDF5 1.8 file format");
    return access;
}

}  // namespace

// ---------------------------------------------------------------------------------------

struct RunWriter::Impl {
    std::string target;
    // Declared before the HDF5 handles: destroyed after them, so the file is closed before
    // an uncommitted temporary file is removed.
    AtomicOutputFile output;
    Hdf5Handle file;
    Hdf5Handle metrics_group;
    std::vector<Hdf5Handle> metric_datasets;  // in the order of metric_columns
    hsize_t outputs = 0;                            // rows written to every time series

    bool write_frames;
    Hdf5Handle frames_group, frame_time, frame_position, frame_velocity;
    std::size_t frame_disks = 0;

    bool committed = false;
    std::map<std::string, std::string> root_text;  // every root attribute, for their checksum

    void write_root_text(const std::string& name, const std::string& value) {
        write_string_attribute(file.get(), name, value, target);
        root_text[name] = value;
    }

    Impl(const std::string& path, bool frames)
        : target(path), output(path), write_frames(frames) {
        file = file_handle(checked(H5Fcreate(output.temporary_path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT,
                                             checksummed_metadata_access(target).get()),
                                   target, "create the HDF5 file '" + output.temporary_path() + "'"));
        write_root_text("format", "collide-run");
        write_root_text("format_version", run_format_version);
        create_metric_datasets();
        if (write_frames) frames_group = create_group(file.get(), "frames", target);
    }

    void create_metric_datasets() {
        metrics_group = create_group(file.get(), "metrics", target);
        for (const MetricColumn& column : metric_columns) {
            Hdf5Handle dataset = create_growing_dataset(metrics_group.get(), column.name,
                                                        column.integer() ? H5T_STD_I64LE : H5T_IEEE_F64LE, {},
                                                        metrics_chunk_rows, false, target + ": /metrics");
            describe(dataset.get(), column.units, column.description, target + ": /metrics/" + column.name);
            metric_datasets.push_back(std::move(dataset));
        }
    }

    // The frame datasets need N, so they are created at the first output time.
    void create_frame_datasets(std::size_t disks) {
        if (disks == 0) throw Hdf5Error(target + ": cannot store frames of a run without disks");
        frame_disks = disks;
        const std::string where = target + ": /frames";
        const std::size_t frame_bytes = disks * 2 * sizeof(double);
        const hsize_t frames_per_chunk = std::clamp<std::size_t>(frame_chunk_target_bytes / frame_bytes, 1, 1024);
        frame_time = create_growing_dataset(frames_group.get(), "time", H5T_IEEE_F64LE, {}, frames_per_chunk,
                                            false, where);
        describe(frame_time.get(), "time", "simulation time of each frame", where + "/time");
        frame_position = create_growing_dataset(frames_group.get(), "position", H5T_IEEE_F64LE, {disks, 2},
                                                frames_per_chunk, true, where);
        describe(frame_position.get(), "length", "disk centres (x, y) at each frame time", where + "/position");
        frame_velocity = create_growing_dataset(frames_group.get(), "velocity", H5T_IEEE_F64LE, {disks, 2},
                                                frames_per_chunk, true, where);
        describe(frame_velocity.get(), "length/time", "disk velocities (vx, vy) at each frame time",
                 where + "/velocity");
    }

    void append_frame(double time, const ParticleState<double>& state) {
        if (!frame_time) create_frame_datasets(state.size());
        if (state.size() != frame_disks)
            throw Hdf5Error(target + ": frame at t = " + std::to_string(time) + " has " +
                            std::to_string(state.size()) + " disks, earlier frames " + std::to_string(frame_disks));
        const std::vector<hsize_t> row{frame_disks, 2};
        append_row(frame_time.get(), H5T_NATIVE_DOUBLE, outputs, {}, &time, target + ": /frames/time");
        append_row(frame_position.get(), H5T_NATIVE_DOUBLE, outputs, row, interleave(state.x, state.y).data(),
                   target + ": /frames/position");
        append_row(frame_velocity.get(), H5T_NATIVE_DOUBLE, outputs, row, interleave(state.vx, state.vy).data(),
                   target + ": /frames/velocity");
    }

    void append_metrics(const Metrics& metrics) {
        for (std::size_t k = 0; k < metric_column_count; ++k) {
            const MetricColumn& column = metric_columns[k];
            const std::string where = target + ": /metrics/" + column.name;
            if (column.integer()) append_row(metric_datasets[k].get(), H5T_NATIVE_INT64, outputs, {}, &(metrics.*column.count), where);
            else append_row(metric_datasets[k].get(), H5T_NATIVE_DOUBLE, outputs, {}, &(metrics.*column.real), where);
        }
    }

    void require_open(const char* operation) const {
        if (committed)
            throw std::logic_error(target + ": RunWriter::" + operation + " called after commit()");
    }

    // Closes every object, then the file (the file only really closes, and reports a failed
    // final flush, once nothing in it is open).
    void close_file() {
        for (Hdf5Handle& handle : metric_datasets) handle.reset();
        for (Hdf5Handle* handle : {&frame_time, &frame_position, &frame_velocity, &frames_group, &metrics_group})
            handle->reset();
        checked(file.reset(), target, "close the HDF5 file '" + output.temporary_path() + "'");
    }
};

RunWriter::RunWriter(const std::string& path, bool write_frames) {
    silence_hdf5_error_printing();
    impl_ = std::make_unique<Impl>(path, write_frames);
}

// Without commit(): the Impl's members close the file and remove the temporary file.
RunWriter::~RunWriter() = default;

void RunWriter::write_attributes(const std::map<std::string, std::string>& attributes) {
    impl_->require_open("write_attributes");
    for (const auto& [name, value] : attributes) {
        if (name.empty()) throw Hdf5Error(impl_->target + ": provenance attribute with an empty name");
        if (name == attributes_checksum_name) throw Hdf5Error(impl_->target + ": '" + name + "' is the writer's own");
        impl_->write_root_text(name, value);
    }
}

void RunWriter::write_particles(const ParticleState<double>& state) {
    impl_->require_open("write_particles");
    const std::string where = impl_->target + ": /particles";
    Hdf5Handle group = create_group(impl_->file.get(), "particles", impl_->target);
    write_double_array(group.get(), "radius", state.radius, where);
    write_double_array(group.get(), "mass", state.mass, where);
    write_double_array(group.get(), "inv_mass", state.inv_mass, where);
    write_int64_attribute(group.get(), "count", std::int64_t(state.size()), where);
}

void RunWriter::append(const Metrics& metrics, const ParticleState<double>& state) {
    impl_->require_open("append");
    impl_->append_metrics(metrics);
    if (impl_->write_frames) impl_->append_frame(metrics.time, state);
    ++impl_->outputs;
}

void RunWriter::write_stats(const SolverStats& stats) {
    impl_->require_open("write_stats");
    const std::string where = impl_->target + ": /stats";
    Hdf5Handle group = open_or_create_group(impl_->file.get(), "stats", impl_->target);
    write_int64_attribute(group.get(), "steps", stats.steps, where);
    write_int64_attribute(group.get(), "contacts", stats.contacts, where);
    Hdf5Handle phases = open_or_create_group(group.get(), "phase_seconds", where);
    for (const auto& [name, seconds] : stats.phase_seconds)
        write_double_attribute(phases.get(), name, seconds, where + "/phase_seconds");
    Hdf5Handle counters = open_or_create_group(group.get(), "counters", where);
    for (const auto& [name, value] : stats.counters)
        write_double_attribute(counters.get(), name, value, where + "/counters");
}

void RunWriter::commit() {
    impl_->require_open("commit");
    impl_->committed = true;  // whatever happens below, the writer takes no more data
    write_string_attribute(impl_->file.get(), attributes_checksum_name, root_attributes_checksum(impl_->root_text),
                           impl_->target);
    checked(H5Fflush(impl_->file.get(), H5F_SCOPE_GLOBAL), impl_->target, "flush the HDF5 file");
    impl_->close_file();
    impl_->output.commit();
}

std::string root_attributes_checksum(const std::map<std::string, std::string>& attributes) {
    std::string bytes;
    for (const auto& [name, value] : attributes)
        if (name != attributes_checksum_name) bytes.append(name).append(1, '\0').append(value).append(1, '\0');
    return crc32_text(bytes);
}

const std::string& RunWriter::path() const { return impl_->target; }
const std::string& RunWriter::temporary_path() const { return impl_->output.temporary_path(); }

}  // namespace collide
