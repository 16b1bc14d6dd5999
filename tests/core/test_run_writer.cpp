// RunWriter: what it writes is read back with the plain HDF5 C API and compared value by
// value; and its promise of atomic output (a failed or abandoned run leaves no file and never
// damages an existing one) is checked on the file system.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/run_writer.h"
#include "tests/support/hdf5_reader.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

using test::Hdf5File;
using test::ScratchDirectory;

// Distinct values in every field, so a field written into the wrong dataset is caught.
Metrics metrics_at(double t) {
    Metrics m;
    m.time = t;
    m.momentum_x = 1.5 + t;
    m.momentum_y = -2.25 + t;
    m.kinetic_energy = 10.125 + t;
    m.potential_energy = -0.5 * t;
    m.overlapping_pairs = std::int64_t(3 + 10 * t);
    m.max_overlap = 1e-3 * (1 + t);
    m.mean_overlap = 1e-4 * (1 + t);
    m.max_wall_penetration = 1e-6 * (1 + t);
    m.nonfinite = std::int64_t(7 * t);
    return m;
}

ParticleState<double> three_disks() {
    return test::make_state({{1, 2, 0.5, -0.25, 0.5, 2}, {4, 5, -1, 1, 0.25, 3}, {7, 8, 0, 0, 1, 4, true}});
}

// The state at output k: every coordinate shifted, so frames differ from each other.
ParticleState<double> moved(ParticleState<double> s, double k) {
    for (std::size_t i = 0; i < s.size(); ++i) {
        s.x[i] += k;
        s.y[i] -= k;
        s.vx[i] *= 1 + k;
        s.vy[i] += 2 * k;
    }
    return s;
}

TEST(RunWriter, MetricsAreOneGrowingSeriesPerFieldWithEveryValue) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    const std::vector<double> times{0, 0.5, 1.0, 1.5};
    {
        RunWriter writer(path, false);
        writer.write_particles(three_disks());
        for (double t : times) writer.append(metrics_at(t), three_disks());
        writer.commit();
    }
    Hdf5File file(path);
    ASSERT_EQ(file.shape("/metrics/time"), std::vector<hsize_t>{times.size()});
    EXPECT_TRUE(file.is_chunked("/metrics/kinetic_energy"));  // extendible needs chunked storage
    const auto kinetic = file.doubles("/metrics/kinetic_energy");
    const auto px = file.doubles("/metrics/momentum_x");
    const auto py = file.doubles("/metrics/momentum_y");
    const auto potential = file.doubles("/metrics/potential_energy");
    const auto max_overlap = file.doubles("/metrics/max_overlap");
    const auto mean_overlap = file.doubles("/metrics/mean_overlap");
    const auto wall = file.doubles("/metrics/max_wall_penetration");
    const auto pairs = file.int64s("/metrics/overlapping_pairs");
    const auto nonfinite = file.int64s("/metrics/nonfinite");
    const auto time = file.doubles("/metrics/time");
    for (std::size_t k = 0; k < times.size(); ++k) {
        const Metrics m = metrics_at(times[k]);
        EXPECT_EQ(time[k], m.time);
        EXPECT_EQ(px[k], m.momentum_x);
        EXPECT_EQ(py[k], m.momentum_y);
        EXPECT_EQ(kinetic[k], m.kinetic_energy);
        EXPECT_EQ(potential[k], m.potential_energy);
        EXPECT_EQ(max_overlap[k], m.max_overlap);
        EXPECT_EQ(mean_overlap[k], m.mean_overlap);
        EXPECT_EQ(wall[k], m.max_wall_penetration);
        EXPECT_EQ(pairs[k], m.overlapping_pairs);
        EXPECT_EQ(nonfinite[k], m.nonfinite);
    }
    EXPECT_EQ(file.string_attribute("/metrics/momentum_x", "units"), "mass*length/time");
    EXPECT_TRUE(file.has_attribute("/metrics/kinetic_energy", "description"));
    EXPECT_FALSE(file.has("/frames"));  // frames only when asked
}

TEST(RunWriter, MetricsGrowPastManyChunks) {
    ScratchDirectory dir;
    const std::string path = dir.file("long.h5");
    const std::size_t outputs = 1000;  // several chunks of rows
    {
        RunWriter writer(path, false);
        for (std::size_t k = 0; k < outputs; ++k) writer.append(metrics_at(double(k)), {});
        writer.commit();
    }
    const auto time = Hdf5File(path).doubles("/metrics/time");
    ASSERT_EQ(time.size(), outputs);
    for (std::size_t k = 0; k < outputs; ++k) ASSERT_EQ(time[k], double(k)) << "row " << k;
}

TEST(RunWriter, ParticleConstants) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    const auto state = three_disks();
    {
        RunWriter writer(path, false);
        writer.write_particles(state);
        writer.append(metrics_at(0), state);
        writer.commit();
    }
    Hdf5File file(path);
    EXPECT_EQ(file.doubles("/particles/radius"), state.radius);
    EXPECT_EQ(file.doubles("/particles/mass"), state.mass);
    EXPECT_EQ(file.doubles("/particles/inv_mass"), (std::vector<double>{0.5, 1.0 / 3, 0}));
    EXPECT_EQ(file.int64_attribute("/particles", "count"), 3);
}

TEST(RunWriter, ProvenanceAttributesIncludingALongSceneText) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    std::string scene_text;
    for (int line = 0; line < 5000; ++line) scene_text += "# line " + std::to_string(line) + " of a long scene\n";
    ASSERT_GT(scene_text.size(), 64u * 1024);  // beyond HDF5's compact attribute storage
    const std::map<std::string, std::string> provenance{
        {"commit", "0123abc"}, {"dirty", "false"}, {"seed", "42"}, {"scene_text", scene_text},
        {"command_line", "collide run x.toml --out run.h5"}, {"empty_value", ""}};
    {
        RunWriter writer(path, false);
        writer.write_attributes(provenance);
        writer.write_attributes({{"seed", "43"}});  // a key written again keeps the last value
        writer.append(metrics_at(0), {});
        writer.commit();
    }
    Hdf5File file(path);
    for (const auto& [key, value] : provenance) {
        if (key == "seed") continue;
        EXPECT_EQ(file.string_attribute("/", key), value) << key;
    }
    EXPECT_EQ(file.string_attribute("/", "seed"), "43");
    EXPECT_EQ(file.string_attribute("/", "format"), "collide-run");
    EXPECT_EQ(file.string_attribute("/", "format_version"), "2");
}

TEST(RunWriter, SolverStats) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    SolverStats stats;
    stats.steps = 123456789012;
    stats.contacts = 77;
    stats.phase_seconds = {{"grid", 0.25}, {"collide", 1.5}};
    stats.counters = {{"translation_cap_hits", 3}};
    {
        RunWriter writer(path, false);
        writer.append(metrics_at(0), {});
        writer.write_stats(stats);
        writer.commit();
    }
    Hdf5File file(path);
    EXPECT_EQ(file.int64_attribute("/stats", "steps"), stats.steps);
    EXPECT_EQ(file.int64_attribute("/stats", "contacts"), stats.contacts);
    EXPECT_EQ(file.double_attribute("/stats/phase_seconds", "grid"), 0.25);
    EXPECT_EQ(file.double_attribute("/stats/phase_seconds", "collide"), 1.5);
    EXPECT_EQ(file.double_attribute("/stats/counters", "translation_cap_hits"), 3);
}

TEST(RunWriter, FramesAreTimeByDisksByTwoChunkedAndCompressed) {
    ScratchDirectory dir;
    const std::string path = dir.file("frames.h5");
    const auto initial = three_disks();
    const std::vector<double> times{0, 0.1, 0.2, 0.3, 0.4};
    {
        RunWriter writer(path, true);
        writer.write_particles(initial);
        for (std::size_t k = 0; k < times.size(); ++k) writer.append(metrics_at(times[k]), moved(initial, double(k)));
        writer.commit();
    }
    Hdf5File file(path);
    const std::size_t n = initial.size(), frames = times.size();
    EXPECT_EQ(file.shape("/frames/time"), std::vector<hsize_t>{frames});
    EXPECT_EQ(file.shape("/frames/position"), (std::vector<hsize_t>{frames, n, 2}));
    EXPECT_EQ(file.shape("/frames/velocity"), (std::vector<hsize_t>{frames, n, 2}));
    EXPECT_EQ(file.doubles("/frames/time"), times);
    const auto position = file.doubles("/frames/position");
    const auto velocity = file.doubles("/frames/velocity");
    for (std::size_t k = 0; k < frames; ++k) {
        const auto s = moved(initial, double(k));
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t at = (k * n + i) * 2;  // row-major [frame][disk][component]
            EXPECT_EQ(position[at], s.x[i]);
            EXPECT_EQ(position[at + 1], s.y[i]);
            EXPECT_EQ(velocity[at], s.vx[i]);
            EXPECT_EQ(velocity[at + 1], s.vy[i]);
        }
    }
    for (const char* dataset : {"/frames/position", "/frames/velocity"}) {
        EXPECT_TRUE(file.is_chunked(dataset)) << dataset;
        const auto filters = file.filters(dataset);
        EXPECT_NE(std::find(filters.begin(), filters.end(), H5Z_FILTER_DEFLATE), filters.end()) << dataset;
    }
}

TEST(RunWriter, FramesRejectAChangingDiskCount) {
    ScratchDirectory dir;
    RunWriter writer(dir.file("frames.h5"), true);
    writer.append(metrics_at(0), three_disks());
    auto fewer = three_disks();
    fewer.resize(2);
    EXPECT_THROW(writer.append(metrics_at(1), fewer), Hdf5Error);
}

TEST(RunWriter, NothingAppearsUnderTheTargetNameBeforeCommit) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    RunWriter writer(path, false);
    writer.append(metrics_at(0), {});
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_TRUE(std::filesystem::exists(writer.temporary_path()));
    EXPECT_EQ(std::filesystem::path(writer.temporary_path()).parent_path(), dir.path());  // same file system
    writer.commit();
    EXPECT_TRUE(std::filesystem::exists(path));
    EXPECT_EQ(dir.entry_count(), 1u) << "the temporary file is gone after the rename";
}

TEST(RunWriter, AbandonedWriterLeavesNoFile) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    {
        RunWriter writer(path, true);
        writer.write_particles(three_disks());
        writer.append(metrics_at(0), three_disks());
    }  // destroyed without commit(), as when the run throws
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_EQ(dir.entry_count(), 0u) << "the temporary file must be removed";
}

TEST(RunWriter, AbandonedWriterLeavesAnExistingTargetUntouched) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    const std::string earlier = "the results of an earlier run\n";
    test::write_text_file(path, earlier);
    {
        RunWriter writer(path, false);
        writer.append(metrics_at(0), {});
        EXPECT_EQ(test::read_text_file(path), earlier);
    }
    EXPECT_EQ(test::read_text_file(path), earlier);
    EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(RunWriter, CommitReplacesAnExistingTarget) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    test::write_text_file(path, "old");
    {
        RunWriter writer(path, false);
        writer.append(metrics_at(2.5), {});
        writer.commit();
    }
    EXPECT_EQ(Hdf5File(path).doubles("/metrics/time"), std::vector<double>{2.5});
}

TEST(RunWriter, MissingDirectoryFailsUpFrontNamingThePath) {
    ScratchDirectory dir;
    const std::string path = dir.file("no/such/dir/run.h5");
    try {
        RunWriter writer(path, false);
        FAIL() << "expected an error for " << path;
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
    }
    EXPECT_EQ(dir.entry_count(), 0u);
}

TEST(RunWriter, DirectoryInTheWayFailsUpFrontNamingThePath) {
    ScratchDirectory dir;
    const std::string path = dir.file("run.h5");
    std::filesystem::create_directory(path);
    try {
        RunWriter writer(path, false);
        FAIL() << "expected an error for " << path;
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(RunWriter, ReadOnlyDirectoryFailsUpFrontWithTheSystemsReason) {
    if (::geteuid() == 0) GTEST_SKIP() << "root may write into read-only directories";
    ScratchDirectory dir;
    const std::filesystem::path locked = dir.path() / "locked";
    std::filesystem::create_directory(locked);
    ::chmod(locked.c_str(), 0555);
    const std::string path = (locked / "run.h5").string();
    try {
        RunWriter writer(path, false);
        ADD_FAILURE() << "expected an error for " << path;
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("Permission denied"), std::string::npos) << e.what();
    }
    ::chmod(locked.c_str(), 0755);
}

TEST(RunWriter, NoWritesAfterCommit) {
    ScratchDirectory dir;
    RunWriter writer(dir.file("run.h5"), false);
    writer.commit();
    EXPECT_THROW(writer.append(metrics_at(0), {}), std::logic_error);
    EXPECT_THROW(writer.commit(), std::logic_error);
}

}  // namespace
}  // namespace collide
