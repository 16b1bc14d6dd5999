#include "core/structure/pair_correlation.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/uniform_grid.h"
#include "physics/stepping_laws.h"

namespace collide {

ContactCorrelation::ContactCorrelation(double diameter, double width, std::size_t bins)
    : diameter_(diameter), width_(width), counts_(bins, 0.0) {
    if (!(diameter > 0) || !(width > 0) || bins < 2)
        throw std::invalid_argument("ContactCorrelation: expected a positive diameter and width and at least 2 bins");
}

void ContactCorrelation::add(const World& world, const ParticleState<double>& s) {
    const std::size_t n = s.size();
    const double outer = diameter_ + width_, area = world.width() * world.height();
    UniformGrid<double> grid;  // cells at least d + w wide: the 3x3 cells hold every pair in the shell
    grid.configure(world, outer);
    grid.build(s.x.data(), s.y.data(), n);
    const bool periodic = world.boundary == Boundary::periodic;
    const double bins = double(counts_.size());
    for (std::size_t i = 0; i < n; ++i)
        grid.for_each_candidate(s.x[i], s.y[i], [&](std::uint32_t j) {
            if (j <= i) return;  // each pair once
            double dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
            if (periodic) {
                dx = WallLaw<double>::minimum_image(dx, world.width());
                dy = WallLaw<double>::minimum_image(dy, world.height());
            }
            const double r = std::hypot(dx, dy);
            if (r < diameter_ || r >= outer) return;
            counts_[std::min(counts_.size() - 1, std::size_t((r - diameter_) / width_ * bins))] += 1;
        });
    ideal_pairs_per_area_ += 0.5 * double(n) * double(n - 1) / area;
    area_fraction_ = double(n) * std::numbers::pi * diameter_ * diameter_ / (4 * area);
    ++configurations_;
}

double ContactCorrelation::bin_centre(std::size_t b) const {
    return diameter_ + (double(b) + 0.5) * width_ / double(counts_.size());
}

double ContactCorrelation::g(std::size_t b) const {
    const double step = width_ / double(counts_.size());
    const double r1 = diameter_ + double(b) * step, r2 = r1 + step;
    const double ideal = ideal_pairs_per_area_ * std::numbers::pi * (r2 * r2 - r1 * r1);
    return ideal > 0 ? counts_[b] / ideal : std::nan("");
}

double ContactCorrelation::contact() const {
    // Least-squares line g = a + b (r - d) through (bin centre, g); g(d) = a.
    const double m = double(counts_.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t b = 0; b < counts_.size(); ++b) {
        const double x = bin_centre(b) - diameter_, y = g(b);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    return (sy - slope * sx) / m;
}

double ContactCorrelation::compressibility() const { return 1 + 2 * area_fraction_ * contact(); }

}  // namespace collide
