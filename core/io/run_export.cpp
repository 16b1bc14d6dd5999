#include "core/io/run_export.h"

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "core/numerics/number_text.h"
#include "core/io/run_reader.h"
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

// Frame k of a T x N x 2 dataset, or one of its two columns (component 0 or 1), as an XDMF
// HyperSlab: rows of the start, stride and count of the selection, then the whole dataset.
std::string hyperslab(const std::string& h5, const char* dataset, std::size_t k, std::size_t t, std::size_t n,
                      int component, const std::string& indent) {
    const std::string width = component < 0 ? "2" : "1", first = component < 0 ? "0" : std::to_string(component);
    const std::string N = std::to_string(n);
    return indent + "<DataItem ItemType=\"HyperSlab\" Dimensions=\"1 " + N + " " + width + "\" Type=\"HyperSlab\">\n" +
           indent + "  <DataItem Dimensions=\"3 3\" NumberType=\"Int\" Format=\"XML\">" + std::to_string(k) + " 0 " +
           first + "  1 1 1  1 " + N + " " + width + "</DataItem>\n" + indent + "  <DataItem Dimensions=\"" +
           std::to_string(t) + " " + N + " 2\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" + h5 + ":/frames/" +
           dataset + "</DataItem>\n" + indent + "</DataItem>\n";
}

std::string constant_attribute(const std::string& h5, const char* name, std::size_t n) {
    return "        <Attribute Name=\"" + std::string(name) + "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
           "          <DataItem Dimensions=\"" + std::to_string(n) + "\" NumberType=\"Float\" Precision=\"8\" "
           "Format=\"HDF\">" + h5 + ":/particles/" + name + "</DataItem>\n        </Attribute>\n";
}

// A velocity component of frame k as a scalar attribute. Not one Vector attribute: ParaView's
// XDMF readers take a Vector as three components, and joining a zero z needs an XDMF Function,
// whose JOIN interlaces in XDMF 2 but concatenates in XDMF 3; two scalars read the same in every
// reader (docs/exporting.md shows the Calculator that makes the vector in ParaView).
std::string velocity_attribute(const std::string& h5, const RunForExport& run, std::size_t k, int component) {
    return "        <Attribute Name=\"velocity_" + std::string(component == 0 ? "x" : "y") +
           "\" AttributeType=\"Scalar\" Center=\"Node\">\n" +
           hyperslab(h5, "velocity", k, run.times.size(), run.radius.size(), component, "          ") +
           "        </Attribute>\n";
}

// One Uniform grid per output time.
std::string xdmf_frame(const std::string& h5, const RunForExport& run, std::size_t k) {
    const std::size_t t = run.times.size(), n = run.radius.size();
    const std::string N = std::to_string(n);
    return "      <Grid Name=\"frame " + std::to_string(k) + "\" GridType=\"Uniform\">\n"
           "        <Time Value=\"" + exact(run.times[k]) + "\"/>\n"
           "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + N + "\" NodesPerElement=\"1\"/>\n"
           "        <Geometry GeometryType=\"XY\">\n" + hyperslab(h5, "position", k, t, n, -1, "          ") +
           "        </Geometry>\n" + constant_attribute(h5, "radius", n) + constant_attribute(h5, "mass", n) +
           velocity_attribute(h5, run, k, 0) + velocity_attribute(h5, run, k, 1) + "      </Grid>\n";
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

std::string xdmf_text(const std::string& run_path, const std::string& xdmf_path) {
    const RunForExport run(run_path);
    namespace fs = std::filesystem;
    const fs::path folder = fs::absolute(xdmf_path).parent_path();
    const std::string h5 = xml_escaped(fs::relative(fs::absolute(run_path), folder).string());
    // "FILE:/dataset" is how XDMF names HDF5 data, so a ':' in the file name cannot be told apart.
    if (h5.find(':') != std::string::npos)
        throw std::runtime_error(run_path + ": an XDMF file cannot name a run file whose path holds ':'");
    std::string text = "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                       "<!-- Written by `collide export`: points into " + h5 + ", which must stay beside it -->\n"
                       "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n  <Domain>\n"
                       "    <Grid Name=\"" + xml_escaped(run.scene.name) + "\" GridType=\"Collection\" "
                       "CollectionType=\"Temporal\">\n";
    for (std::size_t k = 0; k < run.times.size(); ++k) text += xdmf_frame(h5, run, k);
    return text + "    </Grid>\n  </Domain>\n</Xdmf>\n";
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
