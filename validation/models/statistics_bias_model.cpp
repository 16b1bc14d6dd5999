#include "validation/models/statistics_bias_model.h"

#include <cmath>
#include <limits>

namespace collide::validation {

const StatisticsBiasConstants& fitted_statistics_bias() {
    // Fitted by scripts/fit_statistics_bias.py (scripts/statistics_bias.toml: periodic_gas and
    // box_gas_1000, step and cpu, dt 1.6e-2 to 1e-3, 16 replicates of 8 time units).
    // c_Z: the pooled fit 1.115 +- 0.034 (chi^2/dof 1.15). The two gases alone give 1.03 +- 0.04
    // (box, area fraction 0.31) and 1.27 +- 0.06 (periodic, 0.22): a density dependence that
    // the first-order model leaves out, so the uncertainty is doubled to 0.07 and covers both
    // within 2.2 of it. c_nu: 0.80 +- 0.16 (chi^2/dof 0.13: the rate bias is barely resolved,
    // and consistent with the derived 1). A second run (2026-11-29, output every 0.08, after
    // event's new event order) gave 1.070 +- 0.034 pooled, 1.01 and 1.18 per gas, c_nu 0.83 +-
    // 0.16: inside these constants, which stay (docs/validation.md).
    static const StatisticsBiasConstants c{1.12, 0.07, 0.80, 0.16};
    return c;
}

BiasPrediction predicted_pressure_bias(double nu, double nu_se, double h, double shell,
                                       const StatisticsBiasConstants& c) {
    // Z_step - Z_exact = c_Z nu h / (4 s (2 + s)): the pairs delayed inside the contact shell.
    const double x = nu * h / (4 * shell * (2 + shell));
    BiasPrediction p;
    p.value = c.pressure * x;
    // Relative errors of c_Z and of the reference's nu add in quadrature.
    const double rel_nu = nu != 0 ? nu_se / nu : 0;
    p.uncertainty = std::fabs(x) * std::hypot(c.pressure_uncertainty, c.pressure * rel_nu);
    return p;
}

BiasPrediction predicted_collision_rate_bias(double nu, double nu_se, double h,
                                             const StatisticsBiasConstants& c) {
    // nu_step - nu_exact = -c_nu nu^2 h / 2: each collision cycle is longer by h/2 on average.
    const double x = -nu * nu * h / 2;
    BiasPrediction p;
    p.value = c.rate * x;
    const double rel_nu = nu != 0 ? 2 * nu_se / nu : 0;  // nu^2: twice the relative error
    p.uncertainty = std::fabs(x) * std::hypot(c.rate_uncertainty, c.rate * rel_nu);
    return p;
}

double bias_z_score(double measured, double se_diff, const BiasPrediction& predicted) {
    const double spread = std::hypot(se_diff, predicted.uncertainty);
    const double distance = std::fabs(measured - predicted.value);
    if (spread > 0) return distance / spread;
    return distance == 0 ? 0 : std::numeric_limits<double>::infinity();
}

}  // namespace collide::validation
