// RunFile (core/io/run_reader.h): a file RunWriter wrote reads back value for value; damage made
// with the plain HDF5 C API (a shorter array, a rewritten value, a flipped byte, a NaN the run
// never recorded, format 1) is refused with the file and the dataset named.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "core/io/run_reader.h"
#include "core/io/run_writer.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

using test::ScratchDirectory;

ParticleState<double> three_disks() {  // the last one a stone (inverse mass 0)
    return test::make_state({{1, 2, 0.5, -0.25, 0.5, 2}, {4, 5, -1, 1, 0.25, 3}, {7, 8, 0, 0, 1, 4, true}});
}

Metrics metrics_at(double t, std::int64_t nonfinite = 0) {
    Metrics m;
    m.time = t;
    m.kinetic_energy = 1 + t;
    m.momentum_x = -t;
    m.nonfinite = nonfinite;
    return m;
}

// A run of three outputs with frames; `last` is the state of the last frame.
std::string write_run(const ScratchDirectory& dir, const ParticleState<double>& last, std::int64_t last_nonfinite = 0) {
    const std::string path = dir.file("run.h5");
    RunWriter writer(path, true);
    writer.write_attributes({{"backend", "step"}, {"scene_text", "# scene"}});
    const ParticleState<double> state = three_disks();
    writer.write_particles(state);
    writer.append(metrics_at(0), state);
    writer.append(metrics_at(0.5), state);
    writer.append(metrics_at(1, last_nonfinite), last);
    writer.commit();
    return path;
}

// Opens `path` for writing with the plain C API (as another program would).
struct Rewrite {
    explicit Rewrite(const std::string& path)
        : file(file_handle(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT))) {}
    void replace_1d(const std::string& name, const std::vector<double>& values) {
        H5Ldelete(file.get(), name.c_str(), H5P_DEFAULT);
        const hsize_t n = values.size(), chunk = std::max<hsize_t>(n, 1);
        Hdf5Handle space = dataspace_handle(H5Screate_simple(1, &n, nullptr));
        Hdf5Handle properties = property_list_handle(H5Pcreate(H5P_DATASET_CREATE));
        H5Pset_chunk(properties.get(), 1, &chunk);
        H5Pset_fletcher32(properties.get());  // a careful rewrite: only the shape is wrong
        Hdf5Handle d = dataset_handle(H5Dcreate2(file.get(), name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                                 properties.get(), H5P_DEFAULT));
        H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    }
    void overwrite(const std::string& name, const std::vector<double>& values) {  // checksums recomputed
        Hdf5Handle d = dataset_handle(H5Dopen2(file.get(), name.c_str(), H5P_DEFAULT));
        H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    }
    Hdf5Handle file;
};

// The message of the RunFileError that opening (and reading every frame of) `path` throws.
std::string refusal(const std::string& path) {
    try {
        RunFile(path).verify_frames();
    } catch (const RunFileError& e) {
        return e.what();
    }
    return "";
}

TEST(RunReader, ReadsBackWhatTheWriterWrote) {
    ScratchDirectory dir;
    const std::string path = write_run(dir, three_disks());
    const RunFile run(path);
    const ParticleState<double> expected = three_disks();
    EXPECT_EQ(run.disk_count(), 3u);
    EXPECT_EQ(run.output_count(), 3u);
    EXPECT_EQ(run.constants().radius, expected.radius);
    EXPECT_EQ(run.constants().inv_mass, expected.inv_mass);
    EXPECT_EQ(run.metric("kinetic_energy"), (std::vector<double>{1, 1.5, 2}));
    EXPECT_EQ(run.attribute("backend"), "step");
    ASSERT_TRUE(run.has_frames());
    ParticleState<double> frame;
    run.read_frame(2, frame);
    EXPECT_EQ(frame.x, expected.x);
    EXPECT_EQ(frame.vy, expected.vy);
}

TEST(RunReader, ReadsTheSolversStatistics) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    {
        RunWriter writer(path, false);
        writer.write_attributes({{"backend", "step"}, {"scene_text", "# scene"}});
        writer.write_particles(three_disks());
        writer.append(metrics_at(0), three_disks());
        writer.write_stats({7, 3, {{"grid", 0.25}, {"collide", 0.5}}, {{"pressure", 1.5}}});
        writer.commit();
    }
    const SolverStats stats = RunFile(path).stats();
    EXPECT_EQ(stats.steps, 7);
    EXPECT_EQ(stats.contacts, 3);
    EXPECT_EQ(stats.phase_seconds, (std::map<std::string, double>{{"collide", 0.5}, {"grid", 0.25}}));
    EXPECT_EQ(stats.counters, (std::map<std::string, double>{{"pressure", 1.5}}));
    // A run written without them (or a file whose /stats was removed) says so by name.
    const std::string bare = write_run(dir, three_disks());
    try {
        RunFile(bare).stats();
        ADD_FAILURE() << "no /stats, no refusal";
    } catch (const RunFileError& e) {
        EXPECT_NE(std::string(e.what()).find("/stats: missing"), std::string::npos) << e.what();
    }
}

TEST(RunReader, ArraysOfUnequalLengthAreRefused) {
    ScratchDirectory dir;
    const std::string path = write_run(dir, three_disks());
    Rewrite(path).replace_1d("/particles/mass", {2, 3});
    const std::string message = refusal(path);
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("/particles/mass: shape (2,), expected (3,)"), std::string::npos) << message;
}

TEST(RunReader, ImpossibleValuesAreRefused) {
    ScratchDirectory dir;
    std::string path = write_run(dir, three_disks());
    Rewrite(path).overwrite("/particles/radius", {0.5, -8, 1});
    EXPECT_NE(refusal(path).find("/particles/radius: disk 1: radius -8"), std::string::npos) << refusal(path);
    path = write_run(dir, three_disks());
    Rewrite(path).overwrite("/metrics/kinetic_energy", {1, -4, 2});
    EXPECT_NE(refusal(path).find("/metrics/kinetic_energy: row 1"), std::string::npos) << refusal(path);
}

TEST(RunReader, AFlippedByteFailsItsChecksum) {
    ScratchDirectory dir;
    const std::string path = write_run(dir, three_disks());
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    // The radii 0.5, 0.25, 1 as stored (little-endian doubles): flip one bit of 0.25.
    const double radii[3] = {0.5, 0.25, 1};
    const auto at = bytes.find(std::string(reinterpret_cast<const char*>(radii), sizeof radii));
    ASSERT_NE(at, std::string::npos);
    bytes[at + 8 + 7] ^= 0x01;
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    const std::string message = refusal(path);
    EXPECT_NE(message.find("/particles/radius: cannot read: the file is damaged"), std::string::npos) << message;
}

TEST(RunReader, NonFiniteFramesMustBeTheRunsOwnRecord) {
    ScratchDirectory dir;
    ParticleState<double> last = three_disks();
    last.x[1] = std::numeric_limits<double>::quiet_NaN();
    // Recorded by the run (/metrics/nonfinite = 1): read as it is, for the caller to judge.
    EXPECT_EQ(refusal(write_run(dir, last, 1)), "");
    // Not recorded: damage.
    const std::string message = refusal(write_run(dir, last, 0));
    EXPECT_NE(message.find("frame 2 (t = 1.000000) holds 1 disks with a NaN or Inf"), std::string::npos) << message;
}

TEST(RunReader, FormatOneIsWrittenByAnOlderCollide) {
    ScratchDirectory dir;
    const std::string path = write_run(dir, three_disks());
    {
        Rewrite rewrite(path);
        H5Adelete(rewrite.file.get(), "format_version");
    }
    EXPECT_NE(refusal(path).find("written by an older collide"), std::string::npos) << refusal(path);
}

}  // namespace
}  // namespace collide
