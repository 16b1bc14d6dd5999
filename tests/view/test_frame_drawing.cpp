// The drawing, checked pixel by pixel on both ways of drawing a frame's quads (one
// SDL_RenderGeometry call, the CPU rasteriser): a frame of disks at known places and speeds,
// drawn off-screen, must show each disk's colour at its centre, the box colour where no disk
// is, a red dot where two disks overlap, and a white ring where a comparison disk lies; and the
// two ways must agree with each other.
#include <gtest/gtest.h>

#include <algorithm>
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

Drawn draw(const Scene& scene, const ParticleState<double>& state, const ParticleState<double>* compare,
           DrawPath path, int width = 640, int height = 360) {
    std::vector<OverlapMark> overlaps;
    OverlapFinder().find(scene.world, state, overlaps);
    FrameContent content;
    content.state = &state;
    content.compare = compare;
    content.overlaps = &overlaps;
    content.speed_max = 1.0;
    content.hud = "T 0.000";
    Canvas canvas(width, height, path);
    EXPECT_EQ(canvas.path(), path);
    Geometry geometry;
    Drawn d{make_layout(scene.world, width, height), {}};
    build_frame(content, d.layout, geometry);
    canvas.draw(geometry);
    d.image = canvas.read_pixels();
    return d;
}

// Every pixel test runs on both ways of drawing the quads.
class FrameDrawing : public ::testing::TestWithParam<DrawPath> {};

TEST_P(FrameDrawing, DiskCentresHaveTheirSpeedColourAndEmptySpaceTheBoxColour) {
    const Scene scene = test::box_scene(10, 5);
    const Drawn d = draw(scene, known_state(), nullptr, GetParam());
    EXPECT_EQ(d.at(2.0, 2.0), viridis(1.0));
    EXPECT_EQ(d.at(5.0, 2.0), viridis(0.5));
    EXPECT_EQ(d.at(8.0, 3.5), palette::stone);
    EXPECT_EQ(d.at(6.5, 1.0), palette::box);
    EXPECT_EQ(d.at(9.5, 0.5), palette::box);
    EXPECT_EQ(d.at(1.0, 4.5), palette::box);
    // Just outside a disk's rim is empty box again.
    EXPECT_EQ(d.at(2.0 + 0.62, 2.0), palette::box);
}

TEST_P(FrameDrawing, AnOverlappingPairIsMarkedAndASeparatePairIsNot) {
    const Scene scene = test::box_scene(10, 5);
    const Drawn d = draw(scene, known_state(), nullptr, GetParam());
    EXPECT_EQ(d.at(3.4, 4.0), palette::overlap);   // the midpoint of the overlapping pair
    EXPECT_EQ(d.at(3.5, 2.0), palette::box);       // halfway between disks 0 and 1: no mark
    EXPECT_EQ(d.at(3.0, 4.0), viridis(0.25));      // the pair's own centres keep their colour
}

TEST_P(FrameDrawing, ComparisonDisksAreDrawnAsOutlines) {
    const Scene scene = test::box_scene(10, 5);
    const ParticleState<double> state = known_state();
    ParticleState<double> compare = state;
    compare.x[1] = 6.5;  // the comparison has disk 1 elsewhere, on empty box
    const Drawn d = draw(scene, state, &compare, GetParam());
    EXPECT_EQ(d.at(6.5 + 0.42, 2.0), palette::outline);  // on the ring (0.73 r .. 0.97 r)
    EXPECT_EQ(d.at(6.5, 2.0), palette::box);              // a ring is hollow
    EXPECT_EQ(d.at(2.0, 2.0), viridis(1.0));              // disk 0's centre still shows its fill
    EXPECT_EQ(d.at(2.0 + 0.42, 2.0), palette::outline);   // under its own outline
}

INSTANTIATE_TEST_SUITE_P(Paths, FrameDrawing, ::testing::Values(DrawPath::render_geometry, DrawPath::cpu_raster),
                         [](const auto& info) {
                             return std::string(info.param == DrawPath::cpu_raster ? "cpu_raster" : "render_geometry");
                         });

// The rasteriser draws every disk, however small (1.5 pixels wide at least). SDL's software
// renderer does not: it truncates vertex coordinates to whole pixels, and most quads of 1.5
// pixels then cover no pixel centre; hence the rasteriser on software renderers.
TEST(FrameDrawing, DisksOfLessThanAPixelStillShowOnTheRasteriser) {
    // 2000 disks of radius 0.02 in a 100 x 50 box: 0.13 pixels at 640x360.
    const Scene scene = test::box_scene(100, 50);
    const ParticleState<double> s = test::random_gas(scene, 2000, 0.02, 9, /*allow_overlap=*/false);
    const Drawn d = draw(scene, s, nullptr, DrawPath::cpu_raster);
    int shown = 0;
    for (std::size_t i = 0; i < s.size(); ++i) shown += d.at(s.x[i], s.y[i]) != palette::box;
    EXPECT_EQ(shown, int(s.size()));
}

// The paths must not drift apart. A frame of disks of several sizes (4 to 20 pixels) in the left
// half of the box, one overlapping pair (a mark), the comparison's outlines in the right half,
// legend and HUD: both paths give the same colour at every disk centre, on every ring's middle,
// at every point of the box two pixels clear of any shape, and on every pixel outside the box.
class TwoPathsFrame : public ::testing::Test {
protected:
    void SetUp() override {
        const Scene half = test::box_scene(20, 20);
        s = test::random_gas(half, 200, 0.45, 4, /*allow_overlap=*/false);
        for (std::size_t i = 0; i < s.size(); ++i) s.radius[i] = 0.1 + 0.35 * double(i % 8) / 7;
        s.x[1] = s.x[0] + 0.5 * (s.radius[0] + s.radius[1]), s.y[1] = s.y[0];
        compare = s;
        for (double& x : compare.x) x += 20;
        a = draw(scene, s, &compare, DrawPath::render_geometry, 1920, 1080);
        b = draw(scene, s, &compare, DrawPath::cpu_raster, 1920, 1080);
    }
    bool clear_of_shapes(double x, double y) const {
        const double margin = 2 / a.layout.scale;
        for (const ParticleState<double>* state : {&s, &compare})
            for (std::size_t i = 0; i < state->size(); ++i)
                if (std::hypot(x - state->x[i], y - state->y[i]) < state->radius[i] + margin) return false;
        return true;
    }
    const Scene scene = test::box_scene(40, 20);
    ParticleState<double> s, compare;
    Drawn a, b;
};

TEST_F(TwoPathsFrame, SameColourAtDiskCentresAndTheMark) {
    for (std::size_t i = 0; i < s.size(); ++i) {
        EXPECT_EQ(a.at(s.x[i], s.y[i]), b.at(s.x[i], s.y[i])) << "centre of disk " << i;
        EXPECT_NE(b.at(s.x[i], s.y[i]), palette::box) << "centre of disk " << i;
    }
    const double mark_x = (s.x[0] + s.x[1]) / 2;
    EXPECT_EQ(a.at(mark_x, s.y[0]), palette::overlap);
    EXPECT_EQ(b.at(mark_x, s.y[0]), palette::overlap);
}

// SDL's software renderer also maps the texture with whole-pixel vertices and texels, so the
// middle of its ring may be a little translucent; the rasteriser's is exact.
bool near_outline(Rgb c) { return c.r >= 200 && c.g >= 200 && c.b >= 200; }

TEST_F(TwoPathsFrame, SameColourOnTheRingsOfTheOutlines) {
    int rings = 0;
    for (std::size_t i = 0; i < compare.size(); ++i) {
        // SDL's software renderer moves a quad by up to a pixel (whole-pixel vertices): only
        // bands of 3 pixels or more are hit in the middle by both paths.
        if (0.24 * compare.radius[i] * a.layout.scale < 3) continue;
        ++rings;
        const double r = 0.85 * compare.radius[i];
        EXPECT_TRUE(near_outline(a.at(compare.x[i] + r, compare.y[i]))) << "ring " << i;
        EXPECT_EQ(b.at(compare.x[i] + r, compare.y[i]), palette::outline) << "ring " << i;
    }
    EXPECT_GT(rings, 40);
}

TEST_F(TwoPathsFrame, SameColourInEmptySpaceAndOutsideTheBox) {
    int empty = 0, outside = 0;
    for (double y = 0.25; y < 20; y += 0.5)
        for (double x = 0.25; x < 40; x += 0.5)
            if (clear_of_shapes(x, y)) {
                ++empty;
                EXPECT_EQ(a.at(x, y), palette::box) << x << "," << y;
                EXPECT_EQ(b.at(x, y), palette::box) << x << "," << y;
            }
    const PixelRect box = a.layout.box;
    for (int y = 0; y < a.image.height; ++y)
        for (int x = 0; x < a.image.width; ++x) {
            if (x >= box.x - 1 && x <= box.x + box.w && y >= box.y - 1 && y <= box.y + box.h) continue;
            ++outside;
            if (a.image.at(x, y) != b.image.at(x, y)) ADD_FAILURE() << "pixel " << x << "," << y << " outside the box";
        }
    EXPECT_GT(empty, 1500);
    EXPECT_GT(outside, 400000);
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
