#include "structure.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/complex.h>
#include <pybind11/numpy.h>

#include "core/structure/orientational_order.h"
#include "core/structure/pair_correlation.h"
#include "initialised_caster.h"

namespace py = pybind11;

namespace collide::python {
namespace {

// More bins than any histogram near contact needs: a guard against a typing slip (or hostile
// input) asking for terabytes.
constexpr std::size_t max_bins = 1'000'000;

void require_positive_finite(double value, const char* name) {
    if (!(value > 0) || !std::isfinite(value))
        throw py::value_error(std::string(name) + ": expected a positive finite number, got " + std::to_string(value));
}

// The configurations of `positions`: one (N, 2) array, or a stack (F, N, 2) of F configurations
// of the same N disks. Every coordinate must be finite.
std::vector<ParticleState<double>> configurations(const py::array_t<double, py::array::c_style | py::array::forcecast>& positions,
                                                  double radius) {
    if (positions.ndim() != 2 && positions.ndim() != 3)
        throw py::value_error("positions: expected an (N, 2) array or a stack (F, N, 2), got " +
                              std::to_string(positions.ndim()) + " dimensions");
    if (positions.shape(positions.ndim() - 1) != 2)
        throw py::value_error("positions: expected 2 coordinates (x, y) a disk in the last axis, got " +
                              std::to_string(positions.shape(positions.ndim() - 1)));
    const py::ssize_t frames = positions.ndim() == 3 ? positions.shape(0) : 1;
    const py::ssize_t disks = positions.shape(positions.ndim() - 2);
    if (frames == 0) throw py::value_error("positions: a stack of no configurations");
    const double* p = positions.data();
    std::vector<ParticleState<double>> out{std::size_t(frames)};
    for (py::ssize_t f = 0; f < frames; ++f)
        for (py::ssize_t i = 0; i < disks; ++i) {
            const double x = p[2 * (f * disks + i)], y = p[2 * (f * disks + i) + 1];
            if (!std::isfinite(x) || !std::isfinite(y))
                throw py::value_error("positions: disk " + std::to_string(i) + " of configuration " + std::to_string(f) +
                                      " is not finite (" + std::to_string(x) + ", " + std::to_string(y) + ")");
            out[std::size_t(f)].append_disk(x, y, 0, 0, radius, 1, false);
        }
    return out;
}

py::array_t<double> array_of(const std::vector<double>& values) { return py::array_t<double>(py::ssize_t(values.size()), values.data()); }

// g(r) over [d, d + width] in `bins` bins, summed over the configurations (ContactCorrelation).
py::dict pair_correlation(const Scene& scene, const py::array_t<double, py::array::c_style | py::array::forcecast>& positions,
                          double diameter, double width, std::size_t bins) {
    require_positive_finite(diameter, "diameter");
    require_positive_finite(width, "width");
    if (bins < 2 || bins > max_bins)
        throw py::value_error("bins: expected 2 to " + std::to_string(max_bins) + ", got " + std::to_string(bins));
    const World& w = scene.world;
    const double half_side = std::min(w.width(), w.height()) / 2;
    if (w.boundary == Boundary::periodic && diameter + width > half_side)
        throw py::value_error("width: in a periodic box g(r) is the nearest image's up to half the shorter side, r <= " +
                              std::to_string(half_side) + "; d + width = " + std::to_string(diameter + width));
    const std::vector<ParticleState<double>> states = configurations(positions, diameter / 2);
    if (states.front().size() < 2) throw py::value_error("positions: g(r) needs at least 2 disks");
    ContactCorrelation g(diameter, width, bins);
    for (const ParticleState<double>& s : states) g.add(scene.world, s);
    std::vector<double> r(bins), values(bins);
    for (std::size_t b = 0; b < bins; ++b) r[b] = g.bin_centre(b), values[b] = g.g(b);
    py::dict d;
    d["r"] = array_of(r);
    d["g"] = array_of(values);
    d["contact"] = g.contact();
    d["compressibility"] = g.compressibility();
    d["configurations"] = g.configurations();
    return d;
}

py::array_t<std::complex<double>> local_psi6_of(const Scene& scene,
                                                const py::array_t<double, py::array::c_style | py::array::forcecast>& positions,
                                                double cutoff) {
    require_positive_finite(cutoff, "cutoff");
    if (positions.ndim() != 2) throw py::value_error("positions: expected one configuration, an (N, 2) array");
    const std::vector<std::complex<double>> local = local_psi6(scene.world, configurations(positions, cutoff / 2).front(), cutoff);
    return py::array_t<std::complex<double>>(py::ssize_t(local.size()), local.data());
}

}  // namespace

void bind_structure(py::module_& m) {
    m.attr("PSI6_CUTOFF_DIAMETERS") = psi6_cutoff_diameters;
    m.def("pair_correlation", &pair_correlation, py::arg("scene"), py::arg("positions"), py::arg("diameter"),
          py::arg("width"), py::arg("bins"),
          "g(r) of equal disks of `diameter` in the scene's box (minimum image when periodic) over [d, d + width] in "
          "`bins` bins, from one configuration (N, 2) or a stack (F, N, 2): the pairs in each bin over the pairs an "
          "ideal gas of the same N and area puts there, N (N - 1) / 2 * pi (r2^2 - r1^2) / A. Returns a dict: r (bin "
          "centres), g, contact (g(d) by the least-squares line through the bins), compressibility (1 + 2 eta g(d)), "
          "configurations (core/structure/pair_correlation.h)");
    m.def("local_psi6", &local_psi6_of, py::arg("scene"), py::arg("positions"), py::arg("cutoff"),
          "The local bond-orientational order of every disk, (1/n_j) sum_k exp(6 i theta_jk) over its neighbours "
          "within `cutoff` (centre distance, minimum image when periodic; 0 without neighbours), as a complex array; "
          "collide uses cutoff = PSI6_CUTOFF_DIAMETERS * d (core/structure/orientational_order.h)");
    m.def("psi6", [](const Scene& scene, const py::array_t<double, py::array::c_style | py::array::forcecast>& positions,
                     double cutoff) {
              require_positive_finite(cutoff, "cutoff");
              if (positions.ndim() != 2) throw py::value_error("positions: expected one configuration, an (N, 2) array");
              return global_psi6(scene.world, configurations(positions, cutoff / 2).front(), cutoff);
          },
          py::arg("scene"), py::arg("positions"), py::arg("cutoff"),
          "The global psi6 of one configuration: the mean of local_psi6 (a complex number; |psi6| = 1 on a perfect "
          "hexagonal lattice, of order 1/sqrt(N) in a fluid)");
}

}  // namespace collide::python
