// The shared contact law against analytic results for an isolated pair. Expected values come
// from conservation of momentum and Newton's restitution law (docs/stepping-rules.md).
#include <gtest/gtest.h>

#include <cmath>

#include "physics/stepping_laws.h"

namespace collide {
namespace {

struct Disk { double x, y, vx, vy, r, w; };

// Applies both one-sided deltas (i's and the mirror j's) as the stepping rules do.
void collide_pair(Disk& a, Disk& b, double e, double mu) {
    const auto da = ContactLaw<double>::delta(a.x - b.x, a.y - b.y, a.vx - b.vx, a.vy - b.vy, a.r + b.r, a.w, b.w, e, mu);
    const auto db = ContactLaw<double>::delta(b.x - a.x, b.y - a.y, b.vx - a.vx, b.vy - a.vy, a.r + b.r, b.w, a.w, e, mu);
    a.x += da.dx; a.y += da.dy; a.vx += da.dvx; a.vy += da.dvy;
    b.x += db.dx; b.y += db.dy; b.vx += db.dvx; b.vy += db.dvy;
}

TEST(ContactLaw, EqualMassesHeadOnExchangeVelocities) {
    Disk a{0, 0, 1, 0, 1, 1}, b{1.9, 0, -1, 0, 1, 1};
    collide_pair(a, b, 1.0, 0.0);
    EXPECT_DOUBLE_EQ(a.vx, -1.0);
    EXPECT_DOUBLE_EQ(b.vx, 1.0);
    EXPECT_DOUBLE_EQ(a.vy, 0.0);
    // The overlap 0.1 is split evenly.
    EXPECT_NEAR(a.x, -0.05, 1e-15);
    EXPECT_NEAR(b.x, 1.95, 1e-15);
}

TEST(ContactLaw, MassRatioMatchesOneDimensionalElasticFormula) {
    for (double ratio : {10.0, 100.0, 1e6}) {
        const double m1 = 1.0, m2 = ratio, u1 = 1.0, u2 = -0.5;
        Disk a{0, 0, u1, 0, 1, 1 / m1}, b{1.99, 0, u2, 0, 1, 1 / m2};
        collide_pair(a, b, 1.0, 0.0);
        // v1' = ((m1 - m2) u1 + 2 m2 u2) / (m1 + m2), v2' = ((m2 - m1) u2 + 2 m1 u1) / (m1 + m2)
        EXPECT_NEAR(a.vx, ((m1 - m2) * u1 + 2 * m2 * u2) / (m1 + m2), 1e-12 * ratio);
        EXPECT_NEAR(b.vx, ((m2 - m1) * u2 + 2 * m1 * u1) / (m1 + m2), 1e-12);
        // The positional correction leaves the centre of mass where it was.
        EXPECT_NEAR(m1 * a.x + m2 * b.x, m2 * 1.99, 1e-12 * ratio);
    }
}

TEST(ContactLaw, RestitutionScalesNormalRelativeSpeed) {
    for (double e : {0.0, 0.4, 0.85, 1.0}) {
        // Oblique contact: normal along (1, 1)/sqrt 2.
        Disk a{0, 0, 2, 0.5, 1, 1.0}, b{1.4, 1.4, -1, 0.25, 1, 0.5};
        const double nx = -1 / std::sqrt(2.0), ny = -1 / std::sqrt(2.0);
        const double un_before = (a.vx - b.vx) * nx + (a.vy - b.vy) * ny;
        const double px = a.vx / a.w + b.vx / b.w, py = a.vy / a.w + b.vy / b.w;
        collide_pair(a, b, e, 0.0);
        const double un_after = (a.vx - b.vx) * nx + (a.vy - b.vy) * ny;
        EXPECT_NEAR(un_after, -e * un_before, 1e-14);
        EXPECT_NEAR(a.vx / a.w + b.vx / b.w, px, 1e-14);
        EXPECT_NEAR(a.vy / a.w + b.vy / b.w, py, 1e-14);
    }
}

TEST(ContactLaw, SeparatingOverlapGetsCorrectionButNoImpulse) {
    const auto d = ContactLaw<double>::delta(-1.5, 0, -1, 0, 2, 1, 1, 1, 0);  // moving apart
    EXPECT_EQ(d.dvx, 0.0);
    EXPECT_EQ(d.dvy, 0.0);
    EXPECT_DOUBLE_EQ(d.dx, -0.25);
}

TEST(ContactLaw, NoContactGivesZero) {
    const auto d = ContactLaw<double>::delta(-2.0, 0, 1, 0, 2, 1, 1, 1, 0);  // exactly touching
    EXPECT_EQ(d.dx, 0.0);
    EXPECT_EQ(d.dvx, 0.0);
}

TEST(ContactLaw, StoneReflectsTheMovingDiskAndNeverMoves) {
    const double e = 0.7;
    // i moves towards a stone j: i gets the whole impulse (1 + e) u_n.
    const auto d = ContactLaw<double>::delta(-1.9, 0, 3, 0, 2, 1, 0, e, 0);
    EXPECT_DOUBLE_EQ(d.dvx, -(1 + e) * 3);
    EXPECT_NEAR(d.dx, -0.1, 1e-15);
    // The stone's own share is zero.
    const auto s = ContactLaw<double>::delta(1.9, 0, -3, 0, 2, 0, 1, e, 0);
    EXPECT_EQ(s.dvx, 0.0);
    EXPECT_EQ(s.dx, 0.0);
}

TEST(ContactLaw, FrictionReducesTangentialSlipAndNeverReversesIt) {
    for (double mu : {0.1, 0.5, 10.0}) {
        Disk a{0, 0, 1, 3, 1, 1}, b{1.9, 0, -1, -3, 1, 1};
        const double slip_before = (a.vy - b.vy);  // tangent is y for a contact along x
        collide_pair(a, b, 0.5, mu);
        const double slip_after = (a.vy - b.vy);
        EXPECT_LE(std::fabs(slip_after), std::fabs(slip_before));
        EXPECT_GE(slip_after * slip_before, 0.0) << "friction reversed the slip, mu = " << mu;
        EXPECT_NEAR(a.vy + b.vy, 0.0, 1e-14);  // tangential momentum conserved
    }
    // Coulomb regime: slip reduced by exactly 2 * mu * J / m with J = (1 + e) * |u_n| / 2.
    Disk a{0, 0, 1, 3, 1, 1}, b{1.9, 0, -1, -3, 1, 1};
    collide_pair(a, b, 0.5, 0.1);
    EXPECT_NEAR(a.vy - b.vy, 6.0 - 2 * 0.1 * (1.5 * 2 / 2), 1e-14);
}

TEST(ContactLaw, FloatInstantiationAgreesWithDouble) {
    const auto f = ContactLaw<float>::delta(-1.9f, 0.3f, 2.f, -1.f, 2.f, 1.f, 0.5f, 0.9f, 0.2f);
    const auto d = ContactLaw<double>::delta(-1.9, 0.3, 2., -1., 2., 1., 0.5, 0.9, 0.2);
    EXPECT_NEAR(f.dvx, d.dvx, 1e-5 * std::fabs(d.dvx));
    EXPECT_NEAR(f.dvy, d.dvy, 1e-5 * std::fabs(d.dvy) + 1e-6);
}

TEST(WallLaw, ReflectClampsAndReversesWithRestitution) {
    double x = -0.05, v = -2;
    EXPECT_EQ(WallLaw<double>::reflect_axis(&x, &v, 0.1, 0.0, 1.0, 0.5), 1);
    EXPECT_DOUBLE_EQ(x, 0.1);
    EXPECT_DOUBLE_EQ(v, 1.0);
    x = 0.95; v = 3;
    EXPECT_EQ(WallLaw<double>::reflect_axis(&x, &v, 0.1, 0.0, 1.0, 1.0), 1);
    EXPECT_DOUBLE_EQ(x, 0.9);
    EXPECT_DOUBLE_EQ(v, -3.0);
    x = 0.5; v = 3;
    EXPECT_EQ(WallLaw<double>::reflect_axis(&x, &v, 0.1, 0.0, 1.0, 1.0), 0);
}

TEST(WallLaw, PeriodicWrapAndMinimumImage) {
    EXPECT_DOUBLE_EQ(WallLaw<double>::wrap(10.25, 0.0, 10.0), 0.25);
    EXPECT_DOUBLE_EQ(WallLaw<double>::wrap(-0.25, 0.0, 10.0), 9.75);
    EXPECT_LT(WallLaw<double>::wrap(-1e-18, 0.0, 10.0), 10.0);
    EXPECT_DOUBLE_EQ(WallLaw<double>::minimum_image(9.0, 10.0), -1.0);
    EXPECT_DOUBLE_EQ(WallLaw<double>::minimum_image(-7.0, 10.0), 3.0);
}

}  // namespace
}  // namespace collide
