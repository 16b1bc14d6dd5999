// `collide run` as a user runs it: the built program is started with a command line, and its
// exit code, its messages on stderr and the files it leaves behind are checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/hdf5_reader.h"
#include "tests/support/collide_program.h"
#include "tests/support/program_runner.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

using test::Hdf5File;
using test::contains;
using test::run_collide;
using test::run_program;
using test::ScratchDirectory;

const std::string head_on_scene = test::scene_file("head_on_equal.toml");

TEST(RunCommand, MissingSceneFileFailsNamingTheFile) {
    ScratchDirectory dir;
    const std::string missing = dir.file("no_such_scene.toml");
    const auto result = run_collide({"run", missing, "--backend", "step", "--out", dir.file("x.h5")}, dir);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_TRUE(contains(result.err, missing)) << result.err;
    EXPECT_EQ(dir.entry_count(), 0u) << "nothing is written";
}

TEST(RunCommand, UnknownBackendFailsNamingItAndTheChoices) {
    ScratchDirectory dir;
    const auto result = run_collide({"run", head_on_scene, "--backend", "no_such_backend", "--out", dir.file("x.h5")}, dir);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_TRUE(contains(result.err, "no_such_backend")) << result.err;
    EXPECT_TRUE(contains(result.err, "step")) << "the message lists the backends that exist: " << result.err;
    EXPECT_EQ(dir.entry_count(), 0u) << "nothing is written";
}

TEST(RunCommand, MalformedSceneFailsNamingTheFile) {
    ScratchDirectory dir;
    const std::string scene = dir.file("broken.toml");
    test::write_text_file(scene, "[world\nxmax = = 1\n");
    const auto result = run_collide({"run", scene, "--backend", "step"}, dir);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_TRUE(contains(result.err, scene)) << result.err;
}

TEST(RunCommand, OutputIntoAMissingDirectoryFailsAndWritesNothing) {
    ScratchDirectory dir;
    const std::string out = dir.file("missing_dir/run.h5");
    const auto result = run_collide({"run", head_on_scene, "--backend", "step", "--out", out}, dir);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_TRUE(contains(result.err, out)) << result.err;
    EXPECT_TRUE(contains(result.err, "does not exist")) << result.err;
    EXPECT_EQ(dir.entry_count(), 0u) << "nothing is written";
}

TEST(RunCommand, AnExistingOutputSurvivesAFailingRunUnchanged) {
    ScratchDirectory dir;
    const std::string out = dir.file("run.h5");
    const std::string earlier = "an earlier run's results\n";
    test::write_text_file(out, earlier);
    const std::string broken = dir.file("broken.toml");
    test::write_text_file(broken, "[world]\nxmax = \"wide\"\n");
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"run", broken, "--backend", "step", "--out", out},
          std::vector<std::string>{"run", head_on_scene, "--backend", "no_such_backend", "--out", out}}) {
        const auto result = run_collide(args, dir);
        EXPECT_NE(result.exit_code, 0) << args[1];
        EXPECT_EQ(test::read_text_file(out), earlier) << args[1];
    }
    EXPECT_EQ(dir.entry_count(), 2u) << "no temporary file is left behind";
}

// The acceptance run: two equal disks meet head-on. An elastic collision of equal masses
// exchanges their velocities (momentum and energy conservation, docs/stepping-rules.md), and
// the file holds the metrics, the frames and the provenance.
TEST(RunCommand, HeadOnEqualMassesEndToEnd) {
    ScratchDirectory dir;
    const std::string out = dir.file("x.h5");
    const auto result = run_collide({"run", head_on_scene, "--backend", "step", "--out", out, "--frames"}, dir);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(contains(result.out, "energy")) << "a summary on stdout: " << result.out;

    Hdf5File file(out);
    // Provenance: every number traceable to a commit, a build, a scene and a seed.
    for (const char* key : {"git_commit", "git_dirty", "compiler", "compiler_flags", "hdf5_version", "seed",
                            "command_line", "backend", "scene_text", "scene_path", "run_date_utc"})
        EXPECT_TRUE(file.has_attribute("/", key)) << "missing provenance attribute " << key;
    EXPECT_EQ(file.string_attribute("/", "backend"), "step");
    EXPECT_EQ(file.string_attribute("/", "scene_text"), test::read_text_file(head_on_scene));
    EXPECT_TRUE(contains(file.string_attribute("/", "command_line"), out));

    // Conservation, first output against last, relative to the natural scales.
    const auto mass = file.doubles("/particles/mass");
    ASSERT_EQ(mass.size(), 2u);
    const auto time = file.doubles("/metrics/time");
    ASSERT_GE(time.size(), 2u);
    const auto kinetic = file.doubles("/metrics/kinetic_energy");
    const auto px = file.doubles("/metrics/momentum_x"), py = file.doubles("/metrics/momentum_y");
    const double e0 = kinetic.front(), e1 = kinetic.back();
    ASSERT_GT(e0, 0);
    EXPECT_LE(std::fabs(e1 - e0), 1e-12 * e0) << "kinetic energy " << e0 << " -> " << e1;
    // Total momentum may be zero; measure its change against sqrt(2 M E), the momentum the
    // system would have if all its kinetic energy moved all its mass one way.
    const double momentum_scale = std::sqrt(2 * (mass[0] + mass[1]) * e0);
    EXPECT_LE(std::hypot(px.back() - px.front(), py.back() - py.front()), 1e-12 * momentum_scale);

    // The disks collided (they were approaching) and exchanged velocities.
    const auto velocity = file.doubles("/frames/velocity");
    const std::size_t frames = file.shape("/frames/velocity")[0];
    ASSERT_EQ(velocity.size(), frames * 2 * 2);
    const double* first = velocity.data();
    const double* last = velocity.data() + (frames - 1) * 4;  // [frame][disk][component]
    const double speed_scale = std::sqrt(2 * e0 / std::min(mass[0], mass[1]));
    ASSERT_GT(std::hypot(first[0] - first[2], first[1] - first[3]), 0) << "the disks must move relative to each other";
    for (int component = 0; component < 2; ++component) {
        EXPECT_NEAR(last[component], first[2 + component], 1e-12 * speed_scale) << "disk 0, component " << component;
        EXPECT_NEAR(last[2 + component], first[component], 1e-12 * speed_scale) << "disk 1, component " << component;
    }
}

TEST(RunCommand, H5dumpShowsMetricsAndProvenance) {
    if (std::string(H5DUMP_EXECUTABLE).empty()) GTEST_SKIP() << "h5dump (Debian package hdf5-tools) not found";
    ScratchDirectory dir;
    const std::string out = dir.file("x.h5");
    ASSERT_EQ(run_collide({"run", head_on_scene, "--backend", "step", "--out", out}, dir).exit_code, 0);
    const auto dump = run_program(H5DUMP_EXECUTABLE, {"-H", out}, dir);
    ASSERT_EQ(dump.exit_code, 0) << dump.err;
    for (const char* name : {"GROUP \"metrics\"", "DATASET \"kinetic_energy\"", "DATASET \"momentum_x\"",
                             "ATTRIBUTE \"git_commit\"", "ATTRIBUTE \"scene_text\"", "ATTRIBUTE \"seed\""})
        EXPECT_TRUE(contains(dump.out, name)) << "h5dump -H output lacks " << name;
}

// The pressure of a periodic gas of equal elastic disks is in /stats and in the summary; a
// scene with walls has none (core/thermo/pressure_record.h).
TEST(RunCommand, EventRunOfAPeriodicGasRecordsItsPressure) {
    ScratchDirectory dir;
    const std::string out = dir.file("gas.h5");
    const auto result = run_collide({"run", test::scene_file("periodic_gas.toml"), "--backend", "event", "--out", out,
                                     "--set", "run.duration=2"}, dir);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(contains(result.out, "pressure  beta P d^2 = ")) << result.out;
    Hdf5File file(out);
    for (const char* name : {"beta_pressure", "beta_pressure_error", "beta_pressure_correlation_time",
                             "beta_pressure_equilibration", "beta_pressure_batches", "psi6_traversals", "psi6_mixed"})
        EXPECT_TRUE(file.has_attribute("/stats/counters", name)) << name;
    EXPECT_GT(file.double_attribute("/stats/counters", "beta_pressure"), 0);

    const std::string walls = dir.file("walls.h5");
    ASSERT_EQ(run_collide({"run", head_on_scene, "--backend", "event", "--out", walls}, dir).exit_code, 0);
    EXPECT_FALSE(Hdf5File(walls).has_attribute("/stats/counters", "beta_pressure"));
}

// Box2D's version is recorded once, as box2d_version: the installed package's version
// (cmake/build_info.cmake reads it from pkg-config or dpkg at configure time), because Box2D
// 2.4.1's library calls itself 2.4.0 and the build's Find module can tell only 2.4.
TEST(RunCommand, Box2dRunRecordsBox2dVersionOnce) {
    ScratchDirectory dir;
    const std::string out = dir.file("x.h5");
    const auto result = run_collide({"run", head_on_scene, "--backend", "box2d", "--out", out}, dir);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    Hdf5File file(out);
    ASSERT_TRUE(file.has_attribute("/", "box2d_version"));
    const std::string version = file.string_attribute("/", "box2d_version");
    EXPECT_EQ(version, BOX2D_PACKAGE_VERSION);
    EXPECT_NE(version, "unknown") << "neither pkg-config nor dpkg knew the Box2D package at configure time";
    // At least major.minor.patch: more than the "2.4" the headers alone can tell.
    EXPECT_GE(std::count(version.begin(), version.end(), '.'), 2) << version;
    for (const char* other : {"box2d_package_version", "backend_box2d_version"})
        EXPECT_FALSE(file.has_attribute("/", other)) << other << ": a second record of Box2D's version";
}

}  // namespace
}  // namespace collide
