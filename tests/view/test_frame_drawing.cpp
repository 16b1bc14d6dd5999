// The drawing path, checked pixel by pixel: a frame of disks at known places and speeds,
// drawn off-screen, must show each disk's colour at its centre, the box colour where no disk
// is, a red dot where two disks overlap, and a white ring where a comparison disk lies.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/test_scenes.h"
#include "view/bitmap_font.h"
#include "view/canvas.h"
#include "view/color_map.h"
#include "view/frame_geometry.h"
#include "view/overlap_pairs.h"

namespace collide::view {
namespace {

struct Drawn {
    FrameLayout layout;
    Image image;
    Rgb at(double x, double y) const { return image.at(int(layout.px(x)), int(layout.py(y))); }
};

// Disks: 0 fast (speed 1), 1 slow (0.5), 2 a stone, 3 and 4 overlapping (centres 0.8 apart).
ParticleState<double> known_state() {
    return test::make_state({{2.0, 2.0, 1.0, 0.0, 0.5, 1.0},
                             {5.0, 2.0, 0.0, -0.5, 0.5, 1.0},
                             {8.0, 3.5, 0.0, 0.0, 0.5, 1.0, true},
                             {3.0, 4.0, 0.25, 0.0, 0.5, 1.0},
                             {3.8, 4.0, 0.25, 0.0, 0.5, 1.0}});
}

Drawn draw(const Scene& scene, const ParticleState<double>& state, const ParticleState<double>* compare) {
    std::vector<OverlapMark> overlaps;
    OverlapFinder().find(scene.world, state, overlaps);
    FrameContent content;
    content.state = &state;
    content.compare = compare;
    content.overlaps = &overlaps;
    content.speed_max = 1.0;
    content.hud = "T 0.000";
    Canvas canvas(640, 360);
    Geometry geometry;
    Drawn d{make_layout(scene.world, 640, 360), {}};
    build_frame(content, d.layout, geometry);
    canvas.draw(geometry);
    d.image = canvas.read_pixels();
    return d;
}

TEST(FrameDrawing, DiskCentresHaveTheirSpeedColourAndEmptySpaceTheBoxColour) {
    const Scene scene = test::box_scene(10, 5);
    const Drawn d = draw(scene, known_state(), nullptr);
    EXPECT_EQ(d.at(2.0, 2.0), viridis(1.0));
    EXPECT_EQ(d.at(5.0, 2.0), viridis(0.5));
    EXPECT_EQ(d.at(8.0, 3.5), palette::stone);
    EXPECT_EQ(d.at(6.5, 1.0), palette::box);
    EXPECT_EQ(d.at(9.5, 0.5), palette::box);
    EXPECT_EQ(d.at(1.0, 4.5), palette::box);
    // Just outside a disk's rim is empty box again.
    EXPECT_EQ(d.at(2.0 + 0.62, 2.0), palette::box);
}

TEST(FrameDrawing, AnOverlappingPairIsMarkedAndASeparatePairIsNot) {
    const Scene scene = test::box_scene(10, 5);
    const Drawn d = draw(scene, known_state(), nullptr);
    EXPECT_EQ(d.at(3.4, 4.0), palette::overlap);   // the midpoint of the overlapping pair
    EXPECT_EQ(d.at(3.5, 2.0), palette::box);       // halfway between disks 0 and 1: no mark
    EXPECT_EQ(d.at(3.0, 4.0), viridis(0.25));      // the pair's own centres keep their colour
}

TEST(FrameDrawing, ComparisonDisksAreDrawnAsOutlines) {
    const Scene scene = test::box_scene(10, 5);
    const ParticleState<double> state = known_state();
    ParticleState<double> compare = state;
    compare.x[1] = 6.5;  // the comparison has disk 1 elsewhere, on empty box
    const Drawn d = draw(scene, state, &compare);
    EXPECT_EQ(d.at(6.5 + 0.42, 2.0), palette::outline);  // on the ring (0.73 r .. 0.97 r)
    EXPECT_EQ(d.at(6.5, 2.0), palette::box);              // a ring is hollow
    EXPECT_EQ(d.at(2.0, 2.0), viridis(1.0));              // disk 0's centre still shows its fill
    EXPECT_EQ(d.at(2.0 + 0.42, 2.0), palette::outline);   // under its own outline
}

TEST(FrameDrawing, TheBoxKeepsItsAspectRatioInAnyFrameShape) {
    const Scene scene = test::box_scene(20, 4);
    for (auto [w, h] : {std::pair{1280, 720}, std::pair{400, 900}, std::pair{2000, 300}}) {
        const FrameLayout l = make_layout(scene.world, w, h);
        EXPECT_NEAR(l.box.w / l.box.h, 5.0, 1e-3) << w << "x" << h;
        EXPECT_LE(l.box.x + l.box.w, l.legend_bar.x);
        EXPECT_LE(l.box.y + l.box.h, float(h));
    }
}

TEST(ColorMap, ViridisEndsAndClamps) {
    EXPECT_EQ(viridis(0), (Rgb{68, 1, 84}));
    EXPECT_EQ(viridis(1), (Rgb{253, 231, 37}));
    EXPECT_EQ(viridis(7), viridis(1));
    EXPECT_EQ(viridis(std::nan("")), viridis(0));
}

TEST(BitmapFont, LowerCaseIsUpperCaseAndUnknownIsAQuestionMark) {
    EXPECT_EQ(glyph_rows('e'), glyph_rows('E'));
    EXPECT_EQ(glyph_rows('~'), glyph_rows('?'));
    EXPECT_EQ(glyph_rows('1')[4], 0b111);
}

}  // namespace
}  // namespace collide::view
