// collide.stationary_mean and collide.integrated_autocorrelation_time: the estimate every
// recorded pressure goes through (core/statistics/batch_means.h: the equilibration cut chosen
// from the data, tau_int, batch means), bound so that the course and notebooks apply the same
// cut and error bar to a series of their own (docs/python.md, "Statistics"). No second
// implementation.
#pragma once

#include <pybind11/pybind11.h>

namespace collide::python {

void bind_statistics(pybind11::module_& m);

}  // namespace collide::python
