// The memory estimate that refuses scenes too large for the machine before any disk is
// generated: the formula (docs/scenes.md, "Bad input"), the block it names, the numbers in
// its message, and that generation stops before allocating.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

#include "core/scene/memory_estimate.h"
#include "core/scene/scene_loader.h"
#include "tests/support/test_scenes.h"

namespace collide {
namespace {

ParticleGenerator gas_block(std::int64_t count, int source_line) {
    ParticleGenerator g;
    g.kind = "gas";
    g.count = count;
    g.radius = 0.5;
    g.mass = 1.0;
    g.source_line = source_line;
    return g;
}

Scene scene_of(double size, std::vector<ParticleGenerator> blocks) {
    Scene s = test::box_scene(size, size);
    s.source_path = "big.toml";
    s.generators = std::move(blocks);
    return s;
}

constexpr double gib = 1024.0 * 1024.0 * 1024.0;

TEST(MemoryEstimate, IsBytesPerDiskTimesNPlusBytesPerCellTimesCells) {
    EXPECT_EQ(bytes_per_disk, 412.0);
    EXPECT_EQ(bytes_per_grid_cell, 16.0);
    ParticleGenerator list;
    list.kind = "list";
    list.disks = {{1, 1, 0, 0, 0.5, 1, false, 0}, {3, 1, 0, 0, 0.5, 1, false, 0}};
    // Box 10 x 10, r_max 0.5: cells of side 1, 10 x 10 of them.
    const MemoryEstimate e = estimate_memory(scene_of(10, {gas_block(40, 0), list}));
    EXPECT_EQ(e.disks, 42);
    EXPECT_EQ(e.grid_cells, 100.0);
    EXPECT_EQ(e.bytes(), 42 * 412.0 + 100 * 16.0);
}

TEST(MemoryEstimate, GridCellsAreCappedAsTheGridCapsThem) {
    // 10^6 x 10^6 box with disks of radius 0.5: 10^12 cells of side 1, but the grid uses 2^26.
    EXPECT_EQ(estimate_memory(scene_of(1e6, {gas_block(10, 0)})).grid_cells, 67108864.0);
}

TEST(MemoryEstimate, PhysicalMemoryIsKnownOnThisSystem) {
    const double bytes = physical_memory_bytes();
    EXPECT_TRUE(std::isfinite(bytes));
    EXPECT_GT(bytes, 64.0 * 1024 * 1024);
}

TEST(MemoryEstimate, ASceneWithinHalfThePhysicalMemoryPasses) {
    const Scene scene = scene_of(10, {gas_block(1000, 7)});
    EXPECT_NO_THROW(check_memory(scene, 2 * estimate_memory(scene).bytes()));
}

TEST(MemoryEstimate, ASceneBeyondHalfThePhysicalMemoryIsRefusedWithTheNumbers) {
    // Three blocks of 10^6 disks, 412 MB each, and 100 grid cells. With 2 GiB of physical
    // memory the limit is 1 GiB = 1074 MB: two blocks (824 MB) fit, the third crosses it.
    const Scene scene = scene_of(10, {gas_block(1000000, 5), gas_block(1000000, 12), gas_block(1000000, 19)});
    try {
        check_memory(scene, 2 * gib);
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("big.toml:19: [[particles]][3] (gas): 1000000 disks (N = 3000000 in the scene)", 0), 0u)
            << message;
        EXPECT_NE(message.find("need about 1.2 GiB"), std::string::npos) << message;  // 3e6 x 412 B = 1.15 GiB
        EXPECT_NE(message.find("this machine's 2.0 GiB of physical memory"), std::string::npos) << message;
        // (1 GiB - 100 cells x 16 B) / 412 B = 2606165 disks fit.
        EXPECT_NE(message.find("expected at most about 2606165 disks"), std::string::npos) << message;
    }
}

TEST(MemoryEstimate, GenerationRefusesAHugeSceneBeforeAllocating) {
    // 2^31 - 1 disks need 824 GiB, and the grid 1 GiB more: beyond half the memory of any
    // machine that runs this test.
    const Scene scene = scene_of(1e6, {gas_block(max_disk_count, 3)});
    const auto start = std::chrono::steady_clock::now();
    try {
        generate_initial_state(scene);
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("need about 825.0 GiB"), std::string::npos) << e.what();
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0)
        << "refused up front, not after allocating or placing disks";
}

}  // namespace
}  // namespace collide
