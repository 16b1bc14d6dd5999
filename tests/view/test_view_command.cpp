// `collide view --headless` and `collide render` run as a user runs them: every backend draws
// frames, unsupported backends are refused in `collide run`'s words, bad inputs fail clearly
// and leave no file behind.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/backend_registry.h"
#include "core/scene/scene_loader.h"
#include "tests/support/program_runner.h"
#include "tests/support/scratch_directory.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

using test::contains;
using test::run_program;
using test::ScratchDirectory;

const std::string collide_exe = COLLIDE_EXECUTABLE;

TEST(ViewCommand, HeadlessRunsFramesOnEveryBackendThatSupportsTheScene) {
    const std::string scene_path = test::scene_file("glancing.toml");
    const Scene scene = load_scene(scene_path);
    for (const BackendInfo& backend : all_backends()) {
        if (backend.supports(scene)) continue;
        ScratchDirectory dir;
        const std::string png = dir.file("shot.png");
        const auto r = run_program(collide_exe, {"view", scene_path, "--backend", backend.name, "--headless",
                                                 "--frames", "8", "--size", "320x200", "--screenshot", png},
                                   dir);
        EXPECT_EQ(r.exit_code, 0) << backend.name << ": " << r.err;
        EXPECT_TRUE(std::filesystem::exists(png)) << backend.name;
        EXPECT_TRUE(contains(r.out, "t = 0.7")) << backend.name << ": " << r.out;  // 7 steps of 0.1
    }
}

TEST(ViewCommand, RefusesAnUnsupportedBackendWithTheMessageOfRun) {
    const std::string scene_path = test::scene_file("periodic_gas.toml");
    ScratchDirectory dir;
    const auto run = run_program(collide_exe, {"run", scene_path, "--backend", "box2d"}, dir);
    const auto view = run_program(collide_exe, {"view", scene_path, "--backend", "box2d", "--headless", "--frames", "2"}, dir);
    ASSERT_EQ(run.exit_code, 1);
    EXPECT_EQ(view.exit_code, 1);
    EXPECT_TRUE(contains(run.err, "cannot run scene")) << run.err;
    EXPECT_EQ(view.err, run.err);
    // The comparison backend is held to the same rule.
    const auto compare = run_program(
        collide_exe, {"view", scene_path, "--backend", "step", "--compare", "box2d", "--headless", "--frames", "2"}, dir);
    EXPECT_EQ(compare.err, run.err);
}

TEST(ViewCommand, HeadlessWithoutFramesOrWithABadSizeFailsClearly) {
    const std::string scene_path = test::scene_file("glancing.toml");
    ScratchDirectory dir;
    const auto no_frames = run_program(collide_exe, {"view", scene_path, "--headless"}, dir);
    EXPECT_EQ(no_frames.exit_code, 1);
    EXPECT_TRUE(contains(no_frames.err, "--headless needs --frames")) << no_frames.err;
    const auto bad_size = run_program(collide_exe, {"view", scene_path, "--headless", "--frames", "2", "--size", "big"}, dir);
    EXPECT_EQ(bad_size.exit_code, 1);
    EXPECT_TRUE(contains(bad_size.err, "expected WIDTHxHEIGHT")) << bad_size.err;
}

class RenderCommand : public ::testing::Test {
protected:
    void SetUp() override {
        for (auto [scene, out, frames] : {std::tuple{"glancing.toml", "g.h5", true},
                                          std::tuple{"glancing.toml", "plain.h5", false},
                                          std::tuple{"stiff/newtons_cradle.toml", "other.h5", true}}) {
            std::vector<std::string> args = {"run", test::scene_file(scene), "--backend", "step", "--out", dir.file(out)};
            if (frames) args.push_back("--frames");
            ASSERT_EQ(run_program(collide_exe, args, dir).exit_code, 0) << out;
        }
    }
    // Runs render, expects failure with `message`, and checks no output (or temporary) remains.
    void expect_failure(std::vector<std::string> args, const std::string& message) {
        const std::size_t before = dir.entry_count();
        args.insert(args.begin(), "render");
        const auto r = run_program(collide_exe, args, dir);
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_TRUE(contains(r.err, message)) << r.err;
        EXPECT_EQ(dir.entry_count(), before) << "render left a file behind";
    }
    ScratchDirectory dir;
};

TEST_F(RenderCommand, WritesAPngStripOfTheFramesAsked) {
    const auto r = run_program(collide_exe, {"render", dir.file("g.h5"), "--out", dir.file("s.png"), "--frames", "3",
                                             "--size", "100x60"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "3 frames of 100x60")) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir.file("s.png")));
}

TEST_F(RenderCommand, FailsClearlyOnBadInput) {
    expect_failure({dir.file("plain.h5"), "--out", dir.file("x.gif")},
                   "written without --frames: rerun with `collide run ... --frames`");
    expect_failure({dir.file("g.h5"), "--compare", dir.file("other.h5"), "--out", dir.file("x.gif")},
                   "has 2 disks but");
    expect_failure({dir.file("g.h5"), "--out", dir.file("x.bmp")}, "unknown output format '.bmp'");
    expect_failure({dir.file("g.h5"), "--out", dir.file("x.gif"), "--frames", "1000"}, "holds only 51 frames");
    expect_failure({dir.file("g.h5"), "--out", dir.file("missing/x.gif")}, "cannot write");
}

}  // namespace
}  // namespace collide
