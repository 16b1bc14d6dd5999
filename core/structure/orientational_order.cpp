#include "core/structure/orientational_order.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/uniform_grid.h"
#include "physics/stepping_laws.h"

namespace collide {
namespace {

// The separation from disk j to disk k, minimum image along periodic axes.
std::complex<double> bond(const World& world, const ParticleState<double>& s, std::size_t j, std::size_t k) {
    double dx = s.x[k] - s.x[j], dy = s.y[k] - s.y[j];
    if (world.boundary == Boundary::periodic) {
        dx = WallLaw<double>::minimum_image(dx, world.width());
        dy = WallLaw<double>::minimum_image(dy, world.height());
    }
    return {dx, dy};
}

// exp(6 i theta) of the bond b = dx + i dy, as b^6 / |b|^6: three complex squarings and one
// division, no angle, no square root (a hypot per bond made psi6 the dearer half of ecmc's
// run, which samples it once per entry).
std::complex<double> sixfold_phase(double dx, double dy, double r2) {
    const double re2 = dx * dx - dy * dy, im2 = 2 * dx * dy;        // b^2
    const double re4 = re2 * re2 - im2 * im2, im4 = 2 * re2 * im2;  // b^4
    const double scale = 1 / (r2 * r2 * r2);                        // 1 / |b|^6
    return {(re4 * re2 - im4 * im2) * scale, (re4 * im2 + im4 * re2) * scale};
}

double wrapped(double d) { return d - 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi)); }

}  // namespace

// Each bond is visited once, from its lower-numbered disk, and its phase added to both ends:
// the bond seen from the other disk is -b, and (-b)^6 = b^6.
std::vector<std::complex<double>> local_psi6(const World& world, const ParticleState<double>& state, double cutoff) {
    const std::size_t n = state.size();
    std::vector<std::complex<double>> local(n);
    if (n == 0) return local;
    UniformGrid<double> grid;  // cells at least `cutoff` wide: the 3x3 cells hold every neighbour
    grid.configure(world, cutoff);
    grid.build(state.x.data(), state.y.data(), n);
    std::vector<std::uint32_t> neighbours(n, 0);
    const double cutoff2 = cutoff * cutoff;
    for (std::size_t j = 0; j < n; ++j) {
        grid.for_each_candidate(state.x[j], state.y[j], [&](std::uint32_t k) {
            if (k <= j) return;
            const std::complex<double> b = bond(world, state, j, k);
            const double r2 = b.real() * b.real() + b.imag() * b.imag();
            if (r2 >= cutoff2 || r2 == 0) return;
            const std::complex<double> phase = sixfold_phase(b.real(), b.imag(), r2);
            local[j] += phase, local[k] += phase;
            ++neighbours[j], ++neighbours[k];
        });
    }
    // (1/n_j) sum_k exp(6 i theta_jk) over j's neighbours within the cutoff; 0 without neighbours.
    for (std::size_t j = 0; j < n; ++j)
        if (neighbours[j] > 0) local[j] /= double(neighbours[j]);
    return local;
}

std::complex<double> global_psi6(const World& world, const ParticleState<double>& state, double cutoff) {
    const std::vector<std::complex<double>> local = local_psi6(world, state, cutoff);
    if (local.empty()) return 0;
    std::complex<double> sum = 0;
    for (const std::complex<double>& psi : local) sum += psi;
    return sum / double(local.size());
}

std::complex<double> global_psi6(const World& world, const ParticleState<double>& state) {
    double diameters = 0;
    for (double r : state.radius) diameters += 2 * r;
    const double mean_diameter = state.size() ? diameters / double(state.size()) : 0;
    if (!(mean_diameter > 0)) return 0;
    return global_psi6(world, state, psi6_cutoff_diameters * mean_diameter);
}

std::size_t phase_traversals(const std::vector<double>& phases) {
    std::size_t traversals = 0;
    double unwrapped = 0, low = 0, high = 0;  // the unwrapped phase, and its span since the last traversal
    for (std::size_t i = 1; i < phases.size(); ++i) {
        unwrapped += wrapped(phases[i] - phases[i - 1]);
        low = std::min(low, unwrapped), high = std::max(high, unwrapped);
        if (high - low >= 2 * std::numbers::pi) {
            ++traversals;
            low = high = unwrapped;
        }
    }
    return traversals;
}

}  // namespace collide
