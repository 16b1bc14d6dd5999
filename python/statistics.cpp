#include "statistics.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "core/statistics/batch_means.h"

namespace py = pybind11;

namespace collide::python {
namespace {

using Series = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A 1-D series of finite numbers (a NaN would make every autocorrelation NaN and Sokal's window
// never close: an O(n^2) sum that means nothing).
std::vector<double> series_of(const Series& x) {
    if (x.ndim() != 1) throw py::value_error("series: expected a 1-D array, got " + std::to_string(x.ndim()) + " dimensions");
    std::vector<double> out(x.data(), x.data() + x.shape(0));
    for (std::size_t i = 0; i < out.size(); ++i)
        if (!std::isfinite(out[i]))
            throw py::value_error("series: entry " + std::to_string(i) + " is not finite (" + std::to_string(out[i]) + ")");
    return out;
}

py::dict stationary_mean(const Series& x, bool cut_from_data, std::size_t batches) {
    const std::vector<double> series = series_of(x);
    if (series.size() < 2) throw py::value_error("series: a mean with an error needs at least 2 entries");
    if (batches < 2) throw py::value_error("batches: at least 2 batch means make an error, got " + std::to_string(batches));
    const SeriesEstimate e = estimate_stationary_mean(series, cut_from_data, batches);
    py::list candidates;
    for (const CutCandidate& c : e.candidates) candidates.append(py::make_tuple(c.cut, c.effective_samples));
    py::dict d;
    d["mean"] = e.mean;
    d["error"] = e.error;
    d["autocorrelation_time"] = e.autocorrelation_time;
    d["equilibration_cut"] = e.equilibration_cut;
    d["used"] = e.used;
    d["batches"] = e.batches;
    d["batches_too_short"] = e.batches_too_short();
    d["candidates"] = candidates;
    return d;
}

}  // namespace

void bind_statistics(py::module_& m) {
    m.def("stationary_mean", &stationary_mean, py::arg("series"), py::arg("cut_from_data") = true,
          py::arg("batches") = 20,
          "The mean of a correlated series and its standard error as collide records every pressure "
          "(core/statistics/batch_means.h). The equilibration cut: among the starts t0 = 0, n/20, 2n/20, ... up to "
          "n/2, the one that leaves the most effectively independent samples (n - t0) / (2 tau_int) (Chodera, "
          "J. Chem. Theory Comput. 12, 1799 (2016)); then batch means over what is left. Returns a dict: mean, "
          "error, autocorrelation_time (tau_int of what is left, in entries), equilibration_cut and used (entries "
          "cut and kept), batches, batches_too_short (batches shorter than 5 tau_int: the error is too small), "
          "candidates ([(t0, effective samples), ...]; empty with cut_from_data=False)");
    m.def("integrated_autocorrelation_time",
          [](const Series& x) { return integrated_autocorrelation_time(series_of(x)); }, py::arg("series"),
          "tau_int = 1/2 + sum_k rho(k) of a series, summed to Sokal's window k >= 5 tau_int, in entries (0.5 for "
          "an uncorrelated series)");
}

}  // namespace collide::python
