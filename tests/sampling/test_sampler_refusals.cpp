// What a sampler cannot take is refused with the reason (issue "A second route", item 7), and a
// sampler's cases leave out the checks that read time or velocities, saying why.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/backend_registry.h"
#include "core/scene/scene_features.h"
#include "sampling/sampler_input.h"
#include "tests/support/test_scenes.h"
#include "validation/judge/checks.h"
#include "validation/record/tolerances.h"

namespace collide::test {
namespace {

// Four equal disks well apart in a periodic 10 x 10 box.
Scene periodic_box() { return box_scene(10, 10, Boundary::periodic); }
ParticleState<double> four_disks() {
    return make_state({{2, 2, 0, 0, 0.5, 1}, {5, 2, 0, 0, 0.5, 1}, {2, 5, 0, 0, 0.5, 1}, {5, 5, 0, 0, 0.5, 1}});
}

// The message `ecmc` throws on load, or "" if it loads.
std::string refusal(const Scene& scene, const ParticleState<double>& start) {
    auto sampler = find_backend("ecmc").create(BackendOptions{});
    try {
        sampler->load(scene, start);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TEST(SamplerRefusals, SceneStatementsAboutDynamicsAreRefusedWithTheReason) {
    const BackendInfo& ecmc = find_backend("ecmc");
    const std::pair<std::function<void(Scene&)>, std::string> cases[] = {
        {[](Scene& s) { s.world.boundary = Boundary::reflect, s.physics.wall_restitution = 0.9; }, "wall restitution 0.9 < 1"},
        {[](Scene& s) { s.physics.gravity_y = -1; }, "gravity"},
        {[](Scene& s) { s.physics.restitution = 0.9; }, "restitution e = 0.9 < 1"},
        {[](Scene& s) { s.physics.damping = 0.1; }, "damping"},
    };
    for (const auto& [change, reason] : cases) {
        Scene scene = periodic_box();
        change(scene);
        const auto why = ecmc.supports(scene);
        ASSERT_TRUE(why) << reason;
        EXPECT_NE(why->find(reason), std::string::npos) << *why;
        EXPECT_NE(refusal(scene, four_disks()).find(reason), std::string::npos) << reason;
    }
    EXPECT_FALSE(ecmc.supports(periodic_box()));
    EXPECT_EQ(refusal(periodic_box(), four_disks()), "");
    // Elastic walls: ecmc turns its chains back at them (docs/monte-carlo.md, "Walls"); a
    // sampler that declares no walls still refuses them with the reason.
    const Scene walled = box_scene(10, 10, Boundary::reflect);
    EXPECT_FALSE(ecmc.supports(walled));
    EXPECT_EQ(refusal(walled, four_disks()), "");
    const auto no_walls = outside_sampler_model(scene_features(walled), SamplerLimits{.walls = false});
    ASSERT_TRUE(no_walls);
    EXPECT_NE(no_walls->find("reflecting walls"), std::string::npos) << *no_walls;
}

TEST(SamplerRefusals, StartsItCannotSampleAreRefusedNamingTheDisk) {
    ParticleState<double> stone = four_disks();
    stone.inv_mass[2] = 0;
    EXPECT_NE(refusal(periodic_box(), stone).find("particle 2 is a stone"), std::string::npos);
    ParticleState<double> unequal = four_disks();
    unequal.radius[3] = 0.4;
    EXPECT_NE(refusal(periodic_box(), unequal).find("particle 3 has radius 0.4"), std::string::npos);
    ParticleState<double> overlap = four_disks();
    overlap.x[1] = 2.6;  // 0.6 from disk 0, closer than the contact distance 1
    EXPECT_NE(refusal(periodic_box(), overlap).find("particles 0 and 1 overlap"), std::string::npos)
        << refusal(periodic_box(), overlap);

    // Across the periodic edge too: x = 0.2 and x = 9.6 are 0.6 apart through the edge.
    ParticleState<double> across = four_disks();
    across.x[0] = 0.2;
    across.x[1] = 9.6;
    across.y[1] = 2;
    EXPECT_NE(refusal(periodic_box(), across).find("particles 0 and 1 overlap"), std::string::npos);
    Scene narrow = box_scene(2.5, 10, Boundary::periodic);
    EXPECT_NE(refusal(narrow, make_state({{1, 2, 0, 0, 0.5, 1}})).find("at least 3 cells"), std::string::npos);
}

TEST(SamplerRefusals, ASamplersCasesLeaveOutTheChecksOfDynamicsWithTheReason) {
    const BackendInfo& ecmc = find_backend("ecmc");
    EXPECT_TRUE(ecmc.sampler);
    EXPECT_FALSE(ecmc.in_all) << "the default suite keeps its time";
    validation::CaseResult r;
    r.spec.id = "x";
    r.status = validation::RunStatus::completed;
    r.disks = 4;
    Metrics m;
    r.series.push_back(m);
    m.time = 1;
    m.kinetic_energy = 5;  // a drift the checks would fail, were they run
    m.momentum_x = 3;
    r.series.push_back(m);
    const validation::Tolerances tol = validation::default_tolerances(ecmc);
    for (const auto& c : validation::case_checks(r, SceneFeatures{}, tol, ecmc)) {
        if (c.check != "momentum_drift" && c.check != "energy_drift") continue;
        EXPECT_EQ(c.status, validation::CheckStatus::left_out) << c.check;
        EXPECT_NE(c.detail.find("a sampler has no dynamics"), std::string::npos) << c.detail;
    }
    // Overlaps held to an exact solver's rounding limits, not a stepped rule's 0.2.
    const validation::Tolerances exact = validation::default_tolerances(find_backend("event"));
    EXPECT_EQ(tol.max_overlap, exact.max_overlap);
    EXPECT_EQ(tol.mean_overlap, exact.mean_overlap);
    EXPECT_LT(tol.max_overlap, validation::default_tolerances(BackendInfo{}).max_overlap);
}

}  // namespace
}  // namespace collide::test
