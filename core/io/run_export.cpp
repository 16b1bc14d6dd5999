#include "core/io/run_export.h"

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "core/io/hdf5_handle.h"
#include "core/io/output_file.h"
#include "core/io/run_reader.h"
#include "core/numerics/number_text.h"
#include "core/scene/scene_loader.h"

namespace collide {
namespace {

// What the exports need of a run file, read through the one checked reader (run_reader.h):
// every frame is read, and so every checksum verified, before an export is written, and a
// damaged file is named, never exported.
struct RunForExport {
    explicit RunForExport(const std::string& path) : file(path) {
        if (!file.has_frames())
            throw std::runtime_error(path + ": the run has no frames to export: it was written without --frames; "
                                            "rerun it with `collide run ... --frames`");
        file.verify_frames();
        times = file.frame_times();
        radius = file.constants().radius, mass = file.constants().mass, inv_mass = file.constants().inv_mass;
        scene = parse_scene(file.attribute("scene_text"), file.attribute("scene_path"));
    }

    // Positions (what = "position") or velocities ("velocity") of frame k: x0, y0, x1, y1, ...
    std::vector<double> frame(const char* what, std::size_t k) const {
        ParticleState<double> s;
        file.read_frame(k, s);
        const bool position = std::string(what) == "position";
        std::vector<double> xy(2 * s.size());
        for (std::size_t i = 0; i < s.size(); ++i) {
            xy[2 * i] = position ? s.x[i] : s.vx[i];
            xy[2 * i + 1] = position ? s.y[i] : s.vy[i];
        }
        return xy;
    }

    RunFile file;
    std::vector<double> times, radius, mass, inv_mass;
    Scene scene;
};

// The shortest text that reads back as the same double (0.1, not 0.10000000000000001).
std::string exact(double v) { return round_trip_text(v); }

std::string xml_escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

// ---- XDMF: plain per-frame datasets in an HDF5 file beside the XDMF ----------------------
//
// Every DataItem names a whole dataset (no HyperSlab, no Function): ParaView 5.11's Xdmf3
// readers crashed on the HyperSlab items that pointed into the run file, and meshio's
// TimeSeriesReader refused them; a plain HDF DataItem is read alike by every XDMF reader.

// An N x `columns` array of doubles (row-major) as dataset `name` under `parent`.
template <typename T>
void write_dataset(hid_t parent, const std::string& name, const std::vector<T>& values, hsize_t rows, hsize_t columns,
                   hid_t file_type, hid_t memory_type, const std::string& where) {
    const hsize_t dims[2] = {rows, columns};
    Hdf5Handle space = dataspace_handle(checked(H5Screate_simple(columns ? 2 : 1, dims, nullptr), where, "make a dataspace"));
    Hdf5Handle dataset = dataset_handle(checked(
        H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), where,
        "create dataset " + name));
    checked(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), where,
            "write dataset " + name);
}

Hdf5Handle make_group(hid_t parent, const std::string& name, const std::string& where) {
    return group_handle(
        checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), where, "create group " + name));
}

// (x, y) pairs as (x, y, 0) rows: the XYZ geometry and 3-vectors every reader takes.
std::vector<double> with_zero_z(const std::vector<double>& xy) {
    std::vector<double> xyz(xy.size() / 2 * 3, 0.0);
    for (std::size_t i = 0; i < xy.size() / 2; ++i) xyz[3 * i] = xy[2 * i], xyz[3 * i + 1] = xy[2 * i + 1];
    return xyz;
}

// The frames file: /particles/{radius, mass, vertex}, /frames/K/{position, velocity}.
void write_frames_file(const RunForExport& run, const std::string& path) {
    AtomicOutputFile output(path);  // the guard and the atomic rename of every output
    {
        silence_hdf5_error_printing();
        Hdf5Handle file = file_handle(checked(
            H5Fcreate(output.temporary_path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), path, "create the file"));
        const hsize_t n = run.radius.size();
        Hdf5Handle particles = make_group(file.get(), "particles", path);
        write_dataset(particles.get(), "radius", run.radius, n, 0, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, path);
        write_dataset(particles.get(), "mass", run.mass, n, 0, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, path);
        std::vector<std::int64_t> vertex(n);
        for (std::size_t i = 0; i < n; ++i) vertex[i] = std::int64_t(i);
        write_dataset(particles.get(), "vertex", vertex, n, 1, H5T_STD_I64LE, H5T_NATIVE_INT64, path);
        Hdf5Handle frames = make_group(file.get(), "frames", path);
        for (std::size_t k = 0; k < run.times.size(); ++k) {
            Hdf5Handle frame = make_group(frames.get(), std::to_string(k), path);
            write_dataset(frame.get(), "position", with_zero_z(run.frame("position", k)), n, 3, H5T_IEEE_F64LE,
                          H5T_NATIVE_DOUBLE, path);
            write_dataset(frame.get(), "velocity", with_zero_z(run.frame("velocity", k)), n, 3, H5T_IEEE_F64LE,
                          H5T_NATIVE_DOUBLE, path);
        }
        checked(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), path, "write the file");
    }
    output.commit();
}

std::string data_item(const std::string& dims, const char* type, const std::string& source) {
    return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type + "\" Precision=\"8\" Format=\"HDF\">" +
           source + "</DataItem>";
}

std::string attribute(const char* name, const char* kind, const std::string& item) {
    return "        <Attribute Name=\"" + std::string(name) + "\" AttributeType=\"" + kind + "\" Center=\"Node\">" +
           item + "</Attribute>\n";
}

// One Uniform grid per output time: its own points, and the same points as a "position"
// attribute for readers that keep the first grid's points (meshio's TimeSeriesReader).
std::string xdmf_frame(const std::string& h5, const RunForExport& run, std::size_t k) {
    const std::string N = std::to_string(run.radius.size()), frame = h5 + ":/frames/" + std::to_string(k);
    const std::string points = data_item(N + " 3", "Float", frame + "/position");
    return "      <Grid Name=\"frame " + std::to_string(k) + "\" GridType=\"Uniform\">\n"
           "        <Time Value=\"" + exact(run.times[k]) + "\"/>\n"
           "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + N + "\" NodesPerElement=\"1\">" +
           data_item(N + " 1", "Int", h5 + ":/particles/vertex") + "</Topology>\n"
           "        <Geometry GeometryType=\"XYZ\">" + points + "</Geometry>\n" +
           attribute("radius", "Scalar", data_item(N, "Float", h5 + ":/particles/radius")) +
           attribute("mass", "Scalar", data_item(N, "Float", h5 + ":/particles/mass")) +
           attribute("velocity", "Vector", data_item(N + " 3", "Float", frame + "/velocity")) +
           attribute("position", "Vector", points) + "      </Grid>\n";
}

std::string xdmf_text(const RunForExport& run, const std::string& frames_path) {
    const std::string h5 = xml_escaped(std::filesystem::path(frames_path).filename().string());
    std::string text = "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                       "<!-- Written by `collide export`: the data is in " + h5 + ", which must stay beside it -->\n"
                       "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n  <Domain>\n"
                       "    <Grid Name=\"" + xml_escaped(run.scene.name) + "\" GridType=\"Collection\" "
                       "CollectionType=\"Temporal\">\n";
    for (std::size_t k = 0; k < run.times.size(); ++k) text += xdmf_frame(h5, run, k);
    return text + "    </Grid>\n  </Domain>\n</Xdmf>\n";
}

}  // namespace

ExportFormat export_format(const std::string& name, const std::string& out) {
    std::string f = name;
    if (f.empty()) {
        f = std::filesystem::path(out).extension().string();
        if (!f.empty()) f = f.substr(1);
        if (f == "xmf") f = "xdmf";
    }
    if (f == "xdmf") return ExportFormat::xdmf;
    if (f == "xyz") return ExportFormat::xyz;
    if (f == "gsd") return ExportFormat::gsd;
    throw std::runtime_error(name.empty() ? "--out " + out + ": cannot tell the format from the extension; "
                                                             "expected .xdmf, .gsd or .xyz, or name it with --format"
                                          : "--format " + name + ": expected xdmf, gsd or xyz");
}

const char* to_string(ExportFormat f) {
    return f == ExportFormat::xdmf ? "xdmf" : f == ExportFormat::xyz ? "xyz" : "gsd";
}

void require_frames(const std::string& run_path) { RunForExport run(run_path); }

std::string xdmf_frames_path(const std::string& xdmf_path) {
    namespace fs = std::filesystem;
    fs::path p(xdmf_path);
    // Beside the file a link points to (the XDMF written there names its data by name alone).
    std::error_code error;
    if (fs::is_symlink(p, error))
        if (fs::path target = fs::canonical(p, error); !error) p = target;
    return (p.parent_path() / (p.stem().string() + ".frames.h5")).string();
}

void write_xdmf(const std::string& run_path, const std::string& xdmf_path) {
    const std::string frames = xdmf_frames_path(xdmf_path);
    // "FILE:/dataset" is how XDMF names HDF5 data, so a ':' in the file name cannot be told apart.
    if (std::filesystem::path(frames).filename().string().find(':') != std::string::npos)
        throw std::runtime_error(xdmf_path + ": an XDMF file's name cannot hold ':' (its data file " + frames +
                                 " would be misread)");
    check_output_path(frames);  // both places, before either file is written
    check_output_path(xdmf_path);
    const RunForExport run(run_path);
    write_frames_file(run, frames);  // first: the XDMF never names a file that is not there
    write_file_atomically(xdmf_path, xdmf_text(run, frames));
}

std::string xyz_text(const std::string& run_path) {
    const RunForExport run(run_path);
    const World& w = run.scene.world;
    const std::string periodic = run.scene.periodic() ? "T T F" : "F F F";
    // Species X: ASE reads a species as a chemical element, and X is its placeholder for "none";
    // the stones (kinematic disks) are marked by the stone column instead. The cell is the box (its third vector zero: the disks lie in the plane z = 0), placed at
    // the box's corner by Origin (OVITO reads it; ASE keeps it in info).
    const std::string header = "Lattice=\"" + exact(w.width()) + " 0 0 0 " + exact(w.height()) + " 0 0 0 0\" Origin=\"" +
                               exact(w.xmin) + " " + exact(w.ymin) + " 0\" Properties=species:S:1:pos:R:3:radius:R:1:"
                               "mass:R:1:vel:R:3:stone:I:1 pbc=\"" + periodic + "\"";
    std::string text;
    for (std::size_t k = 0; k < run.times.size(); ++k) {
        const std::vector<double> x = run.frame("position", k), v = run.frame("velocity", k);
        text += std::to_string(run.radius.size()) + "\n" + header + " Time=" + exact(run.times[k]) + "\n";
        for (std::size_t i = 0; i < run.radius.size(); ++i)
            text += "X " + exact(x[2 * i]) + " " + exact(x[2 * i + 1]) + " 0 " + exact(run.radius[i]) + " " +
                    exact(run.mass[i]) + " " + exact(v[2 * i]) + " " + exact(v[2 * i + 1]) + " 0 " +
                    (run.inv_mass[i] == 0 ? "1" : "0") + "\n";
    }
    return text;
}

}  // namespace collide
