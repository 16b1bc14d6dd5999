// The pair correlation g(r) of equal disks near contact, and the pressure it gives by the
// contact route. docs/validation.md, "Error bars and mixing", shows where it is used.
//
// g(r) over the shell [d, d + w] in `bins` equal bins: the pairs whose centre distance falls in
// a bin (minimum image in a periodic box), over the pairs an ideal gas of the same N in the same
// area puts there, N (N - 1) / 2 * pi (r2^2 - r1^2) / A. Averaged over configurations by adding
// histograms (add), then read (contact).
//
// Contact value g(d): a straight line fitted by least squares to the bins' values against their
// centres, evaluated at r = d. Near contact g(r) of hard disks falls off smoothly (linearly to
// first order in r - d), so with w a small fraction of d (0.05 to 0.1 d) the line's bias is of
// second order in w; the fit averages the bins' noise instead of reading the first bin alone.
//
// Z by the contact route (2-D virial theorem for hard disks; Hansen & McDonald, Theory of Simple
// Liquids, sec. 2.5): Z = beta P / rho = 1 + (pi / 2) rho d^2 g(d) = 1 + 2 eta g(d), eta the
// area fraction N pi d^2 / (4 A).
#pragma once

#include <cstddef>
#include <vector>

#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide {

class ContactCorrelation {
public:
    // diameter d (the contact distance of equal disks), shell width w, bins in [d, d + w].
    ContactCorrelation(double diameter, double width, std::size_t bins);

    // Adds the pairs of one configuration of equal disks (N and the area fixed across calls).
    void add(const World& world, const ParticleState<double>& state);

    std::size_t configurations() const { return configurations_; }
    double bin_centre(std::size_t b) const;
    // g in bin b, averaged over the configurations added.
    double g(std::size_t b) const;
    // g(d) extrapolated by the least-squares line through the bins (above).
    double contact() const;
    // 1 + 2 eta g(d).
    double compressibility() const;

private:
    double diameter_, width_;
    std::vector<double> counts_;
    std::size_t configurations_ = 0;
    double ideal_pairs_per_area_ = 0;  // N (N - 1) / (2 A), summed over the configurations
    double area_fraction_ = 0;         // eta of the last configuration
};

}  // namespace collide
