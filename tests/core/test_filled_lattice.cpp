// `fill_box = true` lattices (core/scene/filled_lattice.h): the hexagonal crystal that fills Li et
// al.'s 9 : 8 sqrt(3)/2 box with six neighbours at one spacing, and starts without overlaps that
// close periodically in boxes no crystal fills (square, 1 : sqrt(3)/2) at area fraction 0.70;
// the nearest distance the loader checks equals the one measured over every pair; bad keys named.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "core/scene/filled_lattice.h"
#include "core/scene/scene_loader.h"

namespace collide {
namespace {

std::string filled_scene(double width, double height, int count, int columns, double radius,
                         const std::string& boundary = "periodic", const std::string& extra = "") {
    std::ostringstream t;
    t.precision(17);
    t << "description = \"filled lattice\"\n[world]\nbox = [0.0, 0.0, " << width << ", " << height << "]\nboundary = \"" << boundary
      << "\"\n[[particles]]\nkind = \"lattice\"\nlattice = \"hexagonal\"\nfill_box = true\ncount = " << count
      << "\ncolumns = " << columns << "\nradius = " << radius << "\nmass = 1.0\n" << extra;
    return t.str();
}

// Minimum-image distances over every pair: the nearest one, and how many pairs lie within `at`.
struct PairFacts {
    double nearest = INFINITY;
    std::size_t within = 0;
};
PairFacts pair_facts(const ParticleState<double>& s, double width, double height, double at) {
    PairFacts f;
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            double dx = std::abs(s.x[i] - s.x[j]), dy = std::abs(s.y[i] - s.y[j]);
            dx = std::min(dx, width - dx), dy = std::min(dy, height - dy);
            const double d = std::hypot(dx, dy);
            f.nearest = std::min(f.nearest, d);
            if (d <= at) ++f.within;
        }
    return f;
}

TEST(FilledLattice, FillsTheCrystalBoxWithSixNeighboursAtOneSpacing) {
    const double height = 8 * std::sqrt(3.0) / 2;
    const auto s = generate_initial_state(parse_scene(filled_scene(9, height, 72, 9, 0.4393), "crystal.toml"));
    ASSERT_EQ(s.size(), 72u);
    const PairFacts f = pair_facts(s, 9, height, 1 + 1e-9);
    EXPECT_NEAR(f.nearest, 1.0, 1e-9);
    EXPECT_EQ(f.within, 72u * 6 / 2) << "every disk has six neighbours at the spacing, across the boundary too";
    for (std::size_t i = 0; i < s.size(); ++i) {
        EXPECT_GE(s.x[i], 0.0);
        EXPECT_LT(s.x[i], 9.0);
        EXPECT_GE(s.y[i], 0.0);
        EXPECT_LT(s.y[i], height);
    }
}

TEST(FilledLattice, ClosesPeriodicallyInBoxesNoCrystalFillsAtSeventyPercent) {
    struct Box {
        double width, height;
        int count, columns;
    };
    for (const Box& b : {Box{9, 9, 72, 8}, Box{9, 9 * std::sqrt(3.0) / 2, 72, 9}, Box{29, 29, 870, 29}}) {
        const double radius = std::sqrt(0.70 * b.width * b.height / (b.count * M_PI));  // eta = 0.70
        const Scene scene = parse_scene(filled_scene(b.width, b.height, b.count, b.columns, radius), "box.toml");
        const auto s = generate_initial_state(scene);
        const PairFacts f = pair_facts(s, scene.world.width(), scene.world.height(), 0);
        const FilledLattice l = filled_lattice(scene.world.width(), scene.world.height(), b.columns,
                                               b.count / b.columns, true);
        EXPECT_GT(f.nearest, 2 * radius) << b.width << " x " << b.height;
        EXPECT_NEAR(l.nearest_distance(), f.nearest, 1e-9) << "the loader's check is the measured nearest distance";
    }
}

TEST(FilledLattice, OddRowCountsAreShearedToCloseAcrossTheBoundary) {
    // 8 x 9 in a 9 x 9 box: spacings 1.125 and 1; 9 rows, so the shift is 4/9 of a spacing
    // (0.5) and row 9 lands on row 0, 4 whole spacings later. Nearest: the neighbouring row,
    // sqrt(0.5^2 + 1), closer than the 1.125 within a row.
    const FilledLattice l = filled_lattice(9, 9, 8, 9, true);
    EXPECT_DOUBLE_EQ(l.row_shift, 0.5);
    EXPECT_NEAR(std::remainder(9 * l.row_shift, l.dx), 0.0, 1e-12);
    EXPECT_NEAR(l.nearest_distance(), std::hypot(0.5, 1.0), 1e-12);
    EXPECT_DOUBLE_EQ(filled_lattice(9, 9, 8, 9, false).nearest_distance(), 1.0);  // square: rows 1 apart
}

void expect_refused(const std::string& text, const std::string& key) {
    try {
        parse_scene(text, "bad.toml");
        ADD_FAILURE() << "accepted: " << text;
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("bad.toml"), std::string::npos) << e.what();
    }
}

TEST(FilledLattice, RefusesWhatCannotFillTheBoxNamingTheKey) {
    expect_refused(filled_scene(9, 9, 72, 8, 0.56), "radius");                      // neighbours 1.118 apart
    expect_refused(filled_scene(9, 9, 72, 8, 0.4, "reflect"), "fill_box");          // walls: no periodic closure
    expect_refused(filled_scene(9, 9, 70, 8, 0.4), "count");                        // not whole rows
    expect_refused(filled_scene(9, 9, 72, 8, 0.4, "periodic", "spacing = 1.0\n"), "spacing");
}

}  // namespace
}  // namespace collide
