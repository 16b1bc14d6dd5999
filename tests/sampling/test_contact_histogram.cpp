// The contact extrapolation of sampling/contact_histogram.h against a density whose contact value
// is known: gaps drawn from the exponential density (M / lambda) exp(-s / lambda) by stratified
// inverse-CDF quantiles (no noise), so the histogram holds the exact bin integrals to 1 / M.
// The parabola's bias is the third-order term of the exponential over the window (computed for
// a window of 0.05 by a least-squares fit of the exact bin integrals: -2.3e-4 at lambda = 0.15,
// -7.7e-4 at 0.10); a straight line's was -0.8 % and -1.7 %, which these bounds reject.
#include <gtest/gtest.h>

#include <cmath>

#include "sampling/contact_histogram.h"

namespace collide {
namespace {

// The fitted contact density over the true one, M / lambda, for gaps in units of sigma.
double relative_contact_error(double lambda) {
    const int samples = 2'000'000;
    ContactHistogram histogram(0.05, 10);
    for (int k = 0; k < samples; ++k) histogram.add(-lambda * std::log1p(-(k + 0.5) / samples));
    return histogram.contact_density(1.0) / (samples / lambda) - 1;
}

TEST(ContactHistogram, AParabolaExtrapolatesAnExponentialContactDensityToBelowOnePerMille) {
    EXPECT_NEAR(relative_contact_error(0.15), -2.3e-4, 0.5e-4);  // eta = 0.65: beta P d^2 = 6.9
    EXPECT_NEAR(relative_contact_error(0.10), -7.7e-4, 0.5e-4);  // eta = 0.70: beta P d^2 = 9.5
}

TEST(ContactHistogram, ALinearDensityIsExtrapolatedExactly) {
    // Gaps uniform on [0, 0.1): the density per unit gap is M / 0.1 everywhere, its slope zero.
    const int samples = 1'000'000;
    ContactHistogram histogram(0.05, 10);
    for (int k = 0; k < samples; ++k) histogram.add(0.1 * (k + 0.5) / samples);
    EXPECT_NEAR(histogram.contact_density(2.0), samples / 0.1 / 2, 1e-9 * samples);
}

}  // namespace
}  // namespace collide
